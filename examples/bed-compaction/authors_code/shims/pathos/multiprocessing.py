# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Stand-in for pathos.multiprocessing.ProcessingPool (pathos is not
packaged for Debian): a serial map, enough for perigrain's setup scripts."""


class ProcessingPool:
    def __init__(self, *a, **k):
        pass

    def map(self, f, *iterables):
        return list(map(f, *iterables))

    def close(self):
        pass

    def join(self):
        pass
