#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""probe_damaged_restarts.py LMP RESTART READ_INPUT [N [SEED]]: read N copies of the restart
file RESTART, each with 8 random bytes changed, with READ_INPUT (-var file NAME) and sort the
outcomes: a clean ERROR, a run that completes, a hang (60 s), or a crash, with the crashing
frame (gdb) named as LAMMPS's or PERIDEM's. A measurement, not a test: LAMMPS's own restart
reading trusts its input (doc/errors.md)."""
import collections
import os
import random
import subprocess
import sys


def frame_of_crash(lmp, read_input, name):
    out = subprocess.run(['gdb', '-batch', '-ex', 'run', '-ex', 'bt 8', '--args', lmp, '-in',
                          read_input, '-var', 'file', name, '-log', 'none', '-echo', 'none'],
                         capture_output=True, text=True, timeout=120).stdout
    frames = [l for l in out.split('\n') if l.startswith('#')]
    for f in frames:
        if 'LAMMPS_NS::' in f:
            return f.split(' in ')[1].split('(')[0] if ' in ' in f else f
    return frames[0] if frames else 'unknown'


def main():
    lmp, restart, read_input = sys.argv[1:4]
    n = int(sys.argv[4]) if len(sys.argv) > 4 else 60
    rng = random.Random(int(sys.argv[5]) if len(sys.argv) > 5 else 1)
    data = open(restart, 'rb').read()
    outcomes = collections.Counter()
    crashes = collections.Counter()
    for k in range(n):
        spoiled = bytearray(data)
        for _ in range(8):
            spoiled[rng.randrange(len(spoiled))] = rng.randrange(256)
        name = 'probe_%d.restart' % k
        open(name, 'wb').write(spoiled)
        try:
            r = subprocess.run([lmp, '-in', read_input, '-var', 'file', name, '-log', 'none',
                                '-echo', 'none'], capture_output=True, text=True, timeout=60)
            text = r.stdout + r.stderr
            if r.returncode < 0 or r.returncode >= 128 or 'Segmentation' in text:
                outcomes['crash'] += 1
                crashes[frame_of_crash(lmp, read_input, name)] += 1
            elif 'ERROR' in text:
                outcomes['clean error'] += 1
            else:
                outcomes['runs'] += 1
        except subprocess.TimeoutExpired:
            outcomes['hang'] += 1
        os.remove(name)
    print('%d damaged restart files: %s' % (n, dict(outcomes)))
    for frame, count in crashes.most_common():
        print('  crash in %s: %d' % (frame, count))


if __name__ == '__main__':
    main()
