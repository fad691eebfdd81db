#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Stress-strain curve of in.uniaxial (ParticLS Fig. 8): sigma_zz of the packing (compute
peridem/stress) against the strain of the wall gap, beside the wall loads, the lateral
stress, the coordination number and the fabric.

  plot_uniaxial.py [stress_strain.txt] [-o uniaxial_stress.png]
"""
import argparse

import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("file", nargs="?", default="stress_strain.txt")
    ap.add_argument("-o", "--out", default="uniaxial_stress.png")
    a = ap.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    d = np.loadtxt(a.file)
    t, e, sxx, syy, szz = d[:, 0], d[:, 1], d[:, 2], d[:, 3], d[:, 4]
    contact, bond, lid, floor, sides = d[:, 6], d[:, 7], d[:, 9], d[:, 10], d[:, 11]
    Z, Fzz = d[:, 12], d[:, 15]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax.plot(e, szz, "k-", lw=1.6, label=r"$\bar\sigma_{zz}$ (compute peridem/stress)")
    ax.plot(e, 0.5 * (sxx + syy), "b-", lw=1.2, label=r"$(\bar\sigma_{xx}+\bar\sigma_{yy})/2$")
    ax.plot(e, 0.5 * (lid + floor), "r--", lw=1, label="-(lid + floor load)/2A")
    ax.plot(e, sides, "c--", lw=1, label="-side wall load / area")
    ax.plot(e, contact, ":", color="gray", label="contact part (zz)")
    ax.set_xlabel(r"strain $\varepsilon = 1 - H/H_0$")
    ax.set_ylabel("stress (lj units)")
    ax.legend(fontsize=8)
    ax.set_title("uniaxial compression of a packing of peridynamic spheres")
    bx.plot(e, Z, "k-", label="coordination number Z")
    bx.set_xlabel(r"strain $\varepsilon$")
    bx.set_ylabel("Z")
    cx = bx.twinx()
    cx.plot(e, Fzz, "m-", label=r"fabric $F_{zz}$")
    cx.axhline(1 / 3, color="m", lw=0.5, ls=":")
    cx.set_ylabel(r"$F_{zz}$ (isotropic: 1/3)", color="m")
    bx.legend(loc="upper left", fontsize=8)
    cx.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
