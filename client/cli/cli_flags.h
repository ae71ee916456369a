#pragma once
// Every verb and flag `toon` knows, in the tables that both the parser
// (cli_args.cpp) and --help (cli_usage.cpp) read, so neither can list one
// the other lacks.
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "cli_args.h"
#include "text/option_help.h"

namespace toond::cli {

// What the flags write into while a command line is read.
struct FlagTarget {
  Options& options;
  // Resolved against TOOND_URL once the whole line is read.
  std::optional<std::string> server;
};

// Verbs a flag belongs to, one bit per Verb.
using VerbSet = unsigned;
constexpr VerbSet verb_set(Verb verb) { return 1u << static_cast<unsigned>(verb); }
// Before or after any verb, or with none.
inline constexpr VerbSet kGlobal = ~0u;

struct Flag {
  text::OptionHelp help;  // names, value and --help text; no value: a switch
  VerbSet verbs;
  bool repeatable;  // false: a second one is a usage error
  // Reads `value` ("" for a switch); throws UsageError for a bad one.
  void (*apply)(FlagTarget& target, const std::string& value);
};

// In --help's order. A flag whose value or help differs between verbs (-o)
// has a row for each.
std::span<const Flag> flags();

// Digits only, at least one: a port, a scene's index, a size.
bool is_index(std::string_view s);

// How an error names a flag: "-o/--out", "--set".
std::string flag_display(const text::OptionHelp& flag);

struct VerbInfo {
  Verb verb;
  std::string_view name;
  std::string_view synopsis;     // what follows "toon [--server URL] NAME"; a '\n' continues it
  std::string_view summary;      // its line under "Commands:"
  std::string_view description;  // the paragraph of `toon NAME --help`
};

// Every verb but Verb::none, in --help's order.
std::span<const VerbInfo> verbs();

}  // namespace toond::cli
