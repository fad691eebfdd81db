#!/usr/bin/env bash
# Installs what is missing (Debian bookworm, as root) and builds PERIDEM into
# build/ (or $PERIDEM_BUILD_DIR). Incremental: fast when nothing changed.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PERIDEM_BUILD_DIR:-$here/build}"
"$here/scripts/setup-debian.sh"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j "$(nproc)" >/dev/null || cmake --build "$build" -j 1
