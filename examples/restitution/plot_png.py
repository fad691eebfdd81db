# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Runs a matplotlib script (argv: data file, PNG, extra strings) with this Python's matplotlib, else Debian's
(/usr/bin/python3, python3-matplotlib); shared by the two-particle runners."""
import os
import subprocess
import sys


def plot(script, dat, png, *extra):
    for py in [sys.executable, "/usr/bin/python3"]:
        if os.path.exists(py) and subprocess.run([py, "-c", script, dat, png, *extra],
                                                 stderr=subprocess.DEVNULL).returncode == 0:
            print("wrote " + png)
            return True
    print("matplotlib not installed: no " + os.path.basename(png))
    return False
