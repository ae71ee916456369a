#pragma once
// One flag of toond: how the parser reads it and how --help shows it. Both
// read the same tables (options.cpp, limit_options.cpp), so neither can
// list a flag the other lacks.
#include <string>

#include "text/option_help.h"

namespace toond::app {

struct Options;

struct Flag {
  text::OptionHelp help;  // no value: a switch
  // Reads `value` ("" for a switch) into `options`; throws
  // std::invalid_argument naming `flag` for a bad value.
  void (*apply)(Options& options, const std::string& flag, const std::string& value);
};

}  // namespace toond::app
