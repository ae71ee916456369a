#pragma once
// `toon gallery`: every preset and every effect look on a set of models,
// written as OUTDIR/<model>/<look>.png, OUTDIR/contact-sheet.png and
// OUTDIR/index.html.
#include "cli_args.h"

namespace toond::cli {

// 0 when every render succeeded, 1 when any failed (the rest are still
// written), 2 for a usage error (thrown as UsageError before any request).
int run_gallery(const Options& options);

}  // namespace toond::cli
