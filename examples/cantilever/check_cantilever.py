#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""The cantilever's checks (ctest cantilever_*): in.cantilever at two meshes, then the
beam theory it must approach (ParticLS, Sec. 5.5; Timoshenko's shear correction).

    check_cantilever.py --lmp LMP --model pmb|lps [--dim 2|3] [--load bending|axial]
                        [--n N1,N2] [--np 1|2] [--out DIR]

Checks:
  1. at rest, at the finer mesh, the deflection of the centre line has the beam's shape: away from the
     clamp (x > L/4), w(x) / w(L - h/2) is Timoshenko's w_T(x) / w_T(L - h/2) within
     SHAPE (a beam uniformly too stiff or too soft has the same shape; a clamp that
     turns, or an end that shears, has not); --load axial: the bar's u(x) = q (L x -
     x^2/2) / (E A), its modulus instead of its bending stiffness;
  2. the tip deflection converges to Timoshenko's as h and eps = 3h shrink (eps / H =
     3 / n): |D/D_T - 1| falls from the coarser mesh to the finer one, and is within
     TOLERANCE at the finer one;
  3. with --np 2, two ranks give the one-rank deflection (the static state does not
     depend on the decomposition) to 1e-4 (the relaxation stops at a tolerance of 1e-5).
Prints PERIDEM-PASS or PERIDEM-FAIL.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from peridem_post import column, read_dump, verdict  # noqa: E402

SHAPE = 0.02
# |D/D_T - 1| allowed at the finer mesh of the test (README.md's table: the deflection
# at eps / H = 3/7 and 3/11)
TOLERANCE = {("pmb", 2, "bending"): 0.30, ("lps", 2, "bending"): 0.07,
             ("pmb", 3, "bending"): 1.0, ("lps", 3, "axial"): 0.25}
LINE = re.compile(r"^CANTILEVER .*")


def run(lmp, out, np_, args):
    """One in.cantilever run in `out`; the CANTILEVER line's fields as a dict."""
    os.makedirs(out, exist_ok=True)
    shutil.copy(os.path.join(HERE, "in.cantilever"), out)
    mpirun = os.path.join(HERE, "..", "..", "unittest", "scripts", "mpirun.sh")
    cmd = [] if np_ == 1 else [mpirun, str(np_)]
    cmd += [lmp, "-in", "in.cantilever", "-log", "log.lammps", "-echo", "none"] + args
    p = subprocess.run(cmd, cwd=out, capture_output=True, text=True)
    lines = [l for l in p.stdout.splitlines() if LINE.match(l)]
    if p.returncode != 0 or not lines:
        print(p.stdout[-3000:], p.stderr[-3000:])
        raise SystemExit(f"PERIDEM-FAIL in.cantilever {' '.join(args)}: exit {p.returncode}")
    w = lines[-1].split()[1:]
    fields = dict(zip(w[0::2], w[1::2]))
    print(lines[-1])
    return fields


def shape_error(out, fields, dim, load):
    """Largest |w(x)/w(tip) - w_T(x)/w_T(tip)| on the centre line for x > L/4."""
    s = read_dump(os.path.join(out, "cantilever.dump"))[-1]
    x0, y0, z0 = (column(s, c) for c in ("c_ref[1]", "c_ref[2]", "c_ref[3]"))
    uy = column(s, "v_uy" if load == "bending" else "v_ux")
    h, L = float(fields["h"]), float(fields["L"])
    axis = (np.abs(y0) < 1e-3 * h) & ((np.abs(z0) < 1e-3 * h) if dim == 3 else True) & (x0 > 0)
    x, w = x0[axis], uy[axis]
    nu = 1.0 / (dim + 1)
    # Timoshenko's w(x) / q up to the common factor 1/(E I): bending + shear (kappa = 5/6,
    # G = E / (2 (1 + nu)), A = H^(dim-1), I = H^(dim+1)/12: E I / (kappa G A) = H^2 (1 + nu) / 5)
    H = 0.01
    wt = x**2 * (6 * L**2 - 4 * L * x + x**2) / 24 + (L * x - x**2 / 2) * H**2 * (1 + nu) / 5
    if load == "axial":
        wt = L * x - x**2 / 2
    tip = np.argmax(x)
    far = x > L / 4
    return float(np.max(np.abs(w[far] / w[tip] - wt[far] / wt[tip])))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--model", choices=("pmb", "lps"), required=True)
    ap.add_argument("--dim", type=int, choices=(2, 3), default=2)
    ap.add_argument("--load", choices=("bending", "axial"), default="bending")
    ap.add_argument("--n", default="5,7", help="node rows across H: coarser,finer")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--out", default="cantilever_check")
    a = ap.parse_args()
    n1, n2 = (int(v) for v in a.n.split(","))
    fails, ratios = [], {}
    for n in (n1, n2):
        out = os.path.join(a.out, f"n{n}")
        f = run(a.lmp, out, 1, ["-var", "model", a.model, "-var", "dim", str(a.dim),
                                "-var", "load", a.load, "-var", "n", str(n), "-var", "dump", "1"])
        ratios[n] = float(f["timoshenko"])
        err = shape_error(out, f, a.dim, a.load)
        print(f"n {n}: D/D_T {ratios[n]:.5f}, centre-line shape off by {err:.4f} (at most {SHAPE})")
        if n == n2 and err > SHAPE:
            fails.append(f"n {n}: the centre line's shape is off by {err:.4f} > {SHAPE}")
    e1, e2 = abs(ratios[n1] - 1), abs(ratios[n2] - 1)
    tol = TOLERANCE[(a.model, a.dim, a.load)]
    if not e2 < e1:
        fails.append(f"no convergence: |D/D_T - 1| {e1:.4f} at n {n1}, {e2:.4f} at n {n2}")
    if e2 > tol:
        fails.append(f"|D/D_T - 1| = {e2:.4f} > {tol} at n {n2}")
    if a.np > 1:
        f = run(a.lmp, os.path.join(a.out, f"n{n2}_np{a.np}"), a.np,
                ["-var", "model", a.model, "-var", "dim", str(a.dim), "-var", "load", a.load,
                 "-var", "n", str(n2)])
        r = float(f["timoshenko"])
        if abs(r / ratios[n2] - 1) > 1e-4:
            fails.append(f"{a.np} ranks: D/D_T {r:.6f} against {ratios[n2]:.6f} on one")
    return verdict(fails, f"{a.model} {a.dim}d {a.load}: D/D_T {ratios[n1]:.4f} (n {n1}) -> "
                          f"{ratios[n2]:.4f} (n {n2})")


if __name__ == "__main__":
    sys.exit(main())
