#include "parameters.h"

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
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

// A default taken from the library's own parameter struct, so that the table, --help and
// the README cannot drift from what the engine does.
std::string default_of(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}
std::string default_of(int v) { return std::to_string(v); }
std::string default_of(bool v) { return v ? "true" : "false"; }

// "--name" on the command line, "key 'name'" in a case file: as the user wrote it.
std::string option_as_written(const ParamSpec& p, const std::string& source) {
  return source == "command line" ? "--" + p.name : "key '" + p.name + "'";
}

double parse_bound(const std::string& text, const std::string& range) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (...) {
    used = 0;
  }
  if (used == 0 || used != text.size()) throw std::logic_error("parameter range '" + range + "': bad bound '" + text + "'");
  return v;
}

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

}  // namespace

ValueRange ValueRange::parse(const std::string& text, const std::string& reason) {
  ValueRange r;
  r.text = text;
  r.reason = reason;
  const std::string t = trimmed(text);
  if (t.empty()) return r;
  if (t[0] == '[' || t[0] == '(') {
    const auto comma = t.find(',');
    const char close = t.back();
    if (comma == std::string::npos || (close != ']' && close != ')'))
      throw std::logic_error("parameter range '" + text + "': expected [a, b], (a, b], [a, b) or (a, b)");
    r.lo = parse_bound(trimmed(t.substr(1, comma - 1)), text);
    r.hi = parse_bound(trimmed(t.substr(comma + 1, t.size() - comma - 2)), text);
    r.lo_open = t[0] == '(';
    r.hi_open = close == ')';
    return r;
  }
  const bool two = t.size() > 1 && t[1] == '=';
  const std::string op = t.substr(0, two ? 2 : 1);
  const double v = parse_bound(trimmed(t.substr(op.size())), text);
  if (op == ">=" || op == ">") {
    r.lo = v;
    r.lo_open = op == ">";
  } else if (op == "<=" || op == "<") {
    r.hi = v;
    r.hi_open = op == "<";
  } else {
    throw std::logic_error("parameter range '" + text + "': expected >=, >, <=, < or an interval");
  }
  return r;
}

bool ValueRange::contains(double v) const {
  if (lo && (lo_open ? !(v > *lo) : !(v >= *lo))) return false;
  if (hi && (hi_open ? !(v < *hi) : !(v <= *hi))) return false;
  return true;
}

ParamSpec ParamSpec::in(const std::string& range_text, const std::string& reason) const {
  ParamSpec p = *this;
  p.range = ValueRange::parse(range_text, reason);
  return p;
}

std::string validate_parameter(const ParamSpec& p, const std::string& text, const std::string& source) {
  auto fail = [&](const std::string& why) -> std::string {
    throw InputError(source + ": " + option_as_written(p, source) + ": " + why + " (got '" + text + "')");
  };
  auto check_range = [&](double v) {
    if (p.range.contains(v)) return;
    fail("must be " + std::string(p.range.text[0] == '[' || p.range.text[0] == '(' ? "in " : "") + p.range.text +
         (p.range.reason.empty() ? "" : " (" + p.range.reason + ")"));
  };
  switch (p.type) {
    case ParamType::kInt: {
      std::size_t used = 0;
      long long v = 0;
      try {
        v = std::stoll(text, &used);
      } catch (...) {
        fail("expected an integer");
      }
      if (used != text.size()) fail("expected an integer");
      if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
        fail("expected an integer in [" + std::to_string(std::numeric_limits<int>::min()) + ", " +
             std::to_string(std::numeric_limits<int>::max()) + "]");
      check_range(static_cast<double>(v));
      return std::to_string(v);
    }
    case ParamType::kReal: {
      std::size_t used = 0;
      double v = 0;
      try {
        v = std::stod(text, &used);
      } catch (...) {
        fail("expected a finite number");
      }
      if (used != text.size() || !std::isfinite(v)) fail("expected a finite number");
      check_range(v);
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
      ParamSpec{"layers", ParamType::kInt, default_of(ex.growth.layers), "", "number of prism layers per column before any local limiting", kExtrudeCmd | kCheckCmd}.in("[1, " + std::to_string(kMaxLayers) + "]", "more is almost certainly a typo"),
      ParamSpec{"first-height", ParamType::kReal, "", "length", "height of the first (wall) layer; default: 2e-4 x the bounding-box diagonal unless two of total-thickness, last-height, growth-ratio are given", kExtrudeCmd | kCheckCmd}.in("> 0"),
      ParamSpec{"growth-ratio", ParamType::kReal, "", "", "ratio of consecutive layer heights; give N and any two of first-height, last-height, total-thickness, growth-ratio; with only one height given the ratio is " + default_of(kDefaultGrowthRatio), kExtrudeCmd | kCheckCmd}.in("> 0"),
      ParamSpec{"total-thickness", ParamType::kReal, "", "length", "total height of all layers", kExtrudeCmd | kCheckCmd}.in("> 0"),
      ParamSpec{"last-height", ParamType::kReal, "", "length", "height of the last (outermost) layer", kExtrudeCmd | kCheckCmd}.in("> 0"),
      {"relative-heights", ParamType::kBool, "false", "", "read first-height, total-thickness and last-height as multiples of the local mean edge length at each vertex", kExtrudeCmd},
      ParamSpec{"normal-smoothing", ParamType::kInt, default_of(ex.normal_smoothing_iterations), "", "smoothing passes over the step directions on every front (a smoothed direction is kept only if it sees its faces at least as well); 0: none", kExtrudeCmd}.in(">= 0"),
      ParamSpec{"height-smoothing-rings", ParamType::kInt, default_of(ex.height_smoothing_rings), "", "rings of neighbours over which a locally reduced height ramps back to full height, so limited spots leave no step; 0: none", kExtrudeCmd}.in(">= 0"),
      ParamSpec{"proximity-safety", ParamType::kReal, default_of(ex.proximity_safety), "", "a column may cover at most this fraction of the gap to another wall or front ahead of it (<= 0.5: facing fronts meet halfway)", kExtrudeCmd}.in("(0, 0.5]", "two fronts growing towards each other meet in the middle"),
      {"column-directions", ParamType::kString, "kept", "", "kept: a column keeps its (smoothed) wall direction while it sees the current front, and turns only as far as needed to stay visible (straight columns on smooth walls); recomputed: the front's point normals on every layer", kExtrudeCmd, "kept|recomputed"},
      {"limit", ParamType::kString, "compress", "", "what a gap, a front ahead or a failing cell does to a column: compress keeps the first height and the N layers and lowers the upper layers' growth ratio, ending the column only when even uniform layers do not fit; terminate ends the column at the limit with the law's heights", kExtrudeCmd, "compress|terminate"},
      ParamSpec{"max-layer-aspect", ParamType::kReal, default_of(ex.max_layer_aspect), "", "AFLR3-style layer end: a column ends before the first layer higher than this multiple of the mean wall edge at its point; 0: off", kExtrudeCmd}.in(">= 0", "0: off"),
      ParamSpec{"require-thickness", ParamType::kReal, "0", "", "exit with status 3 (after writing the mesh) when fewer than this fraction of the columns reach 90 % of the requested thickness; 0: never", kExtrudeCmd}.in("[0, 1]", "a fraction of the columns; 0: never"),
      ParamSpec{"fan-angle", ParamType::kReal, default_of(ex.fan_angle_deg), "deg", "sharp convex edges turning by more than this get a fan of columns at their points: one per face sector along the sector's own normal, plus sub-normals in between (wall-orthogonal first cells on both faces); 0: one column per point", kExtrudeCmd}.in("[0, 180)", "0: one column per point"),
      ParamSpec{"fan-max-sector", ParamType::kReal, default_of(ex.fan_max_sector_deg), "deg", "largest angle between neighbouring columns of a fan (more sub-normals for smaller values)", kExtrudeCmd}.in("[5, 90]"),
      ParamSpec{"min-visibility", ParamType::kReal, default_of(ex.min_visibility), "", "smallest accepted min over incident faces of n.f (0.05 = 87 deg between the step and a face normal); below it a column stops", kExtrudeCmd}.in("(0, 1)"),
      ParamSpec{"max-step-stretch", ParamType::kReal, default_of(ex.max_step_stretch), "", "cap on the step stretch 1/V that keeps a layer's height above every incident face plane", kExtrudeCmd}.in(">= 1"),
      ParamSpec{"direction-repair-passes", ParamType::kInt, default_of(ex.direction_repair_passes), "", "passes that turn the columns of failing cells towards a common direction before their layers are lowered", kExtrudeCmd}.in(">= 0"),
      {"collision-check", ParamType::kBool, default_of(ex.check_collisions), "", "exact intersection check of every new front against itself, the previous front and the wall (--collision-check=false: faster, no guarantee)", kExtrudeCmd},
      ParamSpec{"max-non-orthogonality", ParamType::kReal, default_of(ex.solver_limits.max_non_orthogonality_deg), "degrees", "largest angle, on a face between two new layer cells or between a new cell and the one below, between the line of their centres and the face normal (OpenFOAM's non-orthogonality); a cell beyond it is repaired like an invalid one; a face over a wall edge may lean further, to the angle whose cosine is the wall's own times max(1/2, cos limit) (twice the wall's lean from 60 on), never to 90; 0: off", kExtrudeCmd}.in("[0, 180]", "0: off"),
      ParamSpec{"max-skewness", ParamType::kReal, default_of(ex.solver_limits.max_skewness), "", "largest skewness of a face between two layer cells, as checkMesh computes it (its limit is 4); 0: off", kExtrudeCmd}.in(">= 0", "0: off"),
      ParamSpec{"max-boundary-skewness", ParamType::kReal, default_of(ex.solver_limits.max_boundary_skewness), "", "largest skewness of a layer cell's wall, envelope and open-edge faces, as checkMesh computes it (checkMesh: 4, snappyHexMesh: 20); 0: off", kExtrudeCmd}.in(">= 0", "0: off"),
      ParamSpec{"max-face-warp", ParamType::kReal, default_of(ex.solver_limits.max_face_warp_deg), "degrees", "largest fold of a layer cell's side quad along either diagonal (angle between the normals of its two triangles); 0: off", kExtrudeCmd}.in("[0, 180]", "0: off"),
      {"face-pyramids-check", ParamType::kBool, default_of(ex.solver_limits.face_pyramids), "", "require the pyramid from each layer cell's centre to each of its faces to be positive (checkMesh's face pyramids check)", kExtrudeCmd},
      {"face-tets-check", ParamType::kBool, default_of(ex.solver_limits.face_tets), "", "require the tets that decompose each face of a layer cell about the cells' centres to be positive (checkMesh -allGeometry's face tets check, the decomposition of particle tracking)", kExtrudeCmd},
      {"envelope", ParamType::kPath, "", "", "also write the outer envelope of the layers as .vtp", kExtrudeCmd},
      {"report", ParamType::kPath, "", "", "also write the run report as JSON", kExtrudeCmd},
      {"fill", ParamType::kBool, "false", "", "fill the domain outside the layers (inside for --side inward) with tetrahedra (TetGen) for a hybrid mesh", kExtrudeCmd},
      {"farfield", ParamType::kPath, "", "", "closed surface bounding the domain for --fill (default: a box, see farfield-scale)", kExtrudeCmd},
      ParamSpec{"farfield-scale", ParamType::kReal, "10", "", "farfield box size for --fill, as a multiple of the body's bounding box (each side)", kExtrudeCmd}.in("> 1", "the box must enclose the body"),
      ParamSpec{"fill-growth", ParamType::kReal, "1.3", "", "size growth rate of the tetrahedra from the layers' envelope to the farfield", kExtrudeCmd}.in(">= 1"),
      {"boundary", ParamType::kPath, "", "", "with --fill: write the boundary triangles with a marker array (1 wall, 2 farfield, 3 symmetry) as .vtp", kExtrudeCmd},
      {"format", ParamType::kString, "auto", "", "format of the extrude mesh output: auto (from -o: .vtu, .cgns, .su2, .msh, or a path ending in constant/polyMesh), vtu, cgns, openfoam (-o names the case directory or its constant/polyMesh), su2, msh", kExtrudeCmd, "auto|vtu|cgns|openfoam|su2|msh"},
      {"vtk-compressor", ParamType::kString, "zlib", "", "compressor of the .vtu/.vtp outputs: zlib (smaller, read by ParaView and meshio; floating-point arrays are stored uncompressed) or lz4 (about 1.7x faster to write, 13-19 % larger, meshio cannot read it)", kAll, "zlib|lz4"},
      ParamSpec{"threads", ParamType::kInt, "0", "", "worker threads (0: all cores)", kAll}.in(">= 0", "0: all cores"),
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
    if (!p.range.text.empty()) help += " (" + p.range.text + ")";
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
        // The shortest text that reads back as the same double: 0.8 stays "0.8" in
        // messages (17 significant digits would quote it as 0.80000000000000004).
        char buf[64];
        const auto res = std::to_chars(buf, buf + sizeof buf, *node.value<double>());
        text.assign(buf, res.ptr);
      } else {
        throw InputError(config + ": key '" + k + "' must be a string, number or boolean");
      }
      if (p->type == ParamType::kPath && !text.empty() && std::filesystem::path(text).is_relative() &&
          k != "output")
        text = (base / text).string();
      from_file[k] = validate_parameter(*p, text, config);
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
        value = validate_parameter(p, cli_.at(p.name), "command line");
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
    if (!p.range.text.empty())
      type += (p.range.text[0] == '[' || p.range.text[0] == '(' ? " in " : " ") + p.range.text;
    os << "| " << name << " | " << type << " | " << (p.default_value.empty() ? "—" : p.default_value) << " | "
       << (p.unit.empty() ? "—" : p.unit) << " | " << cmds << " | " << p.help << " |\n";
  }
  return os.str();
}

}  // namespace blayer
