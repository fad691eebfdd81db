#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Benchmark: LAMMPS's BPM impact example (in.impact_bpm: a three-layer plate of 7,529 particles
# struck by a bonded ball of 3,589) beside the same particles as peridynamic nodes of
# bond_style peridem (in.impact_peridem), struck (v 0.05) and quiet (v 0), on two bond networks:
#   bpm-net   BPM's: bonds to 1.5 (the example)
#   pd-net    a peridynamic horizon of 3 spacings, 3.37 (3 x the fcc nearest-neighbour distance
#             1.1225), bond stiffness (and BPM's bond dashpot) k / 30 for both codes so that the bulk stiffness
#             (c sum |xi| over a horizon) stays about the example's (our choice)
# One LAMMPS binary with both packages (scripts/build_lammps_2025.sh bpm builds it), so that
# both use the same LAMMPS, compiler flags and neighbour code; interleaved, best of `repeats`.
# Prints the bench/fracture table per run (timing.sh).
# The quiet runs with the lists rebuilt every 10 steps give both codes the same list work on
# the same network: their Neigh time compares the neighbour builds alone.
# Usage: bench/fracture/run_bpm_impact.sh LMP [repeats] [steps] [ranks] [case regex]
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
lmp="$(realpath "${1:?usage: run_bpm_impact.sh LMP [repeats] [steps] [ranks] [case regex]}")"
repeats="${2:-3}"
steps="${3:-7500}"
ranks="${4:-1}"
# PERIDEM's runs with its vectorised bond loop (bond_style peridem/opt; BPM has no such
# variant); PERIDEM_BENCH_SUFFIX="" times the portable plain style
suffix="${PERIDEM_BENCH_SUFFIX--sf opt}"
source "$here/unittest/scripts/mpi_env.sh"
source "$here/bench/fracture/timing.sh"
help="$("$lmp" -h)"
for style in "pair_style bpm/spring" "bond_style peridem"; do
  grep -qw "${style#* }" <<< "$help" || { echo "ERROR: $lmp has no ${style}" >&2; exit 1; }
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp "$here/bench/fracture/in.impact_bpm" "$here/bench/fracture/in.impact_peridem" "$work/"

lammps() { # log input variables...
  local log="$1" input="$2"
  shift 2
  (cd "$work" && mpirun -np "$ranks" "$lmp" -in "$input" -var steps "$steps" "$@" -log "$log" \
     -screen none >/dev/null 2>&1) || { echo "ERROR: $input $* failed (log $work/$log):" >&2; tail -5 "$work/$log" >&2; exit 1; }
}

# the example's particles (positions after its random displacement), written by BPM's own
# input, as a peridem data file: grain 1 the plate (x < 1), grain 2 the ball, unit volume and
# density, reference positions = positions
lammps log.points in.impact_bpm -var steps 0 -var points 1
awk '/^ *Atoms/ {section = "Atoms"; print "Atoms # peridem"; next}
     /^ *(Velocities|Masses|Bonds)/ {section = "skip"; next}
     section == "" {print; next}
     section == "Atoms" && NF >= 6 {mol = ($4 < 1.0) ? 1 : 2
       printf "%s %d %s 1.0 1.0 %s %s %s %s %s %s\n", $1, mol, $3, $4, $5, $6, $4, $5, $6; next}
     section == "Atoms" {print}' "$work/impact_points.data" >"$work/impact_points.peridem.data"

# name|input|variables
cases=(
  "BPM, bpm-net, struck|in.impact_bpm|-var cut 1.5 -var v 0.05"
  "BPM, bpm-net, quiet|in.impact_bpm|-var cut 1.5 -var v 0"
  "PERIDEM, bpm-net, struck|in.impact_peridem|-var cut 1.5 -var v 0.05"
  "PERIDEM, bpm-net, quiet|in.impact_peridem|-var cut 1.5 -var v 0"
  "BPM, pd-net, struck|in.impact_bpm|-var cut 3.37 -var k 0.0333333 -var v 0.05"
  "BPM, pd-net, quiet|in.impact_bpm|-var cut 3.37 -var k 0.0333333 -var v 0"
  "PERIDEM, pd-net, struck|in.impact_peridem|-var cut 3.37 -var k 0.0333333 -var v 0.05"
  "PERIDEM, pd-net, quiet|in.impact_peridem|-var cut 3.37 -var k 0.0333333 -var v 0"
  "BPM, bpm-net, quiet, lists every 10|in.impact_bpm|-var cut 1.5 -var v 0 -var rebuild 10"
  "PERIDEM, bpm-net, quiet, lists every 10|in.impact_peridem|-var cut 1.5 -var v 0 -var rebuild 10"
  "BPM, pd-net, quiet, lists every 10|in.impact_bpm|-var cut 3.37 -var k 0.0333333 -var v 0 -var rebuild 10"
  "PERIDEM, pd-net, quiet, lists every 10|in.impact_peridem|-var cut 3.37 -var k 0.0333333 -var v 0 -var rebuild 10"
)
# a subset: the cases whose names match the regular expression $5
if [ -n "${5:-}" ]; then
  all=("${cases[@]}")
  cases=()
  for c in "${all[@]}"; do [[ "${c%%|*}" =~ $5 ]] && cases+=("$c"); done
fi
echo "steps $steps, $ranks rank(s), best of $repeats, $(date -u +%F), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
echo "LAMMPS: $(grep -m1 -E 'Simulator' <<< "$help" || true)"
table_header
best=()
for r in $(seq "$repeats"); do # interleaved: each repeat runs every case once
  for i in "${!cases[@]}"; do
    IFS='|' read -r name input vars <<< "${cases[$i]}"
    # shellcheck disable=SC2086
    extra=""
    [ "$input" = in.impact_peridem ] && extra="$suffix"
    lammps "log.$i.$r" "$input" $vars $extra
    best[i]=$(best_of "${best[i]:-}" "$(log_timing "$work/log.$i.$r")")
  done
done
for i in "${!cases[@]}"; do table_row "${cases[$i]%%|*}" "$steps" "${best[i]}"; done
