/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: fix peridem/lps, the per-node state of bond_style peridem/lps.
------------------------------------------------------------------------- */

#include "fix_peridem_lps.h"
#include "lmp_peridem_compat.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_peridem_bonds.h"
#include "lmp_peridem_own_fix.h"
#include "memory.h"
#include "modify.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {
// m > 0 once computed; -1 before
bool valid_m(double m)
{
  return std::isfinite(m) && (m > 0.0 || m == -1.0);
}
} // namespace

/* ---------------------------------------------------------------------- */

FixPeridemLPS::FixPeridemLPS(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg), wvolume(nullptr), comm_a(nullptr), comm_b(nullptr)
{
  PERIDEM_NS::check_own_fix(lmp, narg, this, ID, "bond_style peridem/lps");
  restart_peratom = 1;
  comm_reverse = 1;
  comm_forward = 2;
  maxexchange = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nmax; i++) wvolume[i] = -1.0;
  adopt_data_file_m();
  adopt_old_restart_m();
}

FixPeridemLPS::~FixPeridemLPS()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(wvolume);
}

/* ---------------------------------------------------------------------- */

void FixPeridemLPS::grow_arrays(int nmax)
{
  memory->grow(wvolume, nmax, "peridem/lps:wvolume");
}

void FixPeridemLPS::set_arrays(int i)
{
  wvolume[i] = -1.0;
}

void FixPeridemLPS::copy_arrays(int i, int j, int)
{
  wvolume[j] = wvolume[i];
}

int FixPeridemLPS::pack_exchange(int i, double *buf)
{
  buf[0] = wvolume[i];
  return 1;
}

int FixPeridemLPS::unpack_exchange(int nlocal, double *buf)
{
  wvolume[nlocal] = buf[0];
  return 1;
}

int FixPeridemLPS::pack_restart(int i, double *buf)
{
  buf[0] = 2;
  buf[1] = wvolume[i];
  return 2;
}

void FixPeridemLPS::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  wvolume[nlocal] = extra[nlocal][m + 1];
  check_restart_m(nlocal);
}

// a damaged file stops here, not in the force loop
void FixPeridemLPS::check_restart_m(int i)
{
  if (!valid_m(wvolume[i]))
    error->one(FLERR,
               "fix {}: invalid weighted volume {} of atom {} in restart file (need a finite m > "
               "0, or -1 where it was not computed; damaged file?)",
               ID, wvolume[i], atom->tag[i]);
}

/* ----------------------------------------------------------------------
   restart files written before this fix existed hold m as the last value
   of fix peridem/bonds' record; that fix, created just before this one by
   the same bond style's init_style(), keeps them per local atom
------------------------------------------------------------------------- */

void FixPeridemLPS::adopt_old_restart_m()
{
  const int ibonds = modify->find_fix(FixPeridemBonds::ID);
  auto *bonds = ibonds < 0 ? nullptr : dynamic_cast<FixPeridemBonds *>(modify->fix[ibonds]);
  if (!bonds) return;
  const std::vector<double> old = bonds->take_old_restart_m();
  const int n = std::min(static_cast<int>(old.size()), atom->nlocal);
  for (int i = 0; i < n; i++) {
    wvolume[i] = old[i];
    check_restart_m(i);
  }
}

double FixPeridemLPS::memory_usage()
{
  return static_cast<double>(atom->nmax) * sizeof(double);
}

/* ----------------------------------------------------------------------
   the passes of bond_style peridem/lps: ghost shares home (newton_bond
   on), then the owners' values out to the ghosts
------------------------------------------------------------------------- */

void FixPeridemLPS::reverse_sum(double *a)
{
  comm_a = a;
  PERIDEM_NS::reverse_comm(comm, this);
}

void FixPeridemLPS::forward(double *a, double *b)
{
  comm_a = a;
  comm_b = b;
  PERIDEM_NS::forward_comm(comm, this);
}

int FixPeridemLPS::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) buf[m++] = comm_a[i];
  return m;
}

void FixPeridemLPS::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int k = 0; k < n; k++) comm_a[list[k]] += buf[k];
}

int FixPeridemLPS::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    buf[m++] = comm_a[list[k]];
    buf[m++] = comm_b[list[k]];
  }
  return m;
}

void FixPeridemLPS::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    comm_a[i] = buf[m++];
    comm_b[i] = buf[m++];
  }
}

/* ----------------------------------------------------------------------
   data files: m is a column of fix peridem/bonds' PeridemDamage section,
   written once some node has it (without it read_data would have m summed
   again over the bonds left); read_data reads it into fix property/atom
   d_peridem_wvolume, which this fix adopts when the bond style creates it
------------------------------------------------------------------------- */

bool FixPeridemLPS::column_written()
{
  int any = 0, any_all = 0;
  for (int i = 0; i < atom->nlocal && !any; i++) any = wvolume[i] > 0.0;
  MPI_Allreduce(&any, &any_all, 1, MPI_INT, MPI_MAX, world);
  return any_all != 0;
}

void FixPeridemLPS::adopt_data_file_m()
{
  int flag = 0, cols = 0;
  const int im = atom->find_custom("peridem_wvolume", flag, cols);
  if (im < 0) {
    refuse_misnamed_m();
    return;
  }
  if (flag != 1 || cols != 0)
    error->all(FLERR, "fix {}: per-atom property peridem_wvolume must be a d_ vector", ID);
  const double *m = atom->dvector[im];
  bigint here = 0, all = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    // 0: a node without bonds when m was summed (written so), -1: not computed
    if (!std::isfinite(m[i]) || (m[i] < 0.0 && m[i] != -1.0))
      error->one(FLERR,
                 "fix {}: invalid weighted volume {} of atom {} in the data file (need a finite "
                 "m > 0, or 0 or -1 where it was not computed)",
                 ID, m[i], atom->tag[i]);
    wvolume[i] = m[i] > 0.0 ? m[i] : -1.0;
    if (m[i] > 0.0) here++;
  }
  MPI_Allreduce(&here, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0)
    utils::logmesg(lmp, "fix {}: weighted volume m of {} nodes taken from property/atom {}\n", ID,
                   all, column_property());
}

// a vector named like the m column but not as this fix reads it (d_wvolume): the column went
// into it, and m would be summed again over the bonds left without a word
void FixPeridemLPS::refuse_misnamed_m()
{
  if (comm->me != 0) return;
  for (int k = 0; k < atom->ndvector; k++) {
    const std::string name = atom->dvname[k] ? atom->dvname[k] : "";
    if (name.find("wvolume") != std::string::npos)
      error->warning(FLERR,
                     "fix {}: per-atom property {} looks like the weighted volume m of a {} "
                     "section but is not read, so m is summed again over the bonds left: name "
                     "the vector d_{}",
                     ID, name, FixPeridemBonds::DATA_SECTION, column_property());
  }
}
