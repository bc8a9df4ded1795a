// The one table of user parameters. It drives the command-line parser, the TOML case
// files (--config), --help, and the README's parameter list (`blayer params`).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace blayer {

enum class ParamType { kInt, kReal, kString, kBool, kPath };

// Commands a parameter belongs to (bit mask).
enum CommandBit : unsigned { kNormalsCmd = 1u, kExtrudeCmd = 2u, kCheckCmd = 4u };

struct ParamSpec {
  std::string name;           // long option without dashes, and the TOML key
  ParamType type;
  std::string default_value;  // empty: no default (optional or required by the command)
  std::string unit;
  std::string help;
  unsigned commands;
  std::string choices = {};   // "a|b|c" for an enumerated string
  char short_name = 0;
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

}  // namespace blayer
