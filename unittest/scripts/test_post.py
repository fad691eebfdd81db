#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Tests of python/peridem_post.py: the crack angle of synthetic straight
damage bands (to 0.5 degree), the dump and fix ave/time readers on small
hand-written files, and the plots (when matplotlib is importable)."""
import math
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "python"))
import peridem_post as pp  # noqa: E402

try:
    import matplotlib  # noqa: F401
    HAVE_MPL = True
except ImportError:
    HAVE_MPL = False


def band(angle_deg, h=0.02, half_width=0.05, centre=(0.3, -0.2), seed=1):
    """Nodes of a square lattice on [-1, 1]^2 with damage 1 within a band of
    half_width around a line at angle_deg through centre, a smooth decay
    beside it and random damage up to 0.3 elsewhere."""
    g = np.arange(-1.0, 1.0 + 1e-9, h)
    x, y = (a.ravel() for a in np.meshgrid(g, g))
    t = math.radians(angle_deg)
    dist = np.abs(-(x - centre[0]) * math.sin(t) + (y - centre[1]) * math.cos(t))
    rng = np.random.default_rng(seed)
    damage = np.where(dist <= half_width, 1.0, 0.3 * rng.random(x.size))
    damage = np.maximum(damage, np.clip(1.0 - (dist - half_width) / 0.05, 0.0, 1.0) * 0.9)
    return x, y, damage


class CrackAngle(unittest.TestCase):
    def test_straight_bands(self):
        for angle in (0.0, 12.5, 30.0, 45.0, 60.0, 89.0, -37.0, 90.0):
            x, y, d = band(angle)
            got, centre, length, mask = pp.crack_angle(x, y, d, threshold=0.5)
            diff = (got - angle + 90.0) % 180.0 - 90.0
            self.assertLess(abs(diff), 0.5, f"band at {angle}: {got}")
            self.assertGreater(length, 1.0)

    def test_too_few_damaged_nodes(self):
        with self.assertRaises(ValueError):
            pp.crack_angle([0.0, 1.0], [0.0, 0.0], [0.0, 0.2])


class GrainContactLoads(unittest.TestCase):
    def test_sums_by_grain_pair_and_skips_self_contact(self):
        ids = [1, 2, 3, 4, 5]
        grains = [10, 10, 20, 20, 30]
        rows = [(1, 3, 2.0), (2, 3, -1.5), (3, 5, 4.0), (1, 2, 9.0), (4, 2, 0.5)]
        pairs, load = pp.grain_contact_loads(ids, grains, rows)
        self.assertEqual(pairs, {(10, 20): 4.0, (20, 30): 4.0})
        self.assertEqual(load, {10: 4.0, 20: 8.0, 30: 4.0})
        # the force is the last column, whatever comes between
        pairs2, _ = pp.grain_contact_loads(ids, grains, [(1, 3, 0.1, 2.0)])
        self.assertEqual(pairs2, {(10, 20): 2.0})
        # a dump local snapshot without entries (read_dump's data None): no contact
        self.assertEqual(pp.grain_contact_loads(ids, grains, None), ({}, {10: 0.0, 20: 0.0, 30: 0.0}))


class Readers(unittest.TestCase):
    def test_dump_custom_and_local(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "dump.txt")
            with open(path, "w") as f:
                for step in (0, 100):
                    f.write(f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n2\n"
                            "ITEM: BOX BOUNDS pp pp pp\n0 1\n0 2\n-0.5 0.5\n"
                            "ITEM: ATOMS id x y c_dmg[1]\n"
                            f"1 0.1 0.2 {step / 1000}\n2 0.3 0.4 0.5\n")
                f.write("ITEM: TIMESTEP\n100\nITEM: NUMBER OF ENTRIES\n1\n"
                        "ITEM: BOX BOUNDS pp pp pp\n0 1\n0 2\n-0.5 0.5\n"
                        "ITEM: ENTRIES c_frag[1] c_frag[3]\n1 2\n")
            snaps = pp.read_dump(path)
            self.assertEqual([s["step"] for s in snaps], [0, 100, 100])
            self.assertEqual(pp.column(snaps[1], "c_dmg[1]").tolist(), [0.1, 0.5])
            self.assertEqual(snaps[0]["box"][1].tolist(), [0.0, 2.0])
            self.assertEqual(pp.column(snaps[2], "c_frag[3]").tolist(), [2.0])

    def test_ave_time_scalar_and_vector(self):
        with tempfile.TemporaryDirectory() as d:
            s = os.path.join(d, "scalar.txt")
            with open(s, "w") as f:
                f.write("# Time-averaged data\n# TimeStep c_bed[6] c_dmg f_wall\n"
                        "0 0.5 0 1\n100 0.6 0.1 3\n")
            steps, v = pp.read_ave_time(s)
            self.assertEqual(steps.tolist(), [0, 100])
            self.assertEqual(v[:, 0].tolist(), [0.5, 0.6])
            vec = os.path.join(d, "vector.txt")
            with open(vec, "w") as f:
                f.write("# TimeStep Number-of-rows\n# Row c_g[1] c_g[2]\n"
                        "0 2\n1 0.5 1.5\n2 2.5 3.5\n100 2\n1 0.6 1.6\n2 2.6 3.6\n")
            blocks = pp.read_ave_time(vec)
            self.assertEqual([b[0] for b in blocks], [0, 100])
            self.assertEqual(blocks[1][1][1].tolist(), [2, 2.6, 3.6])


@unittest.skipUnless(HAVE_MPL, "matplotlib is not installed for this python")
class Plots(unittest.TestCase):
    def test_plots_are_written(self):
        with tempfile.TemporaryDirectory() as d:
            x, y, dmg = band(30.0, h=0.1)
            pp.snapshot(x, y, dmg, os.path.join(d, "dmg.png"))
            pp.snapshot(x, y, (x > 0).astype(float) + 1, os.path.join(d, "frag.png"),
                        fragments=True)
            phi = np.linspace(0.5, 0.8, 10)
            pp.plot_vs_volume_fraction(phi, phi ** 2, phi ** 3, os.path.join(d, "phi.png"))
            for name in ("dmg.png", "frag.png", "phi.png"):
                self.assertGreater(os.path.getsize(os.path.join(d, name)), 1000)


if __name__ == "__main__":
    unittest.main()
