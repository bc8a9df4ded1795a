#include "vtu_writer.h"

#include <lz4.h>
#include <tbb/parallel_for.h>
#include <zlib.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <locale>
#include <vector>

#include "base64.h"
#include "blayer/core/errors.h"

namespace blayer {
namespace detail {

namespace {

// VTK's block size: 32 KiB of values before compression.
constexpr std::size_t kBlockBytes = 32768;
// Blocks converted and compressed together (2 MiB of values): enough work per run for
// the threads, little memory.
constexpr std::size_t kRunBlocks = 64;

// One DataArray: its XML attributes and how its values become bytes.
struct ArraySource {
  std::string name;
  const char* type;  // VTK's type name
  int n_components;
  int value_bytes;
  std::size_t n_values;  // scalar values (tuples x components)
  // Writes values [first, first + n) as bytes of `type` in the host's order.
  std::function<void(std::size_t first, std::size_t n, unsigned char* out)> fill;
};

template <class T, class Source>
void convert(const Source* from, std::size_t n, unsigned char* out) {
  for (std::size_t i = 0; i < n; ++i) {
    const T v = static_cast<T>(from[i]);
    std::memcpy(out + i * sizeof(T), &v, sizeof(T));
  }
}

template <class T>
ArraySource raw_source(const std::string& name, const char* type, int n_components, const T* data, std::size_t n) {
  return {name, type, n_components, static_cast<int>(sizeof(T)), n,
          [data](std::size_t first, std::size_t count, unsigned char* out) {
            std::memcpy(out, data + first, sizeof(T) * count);
          }};
}

ArraySource source_of(const DataArray& a) {
  const std::size_t n = a.values.size();
  switch (a.type()) {
    case ValueType::kInt32:
      return raw_source(a.name, "Int32", a.n_components, a.values.as<std::int32_t>().data(), n);
    case ValueType::kFloat32: return raw_source(a.name, "Float32", a.n_components, a.values.as<float>().data(), n);
    case ValueType::kFloat64: break;
  }
  return raw_source(a.name, "Float64", a.n_components, a.values.as<double>().data(), n);
}

// The connectivity's 32-bit ids as Int64, VTK's own id type, which every reader takes.
ArraySource widened_ids(const std::string& name, const std::vector<PointId>& ids) {
  const PointId* data = ids.data();
  return {name, "Int64", 1, 8, ids.size(), [data](std::size_t first, std::size_t count, unsigned char* out) {
            convert<std::int64_t>(data + first, count, out);
          }};
}

// A zlib stream that compresses one block at a time at a fixed level, as compress2
// does (deflateInit's window and memory level; deflateReset between blocks gives the
// same bytes as a new stream). compress2 allocates and frees the stream's state for
// every 32 KiB block (256 KiB and a few more by zlib's own formula for window 15 and
// memory level 8), and with the run's one malloc arena the threads waited on each other
// for it; a stream per thread and level is allocated once.
class Deflater {
 public:
  explicit Deflater(int level) { ok_ = deflateInit(&z_, level) == Z_OK; }
  ~Deflater() {
    if (ok_) deflateEnd(&z_);
  }
  Deflater(const Deflater&) = delete;
  Deflater& operator=(const Deflater&) = delete;
  // The zlib stream of raw in *out (resized to hold it); its size, 0 on failure.
  std::size_t compress(const std::vector<unsigned char>& raw, std::vector<unsigned char>* out) {
    if (!ok_ || deflateReset(&z_) != Z_OK) return 0;
    out->resize(deflateBound(&z_, static_cast<uLong>(raw.size())));
    z_.next_in = const_cast<Bytef*>(raw.data());
    z_.avail_in = static_cast<uInt>(raw.size());
    z_.next_out = out->data();
    z_.avail_out = static_cast<uInt>(out->size());
    return deflate(&z_, Z_FINISH) == Z_STREAM_END ? static_cast<std::size_t>(z_.total_out) : 0;
  }

 private:
  z_stream z_{};
  bool ok_ = false;
};

// One block compressed as VTK's compressors do it (vtkZLibDataCompressor: compress2 at
// the level, here its stream kept per thread; vtkLZ4DataCompressor: LZ4_compress_fast
// at the acceleration its level gives, 10 - level), called directly so that writing a
// .vtu needs no VTK library: they take 17 ms to load, on every run. Returns the
// compressed size, 0 on failure.
std::size_t compress_block(VtkCompressor c, const std::vector<unsigned char>& raw, std::vector<unsigned char>* out) {
  if (c == VtkCompressor::kLz4) {
    const int n = static_cast<int>(raw.size());
    out->resize(static_cast<std::size_t>(LZ4_compressBound(n)));
    const int size = LZ4_compress_fast(reinterpret_cast<const char*>(raw.data()), reinterpret_cast<char*>(out->data()),
                                       n, static_cast<int>(out->size()), 10 - kLz4Level);
    return size > 0 ? static_cast<std::size_t>(size) : 0;
  }
  thread_local Deflater deflater(kZlibLevel);
  return deflater.compress(raw, out);
}

// Floating-point values compress poorly (zlib level 1 shrinks the coordinates and
// quality measures of a layer mesh only to 80-94 %, at about 46 MB/s on one core), so
// with zlib their blocks are stored: deflate level 0, a valid zlib stream that every
// zlib reader inflates, written at memory speed (vtk_io.h has the measured effect).
// Integer arrays (connectivity: to 17 %) are compressed at level 1, as VTK does.
bool stored_block(VtkCompressor c, const ArraySource& a) { return c == VtkCompressor::kZlib && a.type[0] == 'F'; }

std::size_t store_block(const std::vector<unsigned char>& raw, std::vector<unsigned char>* out) {
  thread_local Deflater stored(0);
  return stored.compress(raw, out);
}

const char* compressor_name(VtkCompressor c) {
  return c == VtkCompressor::kLz4 ? "vtkLZ4DataCompressor" : "vtkZLibDataCompressor";
}

// Base64 of a byte stream written in pieces (base64.h): whole groups of three
// bytes as they come, the 0 to 2 left over carried to the next piece, '=' padding at
// the end.
class Base64Writer {
 public:
  explicit Base64Writer(std::ostream& out) : out_(out) {}
  void write(const unsigned char* data, std::size_t n) {
    std::size_t i = 0;
    while (carry_n_ > 0 && carry_n_ < 3 && i < n) carry_[carry_n_++] = data[i++];
    if (carry_n_ == 3) {
      encode(carry_, 3);
      carry_n_ = 0;
    }
    const std::size_t whole = (n - i) / 3 * 3;
    encode(data + i, whole);
    for (i += whole; i < n; ++i) carry_[carry_n_++] = data[i];
  }
  void finish() {
    encode(carry_, carry_n_);
    carry_n_ = 0;
  }

 private:
  // Groups of three bytes encode independently, so a long piece is encoded in chunks
  // of kEncodeChunk bytes (a multiple of 3) in parallel; only the last chunk may be
  // padded.
  void encode(const unsigned char* data, std::size_t n) {
    if (n == 0) return;
    text_.resize(4 * ((n + 2) / 3));
    const std::size_t n_chunks = (n + kEncodeChunk - 1) / kEncodeChunk;
    tbb::parallel_for(std::size_t(0), n_chunks, [&](std::size_t c) {
      const std::size_t first = c * kEncodeChunk, length = std::min(kEncodeChunk, n - first);
      encode_base64(data + first, length, text_.data() + first / 3 * 4);
    });
    out_.write(reinterpret_cast<const char*>(text_.data()), static_cast<std::streamsize>(text_.size()));
  }
  static constexpr std::size_t kEncodeChunk = 3 * 65536;
  std::ostream& out_;
  std::vector<unsigned char> text_;
  unsigned char carry_[3];
  int carry_n_ = 0;
};

void write_header(std::ostream& out, const std::vector<std::uint64_t>& words) {
  Base64Writer b(out);
  b.write(reinterpret_cast<const unsigned char*>(words.data()), 8 * words.size());
  b.finish();
}

// The base64 text of one array: the header (placeholder first), then its blocks, run by
// run, each run converted and compressed in parallel.
void write_array_data(std::ostream& out, const ArraySource& a, VtkCompressor compressor) {
  const std::size_t total = a.n_values * static_cast<std::size_t>(a.value_bytes);
  const std::size_t n_blocks = (total + kBlockBytes - 1) / kBlockBytes;
  const std::size_t values_per_block = kBlockBytes / static_cast<std::size_t>(a.value_bytes);
  std::vector<std::uint64_t> header(3 + n_blocks, 0);
  header[0] = n_blocks;
  header[1] = kBlockBytes;
  header[2] = total % kBlockBytes;
  const std::streampos header_at = out.tellp();
  write_header(out, header);
  Base64Writer data(out);
  std::vector<std::vector<unsigned char>> compressed(std::min(n_blocks, kRunBlocks));
  std::vector<unsigned char> run_bytes;
  for (std::size_t run = 0; run < n_blocks; run += kRunBlocks) {
    const std::size_t n_run = std::min(kRunBlocks, n_blocks - run);
    tbb::parallel_for(std::size_t(0), n_run, [&](std::size_t i) {
      const std::size_t b = run + i;
      const std::size_t first = b * values_per_block;
      const std::size_t n = std::min(values_per_block, a.n_values - first);
      thread_local std::vector<unsigned char> raw;
      raw.resize(n * static_cast<std::size_t>(a.value_bytes));
      a.fill(first, n, raw.data());
      std::vector<unsigned char>& c = compressed[i];
      std::size_t size;
      if (stored_block(compressor, a)) {
        size = store_block(raw, &c);
      } else {
        size = compress_block(compressor, raw, &c);
      }
      if (size == 0) throw IoError("cannot compress the values of array '" + a.name + "'");
      c.resize(size);
    });
    // The run's blocks, in order, as one piece for the encoder.
    run_bytes.clear();
    for (std::size_t i = 0; i < n_run; ++i) {
      header[3 + run + i] = compressed[i].size();
      run_bytes.insert(run_bytes.end(), compressed[i].begin(), compressed[i].end());
    }
    data.write(run_bytes.data(), run_bytes.size());
  }
  data.finish();
  const std::streampos end = out.tellp();
  out.seekp(header_at);
  write_header(out, header);
  out.seekp(end);
}

std::string xml_escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

void write_array(std::ostream& out, const ArraySource& a, VtkCompressor compressor) {
  out << "        <DataArray type=\"" << a.type << "\" Name=\"" << xml_escaped(a.name) << '"';
  if (a.n_components != 1) out << " NumberOfComponents=\"" << a.n_components << '"';
  out << " format=\"binary\">\n          ";
  write_array_data(out, a, compressor);
  out << "\n        </DataArray>\n";
}

bool little_endian() {
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

}  // namespace

void write_vtu_blocks(const VolumeMesh& mesh, const std::string& path, const std::string& target,
                      VtkCompressor compressor) {
  auto failed = [&target] { return IoError(target + ": cannot write the file (" + std::strerror(errno) + ")"); };
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw failed();
  out.imbue(std::locale::classic());  // counts without digit grouping, whatever the global locale
  const std::size_t n_cells = mesh.n_cells();
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
      << (little_endian() ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\" compressor=\""
      << compressor_name(compressor) << "\">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << mesh.points.size() << "\" NumberOfCells=\"" << n_cells << "\">\n";
  out << "      <PointData>\n";
  for (const DataArray& a : mesh.point_data) write_array(out, source_of(a), compressor);
  out << "      </PointData>\n      <CellData>\n";
  for (const DataArray& a : mesh.cell_data) write_array(out, source_of(a), compressor);
  out << "      </CellData>\n      <Points>\n";
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
  write_array(out,
              raw_source("Points", "Float64", 3, mesh.points.empty() ? nullptr : mesh.points.data()->data(),
                         3 * mesh.points.size()),
              compressor);
  out << "      </Points>\n      <Cells>\n";
  write_array(out, widened_ids("connectivity", mesh.connectivity), compressor);
  // VTK's offsets are the cells' ends: mesh.offsets without its leading 0.
  write_array(out, raw_source("offsets", "Int64", 1, mesh.offsets.data() + 1, n_cells), compressor);
  ArraySource types{"types", "UInt8", 1, 1, n_cells, [&mesh](std::size_t first, std::size_t n, unsigned char* o) {
                      for (std::size_t i = 0; i < n; ++i) o[i] = static_cast<unsigned char>(mesh.cell_types[first + i]);
                    }};
  write_array(out, types, compressor);
  out << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  // Some file systems report a failed write only when the file is closed.
  out.close();
  if (!out) throw failed();
}

}  // namespace detail
}  // namespace blayer
