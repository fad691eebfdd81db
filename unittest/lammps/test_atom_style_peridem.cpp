/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// atom_style peridem: registration, survival of `clear`, and round trips of
// grain IDs, volumes, masses, reference positions and bonds through
// write_data/read_data and write_restart/read_restart.

#include "lammps_fixture.h"

#include "atom.h"
#include "atom_vec.h"
#include "force.h"
#include "lammps.h"
#include "exceptions.h"
#include "register_driver.h"
#include "version.h"

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <unistd.h>

using namespace LAMMPS_NS;

namespace {

struct NodeState {
  int type;
  tagint grain;
  double volume, mass;
  double x0[3];
};

using BondSet = std::set<std::tuple<int, tagint, tagint>>;

std::map<tagint, NodeState> node_states(LAMMPS *lmp)
{
  std::map<tagint, NodeState> out;
  Atom *atom = lmp->atom;
  for (int i = 0; i < atom->nlocal; i++) {
    NodeState s{atom->type[i], atom->molecule[i], atom->vfrac[i], atom->rmass[i], {}};
    for (int d = 0; d < 3; d++) s.x0[d] = atom->x0[i][d];
    out[atom->tag[i]] = s;
  }
  return out;
}

// every bond once, as (type, smaller tag, larger tag), whoever stores it
BondSet bond_set(LAMMPS *lmp)
{
  BondSet out;
  Atom *atom = lmp->atom;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < atom->num_bond[i]; m++) {
      tagint a = atom->tag[i], b = atom->bond_atom[i][m];
      out.emplace(atom->bond_type[i][m], std::min(a, b), std::max(a, b));
    }
  return out;
}

// Two grains of different materials; x0 differs from x (deformed state) and
// the numbers have no short decimal form, so a lossy round trip shows.
std::string test_data_file()
{
  std::ostringstream s;
  s.precision(17);
  s << "PERIDEM test data\n\n8 atoms\n2 atom types\n7 bonds\n2 bond types\n\n"
    << "-1 5 xlo xhi\n-1 5 ylo yhi\n-1 5 zlo zhi\n\nAtoms # peridem\n\n";
  for (int id = 1; id <= 8; id++) {
    const int grain = id <= 4 ? 1 : 2;
    const int type = grain;
    const double volume = 0.001 * (1.0 + id / 7.0);
    const double density = grain == 1 ? 2.5 + id / 3.0 : 7.85;
    const double x0[3] = {0.3 * id + 1.0 / 3.0, 0.2 * (id % 3) + std::sqrt(2.0), 0.1 * id / 7.0};
    const double x[3] = {x0[0] + 0.01 / id, x0[1] - 0.02 / id, x0[2] + 0.005};
    s << id << " " << grain << " " << type << " " << volume << " " << density << " " << x[0] << " "
      << x[1] << " " << x[2] << " " << x0[0] << " " << x0[1] << " " << x0[2] << "\n";
  }
  s << "\nBonds\n\n1 1 1 2\n2 1 2 3\n3 1 3 4\n4 1 1 3\n5 2 5 6\n6 2 6 7\n7 2 7 8\n";
  return s.str();
}

void expect_same_nodes(const std::map<tagint, NodeState> &a, const std::map<tagint, NodeState> &b)
{
  ASSERT_EQ(a.size(), b.size());
  for (const auto &[tag, s] : a) {
    const NodeState &t = b.at(tag);
    EXPECT_EQ(s.type, t.type) << "atom " << tag;
    EXPECT_EQ(s.grain, t.grain) << "atom " << tag;
    // LAMMPS 29 Sep 2021 writes data files with 17 significant digits (exact round trip),
    // 4 Feb 2025 with 16: one rounding of the 16th digit
    EXPECT_NEAR(s.volume, t.volume, 5e-16 * s.volume) << "atom " << tag;
    // mass = density * volume is rebuilt from the written density: one more rounding
    EXPECT_NEAR(s.mass, t.mass, 1e-15 * s.mass) << "atom " << tag;
    for (int d = 0; d < 3; d++) EXPECT_EQ(s.x0[d], t.x0[d]) << "atom " << tag << " dim " << d;
  }
}

} // namespace

class AtomStylePeridem : public LammpsTest {
 protected:
  void read_test_data()
  {
    write_text_file(scratch() + "in.data", test_data_file());
    command("atom_style peridem\natom_modify map array\nread_data " + scratch() + "in.data");
  }
};

TEST_F(AtomStylePeridem, IsRegistered)
{
  EXPECT_EQ(lmp->atom->avec_map->count("peridem"), 1u);
  command("atom_style peridem");
  EXPECT_STREQ(lmp->atom->atom_style, "peridem");
  EXPECT_EQ(lmp->atom->molecule_flag, 1);
  EXPECT_EQ(lmp->atom->rmass_flag, 1);
  EXPECT_EQ(lmp->atom->vfrac_flag, 1);
  EXPECT_EQ(lmp->atom->avec->bonds_allow, 1);
}

TEST_F(AtomStylePeridem, ClearKeepsTheStyles)
{
  command("atom_style peridem\nclear");
  // `clear` replaced Atom: its style map must hold PERIDEM's styles again
  EXPECT_EQ(lmp->atom->avec_map->count("peridem"), 1u);
  command("atom_style peridem");
  EXPECT_STREQ(lmp->atom->atom_style, "peridem");
  command("clear\nclear\natom_style peridem");
  EXPECT_STREQ(lmp->atom->atom_style, "peridem");
}

TEST_F(AtomStylePeridem, ReadDataGivesMassFromDensityAndVolume)
{
  read_test_data();
  const auto nodes = node_states(lmp);
  ASSERT_EQ(nodes.size(), 8u);
  const NodeState &n3 = nodes.at(3);
  EXPECT_EQ(n3.grain, 1);
  EXPECT_DOUBLE_EQ(n3.volume, 0.001 * (1.0 + 3 / 7.0));
  EXPECT_DOUBLE_EQ(n3.mass, (2.5 + 3 / 3.0) * 0.001 * (1.0 + 3 / 7.0));
  EXPECT_DOUBLE_EQ(n3.x0[0], 0.3 * 3 + 1.0 / 3.0);
  EXPECT_EQ(nodes.at(6).grain, 2);
  EXPECT_EQ(bond_set(lmp).size(), 7u);
}

TEST_F(AtomStylePeridem, WriteDataReadDataRoundTrip)
{
  read_test_data();
  const auto before = node_states(lmp);
  const BondSet bonds_before = bond_set(lmp);
  command("write_data " + scratch() + "out.data");
  command("clear\natom_style peridem\natom_modify map array\nread_data " + scratch() + "out.data");
  expect_same_nodes(before, node_states(lmp));
  EXPECT_EQ(bonds_before, bond_set(lmp));
}

TEST_F(AtomStylePeridem, RestartRoundTrip)
{
  read_test_data();
  const auto before = node_states(lmp);
  const BondSet bonds_before = bond_set(lmp);
  command("write_restart " + scratch() + "state.restart");
  command("clear\nread_restart " + scratch() + "state.restart");
  EXPECT_STREQ(lmp->atom->atom_style, "peridem");
  const auto after = node_states(lmp);
  ASSERT_EQ(before.size(), after.size());
  for (const auto &[tag, s] : before) EXPECT_EQ(s.mass, after.at(tag).mass) << "atom " << tag;
  expect_same_nodes(before, after);
  EXPECT_EQ(bonds_before, bond_set(lmp));
}

TEST_F(AtomStylePeridem, CreateAtomsSetsReferencePositionToPosition)
{
  command("atom_style peridem\nregion box block 0 2 0 2 0 2\ncreate_box 1 box\n"
          "create_atoms 1 single 0.5 0.75 1.25");
  ASSERT_EQ(lmp->atom->nlocal, 1);
  for (int d = 0; d < 3; d++) EXPECT_EQ(lmp->atom->x0[0][d], lmp->atom->x[0][d]);
  EXPECT_EQ(lmp->atom->vfrac[0], 1.0);
}

TEST(PeridemRegistration, VersionStringsMustMatch)
{
  EXPECT_TRUE(PERIDEM_NS::version_mismatch_message(LAMMPS_VERSION, LAMMPS_VERSION).empty());
  const std::string msg = PERIDEM_NS::version_mismatch_message("29 Sep 2021", "7 Feb 2024");
  EXPECT_NE(msg.find("compiled against LAMMPS version '29 Sep 2021'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'7 Feb 2024'"), std::string::npos) << msg;
  EXPECT_STREQ(peridem_lammps_version(), LAMMPS_VERSION);
}

TEST(PeridemRegistrationDeathTest, OtherLammpsVersionIsRefused)
{
  // The LAMMPS error goes to the screen (stdout): send it to stderr, which
  // the death test reads. LAMMPS 29 Sep 2021 ends the process with exit code
  // 1; later versions throw LAMMPSException, which their main() turns into exit 1.
  EXPECT_EXIT(
      {
        dup2(STDERR_FILENO, STDOUT_FILENO);
        try {
          LAMMPS *lmp = make_lammps({}, true);
          PERIDEM_NS::register_styles(lmp, "1 Jan 2000");
        } catch (LAMMPSException &) {
          exit(1);
        }
      },
      ::testing::ExitedWithCode(1),
      "ERROR: PERIDEM was compiled against LAMMPS version '1 Jan 2000' but is being loaded into "
      "LAMMPS version '" LAMMPS_VERSION "'");
}
