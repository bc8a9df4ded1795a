#include "expected_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <toml++/toml.h>

namespace blayer::cases {

std::vector<ExpectedFigure> read_expected_figures(const std::string& path, int* exit_status) {
  const toml::table table = toml::parse_file(path);
  *exit_status = table["exit_status"].value_or(0);
  std::vector<ExpectedFigure> figures;
  for (const auto& [key, node] : table) {
    ExpectedFigure f;
    f.name = std::string(key.str());
    if (f.name == "exit_status") continue;
    const toml::array* spec = node.as_array();
    auto bad = [&](const std::string& why) { return std::runtime_error(path + ": figure " + f.name + ": " + why); };
    if (!spec || spec->size() < 2 || spec->size() > 3) throw bad("expected [op, value] or [op, value, tolerance]");
    f.op = spec->get(0)->value_or(std::string());
    if (f.op != "==" && f.op != "~=" && f.op != ">=" && f.op != "<=") throw bad("unknown operator '" + f.op + "'");
    const auto value = spec->get(1)->value<double>();
    if (!value) throw bad("the value is not a number");
    f.value = *value;
    if (spec->size() == 3) {
      const auto tol = spec->get(2)->value<double>();
      if (!tol || *tol < 0.0) throw bad("the tolerance is not a non-negative number");
      if (f.op == "==") throw bad("== takes no tolerance");
      f.tolerance = *tol;
      f.has_tolerance = true;
    }
    if (f.op == "~=" && !f.has_tolerance) throw bad("~= needs a relative tolerance");
    figures.push_back(f);
  }
  return figures;
}

bool figure_passes(const ExpectedFigure& f, double actual, std::string* accepted) {
  const double slack = f.tolerance * std::fabs(f.value);
  char buf[160];
  bool ok = false;
  if (f.op == "==") {
    ok = actual == f.value;
    std::snprintf(buf, sizeof buf, "== %.17g", f.value);
  } else if (f.op == "~=") {
    ok = std::fabs(actual - f.value) <= slack;
    std::snprintf(buf, sizeof buf, "%.10g +- %.3g (%.3g %%)", f.value, slack, 100.0 * f.tolerance);
  } else if (f.op == ">=") {
    ok = actual >= f.value - slack;
    std::snprintf(buf, sizeof buf, ">= %.10g (%.10g less %.3g %%)", f.value - slack, f.value, 100.0 * f.tolerance);
  } else {
    ok = actual <= f.value + slack;
    std::snprintf(buf, sizeof buf, "<= %.10g (%.10g plus %.3g %%)", f.value + slack, f.value, 100.0 * f.tolerance);
  }
  *accepted = buf;
  return ok && std::isfinite(actual);
}

namespace {

std::string format_value(double v, const std::string& op, double tolerance) {
  char buf[64];
  if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e15) {
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
  }
  int digits = 17;
  if (op != "==" && tolerance > 0.0)
    digits = std::max(7, std::min(17, static_cast<int>(std::ceil(-std::log10(tolerance))) + 4));
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

}  // namespace

std::string rewrite_with_measured(const std::string& toml_text, const std::map<std::string, double>& actual) {
  // "name" = ["op", value(, tolerance)]  # comment
  static const std::regex figure_line(
      R"re(^(\s*"?([^"=\s]+)"?\s*=\s*\[\s*"(==|~=|>=|<=)"\s*,\s*)([-+0-9.eE]+)(\s*(,\s*([-+0-9.eE]+))?\s*\].*)$)re");
  std::istringstream in(toml_text);
  std::string line, out;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, figure_line)) {
      const auto it = actual.find(m[2].str());
      // A closed-form or derived value is what the figure must be, not a measurement:
      // it stays, and a measured difference shows as a failing figure instead.
      const std::string rest = m[5].str();
      const std::size_t hash = rest.find('#');
      const std::string comment = hash == std::string::npos ? "" : rest.substr(hash);
      const bool fixed = comment.find("closed form") != std::string::npos || comment.find("derived") != std::string::npos;
      if (it != actual.end() && !fixed) {
        const double tol = m[7].matched ? std::stod(m[7].str()) : 0.0;
        line = m[1].str() + format_value(it->second, m[3].str(), tol) + m[5].str();
      }
    }
    out += line + "\n";
  }
  return out;
}

}  // namespace blayer::cases
