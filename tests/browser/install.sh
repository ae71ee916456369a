#!/usr/bin/env bash
# Installs the browser tests' npm dependencies (playwright-core, and the game
# engines phaser and pixi.js; pinned by package-lock.json) into
# tests/browser/node_modules. Idempotent: does
# nothing when that exact lock file is installed already, so scripts/test.sh
# and the CTest fixture can both call it; a lock keeps parallel runs (two
# build dirs testing at once) from deleting each other's node_modules.
# The browser itself is Debian's chromium (scripts/install-deps.sh).
set -euo pipefail
cd "$(dirname "$0")"
stamp=node_modules/.toond-lock-sha256
want=$(sha256sum package-lock.json | cut -d' ' -f1)
exec 9>.npm-install.lock
flock 9
if [ -d node_modules/playwright-core ] && [ "$(cat "$stamp" 2>/dev/null)" = "$want" ]; then
  echo "browser test deps: already installed"
  exit 0
fi
npm ci --no-audit --no-fund --loglevel=error
echo "$want" > "$stamp"
echo "browser test deps: installed $(node -p "['playwright-core', 'phaser', 'pixi.js'].map((p) => p + ' ' + require('./node_modules/' + p + '/package.json').version).join(', ')")"
