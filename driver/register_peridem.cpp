/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: the list of all PERIDEM styles (for_each_style), read by the
   routes that register them without LAMMPS's style headers: lmp_peridem and
   libperidem (driver/register_driver.cpp) and peridemplugin.so. Not part of
   src/: in a LAMMPS source tree the style headers register the styles
   (their *Style(...) macros), so a new style goes both there and here.
------------------------------------------------------------------------- */

#include "register_peridem.h"

#include "atom_vec_peridem.h"
#include "bond_peridem.h"
#include "bond_peridem_lps.h"
#include "bond_peridem_opt.h"
#include "compute_peridem_bed.h"
#include "compute_peridem_contacts.h"
#include "compute_peridem_damage.h"
#include "compute_peridem_dilation.h"
#include "compute_peridem_fragments.h"
#include "compute_peridem_grain.h"
#include "compute_peridem_stress.h"
#include "create_peridem_bed.h"
#include "create_peridem_grains.h"
#include "cut_peridem_bonds.h"
#include "fix_peridem_bonds.h"
#include "fix_peridem_escapes.h"
#include "fix_peridem_lps.h"
#include "fix_peridem_order.h"
#include "fix_peridem_vhistory.h"
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

} // namespace

namespace LAMMPS_NS {
namespace PERIDEM_NS {

// One line per style: the only list of PERIDEM styles (register_styles
// and peridemplugin.so both read it).
void for_each_style(StyleSink &sink)
{
  sink.atom("peridem", &atom_vec_creator<AtomVecPeridem>);
  sink.bond("peridem", &bond_creator<BondPeridem>);
  sink.bond("peridem/lps", &bond_creator<BondPeridemLPS>);
  sink.bond("peridem/opt", &bond_creator<BondPeridemOpt>);
  sink.pair("peridem/contact", &pair_creator<PairPeridemContact>);
  sink.fix("peridem/bonds", &fix_creator<FixPeridemBonds>);
  sink.fix("peridem/escapes", &fix_creator<FixPeridemEscapes>);
  sink.fix("peridem/lps", &fix_creator<FixPeridemLPS>);
  sink.fix("peridem/order", &fix_creator<FixPeridemOrder>);
  sink.fix("peridem/wall", &fix_creator<FixPeridemWall>);
  sink.fix("peridem/vhistory", &fix_creator<FixPeridemVelocityHistory>);
  sink.compute("peridem/damage", &compute_creator<ComputePeridemDamage>);
  sink.compute("peridem/fragments", &compute_creator<ComputePeridemFragments>);
  sink.compute("peridem/grain", &compute_creator<ComputePeridemGrain>);
  sink.compute("peridem/bed", &compute_creator<ComputePeridemBed>);
  sink.compute("peridem/dilation", &compute_creator<ComputePeridemDilation>);
  sink.compute("peridem/stress", &compute_creator<ComputePeridemStress>);
  sink.compute("peridem/contacts", &compute_creator<ComputePeridemContacts>);
  sink.command("create_peridem_grains", &command_creator<CreatePeridemGrains>);
  sink.command("cut_peridem_bonds", &command_creator<CutPeridemBonds>);
  sink.command("create_peridem_bed", &command_creator<CreatePeridemBed>);
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS
