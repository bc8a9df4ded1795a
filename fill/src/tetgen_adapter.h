// Plain-data wrapper around one tetrahedralize() call. The only file that includes
// tetgen.h is tetgen_adapter.cpp. Meant to run inside run_isolated(): TetGen may crash.
#pragma once

#include <string>
#include <vector>

namespace blayer::fill_detail {

struct TetgenPlc {
  std::vector<double> points;        // #P by 3
  std::vector<int> triangles;        // #F by 3, 0-based; each becomes a one-polygon facet
  std::vector<int> markers;          // #F facet markers
  std::vector<double> holes;         // #H by 3 hole seeds
  std::vector<double> point_metric;  // empty, or #P circumradius bounds (m switch)
};

struct TetgenMesh {
  std::vector<double> points;  // #P by 3; the input points first, in input order
  std::vector<int> tets;       // #T by 4, TetGen's corner order
  std::vector<int> faces;      // #F by 3: boundary faces, or intersecting faces with d
  std::vector<int> face_markers;
};

// Runs TetGen with the given switch string (0-based indices). Throws TetGen's int on
// failure; may crash on bad input.
TetgenMesh run_tetgen(const TetgenPlc& plc, const std::string& switches);

// Flat binary encoding for the pipe between the child and the caller.
std::string encode(const TetgenMesh& m);
// Throws std::runtime_error when the bytes are truncated or inconsistent.
TetgenMesh decode(const std::string& bytes);

// Meaning of TetGen 1.5's thrown error codes.
std::string describe_tetgen_error(int code);

}  // namespace blayer::fill_detail
