/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/fragments.

   The fragments of a grain are the connected components of its intact
   bonds (Bhattacharya & Lipton 2023, §6.4 counts 2 and 3 pieces of a notched disk;
   the bond-fraction damage of §3.1 does not tell them apart). Broken bonds
   have left the bond arrays (fix peridem/bonds), so every stored bond of
   positive type is intact.

   Components across ranks and periodic images: each rank joins its owned
   atoms and their bond partners (owned or ghost) in a union-find over its
   local indices once; then labels (the smallest atom ID seen) are
   propagated: every local component takes the smallest label of its
   members, ghosts send their label home (reverse communication, needed
   with newton_bond on, where a bond is stored by one atom only) and owners
   send theirs to every ghost image (forward communication), until no rank
   sees an owned label change (MPI_Allreduce). The result is exact for any
   decomposition: the rounds needed are the number of subdomains a
   fragment spans, not its size in bonds. This is the scheme of LAMMPS's
   compute cluster/atom, with the local sweeps replaced by a union-find.
------------------------------------------------------------------------- */

#include "compute_peridem_fragments.h"
#include "lmp_peridem_compat.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "lmp_peridem_grains.h"
#include "lmp_peridem_parse.h"
#include "memory.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>

using namespace LAMMPS_NS;

namespace {
const char *const STYLE = "compute peridem/fragments";
enum { ID, GRAIN, NNODES, VOL, MASS };
enum { COMM_LABEL_FORWARD, COMM_LABEL_REVERSE };

int find_root(std::vector<int> &parent, int i)
{
  while (parent[i] != i) {
    parent[i] = parent[parent[i]]; // path halving
    i = parent[i];
  }
  return i;
}
} // namespace

/* ----------------------------------------------------------------------
   compute ID group peridem/fragments [min nodes N | min volume V]
------------------------------------------------------------------------- */

ComputePeridemFragments::ComputePeridemFragments(LAMMPS *lmp, int narg, char **arg)
    : Compute(lmp, narg, arg), min_kind(NODES), min_size(1.0), nmax(0), label(nullptr),
      maxmol(0), stats{0.0, 0.0, 0.0, 0.0}, per_grain(nullptr), last_step(-1), last_ncalls(-1),
      iterations(0)
{
  if (!atom->molecular || !atom->molecule_flag || !atom->x0_flag || !atom->vfrac_flag ||
      !atom->rmass_flag)
    error->all(FLERR, "{} requires atom style peridem (bonds, grain IDs, volumes and x0)", STYLE);
  for (int iarg = 3; iarg < narg;) {
    if (strcmp(arg[iarg], "min") == 0) {
      if (iarg + 3 > narg)
        error->all(FLERR, "Illegal {} command: min needs nodes N or volume V", STYLE);
      if (strcmp(arg[iarg + 1], "nodes") == 0)
        min_kind = NODES;
      else if (strcmp(arg[iarg + 1], "volume") == 0)
        min_kind = VOLUME;
      else
        error->all(FLERR, "Illegal {} command: min {}: expected nodes or volume", STYLE,
                   arg[iarg + 1]);
      // a node count is a whole number (2.5 would silently mean 3)
      min_size =
          min_kind == NODES
              ? static_cast<double>(PERIDEM_NS::integer(lmp, STYLE, "min nodes", arg[iarg + 2]))
              : PERIDEM_NS::number(lmp, STYLE, "min", arg[iarg + 2]);
      if (min_size < 0.0)
        error->all(FLERR, "Illegal {} command: min {} {} must not be negative", STYLE,
                   arg[iarg + 1], arg[iarg + 2]);
      iarg += 3;
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword {}", STYLE, arg[iarg]);
  }

  peratom_flag = 1;
  size_peratom_cols = 0;
  scalar_flag = vector_flag = array_flag = local_flag = 1;
  size_vector = 4;
  extscalar = extvector = extarray = 0;
  size_local_cols = NCOLS;
  comm_forward = comm_reverse = 1;

  // grains are fixed at creation: the per-grain array has a row per grain ID
  maxmol = PERIDEM_NS::max_grain_id(lmp);
  size_array_rows = std::max<tagint>(maxmol, 1);
  size_array_cols = 2;
  memory->create(per_grain, size_array_rows, 2, "peridem/fragments:per_grain");
  array = per_grain;
  vector = stats;
}

ComputePeridemFragments::~ComputePeridemFragments()
{
  memory->destroy(label);
  memory->destroy(per_grain);
  memory->destroy(array_local);
}

void ComputePeridemFragments::init()
{
  if (PERIDEM_NS::max_grain_id(lmp) > maxmol)
    error->all(FLERR, "{} {}: grain IDs beyond {} were added after the compute was defined", STYLE,
               id, maxmol);
  last_step = -1;
}

/* ----------------------------------------------------------------------
   labels: one union-find over local indices, then rounds of communication
------------------------------------------------------------------------- */

void ComputePeridemFragments::propagate()
{
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  if (atom->nmax > nmax) {
    memory->destroy(label);
    nmax = atom->nmax;
    memory->create(label, nmax, "peridem/fragments:label");
  }
  const int *mask = atom->mask;
  const tagint *tag = atom->tag;

  root.resize(nall);
  std::iota(root.begin(), root.end(), 0);
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int m = 0; m < atom->num_bond[i]; m++) {
      if (atom->bond_type[i][m] <= 0) continue; // turned off by delete_bonds: not a bond
      const tagint partner = atom->bond_atom[i][m];
      const int j = atom->map(partner);
      if (j < 0)
        error->one(FLERR, "{}: atom {} bonded to atom {} is missing on proc {}", STYLE, partner,
                   tag[i], comm->me);
      if (!(mask[j] & groupbit)) continue;
      const int ri = find_root(root, i), rj = find_root(root, j);
      if (ri != rj) root[std::max(ri, rj)] = std::min(ri, rj);
    }
  }
  for (int i = 0; i < nall; i++) root[i] = find_root(root, i);

  for (int i = 0; i < nlocal; i++) label[i] = (mask[i] & groupbit) ? double(tag[i]) : 0.0;
  PERIDEM_NS::forward_comm(comm, this);

  const double none = std::numeric_limits<double>::max();
  rootmin.assign(nall, none);
  iterations = 0;
  while (true) {
    iterations++;
    int changed = 0;
    for (int i = 0; i < nall; i++)
      if (label[i] > 0.0) rootmin[root[i]] = std::min(rootmin[root[i]], label[i]);
    for (int i = 0; i < nall; i++) {
      if (label[i] <= 0.0) continue;
      const double m = rootmin[root[i]];
      if (m < label[i]) {
        label[i] = m;
        if (i < nlocal) changed = 1;
      }
    }
    if (force->newton_bond) { // a bond is stored by one of its atoms only
      std::vector<double> before(label, label + nlocal);
      PERIDEM_NS::reverse_comm(comm, this);
      for (int i = 0; i < nlocal && !changed; i++) changed = label[i] != before[i];
    }
    PERIDEM_NS::forward_comm(comm, this);
    int any = 0;
    MPI_Allreduce(&changed, &any, 1, MPI_INT, MPI_MAX, world);
    if (!any) break;
  }
}

int ComputePeridemFragments::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  for (int k = 0; k < n; k++) buf[k] = label[list[k]];
  return n;
}

void ComputePeridemFragments::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) label[first + k] = buf[k];
}

int ComputePeridemFragments::pack_reverse_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) buf[k] = label[first + k];
  return n;
}

void ComputePeridemFragments::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    if (buf[k] > 0.0 && (label[j] <= 0.0 || buf[k] < label[j])) label[j] = buf[k];
  }
}

/* ----------------------------------------------------------------------
   sizes of all fragments: local sums per label, gathered on every rank
   (the counts are global outputs), merged by label
------------------------------------------------------------------------- */

void ComputePeridemFragments::collect()
{
  const int nlocal = atom->nlocal;
  std::vector<int> order;
  order.reserve(nlocal);
  for (int i = 0; i < nlocal; i++)
    if (label[i] > 0.0) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return label[a] < label[b]; });
  std::vector<double> mine;
  for (const int i : order) {
    if (mine.empty() || mine[mine.size() - NCOLS + ID] != label[i])
      mine.insert(mine.end(), {label[i], double(atom->molecule[i]), 0.0, 0.0, 0.0});
    double *f = &mine[mine.size() - NCOLS];
    f[NNODES] += 1.0;
    f[VOL] += atom->vfrac[i];
    f[MASS] += atom->rmass[i];
  }

  const std::vector<double> all = PERIDEM_NS::gather_all(lmp, mine);

  // merge the pieces of a fragment that lie on several ranks
  const size_t n = all.size() / NCOLS;
  std::vector<size_t> idx(n);
  std::iota(idx.begin(), idx.end(), size_t(0));
  std::sort(idx.begin(), idx.end(),
            [&](size_t a, size_t b) { return all[a * NCOLS + ID] < all[b * NCOLS + ID]; });
  fragments.clear();
  for (const size_t k : idx) {
    const double *piece = &all[k * NCOLS];
    if (fragments.empty() || fragments[fragments.size() - NCOLS + ID] != piece[ID])
      fragments.insert(fragments.end(), {piece[ID], piece[GRAIN], 0.0, 0.0, 0.0});
    double *f = &fragments[fragments.size() - NCOLS];
    for (int c = NNODES; c < NCOLS; c++) f[c] += piece[c];
  }

  for (int g = 0; g < size_array_rows; g++) per_grain[g][0] = per_grain[g][1] = 0.0;
  for (int c = 0; c < 4; c++) stats[c] = 0.0;
  for (size_t k = 0; k < fragments.size(); k += NCOLS) {
    const double *f = &fragments[k];
    const bool large = passes(f);
    stats[0] += 1.0;
    stats[large ? 1 : 2] += 1.0;
    if (!large) stats[3] += f[VOL];
    const tagint g = tagint(f[GRAIN]);
    if (g >= 1 && g <= maxmol) {
      per_grain[g - 1][0] += 1.0;
      if (large) per_grain[g - 1][1] += 1.0;
    }
  }
}

bool ComputePeridemFragments::passes(const double *frag) const
{
  return (min_kind == NODES ? frag[NNODES] : frag[VOL]) >= min_size;
}

double ComputePeridemFragments::grain_fragments(tagint g) const
{
  return (g >= 1 && g <= maxmol) ? per_grain[g - 1][1] : 0.0;
}

/* ----------------------------------------------------------------------
   all outputs of one step come from one labelling; a new run (setup
   rebuilds the neighbour lists) or a new step labels again
------------------------------------------------------------------------- */

void ComputePeridemFragments::refresh()
{
  if (update->ntimestep == last_step && neighbor->ncalls == last_ncalls) return;
  propagate();
  collect();
  last_step = update->ntimestep;
  last_ncalls = neighbor->ncalls;
}

double ComputePeridemFragments::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  refresh();
  scalar = stats[0];
  return scalar;
}

void ComputePeridemFragments::compute_vector()
{
  invoked_vector = update->ntimestep;
  refresh();
}

void ComputePeridemFragments::compute_array()
{
  invoked_array = update->ntimestep;
  refresh();
}

void ComputePeridemFragments::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  refresh();
  vector_atom = label;
}

// rank 0 holds every fragment's row: dump local and compute reduce see each once
void ComputePeridemFragments::compute_local()
{
  invoked_local = update->ntimestep;
  refresh();
  const int rows = comm->me == 0 ? int(fragments.size() / NCOLS) : 0;
  memory->destroy(array_local);
  memory->create(array_local, std::max(rows, 1), NCOLS, "peridem/fragments:local");
  for (int r = 0; r < rows; r++)
    for (int c = 0; c < NCOLS; c++) array_local[r][c] = fragments[size_t(r) * NCOLS + c];
  size_local_rows = rows;
}

double ComputePeridemFragments::memory_usage()
{
  return double(nmax) * sizeof(double) + root.capacity() * sizeof(int) +
         (rootmin.capacity() + fragments.capacity()) * sizeof(double);
}
