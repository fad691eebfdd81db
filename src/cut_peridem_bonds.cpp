/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: command cut_peridem_bonds, see doc/cut_peridem_bonds.rst.
------------------------------------------------------------------------- */

#include "cut_peridem_bonds.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "lmp_peridem_parse.h"
#include "lmp_peridem_topology.h"

#include "peridem_geometry_bonds.h"

#include <cstring>
#include <vector>

using namespace LAMMPS_NS;

namespace {
constexpr const char *CMD = "cut_peridem_bonds";
}

/* ---------------------------------------------------------------------- */

CutPeridemBonds::CutPeridemBonds(LAMMPS *lmp) : Command(lmp) {}

/* ----------------------------------------------------------------------
   cut_peridem_bonds group-ID segment x1 y1 x2 y2 [segment x1 y1 x2 y2 ...]
------------------------------------------------------------------------- */

void CutPeridemBonds::command(int narg, char **arg)
{
  if (domain->box_exist == 0) error->all(FLERR, "{} command before simulation box is defined", CMD);
  if (!atom->x0_flag || atom->molecular != Atom::MOLECULAR)
    error->all(FLERR, "{} requires atom style peridem", CMD);
  if (narg < 1) error->all(FLERR, "Illegal {} command: expected a group ID", CMD);

  const int igroup = group->find(arg[0]);
  if (igroup == -1) error->all(FLERR, "{}: cannot find group {}", CMD, arg[0]);
  const int groupbit = group->bitmask[igroup];

  std::vector<peridem::CutSegment> cuts;
  for (int iarg = 1; iarg < narg;) {
    if (strcmp(arg[iarg], "segment") != 0)
      error->all(FLERR, "{}: unknown keyword '{}' (expected segment x1 y1 x2 y2)", CMD, arg[iarg]);
    if (iarg + 5 > narg) error->all(FLERR, "{}: segment needs 4 values: x1 y1 x2 y2", CMD);
    double v[4];
    for (int k = 0; k < 4; k++) v[k] = PERIDEM_NS::number(lmp, CMD, "segment", arg[iarg + 1 + k]);
    if (v[0] == v[2] && v[1] == v[3])
      error->all(FLERR, "{}: segment {} {} {} {} has zero length", CMD, arg[iarg + 1],
                 arg[iarg + 2], arg[iarg + 3], arg[iarg + 4]);
    cuts.push_back({{v[0], v[1]}, {v[2], v[3]}});
    iarg += 5;
  }
  if (cuts.empty()) error->all(FLERR, "{}: no segment given", CMD);

  // ghosts carry x0 and the group mask of the partner atoms, as in delete_bonds
  if (comm->me == 0) utils::logmesg(lmp, "System init for {} ...\n", CMD);
  lmp->init();
  domain->pbc();
  domain->reset_box();
  comm->setup();
  comm->exchange();
  comm->borders();

  // both owners of a bond (newton_bond off) decide alike: ends ordered by ID
  const bigint nbonds_previous = atom->nbonds;
  double **x0 = atom->x0;
  int *mask = atom->mask;
  tagint *tag = atom->tag;
  for (int i = 0; i < atom->nlocal; i++) {
    int m = 0;
    while (m < atom->num_bond[i]) {
      const int j = atom->map(atom->bond_atom[i][m]);
      if (j < 0)
        error->one(FLERR,
                   "{}: bond partner {} of atom {} is beyond the ghost cutoff of proc {}: define "
                   "bond_style peridem first (it sets the communication cutoff) or use "
                   "comm_modify cutoff with at least the longest bond",
                   CMD, atom->bond_atom[i][m], tag[i], comm->me);
      bool cut = false;
      if ((mask[i] & groupbit) && (mask[j] & groupbit)) {
        const int a = tag[i] < tag[j] ? i : j, b = tag[i] < tag[j] ? j : i;
        const peridem::Vec2 xa(x0[a][0], x0[a][1]), xb(x0[b][0], x0[b][1]);
        for (const auto &c : cuts) cut = cut || peridem::bond_crosses_cut(xa, xb, c);
      }
      if (!cut) {
        m++;
        continue;
      }
      const int last = --atom->num_bond[i];
      atom->bond_type[i][m] = atom->bond_type[i][last];
      atom->bond_atom[i][m] = atom->bond_atom[i][last];
    }
  }

  const bigint nbonds = PERIDEM_NS::finish_bond_edit(lmp);
  if (comm->me == 0)
    utils::logmesg(lmp, "{}: removed {} bonds crossing {} segment(s), new total = {}\n", CMD,
                   nbonds_previous - nbonds, cuts.size(), nbonds);
}
