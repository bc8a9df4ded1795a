// The VTK module's entry point (../vtk_module.h): its functions with every exception
// caught at the boundary and handed back as a VtkCallError.
#include <exception>
#include <new>

#include "blayer/core/errors.h"
#include "vtk_files.h"
#include "vtk_module.h"

namespace blayer::detail {

namespace {

template <class Call>
auto caught(VtkCallError* error, Call&& call) -> decltype(call()) {
  *error = VtkCallError{};
  try {
    return call();
  } catch (const InputError& e) {
    *error = {VtkCallError::Kind::kInput, e.what()};
  } catch (const IoError& e) {
    *error = {VtkCallError::Kind::kIo, e.what()};
  } catch (const std::exception& e) {
    *error = {VtkCallError::Kind::kOther, e.what()};
  } catch (...) {
    *error = {VtkCallError::Kind::kOther, "an unknown exception inside VTK"};
  }
  return decltype(call())();
}

PolygonSoup parse_vtp(std::string_view bytes, const std::string& name, bool limit_memory, VtkCallError* error) {
  return caught(error, [&] { return parse_vtp_with_vtk(bytes, name, limit_memory); });
}

void write_vtp(const TriSurface& s, const std::vector<DataArray>& point_data, const std::vector<DataArray>& cell_data,
               const std::string& file, const std::string& target, VtkCompressor compressor, VtkCallError* error) {
  caught(error, [&] { write_vtp_file(s, point_data, cell_data, file, target, compressor); });
}

VolumeMeshFile read_volume_mesh(const std::string& path, VtkCallError* error) {
  return caught(error, [&] { return read_volume_mesh_with_vtk(path); });
}

}  // namespace

}  // namespace blayer::detail

extern "C" const blayer::detail::VtkModule* blayer_vtk_module() {
  static const blayer::detail::VtkModule m = [] {
    blayer::detail::VtkModule t;
    t.parse_vtp = &blayer::detail::parse_vtp;
    t.write_vtp = &blayer::detail::write_vtp;
    t.read_volume_mesh = &blayer::detail::read_volume_mesh;
    return t;
  }();
  return &m;
}
