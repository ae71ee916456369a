#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, and starts
# toond serving the built-in demo model. Extra arguments go to toond
# (e.g. --listen 0.0.0.0:8080 --data-dir /var/lib/toond).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh build -DTOOND_TESTS=OFF
echo "toond: open the page at the URL below (the demo model renders without an upload)"
exec build/server/app/toond "$@"
