/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// compute peridem/damage against hand counts: a 4-node grain (a line with
// nearest and next-nearest bonds) loses two bonds when its last node is
// pulled away; a 3-node grain stays intact. Checked with newton_bond on and
// off, through write_restart/read_restart, and (ctest) on 2 MPI ranks.

#include "lammps_fixture.h"

#include "atom.h"
#include "lammps.h"
#include "library.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

using namespace LAMMPS_NS;

namespace {

const char *const DATA = R"(two grains

7 atoms
1 atom types
8 bonds
1 bond types

-1 6 xlo xhi
-2 2 ylo yhi
-2 2 zlo zhi

Atoms # peridem

1 1 1 1.0 1.0 0 0 0 0 0 0
2 1 1 1.0 1.0 1 0 0 1 0 0
3 1 1 1.0 1.0 2 0 0 2 0 0
4 1 1 1.0 1.0 3 0 0 3 0 0
5 2 1 1.0 1.0 0 1 0 0 1 0
6 2 1 1.0 1.0 1 1 0 1 1 0
7 2 1 1.0 1.0 2 1 0 2 1 0

Bonds

1 1 1 2
2 1 2 3
3 1 3 4
4 1 1 3
5 1 2 4
6 1 5 6
7 1 6 7
8 1 5 7
)";

// expected per node: bond-fraction damage phi and Z (s0 = 0.1): node 4
// moved by 0.5 breaks 3-4 (|du|/|xi| = 0.5) and 2-4 (0.25)
const std::map<tagint, std::pair<double, double>> EXPECTED = {
    {1, {0.0, 0.0}}, {2, {1.0 / 3.0, 2.5}}, {3, {1.0 / 3.0, 5.0}}, {4, {1.0, 5.0}},
    {5, {0.0, 0.0}}, {6, {0.0, 0.0}},       {7, {0.0, 0.0}}};
constexpr double GRAIN1 = (0.0 + 1.0 / 3.0 + 1.0 / 3.0 + 1.0) / 4.0;

void check_damage(LAMMPS *lmp, const char *what)
{
  auto **d = static_cast<double **>(lammps_extract_compute(lmp, "dmg", 1, 2));
  for (const auto &[tag, e] : EXPECTED) {
    const int i = lmp->atom->map(tag);
    if (i < 0 || i >= lmp->atom->nlocal) continue; // owned by another rank
    EXPECT_NEAR(d[i][0], e.first, 1e-15) << what << ": phi of atom " << tag;
    EXPECT_NEAR(d[i][1], e.second, 1e-12) << what << ": Z of atom " << tag;
    EXPECT_NEAR(d[i][2], tag <= 4 ? GRAIN1 : 0.0, 1e-15) << what << ": grain of atom " << tag;
  }
  // broken bonds leave the special lists of both nodes (contact exclusion)
  const std::map<tagint, std::vector<tagint>> partners = {
      {1, {2, 3}}, {2, {1, 3}}, {3, {1, 2}}, {4, {}}, {5, {6, 7}}, {6, {5, 7}}, {7, {5, 6}}};
  for (const auto &[tag, expected] : partners) {
    const int i = lmp->atom->map(tag);
    if (i < 0 || i >= lmp->atom->nlocal) continue;
    std::vector<tagint> got(lmp->atom->special[i],
                            lmp->atom->special[i] + lmp->atom->nspecial[i][0]);
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, expected) << what << ": 1-2 special list of atom " << tag;
  }
  auto *v = static_cast<double *>(lammps_extract_compute(lmp, "dmg", 0, 1));
  EXPECT_NEAR(v[0], GRAIN1 / 2.0, 1e-15) << what << ": bulk damage";
  EXPECT_EQ(v[1], 2.0) << what << ": broken bonds";
  EXPECT_EQ(v[2], 8.0) << what << ": reference bonds";
  EXPECT_EQ(v[3], 2.0) << what << ": grains";
  EXPECT_EQ(lmp->atom->nbonds, 6) << what << ": LAMMPS's bond count";
}

} // namespace

class ComputePeridemDamage : public LammpsTest, public ::testing::WithParamInterface<const char *> {
 protected:
  void build(const char *newton)
  {
    write_text_file(scratch() + "grains.data", DATA);
    command(fmt::format("units lj\nnewton on {}\nprocessors * 1 1\natom_style peridem\n"
                        "atom_modify map array\ncomm_modify cutoff 3.0\nread_data {}grains.data\n"
                        "special_bonds lj/coul 0.0 1.0 1.0\nbond_style peridem\n"
                        "bond_coeff 1 c 1.0 s0 0.1 horizon 2.5\ncompute dmg all peridem/damage\n"
                        "thermo_style custom step c_dmg c_dmg[2] c_dmg[3]",
                        newton, scratch()));
  }
};

TEST_P(ComputePeridemDamage, CountsBrokenBondsOfEveryNode)
{
  build(GetParam());
  command("run 0 post no");
  auto *v = static_cast<double *>(lammps_extract_compute(lmp, "dmg", 0, 1));
  EXPECT_EQ(v[1], 0.0);
  EXPECT_EQ(v[2], 8.0);
  // pull node 4 away along x: its two bonds break in the next force evaluation
  command("set atom 4 x 3.5\nrun 0 post no");
  check_damage(lmp, GetParam());

  // broken bonds stay broken and counted through a restart
  command(fmt::format("write_restart {}damage.restart", scratch()));
  command(
      fmt::format("clear\nread_restart {}damage.restart\ncomm_modify cutoff 3.0\n"
                  "compute dmg all peridem/damage\nthermo_style custom step c_dmg\nrun 0 post no",
                  scratch()));
  check_damage(lmp, "after restart");

  // and through write_data/read_data: broken bonds are not in the data file
  command(fmt::format("write_data {}damage.data", scratch()));
  EXPECT_EQ(lmp->atom->nbonds, 6);
}

// Z measures strain, not motion: grain 2 (a line of 3 nodes, bonds along x) turned rigidly by
// theta keeps every bond length, so the stretch measure (the default) reads 0; eq. 14 as printed
// (z displacement) reads |u_j - u_i| / |xi| / s0 = 2 sin(theta/2) / s0 on every bond. A node
// then moved across its bonds shows the two measures apart: node 7 up by 0.05 stretches bond
// 6-7 (length 1) to sqrt(1 + 0.05^2), s/s0 = 0.0125, while |du|/|xi|/s0 = 0.5.
TEST_P(ComputePeridemDamage, ZCountsStrainNotRigidRotation)
{
  build(GetParam());
  command("compute dmgd all peridem/damage z displacement\ngroup g2 molecule 2\n"
          "displace_atoms g2 rotate 1 1 0 0 0 1 17 units box\nrun 0 post no");
  const double theta = 17.0 * std::acos(-1.0) / 180.0;
  auto **z = static_cast<double **>(lammps_extract_compute(lmp, "dmg", 1, 2));
  auto **zd = static_cast<double **>(lammps_extract_compute(lmp, "dmgd", 1, 2));
  for (tagint tag : {5, 6, 7}) {
    const int i = lmp->atom->map(tag);
    if (i < 0 || i >= lmp->atom->nlocal) continue;
    EXPECT_NEAR(z[i][1], 0.0, 1e-12) << "stretch measure of atom " << tag;
    EXPECT_NEAR(zd[i][1], 2.0 * std::sin(theta / 2.0) / 0.1, 1e-12)
        << "displacement measure of atom " << tag;
  }
  auto *v = static_cast<double *>(lammps_extract_compute(lmp, "dmg", 0, 1));
  EXPECT_EQ(v[1], 0.0) << "a rigid rotation breaks no bond";

  // undo the rotation, then move node 7 across its bonds
  command("displace_atoms g2 rotate 1 1 0 0 0 1 -17 units box\n"
          "set atom 7 y 1.05\nrun 0 post no");
  z = static_cast<double **>(lammps_extract_compute(lmp, "dmg", 1, 2));
  zd = static_cast<double **>(lammps_extract_compute(lmp, "dmgd", 1, 2));
  const double s67 = std::sqrt(1.0 + 0.05 * 0.05) - 1.0;
  const std::map<tagint, std::pair<double, double>> expected = {
      {6, {s67 / 0.1, 0.5}},
      {7, {s67 / 0.1, 0.5}},
      {5, {(std::sqrt(4.0 + 0.0025) / 2.0 - 1.0) / 0.1, 0.25}}};
  for (const auto &[tag, e] : expected) {
    const int i = lmp->atom->map(tag);
    if (i < 0 || i >= lmp->atom->nlocal) continue;
    EXPECT_NEAR(z[i][1], e.first, 1e-9) << "stretch measure of atom " << tag;
    EXPECT_NEAR(zd[i][1], e.second, 1e-9) << "displacement measure of atom " << tag;
  }
}

INSTANTIATE_TEST_SUITE_P(Newton, ComputePeridemDamage, ::testing::Values("on", "off"));
