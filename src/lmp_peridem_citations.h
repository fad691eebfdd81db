/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: the papers whose models the styles implement, registered with
   LAMMPS's citation reminder (lmp->citeme), as LAMMPS's own packages do:
   LAMMPS lists them at the end of a run (and in log.cite).
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_CITATIONS_H
#define LMP_PERIDEM_CITATIONS_H

#include "citeme.h"
#include "lammps.h"

namespace LAMMPS_NS {
namespace PERIDEM_NS {

// Bond-based grains, bond pruning, contact with friction and damping, walls, bed packings
static const char cite_peridem_grain_shape[] =
    "PERIDEM package (bond-based grains, contact, walls, beds): Bhattacharya & Lipton 2023\n\n"
    "@Article{BhattacharyaLipton2023,\n"
    " author = {D. Bhattacharya and R. P. Lipton},\n"
    " title = {Simulating Grain Shape Effects and Damage in Granular Media Using {PeriDEM}},\n"
    " journal = {SIAM J.~Sci.~Comput.},\n"
    " year =    2023\n"
    "}\n\n";

// PeriDEM: state-based grains, contact, restitution and centroid damping
static const char cite_peridem_2021[] =
    "PERIDEM package (PeriDEM model, state-based grains, contact damping): Jha et al. 2021\n\n"
    "@Article{Jha2021,\n"
    " author = {P. K. Jha and P. S. Desai and D. Bhattacharya and R. Lipton},\n"
    " title = {Peridynamics-based discrete element method ({PeriDEM}) model of granular systems\n"
    "          involving breakage of arbitrarily shaped particles},\n"
    " journal = {J.~Mech.~Phys.~Solids},\n"
    " year =    2021,\n"
    " volume =  151,\n"
    " pages =   104376\n"
    "}\n\n";

inline void cite_grain_shape(LAMMPS_NS::LAMMPS *lmp)
{
  if (lmp->citeme) lmp->citeme->add(cite_peridem_grain_shape);
}

inline void cite_peridem(LAMMPS_NS::LAMMPS *lmp)
{
  if (lmp->citeme) lmp->citeme->add(cite_peridem_2021);
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
