/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: the chunked force loop of bond_style peridem, included by
   bond_peridem.cpp (the portable style) and bond_peridem_opt.cpp
   (peridem/opt), which compile it with different flags. Each instantiates
   it with a tag type of its own, in an unnamed namespace (see
   BondPeridem::chunked_passes in bond_peridem.h).

   Bonds in chunks of at most CHUNK list entries, in three passes. (a)
   gathers the separations x1 - x2 into short arrays; (b) computes |y|, the
   stretch and F/|y| for the whole chunk without branches, so that the
   compiler can vectorise the square roots and divisions (GCC does so for
   the roots only without errno: -fno-math-errno, which peridem/opt's file
   has); (c) breaks bonds and adds the forces in list order, summing those on
   i1 in registers while i1 repeats. LAMMPS lists the bonds of one atom one
   after the other, so the loop reads the list as pieces with one i1 each
   (fill_pieces): per entry it streams i2 and 1/r0 only (12 bytes; and k when
   the bonds' stiffnesses differ, the type when their types do; LAMMPS's list
   entry is 12 bytes on its own), and x1 once per piece. Each force is the
   same expression as in compute_one_by_one(), and the bond files are
   compiled without FMA contraction (-ffp-contract=off), so the results are
   the same to the bit whatever the compiler vectorises (tested:
   ChunkedLoopEqualsOneByOne, OptEqualsPlain).
------------------------------------------------------------------------- */

#ifndef LMP_BOND_PERIDEM_CHUNKED_H
#define LMP_BOND_PERIDEM_CHUNKED_H

#include "bond_peridem.h"

#include "atom.h"
#include "domain.h"
#include "force.h"

#include "lmp_peridem_bond_loop.h"

#include <cmath>

namespace LAMMPS_NS {

// one chunked pass over the bond list; DIM 2 leaves z out: in 2d every node lies in one
// plane (LAMMPS's 2d model), so z1 - z2 = 0 and |y|, the stretch and the force are the same
// IEEE results without it (to the bit: tested, chunked_equals_one_by_one, 2d), and f_z gets
// nothing. The 2d bed then gathers, sums and scatters two components instead of three.
// ONE_TYPE: every intact entry has type cache.type_all (no per-entry type to stream).
template <class VARIANT, int DIM, bool UNIFORM_K, bool ONE_TYPE>
inline __attribute__((always_inline)) void BondPeridem::chunked_pass()
{
  // LAMMPS's per-atom arrays are contiguous (memory->create): index them flat, as LAMMPS's
  // OPT styles do
  const double *x = atom->x[0];
  const double *inv_r0 = cache.inv_r0.data();
  const double *kb = cache.k.data();
  const double k_all = cache.k_value;
  const PieceView pc = pieces();

  alignas(64) double dx[CHUNK], dy[CHUNK], dz[CHUNK], rv[CHUNK], sv[CHUNK], fb[CHUNK];

  // pass (c) on the base's traversal: entry n is j = n - n0 of the chunk's arrays
  struct Forces {
    PERIDEM_NS::BondForces out;
    const double *dx, *dy, *dz, *rv, *sv, *fb, *r0c;
    int n0 = 0, j = 0;
    void piece(int) {}
    void measure(int n, int, int) { j = n - n0; }
    double stretch(int) const { return sv[j]; }
    double r0(int n) const { return r0c[n]; }
    void bond(int, int i1, int i2, int)
    {
      const double fbond = rv[j] > 0.0 ? fb[j] : 0.0;
      if (DIM == 3)
        out.add(i1, i2, dx[j], dy[j], dz[j], fbond);
      else
        out.add_2d(i1, i2, dx[j], dy[j], fbond);
    }
  } kernel{{atom->f[0], atom->nlocal, force->newton_bond}, dx, dy, dz, rv, sv, fb, cache.r0.data()};

  for (int c = 0; c < pc.nchunks; c++) {
    const int p0 = pc.chunk[c], p1 = pc.chunk[c + 1];
    const int n0 = pc.start[p0], m = pc.start[p1] - n0;
    // (a) gather, x1 once per piece
    for (int p = p0; p < p1; p++) {
      const double *x1 = x + 3 * pc.atom[p];
      const double x10 = x1[0], x11 = x1[1], x12 = DIM == 3 ? x1[2] : 0.0;
      for (int n = pc.start[p], e = pc.start[p + 1]; n < e; n++) {
        const double *x2 = x + 3 * pc.partner[n];
        const int j = n - n0;
        dx[j] = x10 - x2[0];
        dy[j] = x11 - x2[1];
        if (DIM == 3) dz[j] = x12 - x2[2];
      }
    }
    // (b) no branches: vectorisable. An entry with r = 0 (coinciding nodes, or a broken entry,
    // whose partner is i1) gets an infinite or undefined fb here, and no force in (c); so
    // this pass raises the divide-by-zero and invalid flags whenever a bond has broken (a
    // run with floating-point traps, feenableexcept, stops here)
    const double *ir = inv_r0 + n0, *kk = UNIFORM_K ? nullptr : kb + n0;
    for (int j = 0; j < m; j++) {
      const double rsq =
          DIM == 3 ? dx[j] * dx[j] + dy[j] * dy[j] + dz[j] * dz[j] : dx[j] * dx[j] + dy[j] * dy[j];
      const double r = std::sqrt(rsq);
      rv[j] = r;
      sv[j] = peridem::stretch_from_inverse(r, ir[j]);
      fb[j] = -peridem::bond_force_per_length(UNIFORM_K ? k_all : kk[j], ir[j], 1.0 / r);
    }
    // (c) breakage and forces in list order
    kernel.n0 = n0;
    for_each_intact_bond<BREAK_BEFORE_FORCE, ONE_TYPE>(pc, p0, p1, kernel);
  }
  kernel.out.finish();
}

// the pass for this step's case: 2d or 3d, one stiffness or one per entry, one type or one
// per entry
template <class VARIANT> inline __attribute__((always_inline)) void BondPeridem::chunked_passes()
{
  const bool planar = domain->dimension == 2, one_type = bond_pieces.type_all > 0;
  if (cache.k_uniform) {
    if (one_type)
      planar ? chunked_pass<VARIANT, 2, true, true>() : chunked_pass<VARIANT, 3, true, true>();
    else
      planar ? chunked_pass<VARIANT, 2, true, false>() : chunked_pass<VARIANT, 3, true, false>();
  } else {
    if (one_type)
      planar ? chunked_pass<VARIANT, 2, false, true>() : chunked_pass<VARIANT, 3, false, true>();
    else
      planar ? chunked_pass<VARIANT, 2, false, false>() : chunked_pass<VARIANT, 3, false, false>();
  }
}

} // namespace LAMMPS_NS

#endif
