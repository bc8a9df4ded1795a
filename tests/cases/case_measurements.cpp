#include "case_measurements.h"

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>
#include <toml++/toml.h>

#include "blayer/io/vtk_io.h"

namespace blayer::cases {

namespace fs = std::filesystem;

CaseSettings read_case_settings(const std::string& case_dir, const nlohmann::json& report) {
  const toml::table c = toml::parse_file((fs::path(case_dir) / "case.toml").string());
  CaseSettings s;
  const fs::path input(c["input"].value_or(std::string()));
  s.input = (input.is_absolute() ? input : fs::path(case_dir) / input).lexically_normal().string();
  s.surface.side = c["side"].value_or(std::string("outward")) == "inward" ? Side::kInward : Side::kOutward;
  s.surface.allow_open = c["allow-open"].value_or(false);
  // The targets come from the case's own numbers where it states them (h1, r, N), so
  // that a wrong resolution of the growth law inside blayer is caught, not copied.
  const auto layers = c["layers"].value<int>();
  const auto h1 = c["first-height"].value<double>();
  const auto ratio = c["growth-ratio"].value<double>();
  if (layers && h1 && ratio && !c.contains("total-thickness") && !c.contains("last-height") &&
      !c["relative-heights"].value_or(false)) {
    s.targets.layers = *layers;
    s.targets.first_height = *h1;
    s.targets.total_thickness = *ratio == 1.0 ? *h1 * *layers : *h1 * (std::pow(*ratio, *layers) - 1.0) / (*ratio - 1.0);
    s.targets_from_case = true;
  } else {
    const nlohmann::json& g = report.at("growth_law");
    s.targets.layers = g.at("layers").get<int>();
    s.targets.first_height = g.at("first_height").get<double>();
    s.targets.total_thickness = g.at("total_thickness").get<double>();
  }
  return s;
}

int run_command(const std::string& command, const std::string& stdout_path, const std::string& stderr_path) {
  const std::string full = command + " > '" + stdout_path + "' 2> '" + stderr_path + "'";
  const int raw = std::system(full.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

nlohmann::json measure_case_fidelity(const std::string& mesh_path, const CaseSettings& settings) {
  const VolumeMeshFile file = read_volume_mesh(mesh_path);
  const PreparedSurface wall = load_surface(settings.input, settings.surface);
  const std::vector<Vec3>& mp = file.mesh.points;
  if (mp.size() < wall.surface.points.size())
    throw std::runtime_error(mesh_path + " has fewer points than the wall " + settings.input);
  for (std::size_t i = 0; i < wall.surface.points.size(); ++i)
    if (mp[i] != wall.surface.points[i]) {
      std::ostringstream msg;
      msg.precision(17);
      msg << mesh_path << ": point " << i << " (" << mp[i][0] << ", " << mp[i][1] << ", " << mp[i][2]
          << ") is not wall point " << i << " of " << settings.input << " (" << wall.surface.points[i][0] << ", "
          << wall.surface.points[i][1] << ", " << wall.surface.points[i][2] << ")";
      throw std::runtime_error(msg.str());
    }
  nlohmann::json j = layer_fidelity_to_json(measure_layer_fidelity(file.mesh, wall.surface, settings.targets));
  j["target_first_height"] = settings.targets.first_height;
  j["target_total_thickness"] = settings.targets.total_thickness;
  return j;
}

void flatten_numbers(const nlohmann::json& j, const std::string& prefix, std::map<std::string, double>* out) {
  if (j.is_number()) {
    (*out)[prefix] = j.get<double>();
  } else if (j.is_boolean()) {
    (*out)[prefix] = j.get<bool>() ? 1.0 : 0.0;
  } else if (j.is_object()) {
    for (const auto& [k, v] : j.items()) flatten_numbers(v, prefix.empty() ? k : prefix + "." + k, out);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) flatten_numbers(j[i], prefix + "." + std::to_string(i), out);
  }
}

}  // namespace blayer::cases
