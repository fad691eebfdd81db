/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// The fast force loops of bond_style peridem and peridem/lps (steps without energy or
// virial; in 2d without z) against the loops of energy steps, one bond at a time with z:
// the same nodes, sheared and jittered without reneighbouring, forces from calling the bond
// style directly; they must agree to the bit and break the same bonds.
#ifndef PERIDEM_TEST_BOND_LOOP_CHECK_H
#define PERIDEM_TEST_BOND_LOOP_CHECK_H

#include "atom.h"
#include "bond.h"
#include "force.h"
#include "lammps.h"
#include "neighbor.h"

#include "gtest/gtest.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

namespace bond_loop_check {

struct BondForces {
  std::map<LAMMPS_NS::tagint, std::array<double, 3>> f;
  int broken = 0, total = 0;
};

// shear and jitter the nodes (spacing h) of a set-up system and call the bond style, twice
// without rebuilding the bond list: the second call meets the entries broken in the first
// (the forces are those of the second call, which takes back most of the first shear, so
// that a broken entry taken for intact would pull)
// eflag_second (default: eflag) for the second call: an energy step, which breaks bonds one
// at a time, followed by an ordinary one
inline BondForces forces_after_shear(LAMMPS_NS::LAMMPS *lmp, int dim, double h, int eflag,
                                     int eflag_second = -1)
{
  LAMMPS_NS::Atom *atom = lmp->atom;
  for (const double amount : {1.0, -0.9}) {
    if (amount < 0.0 && eflag_second >= 0) eflag = eflag_second;
    for (int i = 0; i < atom->nlocal; i++) {
      const double t = atom->tag[i];
      atom->x[i][0] += amount * (2e-3 * h * std::sin(0.7 * t) + 1e-3 * atom->x[i][1]);
      atom->x[i][1] += amount * 2e-3 * h * std::cos(1.3 * t);
      if (dim == 3) atom->x[i][2] += amount * (2e-3 * h * std::sin(2.1 * t) + 5e-4 * atom->x[i][0]);
    }
    for (int i = 0; i < atom->nlocal + atom->nghost; i++)
      atom->f[i][0] = atom->f[i][1] = atom->f[i][2] = 0.0;
    lmp->force->bond->compute(eflag, 0);
  }
  BondForces r;
  for (int i = 0; i < atom->nlocal; i++)
    r.f[atom->tag[i]] = {atom->f[i][0], atom->f[i][1], atom->f[i][2]};
  r.total = lmp->neighbor->nbondlist;
  for (int n = 0; n < r.total; n++) r.broken += lmp->neighbor->bondlist[n][2] <= 0;
  return r;
}

// the longest run of entries with one i1 in LAMMPS's bond list (the fast loops take runs
// longer than their chunk of 64 entries in pieces)
inline int longest_run(LAMMPS_NS::LAMMPS *lmp)
{
  int longest = 0, run = 0;
  const int *const *bl = lmp->neighbor->bondlist;
  for (int k = 0; k < lmp->neighbor->nbondlist; k++) {
    run = (k > 0 && bl[k][0] == bl[k - 1][0]) ? run + 1 : 1;
    longest = std::max(longest, run);
  }
  return longest;
}

// one bond at a time (eflag 1) against the fast loop (eflag 0): the same bits
inline void expect_same_bits(const BondForces &one, const BondForces &fast, int dim,
                             const char *what)
{
  std::printf("  %dd %s: %d of %d bonds broken\n", dim, what, one.broken, one.total);
  EXPECT_GT(one.broken, 0) << dim << "d " << what;
  EXPECT_LT(one.broken, one.total / 2) << dim << "d " << what;
  EXPECT_EQ(one.broken, fast.broken) << dim << "d " << what;
  ASSERT_EQ(one.f.size(), fast.f.size());
  int differ = 0;
  double fmax = 0.0, fzmax = 0.0;
  for (const auto &[tag, f] : one.f) {
    for (int d = 0; d < 3; d++) differ += f[d] != fast.f.at(tag)[d];
    fmax = std::max(fmax, std::hypot(f[0], f[1], f[2]));
    fzmax = std::max(fzmax, std::fabs(f[2]));
  }
  EXPECT_EQ(differ, 0) << dim << "d " << what;
  EXPECT_GT(fmax, 0.0);
  if (dim == 3) EXPECT_GT(fzmax, 0.0);
}

} // namespace bond_loop_check

#endif
