// The figures of a case's expected.toml: reading them, judging measured values against
// them, and re-writing the file with measured values for a human to review.
//
// One line per figure: "dotted.path" = [op, value] or [op, value, tolerance], with op
//   ==  actual equals value exactly (counts; derivation in the comment);
//   ~=  |actual - value| <= tolerance x |value| (tolerance relative and required);
//   >=  actual >= value - tolerance x |value| (tolerance optional, default 0);
//   <=  actual <= value + tolerance x |value| (likewise).
// So the value is always the figure as last measured (or derived), and the operator and
// tolerance say how far and in which direction it may drift. A trailing comment gives
// the reason for the tolerance; `exit_status = N` (default 0) is blayer's exit status.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace blayer::cases {

struct ExpectedFigure {
  std::string name;  // dotted path into the measurements
  std::string op;
  double value = 0.0;
  double tolerance = 0.0;
  bool has_tolerance = false;
};

// Throws std::runtime_error naming the file and the figure for a malformed entry.
std::vector<ExpectedFigure> read_expected_figures(const std::string& path, int* exit_status);

// Whether actual passes; *limit gets a human-readable form of the accepted range.
bool figure_passes(const ExpectedFigure& f, double actual, std::string* accepted);

// The text of expected.toml with every figure's value replaced by the measured one
// (actual[name]), operators, tolerances, comments and all other lines kept as they are.
// Kept as well: the values of figures without a measurement, and of figures whose comment
// says "closed form" or "derived" (those are what the figure must be; a difference is a
// failure to look into, not a new value). Values are printed with enough digits for
// their tolerance (all 17 for == and untoleranced bounds).
std::string rewrite_with_measured(const std::string& toml_text, const std::map<std::string, double>& actual);

}  // namespace blayer::cases
