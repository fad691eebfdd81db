#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Checks of the reduced compaction of plus and square beds (ctest bed_shapes_compaction_*:
in.compaction, 40 grains in an 8 mm container, h = eps/5 = R_c, the authors' bond constants), the
physics Bhattacharya & Lipton (2023, §7.4.1, Fig. 14) report that holds at this scale
(README.md):

  1. damage starts in the plus bed at a lower volume fraction than in the square bed
     (the paper: plus first, at phi = 0.31; squares last, at 0.71);
  2. in each bed the top wall carries load before the first bond breaks, and the load rises
     towards it: the load at the first broken bond exceeds the load halfway (in phi) from the
     start to it, and is positive;
  3. the bulk damage never decreases and the broken-bond count never decreases;
  4. damage grows after its onset: each bed ends with more than 10 broken bonds.

    check_shapes.py PLUS_LOG SQUARE_LOG
Prints PERIDEM-PASS or PERIDEM-FAIL.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from peridem_post import read_thermo, verdict  # noqa: E402


def onset_index(rows):
    return next((k for k, r in enumerate(rows) if r["c_dmg[2]"] > 0.5), None)


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    beds = {"plus": read_thermo(sys.argv[1]), "square": read_thermo(sys.argv[2])}
    fails, onset_phi = [], {}
    for name, rows in beds.items():
        k = onset_index(rows)
        if k is None or k == 0:
            fails.append(f"{name}: no bond broke during the run" if k is None else
                         f"{name}: bonds broken at the start")
            continue
        onset_phi[name] = rows[k]["c_bed"]
        phi_mid = 0.5 * (rows[0]["c_bed"] + rows[k]["c_bed"])
        mid = next(r for r in rows if r["c_bed"] >= phi_mid)
        load_onset, load_mid = rows[k - 1]["f_box[21]"], mid["f_box[21]"]
        print(f"{name}: first broken bond at phi {onset_phi[name]:.4f} "
              f"(step {int(rows[k]['Step'])}); "
              f"top wall load {load_onset:.4g} N/m just before, {load_mid:.4g} N/m at phi "
              f"{mid['c_bed']:.4f}; end: phi {rows[-1]['c_bed']:.4f}, bulk damage "
              f"{rows[-1]['c_dmg']:.4g}, {int(rows[-1]['c_dmg[2]'])} broken bonds")
        if not (load_onset > 0.0 and load_onset > load_mid):
            fails.append(f"{name}: load before the first break {load_onset:.4g} not above "
                         f"{load_mid:.4g} halfway")
        for a, b in zip(rows, rows[1:]):
            if b["c_dmg"] < a["c_dmg"] or b["c_dmg[2]"] < a["c_dmg[2]"]:
                fails.append(f"{name}: damage decreased at step {int(b['Step'])}")
                break
        if rows[-1]["c_dmg[2]"] <= 10:
            fails.append(f"{name}: only {int(rows[-1]['c_dmg[2]'])} broken bonds at the end")
    if len(onset_phi) == 2 and not onset_phi["plus"] < onset_phi["square"]:
        fails.append(f"damage onset: plus at phi {onset_phi['plus']:.4f} not before square "
                     f"at {onset_phi['square']:.4f}")
    return verdict(fails)


if __name__ == "__main__":
    sys.exit(main())
