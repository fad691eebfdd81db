#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# A cheap stand-in for the in-tree builds (scripts/build_lammps_2025.sh intree, intree-make):
# every src/*.cpp compiled (-fsyntax-only) as a file of a LAMMPS source tree would be, against
# that tree's headers alone (no installed LAMMPS, no MPI: LAMMPS's src/STUBS/mpi.h), with Eigen,
# as C++17, -Wall -Wextra -Wno-unused-parameter -Werror. Catches what only a LAMMPS tree sees:
# a src/ file needing a header of the stand-alone build (driver/, plugin/), an API missing from
# that LAMMPS, a warning with its headers. Usage:
#   scripts/check_intree_compile.sh [LAMMPS_SRC]
# LAMMPS_SRC: the src/ folder of a LAMMPS tree (default: LAMMPS 4 Feb 2025 under
# $PERIDEM_LAMMPS2025_DIR, fetched by scripts/build_lammps_2025.sh fetch when absent).
# PERIDEM_EIGEN_INC (default /usr/include/eigen3), CXX (default g++), PERIDEM_JOBS (default
# nproc). Exit code 0 when every file compiles without a warning.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
root="${PERIDEM_LAMMPS2025_DIR:-/opt/peridem/lammps-2025}"
lsrc="${1:-$root/lammps-4Feb2025/src}"
if [ $# -eq 0 ] && [ ! -f "$lsrc/pointers.h" ]; then
  "$here/scripts/build_lammps_2025.sh" fetch
fi
for h in pointers.h STUBS/mpi.h fmt/format.h; do
  [ -f "$lsrc/$h" ] || { echo "check_intree_compile: no $lsrc/$h (a LAMMPS src/ folder?)" >&2; exit 1; }
done
eigen="${PERIDEM_EIGEN_INC:-/usr/include/eigen3}"
[ -f "$eigen/Eigen/Eigenvalues" ] || { echo "check_intree_compile: no Eigen in $eigen" >&2; exit 1; }
cxx="${CXX:-g++}"
t0=$(date +%s)
# the package folder first, as LAMMPS's CMake adds src/PERIDEM; LAMMPS's headers as in its
# tree (-I, not -isystem: a warning in them under these flags counts)
flags=(-std=c++17 -fsyntax-only -Wall -Wextra -Wno-unused-parameter -Werror -DLAMMPS_SMALLBIG
  -I"$here/src" -I"$lsrc" -I"$lsrc/STUBS" -isystem "$eigen")
files=("$here"/src/*.cpp)
logdir="$(mktemp -d)"
trap 'rm -rf "$logdir"' EXIT
export cxx logdir
# the file is an argument of the inner shell, never part of its script (a path with a space
# or a quote stays one word)
printf '%s\n' "${files[@]}" | xargs -P "${PERIDEM_JOBS:-$(nproc)}" -I{} sh -c \
  'f="$1"; shift; b="${f##*/}"; "$cxx" "$@" "$f" >"$logdir/$b.log" 2>&1 || : >"$logdir/$b.failed"' \
  sh {} "${flags[@]}"
failed=0
for f in "${files[@]}"; do
  b="$(basename "$f")"
  # a file without a log was never compiled: a failure too
  if [ -e "$logdir/$b.failed" ] || [ ! -e "$logdir/$b.log" ]; then
    echo "FAIL $b"
    cat "$logdir/$b.log" 2>/dev/null || true
    failed=$((failed + 1))
  fi
done
echo "check_intree_compile: ${#files[@]} files against $lsrc, $failed failed, $(($(date +%s) - t0)) s"
[ "$failed" -eq 0 ]
