// The one table of user parameters. It drives the command-line parser, the TOML case
// files (--config), --help, and the README's parameter list (`blayer params`), and it
// owns every default and every accepted range: a value outside its range is refused
// here, naming the option as the user wrote it ("--proximity-safety" on the command
// line, key 'proximity-safety' in a case file), before any library code sees it. The
// libraries' own checks (e.g. the extruder's) stay as guards against programming errors.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace blayer {

enum class ParamType { kInt, kReal, kString, kBool, kPath };

// Commands a parameter belongs to (bit mask).
enum CommandBit : unsigned { kNormalsCmd = 1u, kExtrudeCmd = 2u, kCheckCmd = 4u };

// The values a numeric parameter accepts, written as users read it: ">= 0", "> 0",
// "<= 1", "[1, 1000]", "(0, 0.5]", "(0, 1)". Unbounded when empty.
struct ValueRange {
  std::string text;             // as written, shown in messages, --help and the README
  std::optional<double> lo, hi;
  bool lo_open = false, hi_open = false;
  std::string reason;           // why the bound is there (may be empty), shown with it

  // Parses `text`; throws std::logic_error for a malformed range (a bug in the table).
  static ValueRange parse(const std::string& text, const std::string& reason = {});
  bool contains(double v) const;
};

struct ParamSpec {
  std::string name;           // long option without dashes, and the TOML key
  ParamType type;
  std::string default_value;  // empty: no default (optional or required by the command)
  std::string unit;
  std::string help;
  unsigned commands;
  std::string choices = {};   // "a|b|c" for an enumerated string
  char short_name = 0;
  ValueRange range = {};      // kInt and kReal only; checked for given values and defaults

  // The same row with a range, so that a row reads {"name", ...}.in(">= 0"):
  ParamSpec in(const std::string& range_text, const std::string& reason = {}) const;
};

const std::vector<ParamSpec>& parameter_table();

// Effective values for one command: command line over --config file over defaults.
class ParamValues {
 public:
  bool is_set(const std::string& name) const;  // given on the command line or in the file
  std::string get_string(const std::string& name) const;
  int get_int(const std::string& name) const;
  double get_real(const std::string& name) const;
  bool get_bool(const std::string& name) const;
  // name -> value as text, for echoing the effective configuration in reports.
  const std::map<std::string, std::string>& effective() const { return values_; }

 private:
  friend class ParamBinder;
  std::map<std::string, std::string> values_;
  std::map<std::string, bool> set_;
  unsigned command_ = 0;
};

// Registers the table's options for `command` on a CLI11 subcommand, and after parsing
// merges the command line, the --config TOML file and the defaults. Throws InputError
// for unknown TOML keys, values of the wrong type or out of range.
class ParamBinder {
 public:
  ParamBinder(CLI::App* sub, unsigned command);
  ParamValues resolve() const;

 private:
  CLI::App* sub_;
  unsigned command_;
  std::map<std::string, std::string> cli_;  // CLI11 writes the raw text here
  std::map<std::string, bool> flags_;
};

// The table as Markdown (for the README).
std::string parameter_table_markdown();

// Parses and checks one value for a parameter; returns its canonical text. `source` is
// "command line" or the case file's path, and decides how the option is named in the
// InputError: "command line: --threads: must be >= 0 (got '-3')", or
// "case.toml: key 'threads': must be >= 0 (got '-3')".
std::string validate_parameter(const ParamSpec& p, const std::string& text, const std::string& source);

}  // namespace blayer
