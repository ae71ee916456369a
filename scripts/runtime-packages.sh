#!/usr/bin/env bash
# Prints the Debian packages that hold the shared libraries the given
# binaries load (ldd), one per line. docker/Dockerfile installs exactly these
# in its runtime stage, so a library added to the build cannot be missing
# from the image.
#   scripts/runtime-packages.sh build/server/app/toond build/client/cli/toon
set -euo pipefail
[ $# -gt 0 ] || { echo "usage: $0 BINARY..." >&2; exit 2; }

owner() {
  # Debian 12 merged /usr: dpkg may record a library under /lib or /usr/lib.
  local lib=$1 real
  real=$(readlink -f "$lib")
  for path in "$lib" "$real" "${lib#/usr}" "${real#/usr}" "/usr$lib" "/usr$real"; do
    if pkg=$(dpkg-query -S "$path" 2>/dev/null); then
      echo "${pkg%%:*}"
      return 0
    fi
  done
  echo "runtime-packages: no package owns $lib" >&2
  return 1
}

libs=$(ldd "$@" | awk '$2 == "=>" && $3 ~ /^\// { print $3 }' | sort -u)
for lib in $libs; do owner "$lib"; done | sort -u
