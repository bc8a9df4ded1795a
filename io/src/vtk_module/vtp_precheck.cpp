#include "vtp_precheck.h"

#include <vtkAbstractArray.h>
#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <optional>
#include <sstream>
#include <vector>

namespace blayer::detail {

double vtp_decoded_bytes_allowed(std::size_t file_bytes) {
  return 64.0 * static_cast<double>(file_bytes) + 2.0 * 1024 * 1024 * 1024;
}

namespace {

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

// Consecutive bytes of one array's data as VTK reads them: raw from a position of the
// file, or decoded from base64 four characters at a time ('=' pads the last group of a
// separately encoded part: VTK encodes an array's header, then all its blocks, as two
// base64 streams).
class DataBytes {
 public:
  // run_end: for base64, where the run of base64 characters holding the data ends
  // (base64_run_end); ignored for raw data.
  DataBytes(std::string_view file, std::size_t pos, bool base64, std::size_t run_end)
      : file_(file), pos_(pos), base64_(base64), run_end_(run_end) {}

  // The next n bytes, or nullopt when the file ends first or a character is not base64.
  std::optional<std::string> read(std::size_t n) {
    std::string out;
    if (!base64_) {
      if (pos_ > file_.size() || file_.size() - pos_ < n) return std::nullopt;
      out.assign(file_.substr(pos_, n));
      pos_ += n;
      return out;
    }
    while (out.size() < n) {
      if (pending_.empty() && !decode_group()) return std::nullopt;
      const std::size_t take = std::min(n - out.size(), pending_.size());
      out.append(pending_, 0, take);
      pending_.erase(0, take);
    }
    return out;
  }

  // An upper bound on the bytes left after the current position.
  double bytes_left() const {
    if (!base64_) return pos_ >= file_.size() ? 0.0 : static_cast<double>(file_.size() - pos_);
    const std::size_t chars = run_end_ > pos_ ? run_end_ - pos_ : 0;  // the base64 run from here
    return static_cast<double>(pending_.size()) + 0.75 * static_cast<double>(chars);
  }

 private:
  bool decode_group() {
    if (pos_ > file_.size() || file_.size() - pos_ < 4) return false;
    int v[4];
    for (int k = 0; k < 4; ++k) v[k] = base64_value(file_[pos_ + k]);
    if (v[0] < 0 || v[1] < 0) return false;
    const bool pad2 = file_[pos_ + 2] == '=', pad3 = file_[pos_ + 3] == '=';
    if ((v[2] < 0 && !pad2) || (v[3] < 0 && !pad3) || (pad2 && !pad3)) return false;
    pending_.push_back(static_cast<char>((v[0] << 2) | (v[1] >> 4)));
    if (!pad2) pending_.push_back(static_cast<char>(((v[1] & 15) << 4) | (v[2] >> 2)));
    if (!pad3) pending_.push_back(static_cast<char>(((v[2] & 3) << 6) | v[3]));
    pos_ += 4;
    return true;
  }

  std::string_view file_;
  std::size_t pos_;
  bool base64_;
  std::size_t run_end_;
  std::string pending_;
};

// Where the run of base64 characters (and '=' padding) from pos ends.
std::size_t base64_run_end(std::string_view file, std::size_t pos) {
  std::size_t end = std::min(pos, file.size());
  while (end < file.size() && (base64_value(file[end]) >= 0 || file[end] == '=')) ++end;
  return end;
}

// How the file's header words are stored (the VTKFile element's attributes).
struct HeaderFormat {
  std::size_t word_bytes = 4;
  bool big_endian = false;
};

constexpr const char* kAllowance = " (64 times the file's size plus 2 GiB)";

std::uint64_t word_at(const std::string& bytes, std::size_t i, const HeaderFormat& f) {
  std::uint64_t v = 0;
  for (std::size_t b = 0; b < f.word_bytes; ++b) {
    const std::size_t at = i * f.word_bytes + (f.big_endian ? b : f.word_bytes - 1 - b);
    v = (v << 8) | static_cast<unsigned char>(bytes[at]);
  }
  return v;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Where VTK starts reading an inline array: after its start tag and the white space
// that follows (vtkXMLDataParser::SeekInlineDataPosition, from the same byte index).
std::size_t inline_data_position(vtkXMLDataElement& e, std::string_view file) {
  std::size_t i = static_cast<std::size_t>(std::max<vtkTypeInt64>(e.GetXMLByteIndex(), 0));
  while (i < file.size() && file[i] != '>') ++i;
  if (i < file.size()) ++i;
  while (i < file.size() && is_space(file[i])) ++i;
  return i;
}

// A byte count as a whole number, however large the claim.
std::string bytes_text(double bytes) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(0) << bytes;
  return out.str();
}

std::string named(vtkXMLDataElement& e) {
  const char* name = e.GetAttribute("Name");
  return std::string(e.GetName() ? e.GetName() : "element") + (name ? " \"" + std::string(name) + "\"" : " (no Name)");
}

// What one compressed array's header claims that the file cannot back ("claims ..."),
// or "".
std::string header_claim(DataBytes& data, const HeaderFormat& f, double block_allowed) {
  const std::optional<std::string> head = data.read(3 * f.word_bytes);
  if (!head) return "is cut short or not base64";
  const std::uint64_t blocks = word_at(*head, 0, f), block = word_at(*head, 1, f), last = word_at(*head, 2, f);
  std::ostringstream why;
  const double table = static_cast<double>(blocks) * static_cast<double>(f.word_bytes);
  if (table > data.bytes_left()) {
    why << "claims " << blocks << " blocks, a table of "
        << bytes_text(table) << " bytes, where the file holds " << bytes_text(data.bytes_left()) << " more bytes";
    return why.str();
  }
  if (static_cast<double>(block) > block_allowed || static_cast<double>(last) > block_allowed) {
    why << "claims blocks of " << std::max(block, last)
        << " bytes decompressed, more than " << bytes_text(block_allowed) << kAllowance;
    return why.str();
  }
  // VTK divides by the block size, and finds the block of an offset as offset / size
  // with the last block's size bounding the total: a zero size, a last block larger
  // than the others, or a last block without blocks makes it divide by zero or read
  // past its table of blocks.
  if (blocks == 0 && last != 0) {
    why << "claims 0 blocks but a last block of " << last << " bytes";
    return why.str();
  }
  if (blocks > 0 && block == 0) {
    why << "claims " << blocks << " blocks of 0 bytes";
    return why.str();
  }
  if (last > block) {
    why << "claims a last block of " << last
        << " bytes, larger than its blocks of " << block << " bytes";
    return why.str();
  }
  const std::optional<std::string> sizes = data.read(static_cast<std::size_t>(table));
  if (!sizes) return "is cut short or not base64";
  double compressed = 0;
  for (std::uint64_t i = 0; i < blocks; ++i) compressed += static_cast<double>(word_at(*sizes, i, f));
  if (compressed > data.bytes_left()) {
    why << "claims " << bytes_text(compressed)
        << " bytes of compressed blocks, where the file holds " << bytes_text(data.bytes_left()) << " more bytes";
    return why.str();
  }
  return "";
}

// VTK's points have 3 components (NumberOfComponents defaults to 1).
std::string check_points(vtkXMLDataElement& points) {
  for (int i = 0; i < points.GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement& a = *points.GetNestedElement(i);
    int components = 1;
    a.GetScalarAttribute("NumberOfComponents", components);
    if (components != 3)
      return "the points' " + named(a) + " has " + std::to_string(components) + " components per point, not 3";
  }
  return "";
}

std::string check_compressed_header(DataBytes data, const HeaderFormat& f, double block_allowed,
                                    const std::string& array) {
  const std::string claim = header_claim(data, f, block_allowed);
  return claim.empty() ? claim : "the compressed-data header of " + array + " " + claim + " (a corrupt header)";
}

// Bytes per value of a DataArray's type attribute (1 when unknown: the least any takes).
double value_bytes(vtkXMLDataElement& a) {
  int type = 0;
  return a.GetWordTypeAttribute("type", type) ? std::max(vtkAbstractArray::GetDataTypeSize(type), 1) : 1;
}

// What the element counts make VTK allocate before it reads any data: the points and
// every point- and cell-data array and each cell type's offsets, all sized from the
// counts summed over the pieces. A count too large for the allowance fails
// VTK's allocation, after which VTK 9.1 leaks the arrays it had made.
std::string count_problem(vtkXMLDataElement& root, double allowed) {
  std::vector<vtkXMLDataElement*> pieces;
  std::vector<vtkXMLDataElement*> stack{&root};
  while (!stack.empty()) {
    vtkXMLDataElement* e = stack.back();
    stack.pop_back();
    if (e->GetName() && std::strcmp(e->GetName(), "Piece") == 0) pieces.push_back(e);
    for (int i = 0; i < e->GetNumberOfNestedElements(); ++i) stack.push_back(e->GetNestedElement(i));
  }
  // Each count summed over the pieces: VTK sizes its arrays for the whole output.
  constexpr const char* kCounts[] = {"NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips",
                                     "NumberOfPolys"};
  double total[5] = {0, 0, 0, 0, 0};
  for (vtkXMLDataElement* piece : pieces)
    for (int k = 0; k < 5; ++k) {
      vtkIdType n = 0;
      if (piece->GetScalarAttribute(kCounts[k], n) && n > 0) total[k] += static_cast<double>(n);
    }
  const double points = total[0], cells = total[1] + total[2] + total[3] + total[4];
  std::ostringstream why;
  for (int k = 0; k < 5; ++k) {
    const double bytes = k == 0 ? 12.0 * total[k] : 4.0 * (total[k] + 1);
    if (total[k] > 0 && bytes > allowed) {
      why << "the pieces claim " << kCounts[k] << "=" << bytes_text(total[k]) << " in all, " << bytes_text(bytes)
          << " bytes or more, more than " << bytes_text(allowed) << kAllowance;
      return why.str();
    }
  }
  for (vtkXMLDataElement* piece : pieces)
    for (int i = 0; i < piece->GetNumberOfNestedElements(); ++i) {
      vtkXMLDataElement& group = *piece->GetNestedElement(i);
      const char* g = group.GetName();
      const bool per_point = g && (std::strcmp(g, "PointData") == 0 || std::strcmp(g, "Points") == 0);
      const bool per_cell = g && std::strcmp(g, "CellData") == 0;
      if (!per_point && !per_cell) continue;
      for (int j = 0; j < group.GetNumberOfNestedElements(); ++j) {
        vtkXMLDataElement& a = *group.GetNestedElement(j);
        int components = 1;
        a.GetScalarAttribute("NumberOfComponents", components);
        const double bytes = (per_point ? points : cells) * std::max(components, 1) * value_bytes(a);
        if (bytes > allowed) {
          why << named(a) << " of " << components << " components per " << (per_point ? "point" : "cell")
              << " needs " << bytes_text(bytes) << " bytes, more than " << bytes_text(allowed)
              << kAllowance;
          return why.str();
        }
      }
    }
  return "";
}

// The first element named `name` in document order, or null.
vtkXMLDataElement* find_element(vtkXMLDataElement& e, const char* name) {
  if (e.GetName() && std::strcmp(e.GetName(), name) == 0) return &e;
  for (int i = 0; i < e.GetNumberOfNestedElements(); ++i)
    if (vtkXMLDataElement* found = find_element(*e.GetNestedElement(i), name)) return found;
  return nullptr;
}

struct Walk {
  std::string_view file;
  bool compressed = false;
  HeaderFormat format;
  std::size_t appended_at = 0;   // where the appended data start (0 without them)
  bool appended_base64 = true;
  std::size_t appended_run_end = 0;  // base64: where their run of base64 characters ends
  double block_allowed = 0;

  // VTK reads an element that has an offset attribute from the appended data (an offset
  // that does not parse is 0), whatever its format says, and one without an offset
  // whose format is "binary" inline; whatever its tag is named.
  std::string array(vtkXMLDataElement& e) const {
    if (e.GetAttribute("offset")) {
      vtkTypeInt64 offset = 0;
      e.GetScalarAttribute("offset", offset);
      if (offset < 0 || static_cast<std::uint64_t>(offset) > file.size() - appended_at)
        return named(e) + " has an offset of " + std::to_string(offset) + " outside the file";
      const std::size_t at = appended_at + static_cast<std::size_t>(offset);
      const std::size_t run_end =
          !appended_base64 ? 0 : at <= appended_run_end ? appended_run_end : base64_run_end(file, at);
      return check_compressed_header(DataBytes(file, at, appended_base64, run_end), format, block_allowed, named(e));
    }
    const char* how = e.GetAttribute("format");
    if (!how || std::strcmp(how, "binary") != 0) return "";
    const std::size_t at = inline_data_position(e, file);
    return check_compressed_header(DataBytes(file, at, true, base64_run_end(file, at)), format, block_allowed,
                                   named(e));
  }

  std::string element(vtkXMLDataElement& e) const {
    const char* name = e.GetName();
    if (name && std::strcmp(name, "Points") == 0) {
      std::string why = check_points(e);
      if (!why.empty()) return why;
    }
    if (compressed) {
      std::string why = array(e);
      if (!why.empty()) return why;
    }
    for (int i = 0; i < e.GetNumberOfNestedElements(); ++i) {
      std::string why = element(*e.GetNestedElement(i));
      if (!why.empty()) return why;
    }
    return "";
  }
};

}  // namespace

std::string vtp_precheck_problem(std::string_view bytes) {
  std::istringstream stream{std::string(bytes)};
  vtkNew<vtkXMLDataParser> parser;
  parser->SetStream(&stream);
  // A file whose XML does not parse: the parser's error (the caller's captured VTK
  // messages) says why.
  if (!parser->Parse() || !parser->GetRootElement()) return "";
  vtkXMLDataElement& root = *parser->GetRootElement();
  Walk walk;
  walk.file = bytes;
  walk.block_allowed = vtp_decoded_bytes_allowed(bytes.size());
  const std::string counts = count_problem(root, walk.block_allowed);
  if (!counts.empty()) return counts;
  const char* compressor = root.GetAttribute("compressor");
  walk.compressed = compressor && *compressor;
  const char* header_type = root.GetAttribute("header_type");
  walk.format.word_bytes = header_type && std::strcmp(header_type, "UInt64") == 0 ? 8 : 4;
  const char* order = root.GetAttribute("byte_order");
  walk.format.big_endian = order && std::strcmp(order, "BigEndian") == 0;
  walk.appended_at =
      std::min(static_cast<std::size_t>(std::max<vtkTypeInt64>(parser->GetAppendedDataPosition(), 0)), bytes.size());
  // VTK reads appended data as base64 unless their encoding is "raw".
  if (vtkXMLDataElement* appended = find_element(root, "AppendedData")) {
    const char* encoding = appended->GetAttribute("encoding");
    walk.appended_base64 = !(encoding && std::strcmp(encoding, "raw") == 0);
  }
  // Where the appended base64 run ends, found once, and only if a header will be read
  // there (raw data need no run end; without compression no header is read at all).
  if (walk.compressed && walk.appended_base64) walk.appended_run_end = base64_run_end(bytes, walk.appended_at);
  return walk.element(root);
}

}  // namespace blayer::detail
