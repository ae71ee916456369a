// toon's --help, written from the tables of verbs and flags (cli_flags.h)
// that the parser reads too.
#include <string>
#include <vector>

#include "cli_args.h"
#include "cli_flags.h"

namespace toond::cli {
namespace {

constexpr std::size_t kIndent = 2;

// "PREFIX SYNOPSIS" from `indent`, the synopsis's further lines set under
// its first.
std::string synopsis_lines(const std::string& prefix, std::size_t indent, std::string_view synopsis) {
  if (synopsis.empty()) return std::string(indent, ' ') + prefix + "\n";
  return text::option_lines({"", prefix, "", synopsis}, indent, indent + prefix.size() + 1);
}

// The option list of `verb`: its own flags, or the global ones for
// Verb::none (the overview), aligned like every option list of toon.
std::string option_list(Verb verb) {
  std::vector<text::OptionHelp> all;
  for (const Flag& flag : flags()) all.push_back(flag.help);
  const std::size_t column = text::help_column(all, kIndent);
  std::string out;
  for (const Flag& flag : flags()) {
    const bool global = flag.verbs == kGlobal;
    if (verb == Verb::none ? global : !global && (flag.verbs & verb_set(verb)) != 0) {
      out += text::option_lines(flag.help, kIndent, column);
    }
  }
  return out;
}

std::string overview() {
  std::string out = "toon - command-line client for toond, the toon-rendering daemon\n\nUsage:\n";
  for (const VerbInfo& v : verbs()) {
    out += synopsis_lines("toon [--server URL] " + std::string(v.name), kIndent, v.synopsis);
  }
  std::vector<text::OptionHelp> commands;
  for (const VerbInfo& v : verbs()) commands.push_back({"", v.name, "", v.summary});
  commands.push_back({"", "help", "CMD", "show the options of one command (same as toon CMD --help)"});
  // A gap of two: a command and its summary are both plain words.
  const std::size_t column = text::help_column(commands, kIndent) + 1;
  out += "\nCommands:\n";
  for (const text::OptionHelp& command : commands) out += text::option_lines(command, kIndent, column);
  out += "\nGlobal options (before or after the command):\n" + option_list(Verb::none);
  return out + "\nExit status: 0 success, 1 server or network error, 2 usage or parameter error.\n";
}

}  // namespace

std::string usage_text(Verb verb) {
  for (const VerbInfo& v : verbs()) {
    if (v.verb != verb) continue;
    std::string out = synopsis_lines("Usage: toon [--server URL] " + std::string(v.name), 0, v.synopsis);
    out += "\n" + std::string(v.description);
    if (const std::string options = option_list(verb); !options.empty()) out += "\nOptions:\n" + options;
    return out;
  }
  return overview();
}

}  // namespace toond::cli
