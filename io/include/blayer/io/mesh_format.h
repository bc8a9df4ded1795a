// Which file format a volume mesh output is written in: named by the user, or taken
// from the output path.
//   from the path:  .vtu -> vtu, .cgns -> cgns, .su2 -> su2, .msh -> msh,
//                   a path ending in constant/polyMesh -> openfoam
//   named:          "vtu", "cgns", "openfoam", "su2", "msh"; "auto" or "" = from the path
// A named format must agree with a recognised extension (-o x.su2 --format msh is an
// error); "openfoam" accepts any directory path (the case directory or its polyMesh).
#pragma once

#include <string>

namespace blayer {

enum class MeshFormat { kVtu, kCgns, kOpenFoam, kSu2, kMsh };

// Throws InputError naming the output when the format cannot be decided or disagrees.
MeshFormat choose_mesh_format(const std::string& output, const std::string& format);

const char* mesh_format_name(MeshFormat f);

}  // namespace blayer
