/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: fix peridem/escapes. A node beyond a fixed ('f') box boundary is
   lost by LAMMPS at the next reneighbouring, and its partners' bonds then
   name a missing atom ("Bond atoms missing"). Checked at every
   reneighbouring: the run stops with the node and its grain named, unless
   a fix peridem/wall with 'lost delete' removes such nodes, or
   thermo_modify lost ignore|warn lets atoms go (as BPM's users do for
   fragments that fly off): then they are deleted here with their bonds,
   and counted.
------------------------------------------------------------------------- */

#include "fix_peridem_escapes.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_peridem_wall.h"
#include "lmp_peridem_own_fix.h"
#include "lmp_peridem_topology.h"
#include "modify.h"
#include "output.h"
#include "thermo.h"
#include "update.h"

#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

FixPeridemEscapes::FixPeridemEscapes(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  PERIDEM_NS::check_own_fix(lmp, narg, this, ID, "bond_style peridem");
  scalar_flag = 1; // nodes deleted with their bonds (thermo_modify lost ignore|warn)
  global_freq = 1;
  extscalar = 1;
}

int FixPeridemEscapes::setmask()
{
  return PRE_EXCHANGE;
}

void FixPeridemEscapes::init()
{
  walls_delete = false;
  for (int f = 0; f < modify->nfix; f++) {
    auto *wall = dynamic_cast<FixPeridemWall *>(modify->fix[f]);
    if (wall && wall->deletes_lost()) walls_delete = true;
  }
  lost_allowed = output->thermo && output->thermo->lostflag != Thermo::ERROR;
  deleted_run = 0;
}

void FixPeridemEscapes::setup_pre_exchange()
{
  check();
}

void FixPeridemEscapes::pre_exchange()
{
  check();
}

void FixPeridemEscapes::check()
{
  if (walls_delete) return;
  double **x = atom->x;
  std::vector<int> doomed;
  for (int i = 0; i < atom->nlocal; i++) {
    const int face = PERIDEM_NS::outside_fixed_boundary(domain, x[i]);
    if (face < 0) continue;
    if (lost_allowed) {
      doomed.push_back(i);
      continue;
    }
    static const char *const faces[] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};
    error->one(FLERR,
               "atom {} of grain {} left the simulation box through {} at ({}, {}, {}) at step "
               "{}: LAMMPS would lose it and its bonds. Enlarge the box, contain the grains "
               "(fix peridem/wall), or delete escaping nodes with their bonds (fix peridem/wall "
               "... lost delete, or thermo_modify lost ignore)",
               atom->tag[i], atom->molecule[i], faces[face], x[i][0], x[i][1], x[i][2],
               update->ntimestep);
  }
  if (!lost_allowed) return;
  // every rank takes part (the deletion communicates), with or without nodes of its own
  const bigint gone = PERIDEM_NS::delete_nodes_breaking_bonds(lmp, doomed);
  deleted_run += gone;
  deleted_total += gone;
}

/* ----------------------------------------------------------------------
   nodes deleted with their bonds since the fix was created (thermo_modify
   lost ignore|warn); reported at the end of each run
------------------------------------------------------------------------- */

double FixPeridemEscapes::compute_scalar()
{
  return static_cast<double>(deleted_total);
}

void FixPeridemEscapes::post_run()
{
  if (!lost_allowed || deleted_run == 0 || comm->me != 0) return;
  if (output->thermo->lostflag == Thermo::WARN)
    error->warning(FLERR,
                   "fix {}: {} nodes left the box in this run and were deleted with their bonds "
                   "(thermo_modify lost warn; {} so far, f_{})",
                   ID, deleted_run, deleted_total, ID);
  else
    utils::logmesg(lmp,
                   "fix {}: {} nodes left the box in this run and were deleted with their bonds "
                   "(thermo_modify lost ignore; {} so far, f_{})\n",
                   ID, deleted_run, deleted_total, ID);
}
