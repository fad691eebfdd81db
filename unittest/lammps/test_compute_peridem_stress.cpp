/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// compute peridem/stress and compute peridem/contacts through LAMMPS (2d, lj units):
// - a square grain at rest between a floor and a servo lid is under uniaxial stress: the mean
//   stress over the grain's width a times the wall gap is -F/a along the load, 0 across it
//   (the virial theorem for a body at rest: sum x f over its nodes balances the walls' loads);
// - a bed of disks at rest under a servo lid in a box: sigma_yy = -lid load / width and
//   sigma_xx = -side load / gap, the contact part carrying the load between grains;
// - the fabric of a hexagonal cluster of disks is isotropic, that of a row is not.
// Run on 1 rank here and on 2 ranks by ctest (mpi2.compute_peridem_stress).

#include "lammps_fixture.h"

#include "fix.h"
#include "input.h"
#include "lammps.h"
#include "library.h"
#include "modify.h"
#include "variable.h"

#include <cmath>
#include <cstdio>
#include <string>

using namespace LAMMPS_NS;

namespace {
enum { XX, YY, ZZ, XY, XZ, YZ };
enum { TOTAL = 0, KINETIC = 6, CONTACT = 12, BOND = 18, WALL = 24 };
enum { Z, NCONTACT, NGRAIN, NNODE, FABRIC };

// lj units: grains of density 1 at spacing 0.2, horizon 0.6 (c = 50), contact Kn 150 (of the
// order of the bonds' stiffness), R_c = 0.15
const char *const SETUP = "units lj\ndimension 2\nboundary f f p\natom_style peridem\n"
                          "atom_modify map array\nregion box block -1 8 -1 8 -0.5 0.5\n"
                          "create_box 1 box bond/types 1 extra/bond/per/atom 40 "
                          "extra/special/per/atom 0\nspecial_bonds lj/coul 0.0 1.0 1.0\n"
                          "comm_modify cutoff 1.0\ntimestep 0.005\n";
const char *const BONDS = "bond_style peridem\nbond_coeff * c 50 s0 10 horizon 0.60001\n";
} // namespace

class ComputePeridemStress : public LammpsTest {
 protected:
  double value(const char *id, int k)
  {
    return static_cast<double *>(lammps_extract_compute(lmp, id, 0, 1))[k];
  }
  // fix peridem/wall output: wall w (xlo xhi ylo yhi) entry j (0 position, 2 normal load)
  double wall(int w, int j)
  {
    return lmp->modify->fix[lmp->modify->find_fix("wall")]->compute_vector(6 * w + j);
  }
  void expect_parts_sum(const char *id)
  {
    for (int k = 0; k < 6; k++)
      EXPECT_NEAR(value(id, TOTAL + k),
                  value(id, KINETIC + k) + value(id, CONTACT + k) + value(id, BOND + k) +
                      value(id, WALL + k),
                  1e-12 * std::fabs(value(id, TOTAL + YY)));
  }
};

TEST_F(ComputePeridemStress, SquareGrainAtRestIsUnderUniaxialStress)
{
  command(SETUP);
  command(BONDS);
  command("create_peridem_grains 1 square side 2 spacing 0.2 horizon 0.6 density 1 at 3 1.2 0\n"
          "pair_style zero 0.3\npair_coeff * *\n"
          "fix wall all peridem/wall ylo 0.0 yhi 2.4 servo yhi 0.05 0.5 0.05 Kn 150 Rc 0.15\n"
          "fix_modify wall virial yes\n"
          "fix nve all nve\nfix plane all enforce2d\nfix calm all viscous 0.1\n"
          "variable vol equal 2.0*f_wall[19]\n" // grain width times the wall gap
          "compute st all peridem/stress volume v_vol\n"
          "thermo_style custom step c_st c_st[2] f_wall[21]\nthermo 5000\nrun 30000 post no");
  const double load = wall(3, 2); // force per unit thickness on the lid
  const double syy = value("st", TOTAL + YY);
  std::printf("[ measure  ] square at rest: lid load %.6g (target %.6g), sigma_yy %.6g, "
              "-F/a %.6g, sigma_xx %.3g, sigma_xy %.3g, bond part %.6g, wall part %.6g\n",
              load, 0.05 * 9.0, syy, -load / 2.0, value("st", XX), value("st", XY),
              value("st", BOND + YY), value("st", WALL + YY));
  EXPECT_NEAR(load / (0.05 * 9.0), 1.0, 0.01); // the servo holds its target (box width 9)
  EXPECT_NEAR(syy / (-load / 2.0), 1.0, 2e-3);
  EXPECT_LT(std::fabs(value("st", XX)), 2e-3 * std::fabs(syy));
  EXPECT_LT(std::fabs(value("st", XY)), 2e-3 * std::fabs(syy));
  EXPECT_EQ(value("st", CONTACT + YY), 0.0); // one grain, no pair forces
  EXPECT_LT(std::fabs(value("st", KINETIC + YY)), 1e-6 * std::fabs(syy));
  // the bonds carry the load through the grain; the walls' part is their contact layer
  EXPECT_GT(std::fabs(value("st", BOND + YY)), 5.0 * std::fabs(value("st", WALL + YY)));
  expect_parts_sum("st");
  // the pressure (scalar) is -tr(sigma)/2
  EXPECT_NEAR(*static_cast<double *>(lammps_extract_compute(lmp, "st", 0, 0)),
              -(value("st", XX) + syy) / 2.0, 1e-12 * std::fabs(syy));
}

TEST_F(ComputePeridemStress, BedAtRestCarriesTheWallPressures)
{
  command(SETUP);
  command(BONDS);
  // three disks on the floor, two above their hollows, side walls 0.2 from the outer disks;
  // contacts stiff enough for the lid to rest on single nodes (Kn 5000)
  command("create_peridem_grains 1 disk radius 1 spacing 0.2 horizon 0.6 density 1 "
          "at 1.2 1.2 0 at 3.4 1.2 0 at 5.6 1.2 0 at 2.3 3.1 0 at 4.5 3.1 0\n"
          "pair_style peridem/contact\npair_coeff * * Kn 5000 Rc 0.15\n"
          "fix wall all peridem/wall xlo 0.0 xhi 6.8 ylo 0.0 yhi 4.3 servo yhi 0.02 2 0.05 "
          "Kn 5000 Rc 0.15\nfix_modify wall virial yes\n"
          "fix nve all nve\nfix plane all enforce2d\nfix calm all viscous 0.1\n"
          "variable vol equal 6.8*f_wall[19]\n"
          "compute st all peridem/stress volume v_vol\ncompute net all peridem/contacts\n"
          "thermo_style custom step c_st[1] c_st[2] f_wall[21] c_net\nthermo 10000\n"
          "run 80000 post no");
  const double lid = wall(3, 2), side = wall(0, 2), gap = wall(3, 0) - wall(2, 0);
  const double sxx = value("st", XX), syy = value("st", YY);
  std::printf("[ measure  ] bed at rest: lid %.6g side %.6g gap %.6g; sigma_yy %.6g vs "
              "%.6g, sigma_xx %.6g vs %.6g; contact part yy %.6g; Z %.3f, contacts %g, "
              "fabric %.3f %.3f %.3f\n",
              lid, side, gap, syy, -lid / 6.8, sxx, -side / gap, value("st", CONTACT + YY),
              value("net", Z), value("net", NCONTACT), value("net", FABRIC + XX),
              value("net", FABRIC + YY), value("net", FABRIC + XY));
  EXPECT_NEAR(lid / (0.02 * 6.8), 1.0, 0.01);
  EXPECT_NEAR(syy / (-lid / 6.8), 1.0, 5e-3);
  EXPECT_GT(side, 0.05 * lid); // the upper disks wedge the lower ones against the side walls
  EXPECT_NEAR(sxx / (-side / gap), 1.0, 0.02);
  EXPECT_LT(std::fabs(value("st", KINETIC + YY)), 1e-5 * std::fabs(syy));
  // node-level parts: a contact's arm is a node pair (< R_c), the bonds carry the load
  // across each grain, so the contact part is small but compressive
  EXPECT_LT(value("st", CONTACT + YY), 0.0);
  EXPECT_LT(std::fabs(value("st", CONTACT + YY)), std::fabs(value("st", BOND + YY)));
  expect_parts_sum("st");
  // contacts: each upper disk on the two below it
  EXPECT_EQ(value("net", NGRAIN), 5.0);
  EXPECT_EQ(value("net", NCONTACT), 4.0);
  EXPECT_NEAR(value("net", Z), 8.0 / 5.0, 1e-12);
  EXPECT_NEAR(value("net", FABRIC + XX) + value("net", FABRIC + YY), 1.0, 1e-12);
}

TEST_F(ComputePeridemStress, FabricOfHexagonalClusterIsIsotropic)
{
  command(SETUP);
  // a disk and its six neighbours 60 degrees apart (centres 2.025 apart, each lattice turned):
  // 12 grain contacts, Z = 24/7, F = I/2 up to the facets of the lattice disks (node
  // normals of one grain pair; within 0.05 at spacing 0.1, 0.02 at 0.05, seeds 7-9); then a
  // row of three: F_xx = 1
  std::string at;
  const double d = 2.025, cx = 3.5, cy = 3.5;
  at += "at " + std::to_string(cx) + " " + std::to_string(cy) + " 0 ";
  for (int k = 0; k < 6; k++)
    at += "at " + std::to_string(cx + d * std::cos(k * M_PI / 3.0)) + " " +
          std::to_string(cy + d * std::sin(k * M_PI / 3.0)) + " 0 ";
  command("create_peridem_grains 1 disk radius 1 spacing 0.05 horizon 0.15 density 1 " + at +
          "rotate random 7\n"
          "bond_style zero\nbond_coeff *\n"
          "pair_style peridem/contact\npair_coeff * * Kn 150 Rc 0.1\n"
          "compute net all peridem/contacts\nthermo_style custom step c_net\nrun 0 post no");
  std::printf("[ measure  ] hexagonal cluster: Z %.4f contacts %g node contacts %g fabric "
              "%.4f %.4f %.4f\n",
              value("net", Z), value("net", NCONTACT), value("net", NNODE),
              value("net", FABRIC + XX), value("net", FABRIC + YY), value("net", FABRIC + XY));
  EXPECT_EQ(value("net", NCONTACT), 12.0);
  EXPECT_NEAR(value("net", Z), 24.0 / 7.0, 1e-12);
  EXPECT_NEAR(value("net", FABRIC + XX), 0.5, 0.025);
  EXPECT_NEAR(value("net", FABRIC + YY), 0.5, 0.025);
  EXPECT_NEAR(value("net", FABRIC + XY), 0.0, 0.025);
  EXPECT_EQ(value("net", FABRIC + ZZ), 0.0);

  command("delete_atoms group all\n"
          "create_peridem_grains 1 disk radius 1 spacing 0.05 horizon 0.15 density 1 "
          "at 1.5 3 0 at 3.525 3 0 at 5.55 3 0\nrun 0 post no");
  EXPECT_EQ(value("net", NCONTACT), 2.0);
  EXPECT_NEAR(value("net", FABRIC + XX), 1.0, 1e-3);
  EXPECT_NEAR(value("net", Z), 4.0 / 3.0, 1e-12);
}
