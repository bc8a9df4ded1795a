#include "plane_facet.h"

// CGAL's 2D constrained Delaunay triangulation and mesher, in this translation unit only
// (each CGAL unit costs ~30 s and ~1 GB to compile).
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include "blayer/core/assert.h"
#include "blayer/core/errors.h"

namespace blayer::fill_detail {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
// 0.125 is CGAL's bound B on sin^2 of the smallest angle: 20.7 degrees, the largest for
// which Delaunay refinement is guaranteed to terminate.
constexpr double kShapeBound = 0.125;

// Triangles are bad when their smallest angle is below the bound (BAD) or their longest
// edge exceeds the local target size at their centroid (IMPERATIVELY_BAD, refined
// first, largest overshoot first): the fill's graded size field, so the facet's
// triangles grow from the layers' cut to the box like the tets beside them.
class GradedCriteria : public CGAL::Delaunay_mesh_criteria_2<Cdt> {
 public:
  using Base = CGAL::Delaunay_mesh_criteria_2<Cdt>;
  using SizeAt = std::function<double(const K::Point_2&)>;

  // first: squared sine of the smallest angle; second: (longest edge / target size)^2.
  struct Quality : public std::pair<double, double> {
    Quality() = default;
    Quality(double sine, double size) : std::pair<double, double>(sine, size) {}
    double sine() const { return first; }
    double size() const { return second; }
    bool operator<(const Quality& q) const {
      if (size() > 1 || q.size() > 1) return size() > q.size();
      return sine() < q.sine();
    }
  };

  class Is_bad : public Base::Is_bad {
   public:
    Is_bad(double bound, const SizeAt* size) : Base::Is_bad(bound, K()), size_(size) {}
    CGAL::Mesh_2::Face_badness operator()(const Quality q) const {
      if (q.size() > 1) return CGAL::Mesh_2::IMPERATIVELY_BAD;
      return q.sine() < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }
    CGAL::Mesh_2::Face_badness operator()(const Cdt::Face_handle& fh, Quality& q) const {
      const K::Point_2& a = fh->vertex(0)->point();
      const K::Point_2& b = fh->vertex(1)->point();
      const K::Point_2& c = fh->vertex(2)->point();
      const double la = CGAL::squared_distance(b, c), lb = CGAL::squared_distance(c, a), lc = CGAL::squared_distance(a, b);
      const double longest = std::max({la, lb, lc});
      const double shortest = std::min({la, lb, lc});
      const double area = std::fabs(CGAL::area(a, b, c));
      // sin^2 of the smallest angle: (2 area)^2 / (product of its two sides squared).
      const double sine = 4.0 * area * area / (longest * (la + lb + lc - longest - shortest));
      const K::Point_2 centroid((a.x() + b.x() + c.x()) / 3.0, (a.y() + b.y() + c.y()) / 3.0);
      const double target = (*size_)(centroid);
      q = Quality(sine, longest / (target * target));
      return operator()(q);
    }

   private:
    const SizeAt* size_;
  };

  GradedCriteria(double bound, SizeAt size) : Base(bound), size_(std::move(size)) {}
  Is_bad is_bad_object() const { return Is_bad(this->bound(), &size_); }

 private:
  SizeAt size_;
};

using Mesher = CGAL::Delaunay_mesher_no_edge_refinement_2<Cdt, GradedCriteria>;

}  // namespace

PlaneFacet triangulate_plane_facet(const PlaneFacetInput& in, const SymmetryPlane& plane,
                                   const std::function<double(const Vec3&)>& size) {
  BLAYER_ASSERT(plane.axis >= 0);
  const int u = (plane.axis + 1) % 3, v = (plane.axis + 2) % 3;
  auto to2 = [&](const Vec3& p) { return K::Point_2(p[u], p[v]); };
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handle(in.points.size());
  for (std::size_t i = 0; i < in.points.size(); ++i) {
    handle[i] = cdt.insert(to2(in.points[i]));
    handle[i]->info() = static_cast<int>(i);
  }
  for (const auto& e : in.edges) cdt.insert_constraint(handle[e.first], handle[e.second]);
  if (cdt.number_of_vertices() != in.points.size())
    throw InputError("symmetry plane facet: two points of the plane's boundary or the layers' cut coincide");

  GradedCriteria criteria(kShapeBound, [&](const K::Point_2& q) {
    Vec3 p;
    p[plane.axis] = plane.offset;
    p[u] = q.x();
    p[v] = q.y();
    return size(p);
  });
  Mesher mesher(cdt, criteria);
  const std::vector<K::Point_2> seeds{to2(in.inside_point)};
  mesher.set_seeds(seeds.begin(), seeds.end(), true);
  mesher.refine_mesh();

  PlaneFacet out;
  const int n_in = static_cast<int>(in.points.size());
  // The refinement's vertices carry no index yet: the input ones are known by handle.
  std::map<Cdt::Vertex_handle, int> input_index;
  for (int i = 0; i < n_in; ++i) input_index[handle[i]] = i;
  for (auto vit = cdt.finite_vertices_begin(); vit != cdt.finite_vertices_end(); ++vit) {
    const auto known = input_index.find(vit);
    if (known != input_index.end()) {
      vit->info() = known->second;
      continue;
    }
    vit->info() = n_in + static_cast<int>(out.new_points.size());
    Vec3 p;
    p[plane.axis] = plane.offset;
    p[u] = vit->point().x();
    p[v] = vit->point().y();
    out.new_points.push_back(p);
  }
  for (auto fit = cdt.finite_faces_begin(); fit != cdt.finite_faces_end(); ++fit) {
    if (!fit->is_in_domain()) continue;
    std::array<int, 3> t{fit->vertex(0)->info(), fit->vertex(1)->info(), fit->vertex(2)->info()};
    // CGAL's faces are counter-clockwise in (u, v): their normal is +e_axis (u x v = axis).
    if (plane.normal[plane.axis] < 0) std::swap(t[1], t[2]);
    out.triangles.push_back(t);
  }
  if (out.triangles.empty())
    throw InputError("symmetry plane facet: the region between the farfield and the layers' cut is empty");
  return out;
}

}  // namespace blayer::fill_detail
