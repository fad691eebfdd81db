/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Grain contacts, fabric tensor and coordination number against hand values.

#include "peridem_fabric.h"

#include <gtest/gtest.h>

#include <cmath>

using peridem::GrainContact;

namespace {
GrainContact contact(long long a, long long b, double nx, double ny, double nz = 0.0)
{
  GrainContact c;
  c.a = a;
  c.b = b;
  c.n[0] = nx;
  c.n[1] = ny;
  c.n[2] = nz;
  c.nodes = 1;
  return c;
}
} // namespace

TEST(Fabric, NodeContactsOfOneGrainPairMergeIntoOne)
{
  // three node contacts of grains 1-2 (two on one rank, one on another) and one of 2-5
  const auto merged = peridem::merge_grain_contacts(
      {contact(2, 5, 0, 1), contact(1, 2, 1, 0.1), contact(1, 2, 1, -0.1), contact(1, 2, 1, 0)});
  ASSERT_EQ(merged.size(), 2u);
  EXPECT_EQ(merged[0].a, 1);
  EXPECT_EQ(merged[0].b, 2);
  EXPECT_EQ(merged[0].nodes, 3);
  EXPECT_DOUBLE_EQ(merged[0].n[0], 3.0);
  EXPECT_DOUBLE_EQ(merged[0].n[1], 0.0);
  EXPECT_EQ(merged[1].a, 2);
  EXPECT_EQ(merged[1].b, 5);
}

TEST(Fabric, HexagonalPackingIsIsotropicIn2d)
{
  // a disk in a hexagonal packing touches six neighbours 60 degrees apart: F = I/2 in 2d
  std::vector<GrainContact> c;
  for (int k = 0; k < 6; k++) {
    const double t = 0.3 + k * M_PI / 3.0; // any orientation
    c.push_back(contact(0, k + 1, std::cos(t), std::sin(t)));
  }
  const auto f = peridem::fabric_tensor(peridem::merge_grain_contacts(c));
  EXPECT_NEAR(f[0], 0.5, 1e-14);
  EXPECT_NEAR(f[1], 0.5, 1e-14);
  EXPECT_NEAR(f[2], 0.0, 1e-14);
  EXPECT_NEAR(f[3], 0.0, 1e-14);
}

TEST(Fabric, ColumnIsFullyAnisotropicAndTraceIsOne)
{
  // a vertical column: every normal along y (either sign), whatever the normal's length
  const auto f = peridem::fabric_tensor({contact(1, 2, 0, 2.5), contact(2, 3, 0, -0.1)});
  EXPECT_DOUBLE_EQ(f[1], 1.0);
  EXPECT_DOUBLE_EQ(f[0] + f[2] + f[3] + f[4] + f[5], 0.0);
  // 3d: simple cubic contacts along the three axes
  const auto g = peridem::fabric_tensor(
      {contact(1, 2, 1, 0, 0), contact(1, 3, 0, 1, 0), contact(1, 4, 0, 0, 1)});
  EXPECT_DOUBLE_EQ(g[0] + g[1] + g[2], 1.0);
  EXPECT_DOUBLE_EQ(g[2], 1.0 / 3.0);
}

TEST(Fabric, CancellingNormalsAndNoContacts)
{
  // a pair whose node normals cancel has no direction: it is left out of F
  const auto f = peridem::fabric_tensor(peridem::merge_grain_contacts(
      {contact(1, 2, 1, 0), contact(1, 2, -1, 0), contact(2, 3, 0, 1)}));
  EXPECT_DOUBLE_EQ(f[1], 1.0);
  const auto none = peridem::fabric_tensor({});
  for (double v : none) EXPECT_EQ(v, 0.0);
  EXPECT_DOUBLE_EQ(peridem::coordination_number(9, 6), 3.0);
  EXPECT_EQ(peridem::coordination_number(0, 0), 0.0);
}
