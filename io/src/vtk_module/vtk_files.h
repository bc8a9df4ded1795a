// What the VTK module (../vtk_module.h) does with VTK, as ordinary functions that throw
// blayer's exceptions; module_entry.cpp turns those into VtkCallErrors at the module's
// boundary. Linked into the module, and into the tests that call them directly.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/io/read_surface.h"
#include "blayer/io/vtk_io.h"

namespace blayer::detail {

// parse_vtp (surface_parsers.h) in this process; with limit_memory, under the
// address-space limit the file's size allows (vtp_parse.cpp), for a child process that
// exists only to parse.
PolygonSoup parse_vtp_with_vtk(std::string_view bytes, const std::string& name, bool limit_memory);

// The triangles of s as PolyData with the given arrays (sizes checked by the caller),
// written to `file` by VTK's writer with the compressor's settings (vtu_writer.h);
// IoError naming `target` when VTK cannot write it.
void write_vtp_file(const TriSurface& s, const std::vector<DataArray>& point_data,
                    const std::vector<DataArray>& cell_data, const std::string& file, const std::string& target,
                    VtkCompressor compressor);

// read_volume_mesh (vtk_io.h).
VolumeMeshFile read_volume_mesh_with_vtk(const std::string& path);

}  // namespace blayer::detail
