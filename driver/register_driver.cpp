/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: registration of all PERIDEM styles into a LAMMPS instance, for
   lmp_peridem, libperidem's post_create hook and the Python routes
   (peridem_register). LAMMPS as packaged by Debian has no PLUGIN package;
   the style maps of Force, Modify, Atom and Input are public, so the styles
   are inserted there directly, as the PLUGIN package would do.

   This file is not part of src/: in a LAMMPS source tree the styles are
   registered by LAMMPS itself through the style headers.
------------------------------------------------------------------------- */

#include "register_driver.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "version.h"

#include "register_peridem.h"

using namespace LAMMPS_NS;

namespace {

// inserts each style into the style map of its kind
class MapInserter : public PERIDEM_NS::StyleSink {
 public:
  explicit MapInserter(LAMMPS *lmp) : lmp(lmp) {}
  void atom(const char *name, PERIDEM_NS::AtomVecCreator c) override
  {
    (*lmp->atom->avec_map)[name] = c;
  }
  void bond(const char *name, PERIDEM_NS::BondCreator c) override
  {
    (*lmp->force->bond_map)[name] = c;
  }
  void pair(const char *name, PERIDEM_NS::PairCreator c) override
  {
    (*lmp->force->pair_map)[name] = c;
  }
  void fix(const char *name, PERIDEM_NS::FixCreator c) override
  {
    (*lmp->modify->fix_map)[name] = c;
  }
  void compute(const char *name, PERIDEM_NS::ComputeCreator c) override
  {
    (*lmp->modify->compute_map)[name] = c;
  }
  void command(const char *name, PERIDEM_NS::CommandCreator c) override
  {
    (*lmp->input->command_map)[name] = c;
  }

 private:
  LAMMPS *lmp;
};

} // namespace

namespace LAMMPS_NS {
namespace PERIDEM_NS {

std::string version_mismatch_message(const std::string &compiled, const std::string &running)
{
  if (compiled == running) return {};
  return "PERIDEM was compiled against LAMMPS version '" + compiled +
         "' but is being loaded into LAMMPS version '" + running +
         "'; rebuild PERIDEM with PERIDEM_LAMMPS_SRC pointing at the matching LAMMPS source tree";
}

void check_lammps_version(LAMMPS *lmp, const std::string &expected_version)
{
  const std::string mismatch = version_mismatch_message(expected_version, lmp->version);
  if (!mismatch.empty()) lmp->error->all(FLERR, mismatch);
}

void register_styles(LAMMPS *lmp, const std::string &expected_version)
{
  check_lammps_version(lmp, expected_version);
  MapInserter inserter(lmp);
  for_each_style(inserter);
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

extern "C" int peridem_register(void *lmp)
{
  if (!lmp) return 1;
  PERIDEM_NS::register_styles(static_cast<LAMMPS *>(lmp), LAMMPS_VERSION);
  return 0;
}

extern "C" const char *peridem_lammps_version()
{
  return LAMMPS_VERSION;
}
