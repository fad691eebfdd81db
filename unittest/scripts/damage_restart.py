#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""damage_restart.py IN OUT X0 Y0 Z0 FIELD VALUE: copy the LAMMPS restart file IN to OUT with
one value of one atom changed, for the damaged-restart tests.

The atom is the one whose reference position x0 is (X0, Y0, Z0) (the 3 doubles, bit for
bit). Its per-atom record in a restart of atom_style peridem (LAMMPS 29Sep2021 and 4Feb2025,
AtomVec::pack_restart) is: size, x (3), tag, type, mask, image, v (3), then the style's
fields molecule, num_bond, bond_type (num_bond), bond_atom (num_bond), rmass, vfrac, x0 (3),
then each fix's block (its length first). Integers are stored as the bits of an int64.
FIELD: tag, molecule, bond_type (the first bond), vfrac, x0z, or fixblock:LEN:K (value K,
1-based, of the first fix block of length LEN). Global sections, where X0 Y0 Z0 are not used:
double:OLD (the one double of value OLD in the file) and int_after:TAG:K (the K-th int after
the one int TAG, a style's restart tag). VALUE: a number, nan or inf; an integer for tag,
molecule, bond_type and int_after."""
import struct
import sys


def main():
    src, dst, x0, y0, z0, field, value = sys.argv[1:8]
    data = bytearray(open(src, 'rb').read())
    if field.startswith('double:') or field.startswith('int_after:'):
        replace_global(data, field, value)
        open(dst, 'wb').write(data)
        print('damage_restart.py: %s set to %s' % (field, value))
        return
    key = struct.pack('<3d', float(x0), float(y0), float(z0))
    at = data.find(key)
    if at < 0 or data.find(key, at + 1) >= 0:
        sys.exit('damage_restart.py: the reference position is not in the file exactly once')

    def get(k):  # double k of the record, counted from x0's first value
        return data[at + 8 * k:at + 8 * k + 8]

    def as_int(b):
        return struct.unpack('<q', b)[0]

    def as_double(k):
        return struct.unpack('<d', get(k))[0]

    def consistent(n):
        # num_bond, 3 + 2 n doubles before x0, reads n, and the record's size (its first
        # double, 15 + 2 n before x0) ends exactly after whole fix blocks
        if as_int(get(-3 - 2 * n)) != n:
            return False
        size, end = as_double(-15 - 2 * n), 3
        if size != int(size) or size < 18 + 2 * n or size > 18 + 2 * n + 1000:
            return False
        while end < size - 15 - 2 * n:
            block = as_double(end)
            if block != int(block) or block < 1:
                return False
            end += int(block)
        return end == size - 15 - 2 * n

    nb = next((n for n in range(1, 1000) if consistent(n)), None)
    if nb is None:
        sys.exit('damage_restart.py: no consistent record with bonds around x0')
    if field == 'tag':
        offset, packed = -11 - 2 * nb, struct.pack('<q', int(value))
    elif field == 'molecule':
        offset, packed = -4 - 2 * nb, struct.pack('<q', int(value))
    elif field == 'bond_type':
        offset, packed = -2 - 2 * nb, struct.pack('<q', int(value))
    elif field == 'vfrac':
        offset, packed = -1, struct.pack('<d', float(value))
    elif field == 'x0z':
        offset, packed = 2, struct.pack('<d', float(value))
    elif field.startswith('fixblock:'):
        _, length, k = field.split(':')
        offset = 3
        size = as_double(offset)
        while int(size) != int(length):
            offset += int(size)
            size = as_double(offset)
            if offset > 1000:
                sys.exit('damage_restart.py: no fix block of length ' + length)
        offset, packed = offset + int(k), struct.pack('<d', float(value))
    else:
        sys.exit('damage_restart.py: unknown field ' + field)
    data[at + 8 * offset:at + 8 * offset + 8] = packed
    open(dst, 'wb').write(data)
    print('damage_restart.py: atom with x0 %s %s %s (%d bonds): %s set to %s' %
          (x0, y0, z0, nb, field, value))


def find_once(data, key, what):
    at = data.find(key)
    if at < 0 or data.find(key, at + 1) >= 0:
        sys.exit('damage_restart.py: %s is not in the file exactly once' % what)
    return at


def replace_global(data, field, value):
    if field.startswith('double:'):
        at = find_once(data, struct.pack('<d', float(field.split(':')[1])), field)
        data[at:at + 8] = struct.pack('<d', float(value))
    else:
        _, tag, k = field.split(':')
        at = find_once(data, struct.pack('<i', int(tag, 0)), field) + 4 * int(k)
        data[at:at + 4] = struct.pack('<i', int(value))


if __name__ == '__main__':
    main()
