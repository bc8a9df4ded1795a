#include "blayer/io/mesh_format.h"

#include <filesystem>
#include <optional>

#include "blayer/core/errors.h"
#include "blayer/io/openfoam_writer.h"

namespace blayer {

namespace {

std::optional<MeshFormat> format_of_path(const std::string& output) {
  if (is_openfoam_polymesh_path(output)) return MeshFormat::kOpenFoam;
  const std::string ext = std::filesystem::path(output).extension().string();
  if (ext == ".vtu") return MeshFormat::kVtu;
  if (ext == ".cgns") return MeshFormat::kCgns;
  if (ext == ".su2") return MeshFormat::kSu2;
  if (ext == ".msh") return MeshFormat::kMsh;
  return std::nullopt;
}

std::optional<MeshFormat> format_of_name(const std::string& name) {
  for (MeshFormat f : {MeshFormat::kVtu, MeshFormat::kCgns, MeshFormat::kOpenFoam, MeshFormat::kSu2, MeshFormat::kMsh})
    if (name == mesh_format_name(f)) return f;
  return std::nullopt;
}

}  // namespace

const char* mesh_format_name(MeshFormat f) {
  switch (f) {
    case MeshFormat::kVtu: return "vtu";
    case MeshFormat::kCgns: return "cgns";
    case MeshFormat::kOpenFoam: return "openfoam";
    case MeshFormat::kSu2: return "su2";
    case MeshFormat::kMsh: return "msh";
  }
  return "";
}

MeshFormat choose_mesh_format(const std::string& output, const std::string& format) {
  const std::optional<MeshFormat> from_path = format_of_path(output);
  if (format.empty() || format == "auto") {
    if (from_path) return *from_path;
    throw InputError(output + ": cannot tell the mesh format from the name: use .vtu, .cgns, .su2, .msh, "
                     "a path ending in constant/polyMesh, or --format");
  }
  const std::optional<MeshFormat> named = format_of_name(format);
  if (!named) throw InputError("--format: unknown mesh format '" + format + "'");
  if (*named == MeshFormat::kOpenFoam) {
    if (from_path && *from_path != MeshFormat::kOpenFoam)
      throw InputError(output + ": --format openfoam writes a directory, not a ." + mesh_format_name(*from_path) + " file");
    return *named;
  }
  if (from_path != named)
    throw InputError(output + ": --format " + format + " needs an output ending in ." + format);
  return *named;
}

}  // namespace blayer
