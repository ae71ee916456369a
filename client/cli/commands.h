#pragma once
// The verbs' network side. Exit statuses: 0 ok, 1 server or network error,
// 2 usage or parameter error (a UsageError thrown before any request).
#include "cli_args.h"

namespace toond::cli {

int run_command(const Options& options);

}  // namespace toond::cli
