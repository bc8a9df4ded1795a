#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "blayer/quality/mesh_check.h"

namespace blayer {

namespace {

void require_matching(const VolumeMesh& mesh, const MeshCheckReport& r, const char* where) {
  if (r.validity.size() != mesh.n_cells())
    throw std::invalid_argument(std::string(where) + ": the report has " + std::to_string(r.validity.size()) +
                                " cells, the mesh " + std::to_string(mesh.n_cells()) + "; check this mesh first");
}

void set_array(std::vector<DataArray>& arrays, DataArray a) {
  for (DataArray& existing : arrays)
    if (existing.name == a.name) {
      existing = std::move(a);
      return;
    }
  arrays.push_back(std::move(a));
}

// The validity and check_flags arrays of the cells `ids` (all cells when null), after
// the metrics in *out.
void append_validity_and_flags(const MeshCheckReport& r, const std::vector<std::size_t>* ids,
                               std::vector<DataArray>* out) {
  const std::size_t n = ids ? ids->size() : r.validity.size();
  DataArray validity{"validity", 1, ArrayValues(ValueType::kInt32, n)};
  DataArray flags{"check_flags", 1, ArrayValues(ValueType::kInt32, n)};
  std::int32_t* validity_out = validity.values.as<std::int32_t>().data();
  std::int32_t* flags_out = flags.values.as<std::int32_t>().data();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t c = ids ? (*ids)[i] : i;
    validity_out[i] = static_cast<std::int32_t>(r.validity[c]);
    flags_out[i] = static_cast<std::int32_t>(r.flags[c]);
  }
  out->push_back(std::move(validity));
  out->push_back(std::move(flags));
}

// The quality arrays of the cells `ids` (all cells when null).
std::vector<DataArray> quality_arrays(const MeshCheckReport& r, const std::vector<std::size_t>* ids) {
  const std::size_t n = ids ? ids->size() : r.validity.size();
  auto id = [&](std::size_t i) { return ids ? (*ids)[i] : i; };
  std::vector<DataArray> out;
  for (std::size_t k = 0; k < kCheckMetricNames.size(); ++k) {
    DataArray a{kCheckMetricNames[k], 1, ArrayValues(ValueType::kFloat32, n)};
    float* values = a.values.as<float>().data();
    for (std::size_t i = 0; i < n; ++i) values[i] = static_cast<float>(r.metrics[k][id(i)]);
    out.push_back(std::move(a));
  }
  append_validity_and_flags(r, ids, &out);
  return out;
}

}  // namespace

void add_quality_arrays(VolumeMesh& mesh, const MeshCheckReport& report) {
  require_matching(mesh, report, "add_quality_arrays");
  for (DataArray& a : quality_arrays(report, nullptr)) set_array(mesh.cell_data, std::move(a));
}

void move_quality_arrays(VolumeMesh& mesh, MeshCheckReport* report) {
  require_matching(mesh, *report, "move_quality_arrays");
  // The metrics side by side, each one's doubles freed as soon as they are copied: a
  // thread converts one metric at a time, so the memory held beyond the doubles is one
  // Float32 array per thread. Serially they took 33 ms of the perforated block's run,
  // most of it writing fresh memory.
  std::vector<DataArray> arrays(kCheckMetricNames.size());
  tbb::parallel_for(std::size_t{0}, kCheckMetricNames.size(), [&](std::size_t k) {
    arrays[k] = DataArray{kCheckMetricNames[k], 1, ArrayValues(ValueType::kFloat32, report->metrics[k])};
    std::vector<double>().swap(report->metrics[k]);
  });
  append_validity_and_flags(*report, nullptr, &arrays);
  for (DataArray& a : arrays) set_array(mesh.cell_data, std::move(a));
}

void add_quality_arrays(VolumeMesh& mesh) {
  MeshCheckReport report = check_volume_mesh(mesh);
  move_quality_arrays(mesh, &report);
}

VolumeMesh extract_bad_cells(const VolumeMesh& mesh, const MeshCheckReport& report) {
  require_matching(mesh, report, "extract_bad_cells");
  std::vector<std::size_t> bad;
  for (std::size_t c = 0; c < mesh.n_cells(); ++c)
    if (report.cell_fails(c)) bad.push_back(c);

  VolumeMesh out;
  std::vector<std::int64_t> new_id(mesh.points.size(), -1);
  std::vector<std::size_t> old_point;
  for (std::size_t c : bad) {
    std::int64_t nodes[8];
    const int k = corner_count(mesh.cell_types[c]);
    for (int i = 0; i < k; ++i) {
      const std::int64_t p = mesh.connectivity[mesh.offsets[c] + i];
      if (new_id[p] < 0) {
        new_id[p] = static_cast<std::int64_t>(out.points.size());
        out.points.push_back(mesh.points[p]);
        old_point.push_back(static_cast<std::size_t>(p));
      }
      nodes[i] = new_id[p];
    }
    out.add_cell(mesh.cell_types[c], nodes);
  }

  auto subset = [](const DataArray& a, const std::vector<std::size_t>& ids) {
    DataArray s{a.name, a.n_components, ArrayValues(a.type())};
    s.values.reserve(ids.size() * a.n_components);
    for (std::size_t i : ids)
      for (int k = 0; k < a.n_components; ++k) s.values.push_back(a.values[i * a.n_components + k]);
    return s;
  };
  for (const DataArray& a : mesh.point_data)
    if (a.values.size() == mesh.points.size() * a.n_components) out.point_data.push_back(subset(a, old_point));
  for (const DataArray& a : mesh.cell_data)
    if (a.values.size() == mesh.n_cells() * a.n_components) out.cell_data.push_back(subset(a, bad));
  for (DataArray& a : quality_arrays(report, &bad)) set_array(out.cell_data, std::move(a));
  DataArray original{"original_cell_id", 1, ArrayValues(ValueType::kInt32, std::vector<double>(bad.begin(), bad.end()))};
  set_array(out.cell_data, std::move(original));
  return out;
}

}  // namespace blayer
