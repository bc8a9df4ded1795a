// Write time, file size and read time of the XML encodings VTK offers for a .vtu, on
// one generated boundary-layer mesh with the arrays blayer writes (point normals, column
// heights, stop reasons, layer counts; cell layers, the Float32 quality metrics,
// validity and flags). The mesh is an n x n wavy wall grid, each quad split into two
// triangles, extruded by `layers` prisms with growth 1.2.
//
// Usage: vtk_write_bench [n=500] [layers=10] [repeats=3] [dir=$TMPDIR]
//   (default 5,000,000 prisms, about 2.5 GB of memory and 2 GB of disk in dir), or
//        vtk_write_bench MESH.vtu [repeats=3] [dir=$TMPDIR]
//   to measure on a real mesh written by blayer (real coordinates and metrics compress
//   less well than the generated ones).
//
// Every encoding writes the same vtkUnstructuredGrid (read back from a file written
// by write_vtu, so it holds exactly the arrays write_vtu hands to VTK), which isolates
// the encoding from the conversion of blayer's arrays; write_vtu itself (blayer's own
// writer of the default encoding, blocks compressed in parallel) is timed at the end
// on the generated mesh. Runs are interleaved round-robin over the encodings so that load from other
// processes spreads over all of them; the fastest of `repeats` runs is reported (ASCII
// runs once: it is the slowest by far). Ratios are against the appended raw LZ4 layout
// blayer wrote before, which is not well-formed XML.
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "../common/stacked_prisms.h"
#include "blayer/io/vtk_io.h"
#include "blayer/quality/mesh_check.h"

namespace {

blayer::VolumeMesh make_prism_mesh(int n, int layers) {
  blayer::VolumeMesh m;
  blayer::DataArray normal{"normal", 3, std::vector<double>{}};
  blayer::DataArray height{"column_height", 1, std::vector<double>{}};
  blayer::DataArray reason{"stop_reason", 1, blayer::ArrayValues(blayer::ValueType::kInt32)};
  blayer::DataArray n_layers{"layers", 1, blayer::ArrayValues(blayer::ValueType::kInt32)};
  const double total = 1e-3 * (std::pow(1.2, layers) - 1.0) / 0.2;
  blayer::bench::add_stacked_points(m, n, layers, [&](double x, double y, double) {
    // The wall normal of the wavy surface, so the array is as varied as a real one.
    const double gx = -0.3 * std::cos(6.0 * x) * std::cos(4.0 * y), gy = 0.2 * std::sin(6.0 * x) * std::sin(4.0 * y);
    const double len = std::sqrt(gx * gx + gy * gy + 1.0);
    for (double x : {gx / len, gy / len, 1.0 / len}) normal.values.push_back(x);
    height.values.push_back(total);
    reason.values.push_back(0);
    n_layers.values.push_back(layers);
  });
  m.point_data = {std::move(normal), std::move(height), std::move(reason), std::move(n_layers)};
  blayer::bench::add_stacked_wedges(m, n, layers);
  blayer::add_quality_arrays(m);
  return m;
}

struct Encoding {
  const char* name;
  int data_mode;          // vtkXMLWriter::Ascii, Binary (inline base64) or Appended
  bool encode_appended;   // appended data as base64 (well-formed XML) or raw bytes (not XML)
  int compressor;         // vtkXMLWriterBase::NONE, ZLIB, LZ4
  int level;              // the writer's CompressionLevel, 1..9 (VTK's default is 5)
  bool well_formed_xml;
};

// The first entry is the reference of the ratios.
const std::vector<Encoding> kEncodings = {
    {"appended raw LZ4 (before)", vtkXMLWriter::Appended, false, vtkXMLWriterBase::LZ4, 5, false},
    {"appended base64 LZ4", vtkXMLWriter::Appended, true, vtkXMLWriterBase::LZ4, 5, true},
    {"inline LZ4", vtkXMLWriter::Binary, false, vtkXMLWriterBase::LZ4, 5, true},
    {"inline zlib 1", vtkXMLWriter::Binary, false, vtkXMLWriterBase::ZLIB, 1, true},
    {"inline zlib 3", vtkXMLWriter::Binary, false, vtkXMLWriterBase::ZLIB, 3, true},
    {"inline zlib 5 (VTK default)", vtkXMLWriter::Binary, false, vtkXMLWriterBase::ZLIB, 5, true},
    {"inline zlib 6 (zlib default)", vtkXMLWriter::Binary, false, vtkXMLWriterBase::ZLIB, 6, true},
    {"inline uncompressed", vtkXMLWriter::Binary, false, vtkXMLWriterBase::NONE, 5, true},
    {"ASCII", vtkXMLWriter::Ascii, false, vtkXMLWriterBase::NONE, 5, true},
};

struct Timing {
  double wall = 0.0;
  double cpu = 0.0;  // process CPU time: less sensitive to other processes than wall time
};

template <class F>
Timing time_it(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  f();
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
          static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC};
}

Timing write_with(const Encoding& e, vtkUnstructuredGrid* grid, const std::string& path) {
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetInputData(grid);
  w->SetFileName(path.c_str());
  w->SetDataMode(e.data_mode);
  w->SetEncodeAppendedData(e.encode_appended);
  w->SetCompressionLevel(e.level);
  w->SetCompressorType(e.compressor);
  w->SetHeaderTypeToUInt64();
  int ok = 0;
  const Timing t = time_it([&] { ok = w->Write(); });
  if (ok != 1 || w->GetErrorCode() != 0) {
    std::fprintf(stderr, "%s: cannot write\n", path.c_str());
    std::exit(1);
  }
  return t;
}

vtkSmartPointer<vtkUnstructuredGrid> read_grid(const std::string& path) {
  vtkNew<vtkXMLUnstructuredGridReader> r;
  r->SetFileName(path.c_str());
  r->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = r->GetOutput();
  return grid;
}

struct Result {
  Timing best{1e300, 0.0};
  double mb = 0.0;
  Timing read;
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  const bool from_file = argc > 1 && ends_with(argv[1], ".vtu");
  const int shift = from_file ? 1 : 0;  // a file replaces the two mesh-size arguments
  const int n = !from_file && argc > 1 ? std::atoi(argv[1]) : 500;
  const int layers = !from_file && argc > 2 ? std::atoi(argv[2]) : 10;
  const int repeats = argc > 3 - shift ? std::atoi(argv[3 - shift]) : 3;
  const std::filesystem::path dir =
      (argc > 4 - shift ? std::filesystem::path(argv[4 - shift]) : std::filesystem::temp_directory_path()) /
      ("blayer-vtk-write-bench-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto file = [&](std::size_t i) { return (dir / ("e" + std::to_string(i) + ".vtu")).string(); };

  blayer::VolumeMesh mesh;
  const std::string seed = from_file ? std::string(argv[1]) : (dir / "seed.vtu").string();
  if (!from_file) {
    const Timing t_gen = time_it([&] { mesh = make_prism_mesh(n, layers); });
    std::printf("mesh: %zu prisms, %zu points, %zu point and %zu cell arrays (generated in %.1f s)\n", mesh.n_cells(),
                mesh.points.size(), mesh.point_data.size(), mesh.cell_data.size(), t_gen.wall);
    blayer::write_vtu(mesh, seed);
  }
  const vtkSmartPointer<vtkUnstructuredGrid> grid = read_grid(seed);
  const vtkIdType n_cells = grid->GetNumberOfCells();
  if (from_file)
    std::printf("mesh: %s, %lld cells, %lld points\n", seed.c_str(), static_cast<long long>(n_cells),
                static_cast<long long>(grid->GetNumberOfPoints()));

  std::vector<Result> results(kEncodings.size());
  for (int r = 0; r < repeats; ++r)
    for (std::size_t i = 0; i < kEncodings.size(); ++i) {
      if (kEncodings[i].data_mode == vtkXMLWriter::Ascii && r > 0) continue;
      const Timing t = write_with(kEncodings[i], grid, file(i));
      if (t.wall < results[i].best.wall) results[i].best = t;
      std::fprintf(stderr, "  run %d %-30s %6.2f s\n", r + 1, kEncodings[i].name, t.wall);
    }
  for (std::size_t i = 0; i < kEncodings.size(); ++i) {
    results[i].mb = static_cast<double>(std::filesystem::file_size(file(i))) / 1e6;
    vtkIdType cells = 0;
    results[i].read = time_it([&] { cells = read_grid(file(i))->GetNumberOfCells(); });
    if (cells != n_cells) {
      std::fprintf(stderr, "%s: read back %lld cells of %lld\n", kEncodings[i].name, static_cast<long long>(cells),
                   static_cast<long long>(n_cells));
      return 1;
    }
    std::filesystem::remove(file(i));
  }

  const Result& ref = results[0];
  std::printf("\n| encoding | XML | write s (cpu s) | write / before | MB | size / before | read s |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (std::size_t i = 0; i < kEncodings.size(); ++i) {
    const Result& x = results[i];
    std::printf("| %s | %s | %.2f (%.2f) | %.2f | %.0f | %.2f | %.2f |\n", kEncodings[i].name,
                kEncodings[i].well_formed_xml ? "yes" : "no", x.best.wall, x.best.cpu, x.best.wall / ref.best.wall, x.mb,
                x.mb / ref.mb, x.read.wall);
  }

  if (from_file) {
    std::filesystem::remove_all(dir);
    return 0;
  }
  // write_vtu end to end (blayer's own writer), with either compressor.
  for (const blayer::VtkCompressor c : {blayer::VtkCompressor::kZlib, blayer::VtkCompressor::kLz4}) {
    blayer::VtkWriteOptions options;
    options.compressor = c;
    Timing best{1e300, 0.0};
    for (int r = 0; r < repeats; ++r) {
      const Timing t = time_it([&] { blayer::write_vtu(mesh, seed, options); });
      if (t.wall < best.wall) best = t;
    }
    std::printf("%swrite_vtu (%s) end to end: %.2f s (cpu %.2f s), %.0f MB\n",
                c == blayer::VtkCompressor::kZlib ? "\n" : "", c == blayer::VtkCompressor::kZlib ? "zlib" : "lz4",
                best.wall, best.cpu, static_cast<double>(std::filesystem::file_size(seed)) / 1e6);
  }
  std::filesystem::remove_all(dir);
  return 0;
}
