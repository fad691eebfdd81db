/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: fix peridem/vhistory (see the header)
------------------------------------------------------------------------- */

#include "fix_peridem_vhistory.h"
#include "lmp_peridem_compat.h"
#include "lmp_peridem_own_fix.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "output.h"
#include "pair.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixPeridemVelocityHistory *FixPeridemVelocityHistory::instance(LAMMPS *lmp, const char *caller)
{
  return PERIDEM_NS::own_fix<FixPeridemVelocityHistory>(lmp, "peridem/vhistory", caller);
}

FixPeridemVelocityHistory::FixPeridemVelocityHistory(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg), vhalf(nullptr), vend(nullptr), known(nullptr)
{
  PERIDEM_NS::check_own_fix(lmp, narg, this, ID, "pair_style peridem/contact and fix peridem/wall");
  restart_peratom = 1;
  comm_forward = 3;
  maxexchange = NVALUES;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nmax; i++) set_arrays(i);
}

FixPeridemVelocityHistory::~FixPeridemVelocityHistory()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(vhalf);
  memory->destroy(vend);
  memory->destroy(known);
}

int FixPeridemVelocityHistory::setmask()
{
  return PRE_FORCE | END_OF_STEP;
}

// the pair style cannot change within a run: its hooks are found once per run
void FixPeridemVelocityHistory::init()
{
  step_end = run_end = nullptr;
  Pair *pair = force->pair ? force->pair_match("^peridem/contact", 0) : nullptr;
  if (!pair) return;
  int dim = 0;
  step_end = static_cast<const std::function<void()> *>(pair->extract("peridem_step_end", dim));
  run_end = static_cast<const std::function<void()> *>(pair->extract("peridem_run_end", dim));
}

// LAMMPS calls end_of_step after every fix's final_integrate: v = v(n)
void FixPeridemVelocityHistory::end_of_step()
{
  if (step_end && *step_end) (*step_end)();
}

/* ----------------------------------------------------------------------
   setup of a run: the velocity of each node's forces is v(n - 1/2) of the
   last step where the node still has the velocity it ended that run with
   (compared bit for bit), else its velocity; ghosts get their owners'
------------------------------------------------------------------------- */

void FixPeridemVelocityHistory::setup_pre_force(int)
{
  prepared = false;
  if (update->whichflag != 1) return; // minimisation: no dynamics to continue
  double **v = atom->v;
  const double step = double(update->ntimestep);
  for (int i = 0; i < atom->nlocal; i++) {
    const bool same =
        known[i] == step && v[i][0] == vend[i][0] && v[i][1] == vend[i][1] && v[i][2] == vend[i][2];
    if (!same)
      for (int k = 0; k < 3; k++) vhalf[i][k] = v[i][k];
  }
  PERIDEM_NS::forward_comm(comm, this);
  prepared = true;
  in_run = true;
}

const double *FixPeridemVelocityHistory::setup_velocities() const
{
  return prepared && update->setupflag && vhalf ? vhalf[0] : nullptr;
}

/* ----------------------------------------------------------------------
   before the forces: v is v(n - 1/2) (velocity Verlet's first half-kick is
   done), the velocity the dissipative forces take. Kept only where a run
   may continue from: its last step and the steps that write a restart file
   (a copy at every step would stream the velocities once more per step).
   A run ended early (fix halt) leaves an older step's values: the step
   stamp tells.
------------------------------------------------------------------------- */

void FixPeridemVelocityHistory::pre_force(int)
{
  prepared = false;
  const bigint step = update->ntimestep;
  if (step != update->laststep && step != output->next_restart) return;
  double **v = atom->v;
  for (int i = 0; i < atom->nlocal; i++) {
    vhalf[i][0] = v[i][0];
    vhalf[i][1] = v[i][1];
    vhalf[i][2] = v[i][2];
    known[i] = double(step);
  }
}

// the end of a run: the velocities it ended with
void FixPeridemVelocityHistory::post_run()
{
  prepared = false;
  in_run = false;
  double **v = atom->v;
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < 3; k++) vend[i][k] = v[i][k];
  if (run_end && *run_end) (*run_end)();
}

/* ---------------------------------------------------------------------- */

void FixPeridemVelocityHistory::grow_arrays(int nmax)
{
  memory->grow(vhalf, nmax, 3, "peridem/vhistory:vhalf");
  memory->grow(vend, nmax, 3, "peridem/vhistory:vend");
  memory->grow(known, nmax, "peridem/vhistory:known");
}

void FixPeridemVelocityHistory::set_arrays(int i)
{
  for (int k = 0; k < 3; k++) vhalf[i][k] = vend[i][k] = 0.0;
  known[i] = 0.0;
}

void FixPeridemVelocityHistory::copy_arrays(int i, int j, int)
{
  for (int k = 0; k < 3; k++) {
    vhalf[j][k] = vhalf[i][k];
    vend[j][k] = vend[i][k];
  }
  known[j] = known[i];
}

int FixPeridemVelocityHistory::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < 3; k++) {
    buf[k] = vhalf[i][k];
    buf[3 + k] = vend[i][k];
  }
  buf[6] = known[i];
  return NVALUES;
}

int FixPeridemVelocityHistory::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < 3; k++) {
    vhalf[nlocal][k] = buf[k];
    vend[nlocal][k] = buf[3 + k];
  }
  known[nlocal] = buf[6];
  return NVALUES;
}

/* ----------------------------------------------------------------------
   restart files: a restart written in a run (restart N) is written at the
   end of a step, with v = v(n) of that step; one written after a run gets
   the velocities the run ended with
------------------------------------------------------------------------- */

int FixPeridemVelocityHistory::pack_restart(int i, double *buf)
{
  buf[0] = NVALUES + 1;
  const double *ve = in_run ? atom->v[i] : vend[i];
  for (int k = 0; k < 3; k++) {
    buf[1 + k] = vhalf[i][k];
    buf[4 + k] = ve[k];
  }
  buf[7] = known[i];
  return NVALUES + 1;
}

void FixPeridemVelocityHistory::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const double *buf = &extra[nlocal][m + 1];
  bool finite = true;
  for (int k = 0; k < NVALUES; k++) finite = finite && std::isfinite(buf[k]);
  if (!finite || buf[6] < 0.0 || buf[6] != std::floor(buf[6]))
    error->one(FLERR, "fix {}: invalid velocity history of atom {} in restart file (damaged file?)",
               ID, atom->tag[nlocal]);
  unpack_exchange(nlocal, const_cast<double *>(buf));
}

int FixPeridemVelocityHistory::size_restart(int)
{
  return NVALUES + 1;
}

int FixPeridemVelocityHistory::maxsize_restart()
{
  return NVALUES + 1;
}

/* ---------------------------------------------------------------------- */

int FixPeridemVelocityHistory::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int d = 0; d < 3; d++) buf[m++] = vhalf[list[k]][d];
  return m;
}

void FixPeridemVelocityHistory::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < 3; d++) vhalf[i][d] = buf[m++];
}

double FixPeridemVelocityHistory::memory_usage()
{
  return double(NVALUES) * atom->nmax * sizeof(double);
}
