#include "blayer/io/solver_mesh.h"

#include <cmath>

#include <algorithm>
#include <numeric>
#include <set>

#include "blayer/core/edge_topology.h"
#include "blayer/core/errors.h"
#include "blayer/core/surface_components.h"

namespace blayer {

namespace {

// Keeps the points cells use, in their order, and renumbers the connectivity.
VolumeMesh used_points_only(const VolumeMesh& mesh, std::vector<std::int64_t>* point_of_input) {
  point_of_input->assign(mesh.points.size(), -1);
  for (std::int64_t p : mesh.connectivity) (*point_of_input)[p] = 0;
  VolumeMesh out;
  for (std::size_t p = 0; p < mesh.points.size(); ++p) {
    if ((*point_of_input)[p] == -1) continue;
    (*point_of_input)[p] = static_cast<std::int64_t>(out.points.size());
    out.points.push_back(mesh.points[p]);
  }
  out.cell_types = mesh.cell_types;
  out.offsets = mesh.offsets;
  out.connectivity.reserve(mesh.connectivity.size());
  for (std::int64_t p : mesh.connectivity) out.connectivity.push_back((*point_of_input)[p]);
  return out;
}

// Patch of every boundary face: the listed patch whose triangle it is (for a quad: whose
// triangles both its halves are), or `rest`.
std::vector<int> classify_boundary(const MeshFaces& faces, const std::vector<PatchTriangles>& listed,
                                   const std::vector<std::int64_t>& point_of_input, int rest) {
  std::vector<std::pair<TriangleKey, int>> known;  // sorted key -> patch, first listing first
  for (std::size_t p = 0; p < listed.size(); ++p)
    for (const auto& t : listed[p].triangles) {
      const TriangleKey k = sorted_triangle(point_of_input.at(t[0]), point_of_input.at(t[1]), point_of_input.at(t[2]));
      if (k[0] < 0) continue;  // a triangle no cell touches
      known.emplace_back(k, static_cast<int>(p));
    }
  std::stable_sort(known.begin(), known.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  auto patch_of = [&](const TriangleKey& k) {
    auto it = std::lower_bound(known.begin(), known.end(), k,
                               [](const auto& entry, const TriangleKey& key) { return entry.first < key; });
    return it != known.end() && it->first == k ? it->second : -1;
  };
  std::vector<int> patch(faces.n_boundary(), rest);
  for (std::size_t f = faces.n_internal; f < faces.size(); ++f) {
    const auto& n = faces.nodes[f];
    if (faces.n_nodes[f] == 3) {
      const int p = patch_of(sorted_triangle(n[0], n[1], n[2]));
      if (p >= 0) patch[f - faces.n_internal] = p;
      continue;
    }
    // A quad (the top of a fan strip) is listed as its two halves, along either diagonal.
    for (int d = 0; d < 2; ++d) {
      const std::array<TriangleKey, 2> halves = quad_halves(n, d);
      const int a = patch_of(halves[0]);
      const int b = patch_of(halves[1]);
      if (a >= 0 && a == b) {
        patch[f - faces.n_internal] = a;
        break;
      }
    }
  }
  return patch;
}

}  // namespace

std::size_t SolverMesh::n_cells_of(CellType t) const {
  return static_cast<std::size_t>(std::count(cells.cell_types.begin(), cells.cell_types.end(), t));
}

SolverMesh make_solver_mesh(const VolumeMesh& mesh, const std::vector<PatchTriangles>& listed_in,
                            const std::string& rest_name, const SymmetryPlane* symmetry) {
  std::vector<PatchTriangles> listed = listed_in;
  int symmetry_patch = -1;
  if (symmetry) {
    for (std::size_t p = 0; p < listed.size() && symmetry_patch < 0; ++p)
      if (listed[p].kind == PatchKind::kSymmetry) symmetry_patch = static_cast<int>(p);
    if (symmetry_patch < 0) {
      symmetry_patch = static_cast<int>(listed.size());
      listed.push_back({"symmetry", PatchKind::kSymmetry, {}});
    }
  }
  std::set<std::string> names{rest_name};
  for (const PatchTriangles& p : listed)
    if (!names.insert(p.name).second) throw InputError("two boundary patches are named '" + p.name + "'");

  SolverMesh out;
  out.cells = used_points_only(mesh, &out.point_of_input);
  MeshFaces all = build_mesh_faces(out.cells);
  const int rest = static_cast<int>(listed.size());
  std::vector<int> patch = classify_boundary(all, listed, out.point_of_input, rest);
  if (symmetry) {
    // The rest's faces that lie in the plane: the layers' side faces over the cut.
    const double tol = kOnPlaneRelTol * bounding_box_diagonal(out.cells.points);
    for (std::size_t f = all.n_internal; f < all.size(); ++f) {
      int& pf = patch[f - all.n_internal];
      if (pf != rest) continue;
      bool on = true;
      for (int k = 0; k < all.n_nodes[f]; ++k)
        on = on && std::fabs(symmetry->signed_distance(out.cells.points[all.nodes[f][k]])) <= tol;
      if (on) pf = symmetry_patch;
    }
  }

  // Boundary faces patch by patch (stable: each patch keeps the owner order).
  std::vector<std::size_t> order(all.n_boundary());
  std::iota(order.begin(), order.end(), all.n_internal);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return patch[a - all.n_internal] < patch[b - all.n_internal];
  });
  MeshFaces& f = out.faces;
  f.n_internal = all.n_internal;
  f.nodes.assign(all.nodes.begin(), all.nodes.begin() + all.n_internal);
  f.n_nodes.assign(all.n_nodes.begin(), all.n_nodes.begin() + all.n_internal);
  f.owner.assign(all.owner.begin(), all.owner.begin() + all.n_internal);
  f.neighbour.assign(all.neighbour.begin(), all.neighbour.begin() + all.n_internal);
  for (std::size_t b : order) {
    f.nodes.push_back(all.nodes[b]);
    f.n_nodes.push_back(all.n_nodes[b]);
    f.owner.push_back(all.owner[b]);
    f.neighbour.push_back(-1);
  }

  std::vector<std::size_t> count(listed.size() + 1, 0);
  for (int p : patch) ++count[p];
  std::size_t start = f.n_internal;
  for (std::size_t p = 0; p <= listed.size(); ++p) {
    if (count[p] > 0) {
      const bool is_rest = p == listed.size();
      out.patches.push_back({is_rest ? rest_name : listed[p].name, is_rest ? PatchKind::kOpen : listed[p].kind,
                             start, count[p]});
    }
    start += count[p];
  }
  return out;
}

std::vector<PatchTriangles> wall_patches(const TriSurface& wall) {
  const SurfaceComponents comp = edge_connected_components(wall, build_edge_topology(wall));
  std::vector<PatchTriangles> out(comp.count);
  for (int c = 0; c < comp.count; ++c) out[c].name = comp.count == 1 ? "wall" : "wall_" + std::to_string(c + 1);
  for (std::size_t t = 0; t < wall.triangles.size(); ++t) {
    const Triangle& tri = wall.triangles[t];
    out[comp.of_triangle[t]].triangles.push_back({tri[0], tri[1], tri[2]});
  }
  return out;
}

PatchTriangles patch_triangles(const std::string& name, PatchKind kind, const TriSurface& s,
                               const std::vector<std::int64_t>& point_ids) {
  PatchTriangles out{name, kind, {}};
  out.triangles.reserve(s.triangles.size());
  for (const Triangle& t : s.triangles) {
    if (point_ids.empty())
      out.triangles.push_back({t[0], t[1], t[2]});
    else
      out.triangles.push_back({point_ids.at(t[0]), point_ids.at(t[1]), point_ids.at(t[2])});
  }
  return out;
}

}  // namespace blayer
