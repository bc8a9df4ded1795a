#include <dlfcn.h>

#include <stdexcept>
#include <string>

#include "blayer/core/errors.h"
#include "vtk_module.h"

namespace blayer::detail {

const VtkModule& load_vtk_module(const std::string& path) {
  // RTLD_LOCAL: the module's copy of blayer's code stays its own.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw IoError("cannot load blayer's VTK module " + path + " (" + (why ? why : "unknown error") +
                  "; scripts/build.sh builds it)");
  }
  using Entry = const VtkModule* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, "blayer_vtk_module"));
  const VtkModule* m = entry ? entry() : nullptr;
  if (!m || m->version != VtkModule::kVersion) {
    dlclose(handle);
    throw IoError(path + " is not blayer's VTK module of this build (scripts/build.sh builds it)");
  }
  return *m;  // the handle stays open: the functions are used until the process ends
}

const VtkModule& vtk_module(const std::string& target) {
  struct Loaded {
    const VtkModule* module = nullptr;
    std::string error;
  };
  static const Loaded loaded = [] {
    Loaded l;
    try {
      l.module = &load_vtk_module(BLAYER_VTK_MODULE);
    } catch (const IoError& e) {
      l.error = e.what();
    }
    return l;
  }();
  if (!loaded.module) throw IoError(target + ": " + loaded.error);
  return *loaded.module;
}

void rethrow(const VtkCallError& error) {
  switch (error.kind) {
    case VtkCallError::Kind::kNone: return;
    case VtkCallError::Kind::kInput: throw InputError(error.message);
    case VtkCallError::Kind::kIo: throw IoError(error.message);
    case VtkCallError::Kind::kOther: throw std::runtime_error(error.message);
  }
}

}  // namespace blayer::detail
