/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// compute peridem/bed against hand values: three 11 x 11 node squares
// (side 1, spacing 0.1, volume 1.21 each) on the floor of a 6 x 8
// container and a fourth on the middle one; a ring grain for the volume
// with holes counted. Run on 1 rank here and on 2 ranks by ctest.

#include "lammps_fixture.h"

#include "lammps.h"
#include "library.h"

#include <cmath>

using namespace LAMMPS_NS;

namespace {
enum { HMAX, HSURF, HEIGHT, VCONT, VGRAIN, PHI, VFILLED, PHI_FILLED };
constexpr double VSQ = 121 * 0.01;
} // namespace

class ComputePeridemBed : public LammpsTest {
 protected:
  void SetUp() override
  {
    LammpsTest::SetUp();
    command("units lj\ndimension 2\nboundary f f p\nprocessors * 1 1\natom_style peridem\n"
            "atom_modify map array\nregion box block -1 11 -1 11 -0.5 0.5\n"
            "create_box 1 box bond/types 1 extra/bond/per/atom 40 extra/special/per/atom 0\n"
            "special_bonds lj/coul 0.0 1.0 1.0\nregion container block 0 6 0 8 -0.5 0.5\n"
            "bond_style zero\nbond_coeff *\ncomm_modify cutoff 1.0\nvariable lid equal 5");
  }
  double value(const char *id, int k)
  {
    return static_cast<double *>(lammps_extract_compute(lmp, id, 0, 1))[k];
  }
};

TEST_F(ComputePeridemBed, HeightAndVolumeFractionOfSquares)
{
  command("create_peridem_grains 1 square side 1 spacing 0.1 horizon 0.3 density 1 "
          "at 1 0.6 0 at 3 0.6 0 at 5 0.6 0 at 3 1.8 0\n"
          "compute bed all peridem/bed container bin 2\n"
          "compute bmax all peridem/bed container top max bin 2\n"
          "compute breg all peridem/bed container top region\n"
          "compute bvar all peridem/bed container top v_lid\n"
          "thermo_style custom step c_bed c_bmax c_breg c_bvar\nrun 0 post no");
  // bins [0,2) [2,4) [4,6]: highest nodes 1.1, 2.3, 1.1; the median ignores
  // the grain on top
  EXPECT_NEAR(value("bed", HMAX), 2.3, 1e-12);
  EXPECT_NEAR(value("bed", HSURF), 1.1, 1e-12);
  EXPECT_NEAR(value("bed", HEIGHT), 1.1, 1e-12);
  EXPECT_NEAR(value("bed", VCONT), 6 * 1.1, 1e-12);
  EXPECT_NEAR(value("bed", VGRAIN), 4 * VSQ, 1e-12);
  EXPECT_NEAR(value("bed", PHI), 4 * VSQ / (6 * 1.1), 1e-12);
  EXPECT_NEAR(value("bed", VFILLED), 4 * VSQ, 1e-12); // squares have no holes
  EXPECT_NEAR(*static_cast<double *>(lammps_extract_compute(lmp, "bed", 0, 0)), 4 * VSQ / (6 * 1.1),
              1e-12);
  EXPECT_NEAR(value("bmax", PHI), 4 * VSQ / (6 * 2.3), 1e-12);
  EXPECT_NEAR(value("breg", PHI), 4 * VSQ / (6 * 8.0), 1e-12);
  EXPECT_NEAR(value("bvar", PHI), 4 * VSQ / (6 * 5.0), 1e-12);

  // a grain added between runs counts
  command("create_peridem_grains 1 square side 1 spacing 0.1 horizon 0.3 density 1 at 1 1.8 0\n"
          "run 0 post no");
  EXPECT_NEAR(value("breg", VGRAIN), 5 * VSQ, 1e-12);
}

TEST_F(ComputePeridemBed, RingVolumeWithHoleIsTheOuterDisk)
{
  // ring R = 1, r = 0.5 (h = 0.025): Bhattacharya & Lipton's (2023) ring volume
  // fraction (0.92) counts the hole; the node volumes do not
  command("create_peridem_grains 1 ring radius 1 inner_radius 0.5 spacing 0.025 horizon 0.075 "
          "density 1 at 3 1.2 0 rotate 17\n"
          "compute bed all peridem/bed container top region\n"
          "thermo_style custom step c_bed\nrun 0 post no");
  EXPECT_NEAR(value("bed", VGRAIN), M_PI * (1 - 0.25), 0.02 * M_PI * 0.75);
  EXPECT_NEAR(value("bed", VFILLED), M_PI, 0.01 * M_PI);
  EXPECT_NEAR(value("bed", PHI_FILLED), value("bed", VFILLED) / 48.0, 1e-12);
}
