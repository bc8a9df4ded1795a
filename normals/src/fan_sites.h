// The sites of the most-normal problem of one closed fan (docs/normals.md, Part 4):
// link arcs merged along common great circles, and reflex link vertices. Internal to
// blayer_normals.
#pragma once

#include <vector>

#include "blayer/core/tolerances.h"
#include "blayer/core/vec3.h"
#include "blayer/normals/fan_geometry.h"

namespace blayer {
namespace detail {

// A merged arc: the fan's arcs first_face .. first_face + n_faces - 1 (mod k), all on
// the great circle with normal g, from u to v (length < pi).
struct ArcSite {
  Vec3 u, v, g;
  int first_face = 0;
  int n_faces = 1;
};

// A reflex link vertex (f_{j-1}.u_{j+1} < 0): the fluid wedge there exceeds 180 degrees.
struct PointSite {
  Vec3 w;
  int vertex = 0;
};

struct FanSites {
  std::vector<ArcSite> arcs;
  std::vector<PointSite> points;
  std::vector<int> arc_of_face;      // merged arc holding each fan arc
  std::vector<int> point_of_vertex;  // point site of each link vertex, -1 if not reflex
  bool all_reflex = false;           // every junction reflex or straight (convex corner)
};

// Faces whose unit normals lie within this (Euclidean) distance of a run's first face
// are one plane for the candidate passes that go face by face (plateau peaks of V,
// constraint circles): a fan-triangulated CAD face puts dozens of faces on one plane, and
// their pairs would all be tried for candidates that coincide. Such normals differ by
// rounding (about 1e-16, up to ~1e-14 for thin triangles); a candidate built on one
// face's circle then misses the constraint of another of its run by at most 2e-13, five
// times inside kConstraintSlack (1e-12), and is kept as that face's own would be.
constexpr double kSamePlaneNormal = 1e-13;

// The first face of each face's run of consecutive faces (in link order, from face 0)
// within kSamePlaneNormal of that first face's normal; a face starting a run is its own.
void same_plane_runs(const FanGeometry& g, std::vector<int>* first);

// Keeps in *faces one face of each run of same_plane_runs (`first`), the first listed,
// in the list's order: the candidates of that plane are built from it alone.
void drop_repeated_planes(const std::vector<int>& first, std::vector<int>* faces);

// Indices of the points and arcs of a FanSites taking part.
struct SiteSubset {
  const int* points = nullptr;
  int n_points = 0;
  const int* arcs = nullptr;
  int n_arcs = 0;
};

// Junction j (between arcs j-1 and j at dirs[j]) is straight when
// |f_{j-1}.u_{j+1}| <= tol.coplanar_arc with f_{j-1}.f_j > 0, reflex when not straight
// and f_{j-1}.u_{j+1} < 0. Consecutive arcs over straight junctions merge while the
// merged length stays below pi. Sites are listed in link order, starting after the
// first non-straight junction.
void build_fan_sites(const FanGeometry& g, const Tolerances& tol, FanSites* out);

}  // namespace detail
}  // namespace blayer
