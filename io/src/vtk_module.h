// The VTK readers and the .vtp writer, in a module loaded when the first of them is
// used instead of linked. VTK's libraries take 17 ms to load (an empty program linked
// to the five VTK libraries blayer uses: 21-22 ms against 4.3-4.7 ms, perf stat, 30
// runs, three times), in every run, while a run that reads an STL, OBJ, OFF or PLY
// surface and writes a .vtu needs none of them (the .vtu writer calls zlib and liblz4
// itself).
//
// The module (libblayer_vtk.so, built beside blayer_io) holds its own copy of the
// blayer code it uses. No exception crosses its boundary: each function reports a
// failure in a VtkCallError, which the caller here turns back into the exception it
// stands for. Internal to blayer_io.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/io/read_surface.h"
#include "blayer/io/vtk_io.h"

namespace blayer::detail {

// What a module function threw, as data.
struct VtkCallError {
  enum class Kind { kNone, kInput, kIo, kOther };
  Kind kind = Kind::kNone;
  std::string message;
};

// The module's functions; the version guards against a module left from another build.
struct VtkModule {
  static constexpr int kVersion = 1;
  int version = kVersion;
  // The .vtp file's polygons (parse_vtp's contract, surface_parsers.h), in this process;
  // with limit_memory, under an address-space limit set from the file's size first (for
  // a child process that exists only to parse).
  PolygonSoup (*parse_vtp)(std::string_view bytes, const std::string& name, bool limit_memory,
                           VtkCallError* error) = nullptr;
  // Writes the .vtp to `file` directly (the caller stages it); errors name `target`.
  void (*write_vtp)(const TriSurface& s, const std::vector<DataArray>& point_data,
                    const std::vector<DataArray>& cell_data, const std::string& file, const std::string& target,
                    VtkCompressor compressor, VtkCallError* error) = nullptr;
  // read_volume_mesh's contract (vtk_io.h).
  VolumeMeshFile (*read_volume_mesh)(const std::string& path, VtkCallError* error) = nullptr;
};

// Loads the module at `path` and keeps it loaded for the process. Throws IoError naming
// the path and why when it cannot be loaded or is from another build.
const VtkModule& load_vtk_module(const std::string& path);

// The module, loaded on first use (BLAYER_VTK_MODULE, the path the build gave it) and
// kept for the process. Throws IoError naming `target` (the file being read or
// written) and the reason, every time, when it cannot be loaded.
const VtkModule& vtk_module(const std::string& target);

// Throws the exception an error stands for (none for kNone).
void rethrow(const VtkCallError& error);

}  // namespace blayer::detail

// The module's one exported symbol.
extern "C" const blayer::detail::VtkModule* blayer_vtk_module();
