/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// compute peridem/grain against hand values: a 21 x 11 node rectangle
// (width 2, height 1, spacing 0.1) turned by 30 degrees, then rotated by
// 45 degrees about the origin and moved across the periodic boundary; a
// square made across the periodic boundary and cut in two. Lattice
// variances along the sides: h^2 (n^2 - 1) / 12. Run on 1 rank here and on
// 2 and 4 ranks by ctest.

#include "lammps_fixture.h"

#include "atom.h"
#include "lammps.h"
#include "library.h"

#include <cmath>
#include <mpi.h>

using namespace LAMMPS_NS;

namespace {
constexpr double H = 0.1;
const double VAR_LONG = H * H * (21 * 21 - 1) / 12.0, VAR_SHORT = H * H * (11 * 11 - 1) / 12.0;
enum {
  CX = 0,
  VX = 3,
  VOLUME = 6,
  MASS = 7,
  NODES = 8,
  DAMAGE = 9,
  FRAGMENTS = 10,
  EXTENT = 11,
  EIGEN = 12,
  AXIS = 15,
  ANGLE = 18
};

void check_rectangle(const double *row, double cx, double cy, double deg, const char *what)
{
  EXPECT_NEAR(row[CX], cx, 1e-10) << what;
  EXPECT_NEAR(row[CX + 1], cy, 1e-10) << what;
  EXPECT_NEAR(row[CX + 2], 0.0, 1e-12) << what;
  EXPECT_EQ(row[NODES], 231.0) << what;
  EXPECT_NEAR(row[VOLUME], 231 * H * H, 1e-10) << what;
  EXPECT_NEAR(row[MASS], 2.0 * 231 * H * H, 1e-10) << what;
  EXPECT_NEAR(row[EIGEN], VAR_LONG, 1e-10) << what;
  EXPECT_NEAR(row[EIGEN + 1], VAR_SHORT, 1e-10) << what;
  EXPECT_NEAR(row[EIGEN + 2], 0.0, 1e-12) << what;
  EXPECT_NEAR(row[EXTENT], 2.0, 1e-10) << what;
  EXPECT_NEAR(row[ANGLE], deg, 1e-8) << what;
  const double r = deg * M_PI / 180.0;
  EXPECT_NEAR(row[AXIS], std::cos(r), 1e-10) << what;
  EXPECT_NEAR(row[AXIS + 1], std::sin(r), 1e-10) << what;
}
} // namespace

class ComputePeridemGrain : public LammpsTest {
 protected:
  void SetUp() override
  {
    LammpsTest::SetUp();
    command(fmt::format(
        "units lj\ndimension 2\nboundary p p p\nprocessors * 1 1\natom_style peridem\n"
        "atom_modify map array\nregion box block -5 5 -5 5 -0.5 0.5\n"
        "create_box 1 box bond/types 1 extra/bond/per/atom 40 extra/special/per/atom 0\n"
        "special_bonds lj/coul 0.0 1.0 1.0\n"
        "create_peridem_grains 1 rectangle width 2 height 1 spacing {h} horizon {e} density 2 "
        "at 1 -1 0 rotate 30\n"
        "create_peridem_grains 1 square side 2 spacing {h} horizon {e} density 2 at 4.6 3 0\n"
        "bond_style peridem\nbond_coeff 1 c 1.0 s0 0.1 horizon {e}\n"
        "compute dmg all peridem/damage\ncompute frag all peridem/fragments\n"
        "compute g all peridem/grain damage dmg fragments frag\n"
        "thermo_style custom step c_g[1][1] c_g[2][1]",
        fmt::arg("h", H), fmt::arg("e", 3 * H)));
  }
  const double *row(int g)
  {
    auto **a = static_cast<double **>(lammps_extract_compute(lmp, "g", 0, 2));
    return a[g];
  }
};

TEST_F(ComputePeridemGrain, MovedAndRotatedGrainAcrossPeriodicBoundary)
{
  command("velocity all set 1 2 0\nrun 0 post no");
  check_rectangle(row(0), 1.0, -1.0, 30.0, "as made");
  EXPECT_NEAR(row(0)[VX], 1.0, 1e-12);
  EXPECT_NEAR(row(0)[VX + 1], 2.0, 1e-12);
  // the square across x = 5: whole, centroid where it was made
  EXPECT_NEAR(row(1)[CX], 4.6, 1e-10);
  EXPECT_NEAR(row(1)[CX + 1], 3.0, 1e-10);
  EXPECT_NEAR(row(1)[EIGEN], H * H * (21 * 21 - 1) / 12.0, 1e-10);
  EXPECT_NEAR(row(1)[EIGEN + 1], H * H * (21 * 21 - 1) / 12.0, 1e-10);
  EXPECT_EQ(row(1)[FRAGMENTS], 1.0);

  // rotate by 45 degrees about the origin, then move by 4 in x: the
  // rectangle crosses x = 5 and its centroid is unwrapped
  command("displace_atoms all rotate 0 0 0 0 0 1 45 units box\n"
          "displace_atoms all move 4 0 0 units box\nrun 0 post no");
  check_rectangle(row(0), 4.0 + std::sqrt(2.0), 0.0, 75.0, "rotated and moved");

  // the square cut in two: two fragments
  command("cut_peridem_bonds all segment 3 3.05 6 3.05\nrun 0 post no");
  EXPECT_EQ(row(1)[FRAGMENTS], 2.0);
  EXPECT_EQ(row(0)[FRAGMENTS], 1.0);
}

TEST_F(ComputePeridemGrain, DamageIsTheMeanOfNodeDamage)
{
  // stretch grain 1 along x by 1.5: the bonds closest to x break in the
  // next force evaluation; grain 2 stays intact
  command("run 0 post no\ngroup rect molecule 1\n"
          "displace_atoms rect ramp x -1 1 x -1 3 units box\nrun 0 post no");
  auto **d = static_cast<double **>(lammps_extract_compute(lmp, "dmg", 1, 2));
  double sum = 0.0, n = 0.0, grain_mean = -1.0;
  for (int i = 0; i < lmp->atom->nlocal; i++) {
    if (lmp->atom->molecule[i] != 1) continue;
    sum += d[i][0];
    n += 1.0;
    grain_mean = d[i][2];
  }
  double all[2], local[2] = {sum, n};
  MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_GT(all[0] / all[1], 0.05);
  EXPECT_NEAR(row(0)[DAMAGE], all[0] / all[1], 1e-14);
  if (n > 0) EXPECT_NEAR(row(0)[DAMAGE], grain_mean, 1e-14);
  EXPECT_EQ(row(1)[DAMAGE], 0.0);
}
