#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Soak test (doc/soak.md): the 500-grain compaction of in.soak for 1e5 steps on
# 2 ranks, restart files every 1e4 steps, beside a 1-rank run of the same input
# for comparison.
# Checks (printed, exit 1 on failure):
#   * memory flat: the resident set size of every rank (sampled every 10 s from
#     /proc, rss_kb.txt: seconds, then one column per rank) grows by less than
#     5 % after the first 10 % of the samples;
#   * decomposition invariance: bench/soak/compare_thermo.py compares the thermo
#     rows of 1 and 2 ranks over the steps both reached and prints, per column,
#     the first step that differs by more than 1e-9 relative and the largest
#     difference (a dense bed is chaotic: see doc/soak.md);
#   * restart continuation: in.soak_continue reads the 1-rank run's restart file
#     of step SOAK_CONTINUE, runs SOAK_CONTINUE_STEPS more steps on 1 rank, and
#     compare_thermo.py --digits prints, per thermo row, how many significant
#     digits it shares with the uninterrupted run (reported, not a pass/fail:
#     the restart rebuilds the neighbour lists and sorts the atoms, so the force
#     sums change order; doc/soak.md has the measured numbers).
# Environment (all optional):
#   SOAK_DIR       working folder (default: a new /tmp/peridem-soak.XXXXXX)
#   SOAK_STEPS     steps of the 2-rank run (default 100000)
#   SOAK_STEPS_1   steps of the 1-rank run (default SOAK_STEPS; shorter is a
#                  comparison window, not a soak)
#   SOAK_SERIAL=1  run 1 rank, then 2 ranks (default: both at once)
#   SOAK_NICE      nice level of the runs (default 15: the machine is shared)
#   SOAK_EVERY     steps between restart files (default 10000)
#   SOAK_THERMO    steps between thermo rows (default 1000)
#   SOAK_CONTINUE  step of the restart file to continue from (default SOAK_EVERY;
#                  0: no continuation)
#   SOAK_CONTINUE_STEPS  steps of the continuation (default SOAK_EVERY)
#   SOAK_MALLOC    "fixed" (default): glibc's mmap threshold fixed at 128 KiB
#                  (GLIBC_TUNABLES), so that the 21 MB buffer of each restart
#                  write goes back to the system when freed; "default": glibc's
#                  dynamic threshold, under which the freed buffers stay in the
#                  heap and RSS grows by up to ~100 MB (doc/soak.md, "Memory")
# Usage: bench/soak/run_soak.sh [BUILD_DIR] (about 1-2 h on 2 idle cores).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
lmp="$build/lmp_peridem"
source "$root/unittest/scripts/mpi_env.sh" # root in containers, oversubscription
steps="${SOAK_STEPS:-100000}"
steps1="${SOAK_STEPS_1:-$steps}"
nicelvl="${SOAK_NICE:-15}"
every="${SOAK_EVERY:-10000}"
thermo="${SOAK_THERMO:-1000}"
cont="${SOAK_CONTINUE:-$every}"
cont_steps="${SOAK_CONTINUE_STEPS:-$every}"
if [ "${SOAK_MALLOC:-fixed}" = fixed ]; then
  export GLIBC_TUNABLES="glibc.malloc.mmap_threshold=131072${GLIBC_TUNABLES:+:$GLIBC_TUNABLES}"
fi
work="${SOAK_DIR:-$(mktemp -d /tmp/peridem-soak.XXXXXX)}"
mkdir -p "$work"
cd "$work"
echo "soak: working in $work ($(date -u +%H:%M:%S) UTC)"
rss_watch() { # pid outfile: seconds since start, then the RSS (kB) of each lmp_peridem rank
  local t0=$SECONDS
  while kill -0 "$1" 2>/dev/null; do
    local line="$((SECONDS - t0))"
    for p in $(pgrep -P "$1" lmp_peridem 2>/dev/null || echo "$1"); do
      line="$line $(awk '/VmRSS/ {print $2}' "/proc/$p/status" 2>/dev/null || echo 0)"
    done
    echo "$line" >>"$2"
    sleep 10
  done
}
start() { # np steps: one run in np<np>/, returns at once; pid in np<np>/pid
  mkdir -p "np$1"
  (
    cd "np$1"
    if [ "$1" = 1 ]; then
      nice -n "$nicelvl" "$lmp" -in "$here/in.soak" -var potentials "$root/potentials" \
        -var nsteps "$2" -var every "$every" -var thermo_every "$thermo" \
        -log log.lammps -screen none &
    else
      nice -n "$nicelvl" mpirun --oversubscribe -np "$1" "$lmp" -in "$here/in.soak" \
        -var potentials "$root/potentials" -var nsteps "$2" -var every "$every" \
        -var thermo_every "$thermo" -log log.lammps -screen none &
    fi
    pid=$!
    echo "$pid" >pid
    rss_watch "$pid" rss_kb.txt &
    wait "$pid"
  ) &
}
if [ "${SOAK_SERIAL:-0}" = 1 ]; then
  start 1 "$steps1"; wait
  start 2 "$steps"; wait
else
  start 2 "$steps"
  start 1 "$steps1"
  wait
fi
echo "soak: runs ended ($(date -u +%H:%M:%S) UTC)"
if [ "$cont" != 0 ]; then
  if [ -f "np1/soak.$cont.restart" ]; then
    mkdir -p np1_continue
    (cd np1_continue && nice -n "$nicelvl" "$lmp" -in "$here/in.soak_continue" \
      -var potentials "$root/potentials" -var restart "../np1/soak.$cont.restart" \
      -var nsteps "$cont_steps" -var thermo_every "$thermo" -log log.lammps -screen none)
    echo "soak: 1 rank continued from the restart file of step $cont against the uninterrupted run"
    python3 "$here/compare_thermo.py" np1/log.lammps np1_continue/log.lammps --digits
  else
    echo "soak: no restart file np1/soak.$cont.restart: no continuation"
  fi
fi
python3 "$here/compare_thermo.py" np1/log.lammps np2/log.lammps
python3 "$here/memory_flat.py" np1/rss_kb.txt np2/rss_kb.txt
echo "soak: passed ($work)"
