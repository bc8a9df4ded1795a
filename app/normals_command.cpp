#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>

#include "blayer/core/errors.h"
#include "blayer/core/percentile.h"
#include "blayer/core/stopwatch.h"
#include "blayer/io/prepare_surface.h"
#include "blayer/io/vtk_io.h"
#include "mesh_output.h"
#include "blayer/normals/point_normals.h"
#include "commands.h"
#include "surface_options.h"

namespace blayer {

namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

}  // namespace

int run_normals_command(const ParamValues& params) {
  const std::string input = params.get_string("input");
  const std::string output = params.get_string("output");
  if (input.empty()) throw InputError("no input surface given (blayer normals SURFACE -o OUT.vtp)");
  if (output.empty()) throw InputError("no output file given (-o OUT.vtp)");
  NormalMethod method;
  if (!parse_normal_method(params.get_string("method"), &method))
    throw InputError("--method: unknown normal method '" + params.get_string("method") + "'");

  const Stopwatch total;
  const PreparedSurface prepared = load_surface(input, surface_options(params));
  for (const std::string& n : prepared.notes) std::cout << "note: " << n << "\n";
  const TriSurface& s = prepared.surface;
  const Stopwatch solve;
  const VertexFans fans = build_vertex_fans(s);
  const PointNormals pn = compute_point_normals(s, fans, method);
  const double solve_seconds = solve.seconds();

  const std::size_t nv = s.points.size();
  DataArray normal{"normal", 3, {}}, vis{"visibility", 1, {}}, nd{"normality_deg", 1, {}},
      st{"normal_status", 1, ArrayValues(ValueType::kInt32)};
  normal.values.reserve(3 * nv);
  for (std::size_t i = 0; i < nv; ++i) {
    for (int k = 0; k < 3; ++k) normal.values.push_back(pn.normal[i][k]);
    vis.values.push_back(pn.visibility[i]);
    nd.values.push_back(pn.normality[i] * kRadToDeg);
    st.values.push_back(static_cast<int>(pn.status[i]));
  }
  write_vtp(s, {normal, vis, nd, st}, {}, output, vtk_write_options(params));

  std::map<int, int> per_status;
  for (NormalStatus x : pn.status) ++per_status[static_cast<int>(x)];
  const double min_v = nv ? *std::min_element(pn.visibility.begin(), pn.visibility.end()) : 0.0;
  std::printf("blayer normals: %zu vertices, %zu triangles, method %s\n", nv, s.triangles.size(),
              normal_method_name(method));
  for (const auto& [code, count] : per_status)
    std::printf("  status %-24s %d\n", normal_status_name(static_cast<NormalStatus>(code)), count);
  std::printf("  min visibility (min n.f)  %.6f  (max face-normal angle %.3f deg)\n", min_v,
              std::acos(std::clamp(min_v, -1.0, 1.0)) * kRadToDeg);
  const std::vector<double> nd_pct = percentiles(nd.values.as<double>(), {0.0, 0.01, 0.5});
  std::printf("  normality D [deg]         min %.4f  p1 %.4f  p50 %.4f\n", nd_pct[0], nd_pct[1], nd_pct[2]);
  std::printf("  time                      %.3f s normals (%.0f vertices/s), %.3f s in all\n", solve_seconds,
              solve_seconds > 0 ? static_cast<double>(nv) / solve_seconds : 0.0, total.seconds());
  std::printf("  wrote %s\n", output.c_str());
  return 0;
}

}  // namespace blayer
