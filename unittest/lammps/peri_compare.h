/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Helpers of the comparisons with LAMMPS's stock peridynamics (peri/pmb,
// peri/lps): the same nodes in two LAMMPS instances, node by node (by tag).
// Stock peri styles work with force densities: their force is ours over the
// node volume.
#ifndef PERIDEM_TEST_PERI_COMPARE_H
#define PERIDEM_TEST_PERI_COMPARE_H

#include "atom.h"
#include "lammps.h"
#include "library.h"

#include "gtest/gtest.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

namespace peri_compare {

struct NodeState {
  std::array<double, 3> x, f;
};

inline std::map<LAMMPS_NS::tagint, NodeState> nodes(LAMMPS_NS::LAMMPS *lmp)
{
  std::map<LAMMPS_NS::tagint, NodeState> out;
  LAMMPS_NS::Atom *atom = lmp->atom;
  for (int i = 0; i < atom->nlocal; i++)
    out[atom->tag[i]] = {{atom->x[i][0], atom->x[i][1], atom->x[i][2]},
                         {atom->f[i][0], atom->f[i][1], atom->f[i][2]}};
  return out;
}

// after run 0 on the same positions: the largest per-node relative force
// difference (ours / volume against stock), checked < 1e-10; n nodes
inline void expect_same_forces(LAMMPS_NS::LAMMPS *stock, LAMMPS_NS::LAMMPS *ours, double volume,
                               size_t n)
{
  const auto a = nodes(stock), b = nodes(ours);
  ASSERT_EQ(a.size(), n);
  ASSERT_EQ(a.size(), b.size());
  double worst = 0.0, fmax = 0.0;
  for (const auto &[tag, s] : a) {
    const NodeState &t = b.at(tag);
    for (int d = 0; d < 3; d++) ASSERT_EQ(s.x[d], t.x[d]);
    double diff = 0.0, norm = 0.0;
    for (int d = 0; d < 3; d++) {
      diff += std::pow(s.f[d] - t.f[d] / volume, 2);
      norm += s.f[d] * s.f[d];
    }
    fmax = std::max(fmax, std::sqrt(norm));
    worst = std::max(worst, std::sqrt(diff / norm));
  }
  std::printf("  largest per-atom relative force difference: %.2e (max |f| %.3e)\n", worst, fmax);
  EXPECT_GT(fmax, 1e9); // the block is really deformed
  EXPECT_LT(worst, 1e-10);
}

// after the same impact: positions (< 1e-10 m) and node damage (< 1e-12;
// stock compute damage/atom "dmg", ours compute peridem/damage "dmg") agree,
// and more than min_broken bonds broke; n nodes
inline void expect_same_impact(LAMMPS_NS::LAMMPS *stock, LAMMPS_NS::LAMMPS *ours, size_t n,
                               double min_broken)
{
  const auto a = nodes(stock), b = nodes(ours);
  ASSERT_EQ(a.size(), n);
  double worst = 0.0;
  for (const auto &[tag, s] : a)
    for (int d = 0; d < 3; d++) worst = std::max(worst, std::fabs(s.x[d] - b.at(tag).x[d]));

  // damage per node: peri's (volume-weighted, equal volumes here) and ours
  lammps_command(stock, "run 0 post no");
  lammps_command(ours, "run 0 post no");
  auto *dstock = static_cast<double *>(lammps_extract_compute(stock, "dmg", 1, 1));
  auto *dours = static_cast<double **>(lammps_extract_compute(ours, "dmg", 1, 2));
  double dsum_stock = 0.0, dsum_ours = 0.0, dworst = 0.0;
  for (int i = 0; i < stock->atom->nlocal; i++) {
    const int j = ours->atom->map(stock->atom->tag[i]);
    dsum_stock += dstock[i];
    dsum_ours += dours[j][0];
    dworst = std::max(dworst, std::fabs(dstock[i] - dours[j][0]));
  }
  auto *stats = static_cast<double *>(lammps_extract_compute(ours, "dmg", 0, 1));
  std::printf("  after the impact: %.0f broken bonds, sum of node damage %.6f (stock %.6f),\n"
              "  largest position difference %.2e m (lattice 5e-4 m), node damage %.2e\n",
              stats[1], dsum_ours, dsum_stock, worst, dworst);
  EXPECT_GT(stats[1], min_broken); // the impact really breaks bonds
  EXPECT_LT(dworst, 1e-12);
  EXPECT_LT(worst, 1e-10);
}

} // namespace peri_compare

#endif
