// VTK files: the volume mesh as .vtu (XML, appended binary, zlib-compressed), surfaces as
// .vtp, and reading any volume .vtu / legacy .vtk unstructured grid for `blayer check`.
// Every writer goes through AtomicFile: the target appears complete or not at all.
#pragma once

#include <string>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"

namespace blayer {

// Writes mesh (cells in VTK node order) with all its point and cell arrays.
// Throws IoError when the file cannot be written.
void write_vtu(const VolumeMesh& mesh, const std::string& path);

// Writes the triangles of s as PolyData with the given point and cell arrays
// (each array's tuple count must match the points or triangles).
void write_vtp(const TriSurface& s, const std::vector<DataArray>& point_data, const std::vector<DataArray>& cell_data,
               const std::string& path);

struct VolumeMeshFile {
  VolumeMesh mesh;
  int n_skipped_lower_dimension = 0;  // vertices, lines, triangles, quads in the file (boundary markers)
};

// Reads a .vtu or legacy .vtk unstructured grid. Linear tets, pyramids, wedges and hexes
// are kept with their point and cell arrays (as doubles); cells of lower dimension are
// skipped and counted; any other 3D cell type is an InputError naming the cell.
VolumeMeshFile read_volume_mesh(const std::string& path);

}  // namespace blayer
