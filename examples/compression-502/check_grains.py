#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""check_grains.py --lmp LMP [--out DIR]: the two kinds of grains of in.compression on one bed.

Builds a small bed of lattice grains (-var grains lattice, R_c = 0.95 h) and puts the
Gmsh grains of Jha et al.'s code (-var grains gmsh, circle.msh and hexagon.msh: 123 and 91
nodes) on the same bed file (-var new_bed no), with R_c = 0.95 hmin. Checks: every disk
has 123 nodes and every hexagon 91; both kinds have the mass of the same grains (lattice
cells and mesh areas both sum to about the grains' areas: within 2 %); R_c is 0.95 hmin;
a misspelt -var grains or -var new_bed stops the input with its message.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SETUP = re.compile(r"PERIDEM-SETUP stage settle (\d+) nodes .* mass (\S+) kg/m .* R_c (\S+) m")
SMALL = ["-var", "W", "12e-3", "-var", "H", "10e-3", "-var", "t_settle", "0", "-var", "every", "0"]
HMIN = 0.119e-3


def lammps(lmp, out, extra, log):
    cmd = [lmp, "-in", "in.compression"] + SMALL + extra + ["-log", log, "-screen", "none"]
    res = subprocess.run(cmd, cwd=out, capture_output=True, text=True)
    with open(os.path.join(out, log)) as f:
        return res.returncode, f.read()


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--lmp", required=True)
    p.add_argument("--potentials", default=os.path.join(HERE, "..", "..", "potentials"))
    p.add_argument("--out", default="compression_grains")
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    for f in ("in.compression", "circle.msh", "hexagon.msh"):
        shutil.copy(os.path.join(HERE, f), a.out)
    lmp, pot = os.path.abspath(a.lmp), ["-var", "potentials", os.path.abspath(a.potentials)]
    fails = []

    rc_l, log_l = lammps(lmp, a.out, pot + ["-var", "tag", "lat"], "log.lattice")
    rc_g, log_g = lammps(lmp, a.out, pot + ["-var", "tag", "gmsh", "-var", "grains", "gmsh",
                                            "-var", "hmin", str(HMIN), "-var", "new_bed", "no",
                                            "-var", "bed_file", "lat_bed.txt"], "log.gmsh")
    m_l, m_g = SETUP.search(log_l), SETUP.search(log_g)
    if rc_l or rc_g or not (m_l and m_g):
        print(f"PERIDEM-FAIL: exit codes {rc_l} {rc_g} or no PERIDEM-SETUP line ({a.out}/log.*)")
        return 1
    labels = [line.split()[-1] for line in open(os.path.join(a.out, "lat_bed.txt"))
              if not line.startswith("#")]
    disks, hexagons = labels.count("disk"), labels.count("hexagon")
    nodes, expect = int(m_g.group(1)), 123 * disks + 91 * hexagons
    ratio = float(m_g.group(2)) / float(m_l.group(2))
    rc_l_val, rc_g_val = float(m_l.group(3)), float(m_g.group(3))
    print(f"{disks} disks, {hexagons} hexagons: Gmsh nodes {nodes} (expected {expect}), "
          f"lattice nodes {m_l.group(1)}; mass Gmsh / lattice {ratio:.4f}; "
          f"R_c {rc_l_val:.4g} (lattice), {rc_g_val:.4g} (Gmsh)")
    if disks < 5 or hexagons < 1 or nodes != expect:
        fails.append("the Gmsh grains do not have the mesh's 123 and 91 nodes")
    if abs(ratio - 1.0) > 0.02:
        fails.append(f"the two kinds of grains differ in mass by {ratio - 1:+.3%}")
    if abs(rc_l_val - 0.95 * 0.2e-3) > 1e-12 or abs(rc_g_val - 0.95 * HMIN) > 1e-12:
        fails.append("R_c is not 0.95 h (lattice) and 0.95 hmin (Gmsh)")

    for var, value, text in (("grains", "mesh", "-var grains mesh is not lattice or gmsh"),
                             ("new_bed", "maybe", "-var new_bed maybe is not yes or no")):
        rc, log = lammps(lmp, a.out, pot + ["-var", var, value], f"log.bad_{var}")
        if rc == 0 or text not in log:
            fails.append(f"-var {var} {value}: exit code {rc}, message found: {text in log}")

    for f in fails:
        print("PERIDEM-FAIL:", f)
    if not fails:
        print("PERIDEM-PASS")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
