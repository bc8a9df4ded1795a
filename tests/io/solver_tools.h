// The solvers' own tools, run from tests on written meshes, and what the tests read
// from their output. Each tool is a test dependency installed by scripts/install-deps.sh;
// a missing tool fails the test with the package to install (run_tool's exit code 127).
//   checkMesh, gmshToFoam   openfoam      (Debian's build finds its etc/ files only
//                                          through WM_PROJECT_DIR, set here)
//   cgnscheck               cgns-convert
//   gmsh                    gmsh
//   meshio                  python3-meshio (Debian's python, /usr/bin/python3)
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "external_tool.h"

namespace blayer::testing {

inline const char* kOpenFoamEnv = "WM_PROJECT_DIR=/usr/share/openfoam ";

inline ToolRun run_check_mesh(const std::string& case_dir) {
  return run_tool(std::string(kOpenFoamEnv) + "checkMesh -case " + shell_quote(case_dir));
}

inline ToolRun run_gmsh_to_foam(const std::string& msh, const std::string& case_dir) {
  return run_tool(std::string(kOpenFoamEnv) + "gmshToFoam -case " + shell_quote(case_dir) + " " + shell_quote(msh));
}

// The number after `label` on a line of checkMesh's output ("    prisms:        4152"),
// or -1 when no line has it.
inline long check_mesh_figure(const std::string& output, const std::string& label) {
  const std::regex re("\\n\\s*" + label + "\\s+(-?[0-9.e+-]+)");
  std::smatch m;
  return std::regex_search(output, m, re) ? std::stol(m[1]) : -1;
}

// checkMesh's "Mesh non-orthogonality Max: 36.69" and "Max skewness = 2.50".
inline double check_mesh_max(const std::string& output, const std::string& what) {
  const std::regex re(what == "non-orthogonality" ? "non-orthogonality Max: ([0-9.e+-]+)" : "Max skewness = ([0-9.e+-]+)");
  std::smatch m;
  return std::regex_search(output, m, re) ? std::stod(m[1]) : -1.0;
}

// Patch sizes from checkMesh's patch topology table: name -> number of faces.
inline std::map<std::string, long> check_mesh_patches(const std::string& output) {
  std::map<std::string, long> patches;
  const std::regex re("\\n    (\\w+)\\s+([0-9]+)\\s+[0-9]+\\s+ok");
  for (auto it = std::sregex_iterator(output.begin(), output.end(), re); it != std::sregex_iterator(); ++it)
    patches[(*it)[1]] = std::stol((*it)[2]);
  return patches;
}

// meshio's cell counts by type ("tetra", "wedge", "triangle", ...) plus "points".
inline std::map<std::string, long> meshio_counts(const std::string& file, ToolRun* run) {
  *run = run_tool(
      "/usr/bin/python3 -c \"import meshio, sys, collections\n"
      "m = meshio.read(sys.argv[1])\n"
      "n = collections.Counter()\n"
      "for c in m.cells: n[c.type] += len(c.data)\n"
      "n['points'] = len(m.points)\n"
      "for k, v in sorted(n.items()): print('count', k, v)\" " +
      shell_quote(file));
  std::map<std::string, long> counts;
  std::istringstream in(run->output);
  std::string word, type;
  long n;
  while (in >> word)
    if (word == "count" && in >> type >> n) counts[type] = n;
  return counts;
}

// The minimal system/ dictionaries an OpenFOAM utility needs to open a case.
inline void write_openfoam_case_dicts(const std::string& case_dir) {
  std::filesystem::create_directories(case_dir + "/system");
  const std::string header = "FoamFile { version 2.0; format ascii; class dictionary; object ";
  std::ofstream(case_dir + "/system/controlDict") << header << "controlDict; }\napplication none;\nstartFrom startTime;\n"
                                                    "startTime 0;\nstopAt endTime;\nendTime 1;\ndeltaT 1;\n"
                                                    "writeControl timeStep;\nwriteInterval 1;\n";
  std::ofstream(case_dir + "/system/fvSchemes") << header << "fvSchemes; }\nddtSchemes {} gradSchemes {} divSchemes {}\n"
                                                  "laplacianSchemes {} interpolationSchemes {} snGradSchemes {}\n";
  std::ofstream(case_dir + "/system/fvSolution") << header << "fvSolution; }\n";
}

}  // namespace blayer::testing
