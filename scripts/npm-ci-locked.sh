#!/usr/bin/env bash
# npm ci in a test folder that has a package.json and a package-lock.json
# (tests/browser, tests/conformance), installing into its node_modules.
# Idempotent: does nothing when that exact lock file is installed already,
# so scripts/test.sh and a CTest fixture can both call it; a lock keeps
# parallel runs (two build dirs testing at once) from deleting each
# other's node_modules.
#   scripts/npm-ci-locked.sh FOLDER PACKAGE LABEL
# PACKAGE is the one whose presence and version are reported, LABEL names
# the folder's tests in what is printed.
set -euo pipefail
folder=$1 package=$2 label=$3
cd "$folder"
stamp=node_modules/.toond-lock-sha256
want=$(sha256sum package-lock.json | cut -d' ' -f1)
exec 9>.npm-install.lock
flock 9
if [ -d "node_modules/$package" ] && [ "$(cat "$stamp" 2>/dev/null)" = "$want" ]; then
  echo "$label: $package already installed"
  exit 0
fi
npm ci --no-audit --no-fund --loglevel=error
echo "$want" > "$stamp"
echo "$label: installed $package $(node -p "require('./node_modules/$package/package.json').version")"
