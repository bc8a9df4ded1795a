#include "cgns_library.h"

#include <dlfcn.h>

#include <optional>
#include <string>

#include "blayer/core/errors.h"

namespace blayer::detail {

namespace {

template <class F>
void resolve(void* handle, const std::string& path, const char* name, F* out) {
  *out = reinterpret_cast<F>(dlsym(handle, name));
  if (!*out) throw IoError("the CGNS library " + path + " has no function " + name);
}

}  // namespace

CgnsLibrary load_cgns_library(const std::string& path) {
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) handle = dlopen(path.substr(path.find_last_of('/') + 1).c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw IoError("cannot load the CGNS library " + path + " (" + (why ? why : "unknown error") + ")");
  }
  CgnsLibrary c{};
  resolve(handle, path, "cg_open", &c.open);
  resolve(handle, path, "cg_close", &c.close);
  resolve(handle, path, "cg_get_error", &c.get_error);
  resolve(handle, path, "cg_goto", &c.go_to);
  resolve(handle, path, "cg_base_write", &c.base_write);
  resolve(handle, path, "cg_zone_write", &c.zone_write);
  resolve(handle, path, "cg_coord_write", &c.coord_write);
  resolve(handle, path, "cg_exponents_write", &c.exponents_write);
  resolve(handle, path, "cg_dataclass_write", &c.dataclass_write);
  resolve(handle, path, "cg_section_write", &c.section_write);
  resolve(handle, path, "cg_family_write", &c.family_write);
  resolve(handle, path, "cg_fambc_write", &c.fambc_write);
  resolve(handle, path, "cg_famname_write", &c.famname_write);
  resolve(handle, path, "cg_boco_write", &c.boco_write);
  resolve(handle, path, "cg_boco_gridlocation_write", &c.boco_gridlocation_write);
  return c;  // the handle stays open: the functions are used until the process ends
}

const CgnsLibrary& cgns_library(const std::string& target) {
  struct Loaded {
    std::optional<CgnsLibrary> lib;
    std::string error;
  };
  static const Loaded loaded = [] {
    Loaded l;
    try {
      l.lib = load_cgns_library(BLAYER_CGNS_LIBRARY);
    } catch (const IoError& e) {
      l.error = e.what();
    }
    return l;
  }();
  if (!loaded.lib) throw IoError(target + ": " + loaded.error + "; write OpenFOAM, SU2 or Gmsh MSH instead");
  return *loaded.lib;
}

}  // namespace blayer::detail
