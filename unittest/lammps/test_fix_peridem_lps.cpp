/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// fix peridem/lps keeps the weighted volume m of bond_style peridem/lps. Restart files written
// before it existed hold m as the last value of fix PERIDEM_BONDS's per-atom record (broken
// count, Z, m) and no record of fix PERIDEM_LPS; fix peridem/bonds keeps m for fix
// peridem/lps. Stand-ins for the two fixes write that layout here, on any LAMMPS (the file of
// the older build, unittest/lammps/inputs/lps_store, reads only on the LAMMPS that wrote it):
// the run continued from it has every node's m and is the straight run, to the bit.

#include "lammps_fixture.h"

#include "atom.h"
#include "fix_peridem_bonds.h"
#include "fix_peridem_lps.h"
#include "lammps.h"
#include "library.h"
#include "modify.h"

#include <map>
#include <string>

using namespace LAMMPS_NS;

namespace {

FixPeridemLPS *lps_fix(LAMMPS *lmp)
{
  const int i = lmp->modify->find_fix(FixPeridemLPS::ID);
  return i < 0 ? nullptr : dynamic_cast<FixPeridemLPS *>(lmp->modify->fix[i]);
}

// fix peridem/bonds as it wrote restart files before fix peridem/lps: (count, Z, m)
class OldLayoutBonds : public FixPeridemBonds {
 public:
  using FixPeridemBonds::FixPeridemBonds;
  int pack_restart(int i, double *buf) override
  {
    FixPeridemBonds::pack_restart(i, buf);
    buf[0] = 4;
    buf[3] = lps_fix(lmp)->weighted_volume()[i];
    return 4;
  }
  int size_restart(int) override { return 4; }
  int maxsize_restart() override { return 4; }
};

// ... and fix peridem/lps, which then did not write a record of its own
class NoRecordLPS : public FixPeridemLPS {
 public:
  NoRecordLPS(LAMMPS *lmp, int narg, char **arg) : FixPeridemLPS(lmp, narg, arg)
  {
    restart_peratom = 0;
  }
  int pack_restart(int, double *) override { return 0; }
  int size_restart(int) override { return 0; }
  int maxsize_restart() override { return 0; }
};

template <typename F> Fix *create(LAMMPS *lmp, int narg, char **arg)
{
  return new F(lmp, narg, arg);
}

std::map<tagint, double> weighted_volumes(LAMMPS *lmp)
{
  std::map<tagint, double> m;
  const double *w = lps_fix(lmp)->weighted_volume();
  for (int i = 0; i < lmp->atom->nlocal; i++) m[lmp->atom->tag[i]] = w[i];
  return m;
}

const std::string inputs = std::string(PERIDEM_SOURCE_DIR) + "/unittest/lammps/inputs/lps_store/";

} // namespace

class FixPeridemLPSTest : public LammpsTest {};

TEST_F(FixPeridemLPSTest, RestartOfTheOlderLayoutHandsOverM)
{
  (*lmp->modify->fix_map)["peridem/bonds"] = &create<OldLayoutBonds>;
  (*lmp->modify->fix_map)["peridem/lps"] = &create<NoRecordLPS>;
  const std::string file = scratch() + "old.restart";
  command("include " + inputs + "system.lmp\ninclude " + inputs + "run.lmp\nrun 200");
  ASSERT_LT(lammps_get_thermo(lmp, "bonds"), 1000.0); // of 1249: damaged nodes, m not a sum
  command("write_restart " + file + "\nrun 200 post no");
  const double ke = lammps_get_thermo(lmp, "ke"), pe = lammps_get_thermo(lmp, "pe");
  const std::map<tagint, double> m = weighted_volumes(lmp);

  LAMMPS *again = make_lammps();
  lammps_command(again, ("read_restart " + file).c_str());
  lammps_command(again, ("include " + inputs + "run.lmp").c_str());
  lammps_command(again, "run 200 post no");
  EXPECT_EQ(weighted_volumes(again), m);
  EXPECT_EQ(lammps_get_thermo(again, "ke"), ke);
  EXPECT_EQ(lammps_get_thermo(again, "pe"), pe);
  delete again;
}
