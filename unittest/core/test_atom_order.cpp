/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

#include "peridem_atom_order.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>

namespace {

// the atoms at the positions the permutation gives them
template <typename ID> std::vector<ID> permuted(const std::vector<int> &perm, const std::vector<ID> &v)
{
  std::vector<ID> out;
  for (int k : perm) out.push_back(v[k]);
  return out;
}

} // namespace

TEST(AtomOrder, OrderedAtomsNeedNoPermutation)
{
  const std::vector<int> grain = {1, 1, 1, 2, 2, 7}, id = {3, 4, 9, 1, 2, 5};
  EXPECT_TRUE(peridem::grain_major_permutation(grain.data(), id.data(), 6).empty());
  EXPECT_TRUE(peridem::grain_major_permutation(grain.data(), id.data(), 0).empty());
  EXPECT_TRUE(peridem::grain_major_permutation(grain.data(), id.data(), 1).empty());
}

TEST(AtomOrder, GrainFirstThenAtomID)
{
  // grain 2's atoms have lower IDs than grain 1's: the grain decides first
  const std::vector<int64_t> grain = {2, 1, 2, 1, 0}, id = {5, 30, 4, 10, 99};
  const auto perm = peridem::grain_major_permutation(grain.data(), id.data(), 5);
  ASSERT_EQ(perm.size(), 5u);
  EXPECT_EQ(permuted(perm, grain), (std::vector<int64_t>{0, 1, 1, 2, 2}));
  EXPECT_EQ(permuted(perm, id), (std::vector<int64_t>{99, 10, 30, 4, 5}));
}

TEST(AtomOrder, ShuffledGrainsComeBackInCreationOrder)
{
  // 50 grains of 40 nodes numbered grain by grain, shuffled as LAMMPS's spatial sort would
  const int n = 2000;
  std::vector<int> grain(n), id(n), order(n);
  for (int i = 0; i < n; i++) {
    grain[i] = 1 + i / 40;
    id[i] = i + 1;
    order[i] = i;
  }
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  const auto g = permuted(order, grain), t = permuted(order, id);
  const auto perm = peridem::grain_major_permutation(g.data(), t.data(), n);
  ASSERT_EQ(perm.size(), std::size_t(n));
  EXPECT_EQ(permuted(perm, g), grain);
  EXPECT_EQ(permuted(perm, t), id);
  // a permutation: every atom once
  std::vector<int> seen(n, 0);
  for (int k : perm) seen[k]++;
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), n);
}
