#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Independent checks of the YAML references in tests/ (run in ctest).

The references were written by the drivers' own -g/-u flag from our C++ styles;
this script recomputes what it can from the closed forms of the doc pages, in
numpy, from tests/data.peridem alone (no LAMMPS, no PERIDEM code):

* bond-peridem*.yaml: energy, per-atom forces and virial of bond-based
  peridynamics (doc/bond_peridem.rst: F = c w s V_i V_j beta y/|y|,
  E = c w s^2 |xi| V_i V_j beta / 2; c and s0 of its 3d table, the partial-volume
  ramp of volume_correction linear).
* bond-peridem_lps.yaml: the linear peridynamic solid (doc/bond_peridem_lps.rst,
  Jha et al. 2021 eq. 5-10, 33-34): weighted volume m_i, dilation theta_i,
  energy, bond forces, virial.
* pair-peridem_contact.yaml: the repulsion of Bhattacharya and Lipton 2023
  eq. 4.1 between unbonded nodes of different grains closer than R_c: energy,
  forces, virial.
* every pair-*.yaml: the conservative energy equals the repulsion energy
  (damping and friction store none), the forces obey Newton's third law (they
  sum to zero), and the damping and friction part (forces minus the repulsion)
  does no positive work: sum_i (F_i - F_rep,i) . v_i <= 0.
* every pair-*.yaml: the virial equals sum_i x_i (x) F_i of the reference forces
  (no periodic images in data.peridem), damping and friction included.
* fix-timestep-*.yaml are not checked here; see README.md.

Usage: check_references.py [tests-dir]; exit code 1 on any mismatch.
"""
import math
import os
import sys

import numpy as np

TESTS = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "tests")
TOL = 1e-11  # relative; the references are printed with 17 digits
failures = []


def pair_force(F, W, x, i, j, fi):
    """Adds the force fi on i (and -fi on j) and its virial (x_i - x_j) (x) fi."""
    F[i] += fi
    F[j] -= fi
    dd = x[i] - x[j]
    W += [dd[0] * fi[0], dd[1] * fi[1], dd[2] * fi[2], dd[0] * fi[1], dd[0] * fi[2], dd[1] * fi[2]]


def read_data(path):
    sec, atoms, vel, bonds = None, {}, {}, []
    for line in open(path):
        s = line.split("#")[0].strip()
        if not s:
            continue
        if s in ("Atoms", "Velocities", "Bonds"):
            sec = s
            continue
        if s[0].isalpha():
            sec = None
            continue
        w = s.split()
        if sec == "Atoms":
            atoms[int(w[0])] = dict(grain=int(w[1]), type=int(w[2]), vol=float(w[3]),
                                    rho=float(w[4]), x=np.array(list(map(float, w[5:8]))),
                                    x0=np.array(list(map(float, w[8:11]))))
        elif sec == "Velocities":
            vel[int(w[0])] = np.array(list(map(float, w[1:4])))
        elif sec == "Bonds":
            bonds.append((int(w[1]), int(w[2]), int(w[3])))
    n = max(atoms)
    assert sorted(atoms) == list(range(1, n + 1))
    x = np.array([atoms[i]["x"] for i in range(1, n + 1)])
    x0 = np.array([atoms[i]["x0"] for i in range(1, n + 1)])
    v = np.array([vel[i] for i in range(1, n + 1)])
    vol = np.array([atoms[i]["vol"] for i in range(1, n + 1)])
    mass = np.array([atoms[i]["rho"] * atoms[i]["vol"] for i in range(1, n + 1)])
    grain = np.array([atoms[i]["grain"] for i in range(1, n + 1)])
    typ = np.array([atoms[i]["type"] for i in range(1, n + 1)])
    return dict(x=x, x0=x0, v=v, vol=vol, mass=mass, grain=grain, type=typ,
                bonds=[(t, a - 1, b - 1) for t, a, b in bonds])


def read_yaml(path):
    """The few keys we need, from the drivers' simple YAML."""
    out, key, block = {}, None, []
    for line in open(path):
        if line.startswith("---") or line.startswith("..."):
            continue
        if line and not line[0].isspace() and ":" in line:
            if key is not None:
                out[key] = block
            key, rest = line.split(":", 1)
            rest = rest.strip()
            block = [] if rest.startswith("!") else [rest]
        else:
            block.append(line.rstrip("\n"))
    if key is not None:
        out[key] = block
    return out


def yaml_scalar(y, k):
    return float(y[k][0])


def yaml_forces(y, k):
    rows = [l.split() for l in y[k] if l.strip()]
    return np.array([[float(c) for c in r[1:4]] for r in sorted(rows, key=lambda r: int(r[0]))])


def yaml_stress(y, k):
    return np.array([float(c) for c in " ".join(y[k]).split()])


def fdotr(x, F):
    """sum_i x_i (x) F_i: the virial of forces that sum to zero, without periodic images."""
    return np.array([np.sum(x[:, 0] * F[:, 0]), np.sum(x[:, 1] * F[:, 1]), np.sum(x[:, 2] * F[:, 2]),
                     np.sum(x[:, 0] * F[:, 1]), np.sum(x[:, 0] * F[:, 2]), np.sum(x[:, 1] * F[:, 2])])


def close(name, got, ref, tol=TOL):
    got, ref = np.atleast_1d(got), np.atleast_1d(ref)
    scale = np.max(np.abs(ref))
    err = np.max(np.abs(got - ref)) / scale if scale > 0 else np.max(np.abs(got))
    status = "ok" if err <= tol else "MISMATCH"
    print(f"  {name:32s} max rel. error {err:.2e} ({status})")
    if err > tol:
        failures.append(name)


def keywords(words):
    kw = {}
    i = 0
    while i < len(words):
        kw[words[i]] = words[i + 1]
        i += 2
    return kw


def bond_based(d, style_words, coeffs):
    """Energy, forces, virial of bond_style peridem (3d)."""
    vc_linear = "volume_correction" in style_words and \
        style_words[style_words.index("volume_correction") + 1] == "linear"
    par = {}
    for line in coeffs:
        w = line.split()
        kw = keywords(w[1:])
        eps = float(kw["horizon"])
        conic = kw.get("micromodulus", "constant") == "conic"
        if "c" in kw:
            c = float(kw["c"])
        else:  # 3d: K = E / (3 (1 - 2 nu)), nu = 1/4; doc table: 18K/(pi eps^4), conic 90K/(pi eps^4)
            K = float(kw["E"]) / 1.5 if "E" in kw else float(kw["K"])
            c = (90.0 if conic else 18.0) * K / (math.pi * eps ** 4)
        par[int(w[0])] = (c, eps, conic, float(kw.get("spacing", "nan")))
    x, x0, V = d["x"], d["x0"], d["vol"]
    E, F, W = 0.0, np.zeros_like(x), np.zeros(6)
    for t, i, j in d["bonds"]:
        c, eps, conic, h = par[t]
        xi = np.linalg.norm(x0[j] - x0[i])
        y = x[j] - x[i]
        r = np.linalg.norm(y)
        s = (r - xi) / xi
        w = 1.0 - xi / eps if conic else 1.0
        beta = 1.0
        if vc_linear and xi > eps - h / 2:
            beta = (eps + h / 2 - xi) / h
        k = c * w * V[i] * V[j] * beta
        E += 0.5 * k * s * s * xi
        fi = k * s * y / r  # on i, towards j when stretched
        pair_force(F, W, x, i, j, fi)
    return E, F, W


def lps(d, coeffs):
    """Energy, forces, virial of bond_style peridem/lps (3d: a = K, b = 15 G)."""
    par = {}
    for line in coeffs:
        w = line.split()
        kw = keywords(w[1:])
        par[int(w[0])] = (float(kw["K"]), float(kw["G"]), float(kw["horizon"]),
                          kw.get("influence", "conic"))
    x, x0, V = d["x"], d["x0"], d["vol"]
    n = len(V)
    dim = 3

    def omega(t, r):
        K, G, eps, infl = par[t]
        return {"conic": max(0.0, 1 - r / eps), "constant": 1.0, "inverse": 1.0 / r}[infl]

    m, theta = np.zeros(n), np.zeros(n)
    geo = []
    for t, i, j in d["bonds"]:
        r = np.linalg.norm(x0[j] - x0[i])
        y = x[j] - x[i]
        e = np.linalg.norm(y) - r
        om = omega(t, r)
        geo.append((t, i, j, r, y, e, om))
        m[i] += om * r * r * V[j]
        m[j] += om * r * r * V[i]
    for t, i, j, r, y, e, om in geo:
        theta[i] += dim / m[i] * om * r * e * V[j]
        theta[j] += dim / m[j] * om * r * e * V[i]
    # a node's a, b: from the type of its bonds (one bond type per grain here)
    a_of, b_of = np.zeros(n), np.zeros(n)
    for t, i, j, *_ in geo:
        K, G, *_ = par[t]
        a_of[i] = a_of[j] = K
        b_of[i] = b_of[j] = 15.0 * G
    E = float(np.sum(V * a_of / 2 * theta ** 2))
    F, W = np.zeros_like(x), np.zeros(6)
    for t, i, j, r, y, e, om in geo:
        K, G, *_ = par[t]
        a, b = K, 15.0 * G
        E += V[i] * b / (2 * m[i]) * om * (e - theta[i] * r / dim) ** 2 * V[j]
        E += V[j] * b / (2 * m[j]) * om * (e - theta[j] * r / dim) ** 2 * V[i]
        fmag = V[i] * V[j] * om * ((dim * a - b / dim) * (theta[i] / m[i] + theta[j] / m[j]) * r
                                   + b * (1 / m[i] + 1 / m[j]) * e)
        fi = fmag * y / np.linalg.norm(y)
        pair_force(F, W, x, i, j, fi)
    return E, F, W


def repulsion(d, coeff_lines):
    """Bhattacharya and Lipton 2023 eq. 4.1 between unbonded nodes closer than R_c
    (only nodes of different grains come that close in data.peridem)."""
    ntypes = int(d["type"].max())
    Kn = np.zeros((ntypes + 1, ntypes + 1))
    Rc = np.zeros((ntypes + 1, ntypes + 1))
    for line in coeff_lines:
        w = line.split()
        # only the keywords this check needs; damping/friction words are skipped
        kn = float(w[w.index("Kn") + 1])
        rc = float(w[w.index("Rc") + 1])
        ii = range(1, ntypes + 1) if w[0] == "*" else [int(w[0])]
        jj = range(1, ntypes + 1) if w[1] == "*" else [int(w[1])]
        for a in ii:
            for b in jj:
                Kn[a, b] = Kn[b, a] = kn
                Rc[a, b] = Rc[b, a] = rc
    x, V, typ = d["x"], d["vol"], d["type"]
    bonded = {(min(i, j), max(i, j)) for _, i, j in d["bonds"]}
    E, F, W = 0.0, np.zeros_like(x), np.zeros(6)
    n = len(V)
    for i in range(n):
        for j in range(i + 1, n):
            if (i, j) in bonded:
                continue
            sep = x[j] - x[i]
            r = np.linalg.norm(sep)
            kn, rc = Kn[typ[i], typ[j]], Rc[typ[i], typ[j]]
            if r >= rc:
                continue
            E += 0.5 * kn * (rc - r) ** 2 * V[i] * V[j]
            fi = -kn * (rc - r) * V[i] * V[j] * sep / r  # pushes i away from j
            pair_force(F, W, x, i, j, fi)
    return E, F, W


def main():
    d = read_data(os.path.join(TESTS, "data.peridem"))
    for name in sorted(os.listdir(TESTS)):
        if not name.endswith(".yaml"):
            continue
        y = read_yaml(os.path.join(TESTS, name))
        print(name)
        if name.startswith("bond-"):
            style = " ".join(y["bond_style"]).split()
            coeffs = [l.strip() for l in y["bond_coeff"] if l.strip()]
            E, F, W = lps(d, coeffs) if style[0] == "peridem/lps" else bond_based(d, style, coeffs)
            close("init_energy (closed form)", E, yaml_scalar(y, "init_energy"))
            close("init_forces (closed form)", F, yaml_forces(y, "init_forces"))
            close("init_stress (closed form)", W, yaml_stress(y, "init_stress"))
        elif name.startswith("pair-"):
            coeffs = [l.strip() for l in y["pair_coeff"] if l.strip()]
            E, F, W = repulsion(d, coeffs)
            Fref = yaml_forces(y, "init_forces")
            close("init_vdwl = repulsion energy", E, yaml_scalar(y, "init_vdwl"))
            scale = np.max(np.abs(Fref))
            net = np.max(np.abs(Fref.sum(axis=0))) / scale
            print(f"  {'Newton 3rd law: |sum F|/max|F|':32s} {net:.2e}")
            if net > 1e-12:
                failures.append(name + " momentum")
            # the virial of all the forces (damping and friction too) is sum x (x) F: catches
            # a contribution computed but left out of the tally (or counted twice)
            close("init_stress = sum x (x) F", fdotr(d["x"], Fref), yaml_stress(y, "init_stress"))
            dissipative = any(k in " ".join(coeffs) for k in ("damping", "friction"))
            if dissipative:
                power = float(np.sum((Fref - F) * d["v"]))
                print(f"  {'power of damping+friction':32s} {power:.3e} (must be <= 0)")
                if not power < 0.0:
                    failures.append(name + " power")
            else:
                close("init_forces (closed form)", F, Fref)
                close("init_stress (closed form)", W, yaml_stress(y, "init_stress"))
    if failures:
        print("FAILED:", ", ".join(failures))
        return 1
    print("all references agree with the closed forms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
