#!/usr/bin/env bash
# Installs the browser tests' npm dependencies (playwright-core, and the game
# engines phaser and pixi.js; pinned by package-lock.json) into
# tests/browser/node_modules, once per lock file (scripts/npm-ci-locked.sh).
# The browser itself is Debian's chromium (scripts/install-deps.sh).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
exec "$here/../../scripts/npm-ci-locked.sh" "$here" playwright-core "browser test deps"
