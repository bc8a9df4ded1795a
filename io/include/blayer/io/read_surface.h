// Reading a wall surface from a file, before any checking.
//
// Formats: STL (ascii and binary), OBJ, OFF, PLY (ascii and binary), legacy VTK
// PolyData (.vtk) by blayer's own parsers; VTK XML PolyData (.vtp) through VTK. A
// trailing ".gz" (e.g. "wing.off.gz") is decompressed first. Points keep the file's
// order; faces keep the file's order and winding, polygons included (prepare_surface
// triangulates and checks them).
//
// What every parser guarantees, whatever the bytes:
//   - it returns or throws InputError, in time proportional to the file's size: counts
//     in a header are checked against what the file holds before anything is reserved
//     ("the header claims 1000000000000 vertices, the file holds 8");
//   - every coordinate is read whole as a number of the file's precision (double for
//     OBJ, OFF, VTK and double PLY properties; float for STL and float PLY properties)
//     or refused naming the line or record, the vertex and the token ("'1e400' is
//     outside the range of double", "'abc' is not a number"); non-finite values (inf,
//     nan) are refused the same way;
//   - every vertex index is an integer that fits an int, or is refused likewise (the
//     range against the vertex count is prepare_surface's check).
// Messages start with the file name and, for text formats, the line: "wing.off:12: ...".
//
// STL has no vertex list: corners are merged into vertices by exact equality of their
// float coordinates, numbered in order of first appearance. Facets with two corners at
// the same point have zero area and no orientation; they are dropped, and a note says
// how many (PolygonSoup::notes).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "blayer/core/vec3.h"

namespace blayer {

struct PolygonSoup {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;  // vertex indices, as in the file (0-based)
  std::vector<std::string> notes = {};  // what the reader changed (dropped facets), for the user
};

// Throws InputError naming the file when it cannot be opened, has an unknown extension
// or cannot be parsed. An empty file is not an error here (prepare_surface rejects it).
PolygonSoup read_polygon_soup(const std::string& path);

// Parses a file's (decompressed) bytes as `format` ("stl", "obj", "off", "ply", "vtp",
// "vtk"); `name` is the file as shown in messages. Same contract as read_polygon_soup.
PolygonSoup parse_polygon_soup(std::string_view bytes, const std::string& format, const std::string& name);

// Lower-case extension without the dot and without a trailing ".gz": "stl", "off", ...
std::string surface_format(const std::string& path);

}  // namespace blayer
