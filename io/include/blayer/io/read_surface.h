// Reading a wall surface from a file, before any checking.
//
// Formats: STL (ascii and binary), OBJ, OFF, PLY through OpenMesh's readers; VTK
// PolyData (.vtp, legacy .vtk) through VTK. A trailing ".gz" (e.g. "wing.off.gz") is
// decompressed first. Points keep the file's order; faces keep the file's order and
// winding, polygons included (prepare_surface triangulates and checks them).
#pragma once

#include <string>
#include <vector>

#include "blayer/core/vec3.h"

namespace blayer {

struct PolygonSoup {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;  // vertex indices, as in the file (0-based)
};

// Throws InputError naming the file when it cannot be opened, has an unknown extension
// or cannot be parsed. An empty file is not an error here (prepare_surface rejects it).
PolygonSoup read_polygon_soup(const std::string& path);

// Lower-case extension without the dot and without a trailing ".gz": "stl", "off", ...
std::string surface_format(const std::string& path);

}  // namespace blayer
