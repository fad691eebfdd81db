/* ----------------------------------------------------------------------
   PERIDEM as a LAMMPS plugin (peridemplugin.so) for LAMMPS builds with the
   PLUGIN package: "plugin load peridemplugin.so". Debian's LAMMPS has no
   PLUGIN package; there use lmp_peridem, LD_PRELOAD or peridem_register
   (README). Tested by unittest/plugin/plugin_host.cpp, which loads it the
   way the PLUGIN package of LAMMPS 29Sep2021 does.

   The plugin loader of that LAMMPS version registers pair, bond, fix,
   compute and command styles; it has no atom styles ("not yet
   implemented"), so atom_style peridem is inserted into the LAMMPS instance
   directly: "plugin unload" cannot remove it, and "clear" unloads plugins
   in that version (load the plugin again after clear).
------------------------------------------------------------------------- */

#include "lammpsplugin.h"

#include "atom.h"
#include "lammps.h"
#include "version.h"

#include "atom_vec_peridem.h"
#include "bond_peridem.h"
#include "compute_peridem_damage.h"
#include "create_peridem_grains.h"
#include "cut_peridem_bonds.h"
#include "fix_peridem_bonds.h"
#include "fix_peridem_wall.h"
#include "pair_peridem_contact.h"
#include "register_peridem.h"

using namespace LAMMPS_NS;

namespace {

// creators with the signatures of the plugin interface; LAMMPS casts them
// back to its typed creators (Force::PairCreator, Modify::FixCreator, ...)
template <typename Base, typename T> void *make1(void *lmp)
{
  return static_cast<Base *>(new T(static_cast<LAMMPS *>(lmp)));
}
template <typename Base, typename T> void *make2(void *lmp, int narg, char **arg)
{
  return static_cast<Base *>(new T(static_cast<LAMMPS *>(lmp), narg, arg));
}

template <typename T> AtomVec *atom_vec_creator(LAMMPS *lmp)
{
  return new T(lmp);
}

void add(lammpsplugin_regfunc reg, void *lmp, void *handle, const char *style, const char *name,
         lammpsplugin_factory1 *v1, lammpsplugin_factory2 *v2)
{
  lammpsplugin_t plugin;
  plugin.version = LAMMPS_VERSION;
  plugin.style = style;
  plugin.name = name;
  plugin.info = "PERIDEM: deformable, breakable grains (peridynamics + contact)";
  plugin.author = "the PERIDEM developers";
  if (v1)
    plugin.creator.v1 = v1;
  else
    plugin.creator.v2 = v2;
  plugin.handle = handle;
  (*reg)(&plugin, lmp);
}

} // namespace

extern "C" void lammpsplugin_init(void *lmp_ptr, void *handle, void *regfunc)
{
  auto *lmp = static_cast<LAMMPS *>(lmp_ptr);
  // refuses a LAMMPS of another version with a clear error, as peridem_register does
  PERIDEM::check_lammps_version(lmp, LAMMPS_VERSION);
  (*lmp->atom->avec_map)["peridem"] = &atom_vec_creator<AtomVecPeridem>;

  auto reg = (lammpsplugin_regfunc)regfunc;
  add(reg, lmp, handle, "bond", "peridem", &make1<Bond, BondPeridem>, nullptr);
  add(reg, lmp, handle, "pair", "peridem/contact", &make1<Pair, PairPeridemContact>, nullptr);
  add(reg, lmp, handle, "fix", "peridem/bonds", nullptr, &make2<Fix, FixPeridemBonds>);
  add(reg, lmp, handle, "fix", "peridem/wall", nullptr, &make2<Fix, FixPeridemWall>);
  add(reg, lmp, handle, "compute", "peridem/damage", nullptr,
      &make2<Compute, ComputePeridemDamage>);
  add(reg, lmp, handle, "command", "create_peridem_grains", &make1<Command, CreatePeridemGrains>,
      nullptr);
  add(reg, lmp, handle, "command", "cut_peridem_bonds", &make1<Command, CutPeridemBonds>, nullptr);
}
