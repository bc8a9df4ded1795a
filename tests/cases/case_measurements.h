// What the case runner measures for one case: blayer's own report, the layer fidelity
// computed here from the written mesh, and the independent re-check of the written file.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "blayer/io/prepare_surface.h"
#include "blayer/quality/layer_fidelity.h"

namespace blayer::cases {

struct CaseSettings {
  std::string input;  // absolute path of the wall surface
  PrepareOptions surface;
  LayerFidelityTargets targets;
  bool targets_from_case = false;  // false: taken from the report's growth law
};

// The surface file, its side and the growth law of case.toml (relative input paths are
// relative to the case folder). Missing growth-law keys are filled in from the report.
CaseSettings read_case_settings(const std::string& case_dir, const nlohmann::json& report);

// Runs a shell command with stdout and stderr sent to files; returns the exit status
// (-1 when it did not exit normally).
int run_command(const std::string& command, const std::string& stdout_path, const std::string& stderr_path);

// Layer fidelity of mesh.vtu against the case's wall, loaded and oriented as blayer
// loads it. Throws std::runtime_error when the mesh's first points are not the wall's
// points (the contract the measure relies on), naming the first point that differs.
nlohmann::json measure_case_fidelity(const std::string& mesh_path, const CaseSettings& settings);

// Every number in j by its dotted path ("check.cells.wedge"; array elements by index,
// "columns.per_layer.9"); booleans count as 0 / 1, nulls are skipped.
void flatten_numbers(const nlohmann::json& j, const std::string& prefix, std::map<std::string, double>* out);

}  // namespace blayer::cases
