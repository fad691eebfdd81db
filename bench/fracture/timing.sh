#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Sourced by the bench/fracture scripts: one LAMMPS log's timing and one table row.

# the longest run of a log: loop time, Bond Pair Neigh Comm Modify Output seconds, neighbour
# builds, then the bond counts: before the run (BENCH-BONDS0 printed by the input, else the sum of
# the logged "bonds added") and after it (BENCH-BONDS)
log_timing() { # log
  awk '/^Loop time of/ && $9 + 0 > nsteps {loop = $4; nsteps = $9 + 0; b = p = n = c = m = o = builds = ""}
       /^Bond +\|/ && b == "" {b = $5} /^Pair +\|/ && p == "" {p = $5} /^Neigh +\|/ && n == "" {n = $5}
       /^Comm +\|/ && c == "" {c = $5} /^Modify +\|/ && m == "" {m = $5} /^Output +\|/ && o == "" {o = $5}
       /Neighbor list builds/ && builds == "" {builds = $5}
       /bonds added/ {added += $(NF-2)} /^BENCH-BONDS0/ {b0 = $2} /^BENCH-BONDS / {b1 = $2}
       END {if (b0 == "") b0 = added; print loop, b + 0, p + 0, n + 0, c + 0, m + 0, o + 0, builds + 0, b0, b1}' "$1"
}

# the lower loop time of two log_timing lines (the first when equal or when the second is empty)
best_of() { # best line
  if [ -z "$1" ] || awk -v a="${2%% *}" -v b="${1%% *}" 'BEGIN {exit !(a < b)}'; then echo "$2"; else echo "$1"; fi
}

table_header() {
  echo "| run | ms/step | ns/bond-step (Bond) | Bond % | Pair % | Neigh % | Modify % | Comm % | Neigh s | builds | bonds | broken bonds | builds per break |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
}

# a row from a log_timing line; ns per bond-step over the mean bond count of the run
table_row() { # name steps line
  echo "$1|$3" | awk -F'|' -v steps="$2" '{
    split($2, t, " "); loop = t[1]; bondt = t[2]; b0 = t[9]; broken = t[9] - t[10]
    mean = b0 - broken / 2
    printf "| %s | %.3f | %.2f | %.1f | %.1f | %.1f | %.1f | %.1f | %.2f | %d | %d | %d | %s |\n", $1,
      1e3 * loop / steps, 1e9 * bondt / (mean * steps), 100 * bondt / loop, 100 * t[3] / loop,
      100 * t[4] / loop, 100 * t[6] / loop, 100 * t[5] / loop, t[4], t[8], b0, broken,
      (broken > 0 ? sprintf("%.3f", t[8] / broken) : "-") }'
}
