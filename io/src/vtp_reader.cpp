// VTK XML PolyData (.vtp): read by the VTK module (vtk_module.h, vtk_module/vtp_parse.cpp
// says how), in a child process (parse_in_child.h). The module is loaded here, before
// the fork: the child has only the calling thread, and a dlopen there could wait on the
// loader's lock held by a thread that no longer exists.
#include "parse_in_child.h"
#include "surface_parsers.h"
#include "vtk_module.h"

namespace blayer::detail {

PolygonSoup parse_vtp(std::string_view bytes, const std::string& name) {
  const VtkModule& vtk = vtk_module(name);
  return parse_in_child(
      [&] {
        VtkCallError error;
        PolygonSoup soup = vtk.parse_vtp(bytes, name, /*limit_memory=*/true, &error);
        rethrow(error);
        return soup;
      },
      name);
}

}  // namespace blayer::detail
