#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Side-by-side timing of the packer against an older commit:
#   bench/packing/compare.sh REV [-3] [N ...]  (default N: 1500 5000 20000 50000 100000;
#                                               -3: spheres)
# builds bench_packing.cpp with REV's src/peridem_geometry_packing.* (old) and with
# the working tree's (new), -O3 as the Release build, and runs old and new
# alternately for each N so both see the same machine load. Compare the CPU times.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
rev="${1:?usage: compare.sh REV [-3] [N ...]}"
shift
dim=()
if [ "${1:-}" = "-3" ]; then
  dim=(-3)
  shift
fi
sizes=("${@:-1500 5000 20000 50000 100000}")
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/old"
for f in peridem_geometry_packing.cpp peridem_geometry_packing.h peridem_geometry_error.h peridem_math.h; do
  git -C "$here" show "$rev:src/$f" >"$tmp/old/$f"
done
cp "$here/bench/packing/bench_packing.cpp" "$tmp/old/bench.cpp"
g++ -O3 -std=c++17 -DNO_GROW -I"$tmp/old" "$tmp/old/bench.cpp" "$tmp/old/peridem_geometry_packing.cpp" \
  -o "$tmp/bench_old"
g++ -O3 -std=c++17 -I"$here/src" "$here/bench/packing/bench_packing.cpp" \
  "$here/src/peridem_geometry_packing.cpp" -o "$tmp/bench_new"
for n in ${sizes[@]}; do
  echo "old ($rev): $("$tmp/bench_old" "${dim[@]}" "$n")"
  echo "new:        $("$tmp/bench_new" "${dim[@]}" "$n" | tr '\n' ' ')"
done
