#include "parameters.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <toml++/toml.h>

#include "blayer/core/errors.h"
#include "blayer/extruder/extrude_layers.h"

namespace blayer {

namespace {

constexpr unsigned kAll = kNormalsCmd | kExtrudeCmd | kCheckCmd;
constexpr unsigned kSurfaceCmds = kNormalsCmd | kExtrudeCmd;

const char* type_name(ParamType t) {
  switch (t) {
    case ParamType::kInt: return "int";
    case ParamType::kReal: return "real";
    case ParamType::kString: return "string";
    case ParamType::kBool: return "bool";
    case ParamType::kPath: return "path";
  }
  return "";
}

const ParamSpec* find_spec(const std::string& name) {
  for (const ParamSpec& p : parameter_table())
    if (p.name == name) return &p;
  return nullptr;
}

// Parses and range-checks text for a parameter; returns the canonical text.
std::string validate(const ParamSpec& p, const std::string& text, const std::string& where) {
  auto fail = [&](const std::string& why) -> std::string {
    throw InputError(where + ": --" + p.name + ": " + why + " (got '" + text + "')");
  };
  switch (p.type) {
    case ParamType::kInt: {
      std::size_t used = 0;
      long v = 0;
      try {
        v = std::stol(text, &used);
      } catch (...) {
        fail("expected an integer");
      }
      if (used != text.size()) fail("expected an integer");
      return std::to_string(v);
    }
    case ParamType::kReal: {
      std::size_t used = 0;
      double v = 0;
      try {
        v = std::stod(text, &used);
      } catch (...) {
        fail("expected a number");
      }
      if (used != text.size() || !std::isfinite(v)) fail("expected a finite number");
      return text;
    }
    case ParamType::kBool:
      if (text == "true" || text == "1") return "true";
      if (text == "false" || text == "0") return "false";
      return fail("expected true or false");
    case ParamType::kString:
      if (!p.choices.empty()) {
        std::stringstream ss(p.choices);
        std::string c;
        while (std::getline(ss, c, '|'))
          if (c == text) return text;
        fail("expected one of " + p.choices);
      }
      return text;
    case ParamType::kPath:
      if (text.empty()) fail("expected a file name");
      return text;
  }
  return text;
}

// A default taken from the library's own parameter struct, so that the table, --help and
// the README cannot drift from what the engine does.
std::string default_of(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}
std::string default_of(int v) { return std::to_string(v); }
std::string default_of(bool v) { return v ? "true" : "false"; }

}  // namespace

const std::vector<ParamSpec>& parameter_table() {
  static const ExtrusionParams ex{};
  static const std::vector<ParamSpec> table = {
      {"input", ParamType::kPath, "", "", "surface file (STL, OBJ, OFF, PLY, VTP, VTK; optionally .gz) or, for check, a volume mesh (.vtu, .vtk)", kAll},
      {"output", ParamType::kPath, "", "", "output file: .vtp for normals; for extrude the mesh as .vtu, .cgns, .su2, .msh or an OpenFOAM CASE/constant/polyMesh (see format; default: <input name>_layers.vtu in the current directory)", kSurfaceCmds, "", 'o'},
      {"config", ParamType::kPath, "", "", "TOML case file with any of these keys; command-line options override it; relative paths in it are relative to the file", kAll},
      {"side", ParamType::kString, "outward", "", "side the layers grow on: outward (external flow) or inward (internal flow: pipes, arteries); closed surfaces oriented the other way are flipped", kAll, "outward|inward"},
      {"allow-open", ParamType::kBool, "false", "", "accept a surface with boundary edges (holes); layers grow on the side its triangles' normals point to", kAll},
      {"symmetry", ParamType::kString, "auto", "", "half models: auto finds the symmetry plane of an open surface whose whole boundary lies in one plane (and says so); none treats every boundary as a hole", kAll, "auto|none"},
      {"symmetry-plane", ParamType::kString, "", "", "the symmetry plane of a half model: x=C, y=C, z=C or \"a b c d\" (a x + b y + c z = d); its boundary must lie in it", kAll},
      {"method", ParamType::kString, "most-normal", "", "point normal method: most-normal (maximises the minimum angle to the incident triangles), most-visible (maximises min n.f), or a weighted average: angle, area, unit, inverse-area, max", kSurfaceCmds, "most-normal|most-visible|angle|area|unit|inverse-area|max"},
      {"layers", ParamType::kInt, default_of(ex.growth.layers), "", "number of prism layers per column before any local limiting", kExtrudeCmd | kCheckCmd},
      {"first-height", ParamType::kReal, "", "length", "height of the first (wall) layer; default: 2e-4 x the bounding-box diagonal unless two of total-thickness, last-height, growth-ratio are given", kExtrudeCmd | kCheckCmd},
      {"growth-ratio", ParamType::kReal, "", "", "ratio of consecutive layer heights; give N and any two of first-height, last-height, total-thickness, growth-ratio; with only one height given the ratio is " + default_of(kDefaultGrowthRatio), kExtrudeCmd | kCheckCmd},
      {"total-thickness", ParamType::kReal, "", "length", "total height of all layers", kExtrudeCmd | kCheckCmd},
      {"last-height", ParamType::kReal, "", "length", "height of the last (outermost) layer", kExtrudeCmd | kCheckCmd},
      {"relative-heights", ParamType::kBool, "false", "", "read first-height, total-thickness and last-height as multiples of the local mean edge length at each vertex", kExtrudeCmd},
      {"normal-smoothing", ParamType::kInt, default_of(ex.normal_smoothing_iterations), "", "smoothing passes over the step directions on every front (a smoothed direction is kept only if it sees its faces at least as well); 0: none", kExtrudeCmd},
      {"height-smoothing-rings", ParamType::kInt, default_of(ex.height_smoothing_rings), "", "rings of neighbours over which a locally reduced height ramps back to full height, so limited spots leave no step; 0: none", kExtrudeCmd},
      {"proximity-safety", ParamType::kReal, default_of(ex.proximity_safety), "", "a column may cover at most this fraction of the gap to another wall or front ahead of it (<= 0.5: facing fronts meet halfway)", kExtrudeCmd},
      {"column-directions", ParamType::kString, "kept", "", "kept: a column keeps its (smoothed) wall direction while it sees the current front, and turns only as far as needed to stay visible (straight columns on smooth walls); recomputed: the front's point normals on every layer", kExtrudeCmd, "kept|recomputed"},
      {"limit", ParamType::kString, "compress", "", "what a gap, a front ahead or a failing cell does to a column: compress keeps the first height and the N layers and lowers the upper layers' growth ratio, ending the column only when even uniform layers do not fit; terminate ends the column at the limit with the law's heights", kExtrudeCmd, "compress|terminate"},
      {"max-layer-aspect", ParamType::kReal, default_of(ex.max_layer_aspect), "", "AFLR3-style layer end: a column ends before the first layer higher than this multiple of the mean wall edge at its point; 0: off", kExtrudeCmd},
      {"require-thickness", ParamType::kReal, "0", "", "exit with status 3 (after writing the mesh) when fewer than this fraction of the columns reach 90 % of the requested thickness; 0: never", kExtrudeCmd},
      {"fan-angle", ParamType::kReal, default_of(ex.fan_angle_deg), "deg", "sharp convex edges turning by more than this get a fan of columns at their points: one per face sector along the sector's own normal, plus sub-normals in between (wall-orthogonal first cells on both faces); 0: one column per point", kExtrudeCmd},
      {"fan-max-sector", ParamType::kReal, default_of(ex.fan_max_sector_deg), "deg", "largest angle between neighbouring columns of a fan (more sub-normals for smaller values)", kExtrudeCmd},
      {"min-visibility", ParamType::kReal, default_of(ex.min_visibility), "", "smallest accepted min over incident faces of n.f (0.05 = 87 deg between the step and a face normal); below it a column stops", kExtrudeCmd},
      {"max-step-stretch", ParamType::kReal, default_of(ex.max_step_stretch), "", "cap on the step stretch 1/V that keeps a layer's height above every incident face plane", kExtrudeCmd},
      {"direction-repair-passes", ParamType::kInt, default_of(ex.direction_repair_passes), "", "passes that turn the columns of failing cells towards a common direction before their layers are lowered", kExtrudeCmd},
      {"collision-check", ParamType::kBool, default_of(ex.check_collisions), "", "exact intersection check of every new front against itself, the previous front and the wall (--collision-check=false: faster, no guarantee)", kExtrudeCmd},
      {"max-non-orthogonality", ParamType::kReal, default_of(ex.solver_limits.max_non_orthogonality_deg), "degrees", "largest angle, on a face between two new layer cells or between a new cell and the one below, between the line of their centres and the face normal (OpenFOAM's non-orthogonality); a cell beyond it is repaired like an invalid one; 0: off", kExtrudeCmd},
      {"max-skewness", ParamType::kReal, default_of(ex.solver_limits.max_skewness), "", "largest skewness of a face between two layer cells, as checkMesh computes it (its limit is 4); 0: off", kExtrudeCmd},
      {"max-boundary-skewness", ParamType::kReal, default_of(ex.solver_limits.max_boundary_skewness), "", "largest skewness of a layer cell's wall, envelope and open-edge faces, as checkMesh computes it (checkMesh: 4, snappyHexMesh: 20); 0: off", kExtrudeCmd},
      {"max-face-warp", ParamType::kReal, default_of(ex.solver_limits.max_face_warp_deg), "degrees", "largest fold of a layer cell's side quad along either diagonal (angle between the normals of its two triangles); 0: off", kExtrudeCmd},
      {"face-pyramids-check", ParamType::kBool, default_of(ex.solver_limits.face_pyramids), "", "require the pyramid from each layer cell's centre to each of its faces to be positive (checkMesh's face pyramids check)", kExtrudeCmd},
      {"face-tets-check", ParamType::kBool, default_of(ex.solver_limits.face_tets), "", "require the tets that decompose each face of a layer cell about the cells' centres to be positive (checkMesh -allGeometry's face tets check, the decomposition of particle tracking)", kExtrudeCmd},
      {"envelope", ParamType::kPath, "", "", "also write the outer envelope of the layers as .vtp", kExtrudeCmd},
      {"report", ParamType::kPath, "", "", "also write the run report as JSON", kExtrudeCmd},
      {"fill", ParamType::kBool, "false", "", "fill the domain outside the layers (inside for --side inward) with tetrahedra (TetGen) for a hybrid mesh", kExtrudeCmd},
      {"farfield", ParamType::kPath, "", "", "closed surface bounding the domain for --fill (default: a box, see farfield-scale)", kExtrudeCmd},
      {"farfield-scale", ParamType::kReal, "10", "", "farfield box size for --fill, as a multiple of the body's bounding box (each side)", kExtrudeCmd},
      {"fill-growth", ParamType::kReal, "1.3", "", "size growth rate of the tetrahedra from the layers' envelope to the farfield", kExtrudeCmd},
      {"boundary", ParamType::kPath, "", "", "with --fill: write the boundary triangles with a marker array (1 wall, 2 farfield) as .vtp", kExtrudeCmd},
      {"format", ParamType::kString, "auto", "", "format of the extrude mesh output: auto (from -o: .vtu, .cgns, .su2, .msh, or a path ending in constant/polyMesh), vtu, cgns, openfoam (-o names the case directory or its constant/polyMesh), su2, msh", kExtrudeCmd, "auto|vtu|cgns|openfoam|su2|msh"},
      {"vtk-compressor", ParamType::kString, "zlib", "", "compressor of the .vtu/.vtp outputs: zlib (smaller, read by ParaView and meshio) or lz4 (3-4x faster to write, 20-35 % larger, meshio cannot read it)", kAll, "zlib|lz4"},
      {"threads", ParamType::kInt, "0", "", "worker threads (0: all cores)", kAll},
      {"wall", ParamType::kPath, "", "", "check: the wall surface the layers were grown on (any input format); with the growth law (layers and two of first-height, growth-ratio, total-thickness, last-height) measures the layers' fidelity: first height against h1 and thickness against T per column, above the wall planes and as distance to the wall; works on any mesher's prisms and hexahedra", kCheckCmd},
      {"json", ParamType::kPath, "", "", "write the check report as JSON", kCheckCmd},
      {"bad", ParamType::kPath, "", "", "write only the failing cells with their metrics as .vtu", kCheckCmd},
  };
  return table;
}

bool ParamValues::is_set(const std::string& name) const {
  auto it = set_.find(name);
  return it != set_.end() && it->second;
}

std::string ParamValues::get_string(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throw std::logic_error("parameter '" + name + "' is not defined for this command");
  return it->second;
}
int ParamValues::get_int(const std::string& name) const { return std::stoi(get_string(name)); }
double ParamValues::get_real(const std::string& name) const {
  const std::string s = get_string(name);
  return s.empty() ? 0.0 : std::stod(s);
}
bool ParamValues::get_bool(const std::string& name) const { return get_string(name) == "true"; }

ParamBinder::ParamBinder(CLI::App* sub, unsigned command) : sub_(sub), command_(command) {
  for (const ParamSpec& p : parameter_table()) {
    if (!(p.commands & command)) continue;
    std::string help = p.help;
    if (!p.unit.empty()) help += " [" + p.unit + "]";
    if (!p.default_value.empty()) help += " (default: " + p.default_value + ")";
    if (p.name == "input") {
      sub->add_option(p.name, cli_[p.name], help);
    } else if (p.type == ParamType::kBool) {
      sub->add_flag("--" + p.name, flags_[p.name], help);
    } else {
      std::string names = "--" + p.name;
      if (p.short_name) names = std::string("-") + p.short_name + "," + names;
      sub->add_option(names, cli_[p.name], help);
    }
  }
}

ParamValues ParamBinder::resolve() const {
  ParamValues out;
  out.command_ = command_;
  auto given_on_cli = [&](const ParamSpec& p) {
    if (p.name == "input") return sub_->count(p.name) > 0;
    return sub_->count("--" + p.name) > 0;
  };

  // The case file, if any.
  std::map<std::string, std::string> from_file;
  std::string config;
  if (auto it = cli_.find("config"); it != cli_.end()) config = it->second;
  if (!config.empty()) {
    toml::table tbl;
    try {
      tbl = toml::parse_file(config);
    } catch (const toml::parse_error& e) {
      std::ostringstream os;
      os << config << ":" << e.source().begin.line << ": " << e.description();
      throw InputError(os.str());
    } catch (const std::exception& e) {
      throw InputError(config + ": cannot read the case file (" + e.what() + ")");
    }
    const std::filesystem::path base = std::filesystem::path(config).parent_path();
    for (const auto& [key, node] : tbl) {
      const std::string k(key.str());
      const ParamSpec* p = find_spec(k);
      if (!p || !(p->commands & command_) || k == "config")
        throw InputError(config + ": unknown key '" + k + "' for this command (see --help)");
      std::string text;
      if (auto v = node.value<std::string>()) {
        text = *v;
      } else if (node.is_boolean()) {
        text = *node.value<bool>() ? "true" : "false";
      } else if (node.is_integer()) {
        text = std::to_string(*node.value<std::int64_t>());
      } else if (node.is_floating_point()) {
        std::ostringstream os;
        os.precision(17);
        os << *node.value<double>();
        text = os.str();
      } else {
        throw InputError(config + ": key '" + k + "' must be a string, number or boolean");
      }
      if (p->type == ParamType::kPath && !text.empty() && std::filesystem::path(text).is_relative() &&
          k != "output")
        text = (base / text).string();
      from_file[k] = validate(*p, text, config);
    }
  }

  for (const ParamSpec& p : parameter_table()) {
    if (!(p.commands & command_)) continue;
    std::string value = p.default_value;
    bool set = false;
    if (auto it = from_file.find(p.name); it != from_file.end()) {
      value = it->second;
      set = true;
    }
    if (given_on_cli(p)) {
      if (p.type == ParamType::kBool)
        value = flags_.at(p.name) ? "true" : "false";
      else
        value = validate(p, cli_.at(p.name), "command line");
      set = true;
    }
    out.values_[p.name] = value;
    out.set_[p.name] = set;
  }
  return out;
}

std::string parameter_table_markdown() {
  std::ostringstream os;
  os << "| parameter | type | default | unit | commands | meaning |\n|---|---|---|---|---|---|\n";
  for (const ParamSpec& p : parameter_table()) {
    std::string cmds;
    if (p.commands & kNormalsCmd) cmds += "normals ";
    if (p.commands & kExtrudeCmd) cmds += "extrude ";
    if (p.commands & kCheckCmd) cmds += "check ";
    if (!cmds.empty()) cmds.pop_back();
    std::string name = p.name == "input" ? "`INPUT` (positional)" : "`--" + p.name + "`";
    std::string type = type_name(p.type);
    if (!p.choices.empty()) {
      type = p.choices;
      for (char& c : type)
        if (c == '|') c = '/';
    }
    os << "| " << name << " | " << type << " | " << (p.default_value.empty() ? "—" : p.default_value) << " | "
       << (p.unit.empty() ? "—" : p.unit) << " | " << cmds << " | " << p.help << " |\n";
  }
  return os.str();
}

}  // namespace blayer
