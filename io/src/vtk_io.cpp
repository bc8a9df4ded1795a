#include "blayer/io/vtk_io.h"

#include <stdexcept>

#include "blayer/core/errors.h"
#include "blayer/io/atomic_file.h"
#include "vtk_module.h"
#include "vtu_writer.h"

namespace blayer {

namespace {

void check_size(const DataArray& a, std::size_t n, const char* what, const std::string& path) {
  if (a.n_components < 1 || a.values.size() != n * static_cast<std::size_t>(a.n_components))
    throw std::logic_error(path + ": array '" + a.name + "' has " + std::to_string(a.values.size()) +
                           " values for " + std::to_string(n) + " " + what);
}

}  // namespace

void write_vtu(const VolumeMesh& mesh, const std::string& path, const VtkWriteOptions& options) {
  for (const DataArray& a : mesh.point_data) check_size(a, mesh.points.size(), "points", path);
  for (const DataArray& a : mesh.cell_data) check_size(a, mesh.n_cells(), "cells", path);
  if (mesh.offsets.size() != mesh.cell_types.size() + 1 || mesh.offsets.front() != 0 ||
      mesh.offsets.back() != static_cast<std::int64_t>(mesh.connectivity.size()))
    throw std::logic_error(path + ": the mesh's cell offsets do not match its cells and connectivity");
  AtomicOutputs file;
  detail::write_vtu_blocks(mesh, file.stage(path), path, options.compressor);
  file.commit();
}

void write_vtp(const TriSurface& s, const std::vector<DataArray>& point_data, const std::vector<DataArray>& cell_data,
               const std::string& path, const VtkWriteOptions& options) {
  for (const DataArray& a : point_data) check_size(a, s.points.size(), "points", path);
  for (const DataArray& a : cell_data) check_size(a, s.triangles.size(), "triangles", path);
  const detail::VtkModule& vtk = detail::vtk_module(path);
  AtomicOutputs file;
  detail::VtkCallError error;
  vtk.write_vtp(s, point_data, cell_data, file.stage(path), path, options.compressor, &error);
  detail::rethrow(error);
  file.commit();
}

VolumeMeshFile read_volume_mesh(const std::string& path) {
  detail::VtkCallError error;
  VolumeMeshFile mesh = detail::vtk_module(path).read_volume_mesh(path, &error);
  detail::rethrow(error);
  return mesh;
}

}  // namespace blayer
