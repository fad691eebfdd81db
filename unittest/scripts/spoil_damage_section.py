#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""spoil_damage_section.py FILE MODE: spoil the PeridemDamage section of a data file in place,
for the tests of its checks. MODE: huge (the first damaged node's count 1e6), twice (an undamaged
node's line given twice, in place of the line of the first node with an odd count), wvolume
(the first node's weighted volume -2)."""
import sys


def main():
    path, mode = sys.argv[1:3]
    lines = open(path).read().split('\n')
    start = next(i for i, l in enumerate(lines) if l.startswith('PeridemDamage')) + 2
    end = next(i for i in range(start, len(lines)) if not lines[i].strip())
    rows = [lines[i].split() for i in range(start, end)]
    if mode == 'huge':
        k = next(k for k, r in enumerate(rows) if float(r[1]) > 0)
        rows[k][1] = '1000000'
    elif mode == 'twice':
        # an undamaged node's line given twice, in place of the line of a node with an odd count
        k = next(k for k, r in enumerate(rows) if int(float(r[1])) % 2 == 1)
        j = next(j for j, r in enumerate(rows) if float(r[1]) == 0)
        rows[k] = list(rows[j])
    elif mode == 'wvolume':
        rows[0][3] = '-2'
    else:
        sys.exit('spoil_damage_section.py: unknown mode ' + mode)
    lines[start:end] = [' '.join(r) for r in rows]
    open(path, 'w').write('\n'.join(lines))
    print('spoil_damage_section.py: %s spoiled (%s)' % (path, mode))


if __name__ == '__main__':
    main()
