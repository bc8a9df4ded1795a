#include <cmath>
#include <cstdio>
#include <string>

#include "blayer/quality/mesh_check.h"

namespace blayer {

namespace {

constexpr const char* kTypeNames[4] = {"tet", "pyramid", "wedge", "hex"};

void append_counts(std::string& out, const CheckCounts& c, const char* indent) {
  out += indent;
  out += "cells: " + std::to_string(c.cells) + " (";
  for (int t = 0; t < 4; ++t) out += std::string(t ? ", " : "") + kTypeNames[t] + " " + std::to_string(c.by_type[t]);
  out += ")\n";
  out += std::string(indent) + "inverted: " + std::to_string(c.inverted) + "  twisted: " + std::to_string(c.twisted) +
         "  flat: " + std::to_string(c.flat) +
         "  non-conforming: " + std::to_string(c.non_conforming) + "\n";
  char line[256];
  std::snprintf(line, sizeof line, "%s%-20s %10s %11s %11s %11s %11s %11s %11s %11s\n", indent, "metric", "count",
                "min", "p1", "p5", "p50", "p95", "p99", "max");
  out += line;
  for (const MetricSummary& m : c.metrics) {
    std::snprintf(line, sizeof line, "%s%-20s %10zu %11.4g %11.4g %11.4g %11.4g %11.4g %11.4g %11.4g\n", indent,
                  m.name.c_str(), m.count, m.min, m.p1, m.p5, m.p50, m.p95, m.p99, m.max);
    out += line;
  }
}

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json counts_json(const CheckCounts& c, nlohmann::json j) {
  j["cells"] = c.cells;
  j["inverted"] = c.inverted;
  j["twisted"] = c.twisted;
  j["flat"] = c.flat;
  j["non_conforming"] = c.non_conforming;
  nlohmann::json metrics = nlohmann::json::object();
  for (const MetricSummary& m : c.metrics)
    metrics[m.name] = {{"count", m.count}, {"min", number(m.min)}, {"p1", number(m.p1)},   {"p5", number(m.p5)},
                       {"p50", number(m.p50)}, {"p95", number(m.p95)}, {"p99", number(m.p99)}, {"max", number(m.max)}};
  j["metrics"] = metrics;
  return j;
}

}  // namespace

std::string format_check_report(const MeshCheckReport& r) {
  std::string out;
  out += std::string("mesh check: ") + (r.ok() ? "OK" : "FAILED") + "\n";
  out += "points: " + std::to_string(r.n_points) + "\n";
  append_counts(out, r.totals, "");
  out += "faces: boundary " + std::to_string(r.boundary_faces) + ", non-conforming " +
         std::to_string(r.non_conforming_faces) + ", shared by more than two cells " +
         std::to_string(r.overshared_faces) + ", misoriented " + std::to_string(r.misoriented_faces) + "\n";
  for (const LayerCheck& l : r.layers) {
    out += "layer " + std::to_string(l.layer) + ":\n";
    append_counts(out, l.counts, "  ");
  }
  return out;
}

nlohmann::json check_report_to_json(const MeshCheckReport& r) {
  nlohmann::json j = counts_json(r.totals, nlohmann::json::object());
  j["ok"] = r.ok();
  j["n_cells"] = r.totals.cells;
  j["n_points"] = r.n_points;
  nlohmann::json by_type = nlohmann::json::object();
  for (int t = 0; t < 4; ++t) by_type[kTypeNames[t]] = r.totals.by_type[t];
  j["cells"] = by_type;
  j["non_conforming_faces"] = r.non_conforming_faces;
  j["overshared_faces"] = r.overshared_faces;
  j["misoriented_faces"] = r.misoriented_faces;
  j["boundary_faces"] = r.boundary_faces;
  j["min_scaled_jacobian"] = r.totals.cells ? number(r.min_scaled_jacobian()) : nlohmann::json(nullptr);
  if (!r.layers.empty()) {
    nlohmann::json layers = nlohmann::json::array();
    for (const LayerCheck& l : r.layers) layers.push_back(counts_json(l.counts, {{"layer", l.layer}}));
    j["layers"] = layers;
  }
  return j;
}

}  // namespace blayer
