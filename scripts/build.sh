#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
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
