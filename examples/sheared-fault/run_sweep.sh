#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# The pressure sweep of the README: p / sigma_c = RATIOS, contact friction on (mu 0.7) and
# off, JOBS runs at a time (1 rank each), in DIR. Each run leaves DIR/<tag>.txt (the time
# series), <tag>.log and <tag>.final.dump; legs.txt records each run's command and wall time.
#   examples/sheared-fault/run_sweep.sh [DIR]     (VARS="-var L 0.05 ..." for other settings)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
dir="${1:-$here/runs}"
lmp="$(realpath "${LMP:-$here/../../build/lmp_peridem}")" # the runs start in DIR
ratios="${RATIOS:-0.0125 0.05 0.1 0.25 0.5 1.0}"
mus="${MUS:-0.7 0}"
jobs="${JOBS:-2}"
mkdir -p "$dir"
# LAMMPS reads its input as it goes: a copy, so that edits here cannot reach a run
[ "$here/in.fault" -ef "$dir/in.fault" ] || cp "$here/in.fault" "$dir/in.fault"
one() { # ratio mu
  local tag="p${1}_mu${2}" t0
  t0=$(date +%s)
  (cd "$dir" && "$lmp" -in in.fault -var potentials "$here/../../potentials" \
    -var ratio "$1" -var mu "$2" -var tag "$tag" ${VARS:-} -log "$tag.log" -screen none) || {
    echo "$tag failed" >>"$dir/legs.txt"
    return 1
  }
  echo "$tag: $lmp -in in.fault -var ratio $1 -var mu $2 ${VARS:-}: 1 rank, $(($(date +%s) - t0)) s, $(date -u +%F\ %H:%M) UTC" >>"$dir/legs.txt"
}
export -f one
export here dir lmp
for r in $ratios; do for m in $mus; do echo "$r $m"; done; done |
  xargs -P "$jobs" -n 2 bash -c 'one "$0" "$1"'
