#!/usr/bin/env bash
# Installs the conformance suite's npm dependencies (three, the oracle, and
# @xmldom/xmldom, a DOMParser for three's ColladaLoader in Node; pinned by
# package-lock.json) into tests/conformance/node_modules. Idempotent: does
# nothing when that exact lock file is installed already; a lock keeps
# parallel runs (two build dirs testing at once) from deleting each other's
# node_modules. Node itself comes from scripts/install-deps.sh.
set -euo pipefail
cd "$(dirname "$0")"
stamp=node_modules/.toond-lock-sha256
want=$(sha256sum package-lock.json | cut -d' ' -f1)
exec 9>.npm-install.lock
flock 9
if [ -d node_modules/three ] && [ "$(cat "$stamp" 2>/dev/null)" = "$want" ]; then
  echo "conformance deps: three already installed"
  exit 0
fi
npm ci --no-audit --no-fund --loglevel=error
echo "$want" > "$stamp"
echo "conformance deps: installed three $(node -p "require('./node_modules/three/package.json').version")"
