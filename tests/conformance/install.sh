#!/usr/bin/env bash
# Installs the conformance suite's npm dependencies (three, the oracle, and
# @xmldom/xmldom, a DOMParser for three's ColladaLoader in Node; pinned by
# package-lock.json) into tests/conformance/node_modules, once per lock
# file (scripts/npm-ci-locked.sh). Node itself comes from
# scripts/install-deps.sh.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
exec "$here/../../scripts/npm-ci-locked.sh" "$here" three "conformance deps"
