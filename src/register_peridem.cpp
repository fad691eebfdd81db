/* ----------------------------------------------------------------------
   PERIDEM: registration of all PERIDEM styles into a LAMMPS instance.
------------------------------------------------------------------------- */

#include "register_peridem.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "version.h"

#include "atom_vec_peridem.h"
#include "bond_peridem.h"
#include "compute_peridem_damage.h"
#include "create_peridem_grains.h"
#include "cut_peridem_bonds.h"
#include "fix_peridem_bonds.h"
#include "fix_peridem_wall.h"
#include "pair_peridem_contact.h"

using namespace LAMMPS_NS;

namespace {

template <typename T> AtomVec *atom_vec_creator(LAMMPS *lmp)
{
  return new T(lmp);
}

template <typename T> Pair *pair_creator(LAMMPS *lmp)
{
  return new T(lmp);
}

template <typename T> Bond *bond_creator(LAMMPS *lmp)
{
  return new T(lmp);
}

template <typename T> Fix *fix_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}

template <typename T> Compute *compute_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}

template <typename T> Command *command_creator(LAMMPS *lmp)
{
  return new T(lmp);
}

// One line per style. New styles are added here and in the list of names.
void insert_styles(LAMMPS *lmp)
{
  (*lmp->atom->avec_map)["peridem"] = &atom_vec_creator<AtomVecPeridem>;
  (*lmp->force->bond_map)["peridem"] = &bond_creator<BondPeridem>;
  (*lmp->force->pair_map)["peridem/contact"] = &pair_creator<PairPeridemContact>;
  (*lmp->modify->fix_map)["peridem/bonds"] = &fix_creator<FixPeridemBonds>;
  (*lmp->modify->fix_map)["peridem/wall"] = &fix_creator<FixPeridemWall>;
  (*lmp->modify->compute_map)["peridem/damage"] = &compute_creator<ComputePeridemDamage>;
  (*lmp->input->command_map)["create_peridem_grains"] = &command_creator<CreatePeridemGrains>;
  (*lmp->input->command_map)["cut_peridem_bonds"] = &command_creator<CutPeridemBonds>;
}

const char *const style_names[] = {
    "atom_style peridem",     "bond_style peridem", "pair_style peridem/contact",
    "compute peridem/damage", "fix peridem/bonds",  "fix peridem/wall",
    "create_peridem_grains",  "cut_peridem_bonds",  nullptr};

} // namespace

namespace PERIDEM {

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
  insert_styles(lmp);
}

const char *const *registered_style_names()
{
  return style_names;
}

} // namespace PERIDEM

extern "C" int peridem_register(void *lmp)
{
  if (!lmp) return 1;
  PERIDEM::register_styles(static_cast<LAMMPS *>(lmp), LAMMPS_VERSION);
  return 0;
}

extern "C" const char *peridem_lammps_version()
{
  return LAMMPS_VERSION;
}
