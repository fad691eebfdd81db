#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""memory_flat.py RSS_FILE...: each file holds lines "seconds rss_rank0_kB
[rss_rank1_kB ...]" (run_soak.sh samples them every 10 s). Prints, per rank, the
largest RSS in the first 10 % of the samples, the largest after it and the last
one, and exits 1 when a rank grows by more than 5 % after the first 10 %."""
import sys

bad = False
for path in sys.argv[1:]:
    rows = [[int(w) for w in line.split()] for line in open(path) if len(line.split()) > 1]
    rows = [r for r in rows if all(v > 0 for v in r[1:])]  # a rank not started yet
    # before mpirun has started the ranks, a line holds mpirun's own RSS: keep the lines
    # with one column per rank
    ncol = max((len(r) for r in rows), default=0)
    rows = [r for r in rows if len(r) == ncol]
    if len(rows) < 2:
        print(f"{path}: {len(rows)} samples, too few")
        continue
    n = max(1, len(rows) // 10)
    for rank in range(len(rows[0]) - 1):
        col = [r[rank + 1] for r in rows if len(r) > rank + 1]
        base, peak, last = max(col[:n]), max(col[n:] or col), col[-1]
        growth = 100.0 * (peak / base - 1.0)
        print(f"{path} rank {rank}: {len(col)} samples over {rows[-1][0]} s; RSS in the first 10 % "
              f"{base} kB, peak after {peak} kB ({growth:+.1f} %), last {last} kB")
        bad = bad or peak > 1.05 * base
sys.exit("soak: memory grows" if bad else 0)
