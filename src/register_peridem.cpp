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
#include "bond_peridem_lps.h"
#include "compute_peridem_bed.h"
#include "compute_peridem_damage.h"
#include "compute_peridem_dilation.h"
#include "compute_peridem_fragments.h"
#include "compute_peridem_grain.h"
#include "create_peridem_bed.h"
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

// inserts each style into the style map of its kind
class MapInserter : public PERIDEM::StyleSink {
 public:
  explicit MapInserter(LAMMPS *lmp) : lmp(lmp) {}
  void atom(const char *name, PERIDEM::AtomVecCreator c) override
  {
    (*lmp->atom->avec_map)[name] = c;
  }
  void bond(const char *name, PERIDEM::BondCreator c) override
  {
    (*lmp->force->bond_map)[name] = c;
  }
  void pair(const char *name, PERIDEM::PairCreator c) override
  {
    (*lmp->force->pair_map)[name] = c;
  }
  void fix(const char *name, PERIDEM::FixCreator c) override { (*lmp->modify->fix_map)[name] = c; }
  void compute(const char *name, PERIDEM::ComputeCreator c) override
  {
    (*lmp->modify->compute_map)[name] = c;
  }
  void command(const char *name, PERIDEM::CommandCreator c) override
  {
    (*lmp->input->command_map)[name] = c;
  }

 private:
  LAMMPS *lmp;
};

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

// One line per style: the only list of PERIDEM styles (register_styles
// and peridemplugin.so both read it).
void for_each_style(StyleSink &sink)
{
  sink.atom("peridem", &atom_vec_creator<AtomVecPeridem>);
  sink.bond("peridem", &bond_creator<BondPeridem>);
  sink.bond("peridem/lps", &bond_creator<BondPeridemLPS>);
  sink.pair("peridem/contact", &pair_creator<PairPeridemContact>);
  sink.fix("peridem/bonds", &fix_creator<FixPeridemBonds>);
  sink.fix("peridem/wall", &fix_creator<FixPeridemWall>);
  sink.compute("peridem/damage", &compute_creator<ComputePeridemDamage>);
  sink.compute("peridem/fragments", &compute_creator<ComputePeridemFragments>);
  sink.compute("peridem/grain", &compute_creator<ComputePeridemGrain>);
  sink.compute("peridem/bed", &compute_creator<ComputePeridemBed>);
  sink.compute("peridem/dilation", &compute_creator<ComputePeridemDilation>);
  sink.command("create_peridem_grains", &command_creator<CreatePeridemGrains>);
  sink.command("cut_peridem_bonds", &command_creator<CutPeridemBonds>);
  sink.command("create_peridem_bed", &command_creator<CreatePeridemBed>);
}

void register_styles(LAMMPS *lmp, const std::string &expected_version)
{
  check_lammps_version(lmp, expected_version);
  MapInserter inserter(lmp);
  for_each_style(inserter);
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
