/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: shared piece of the bond loops of bond_style peridem and
   peridem/lps.

   LAMMPS lists the bonds of one atom i1 one after the other: both loops
   sum the forces on i1 in plain local variables while i1 repeats and add
   them to f once per atom, so that consecutive bonds do not wait for each
   other's store to f[i1]. The sums stay locals of the loop, which
   add_bond_force() gets by reference (a store object holding them and f
   was measurably slower: bench/README.md). f is indexed flat from f[0], as
   LAMMPS's OPT styles do.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_BOND_LOOP_H
#define LMP_PERIDEM_BOND_LOOP_H

namespace LAMMPS_NS {
namespace PERIDEM_NS {

// f[i] += (a0, a1, a2), f the flat force array
inline void add_force(double *f, int i, double a0, double a1, double a2)
{
  double *fi = f + 3 * i;
  fi[0] += a0;
  fi[1] += a1;
  fi[2] += a2;
}

// the sums on i1 while i1 repeats: a new i1 stores the sums of the previous one (current)
// and starts again from 0
inline void start_atom(double *f, int &current, double *sum, int i1)
{
  if (i1 == current) return;
  if (current >= 0) add_force(f, current, sum[0], sum[1], sum[2]);
  current = i1;
  sum[0] = sum[1] = sum[2] = 0.0;
}

// the force fbond (x1 - x2) of one bond on i1 and its opposite on i2 (when
// to_i2): the forces on i1 are summed in sum[3], a local array of the
// caller, while i1 repeats (current: the atom summed so far, -1 at first);
// finish the loop with add_force(f, current, sum...) when current >= 0
inline void add_bond_force(double *f, int &current, double *sum, int i1, int i2, bool to_i2,
                           double delx, double dely, double delz, double fbond)
{
  start_atom(f, current, sum, i1);
  sum[0] += delx * fbond;
  sum[1] += dely * fbond;
  sum[2] += delz * fbond;
  if (to_i2) add_force(f, i2, -delx * fbond, -dely * fbond, -delz * fbond);
}

// the same in 2d: the bond has no z component, and f_z gets nothing
inline void add_bond_force_2d(double *f, int &current, double *sum, int i1, int i2, bool to_i2,
                              double delx, double dely, double fbond)
{
  start_atom(f, current, sum, i1);
  sum[0] += delx * fbond;
  sum[1] += dely * fbond;
  if (to_i2) {
    double *fi = f + 3 * i2;
    fi[0] -= delx * fbond;
    fi[1] -= dely * fbond;
  }
}

// x1 - x2 of atoms i1 and i2 (x flat from x[0]) into del
inline void separation(const double *x, int i1, int i2, double *del)
{
  const double *x1 = x + 3 * i1, *x2 = x + 3 * i2;
  del[0] = x1[0] - x2[0];
  del[1] = x1[1] - x2[1];
  del[2] = x1[2] - x2[2];
}

// The forces of one pass over the bond list, for the kernels of the bond styles' traversal
// (BondPeridemBase::for_each_intact_bond): a member of the pass's local kernel object, whose
// address never escapes, so that current and sum stay in registers as plain locals do.
struct BondForces {
  double *f; // flat from f[0]
  int nlocal, newton_bond;
  int current = -1; // the i1 whose forces are being summed
  double sum[3] = {0.0, 0.0, 0.0};
  void add(int i1, int i2, double delx, double dely, double delz, double fbond)
  {
    add_bond_force(f, current, sum, i1, i2, newton_bond || i2 < nlocal, delx, dely, delz, fbond);
  }
  void add_2d(int i1, int i2, double delx, double dely, double fbond)
  {
    add_bond_force_2d(f, current, sum, i1, i2, newton_bond || i2 < nlocal, delx, dely, fbond);
  }
  void finish()
  {
    if (current >= 0) add_force(f, current, sum[0], sum[1], sum[2]);
  }
};

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
