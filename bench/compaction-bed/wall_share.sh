#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Share of fix peridem/wall (and of the other big items) in the steps of the
# loaded 500-grain compaction bed, with near_list yes and no: perf record
# (cpu-clock, Debian's perf) of in.timed on 1 rank, counting only the samples
# from the run's first step (the first sample in FixNVE::initial_integrate)
# to its end, so that reading the restart and setup do not count. Shares of
# samples are shares of CPU time, so the load of a shared machine matters
# little.
# Usage: bench/compaction-bed/wall_share.sh [build dir] [steps] [grains]
#   default: build, 1000 steps, 500 grains
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(realpath "${1:-$here/build}")"
source "$here/bench/current_build.sh"
require_current_build "$build"
steps="${2:-1000}"
n="${3:-500}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp "$here/bench/compaction-bed/in.compaction" "$here/bench/compaction-bed/in.timed" "$work/"
cd "$work"
pot="$here/potentials"
"$build/lmp_peridem" -in in.compaction -var potentials "$pot" -var ngrains "$n" -var bond peridem \
  -var warmup 1000 -var restart bed.restart -log log.warm -screen none
for near in yes no; do
  perf record -q -o "perf.$near" "$build/lmp_peridem" -in in.timed -var potentials "$pot" \
    -var restart bed.restart -var steps "$steps" -var near "$near" -log "log.$near" -screen none \
    2> /dev/null
  perf script -i "perf.$near" -F comm,time,ip,sym --comm lmp_peridem 2> /dev/null |
    python3 "$here/bench/compaction-bed/run_samples.py" "near_list $near"
done
