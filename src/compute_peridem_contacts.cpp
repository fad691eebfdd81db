/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/contacts, the contact network of the grains of a
   group: two grains touch where two of their nodes are closer than the
   contact radius R_c of pair_style peridem/contact (Bhattacharya & Lipton
   2023, §4). Each grain contact gets one
   normal, the mean of its node contacts' directions; from these the mean
   coordination number 2 N_c / N_g and the fabric tensor (peridem_fabric.h).
------------------------------------------------------------------------- */

#include "compute_peridem_contacts.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "lmp_peridem_grains.h"
#include "pair_peridem_contact.h"
#include "update.h"

#include "peridem_fabric.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

using namespace LAMMPS_NS;

namespace {
const char *const STYLE = "compute peridem/contacts";
enum { Z, NCONTACT, NGRAIN, NNODE, FABRIC };
} // namespace

ComputePeridemContacts::ComputePeridemContacts(LAMMPS *lmp, int narg, char **arg)
    : Compute(lmp, narg, arg), pair(nullptr), stats{}
{
  if (narg != 3)
    error->all(FLERR, "Illegal {} command: it takes no arguments after the style", STYLE);
  if (!atom->molecule_flag) error->all(FLERR, "{} requires atom style peridem (grain IDs)", STYLE);
  scalar_flag = vector_flag = 1;
  size_vector = 10;
  extscalar = extvector = 0;
  vector = stats;
}

void ComputePeridemContacts::init()
{
  pair = dynamic_cast<PairPeridemContact *>(force->pair);
  if (!pair) error->all(FLERR, "{} needs pair_style peridem/contact", STYLE);
}

/* ---------------------------------------------------------------------- */

void ComputePeridemContacts::compute_vector()
{
  invoked_vector = update->ntimestep;
  std::vector<std::array<int, 2>> node_pairs;
  pair->grain_node_contacts(node_pairs);

  // node contacts between two grains of the group, as (a, b, unit vector a -> b); with newton
  // off a pair across ranks is on both ranks: the rank of the smaller atom ID counts it
  const tagint *mol = atom->molecule, *tag = atom->tag;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const bool newton = force->newton_pair;
  std::vector<double> mine;
  for (const auto &p : node_pairs) {
    const int i = p[0], j = p[1];
    if (!(mask[i] & groupbit) || !(mask[j] & groupbit)) continue;
    if (!newton && j >= nlocal && tag[i] > tag[j]) continue;
    double d[3] = {atom->x[j][0] - atom->x[i][0], atom->x[j][1] - atom->x[i][1],
                   atom->x[j][2] - atom->x[i][2]};
    const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (r == 0.0) continue;
    const double s = (mol[i] < mol[j] ? 1.0 : -1.0) / r;
    mine.insert(mine.end(), {double(std::min(mol[i], mol[j])), double(std::max(mol[i], mol[j])),
                             s * d[0], s * d[1], s * d[2]});
  }
  const std::vector<double> all = PERIDEM_NS::gather_all(lmp, mine);
  std::vector<peridem::GrainContact> contacts(all.size() / 5);
  for (size_t k = 0; k < contacts.size(); k++) {
    const double *c = all.data() + 5 * k;
    contacts[k].a = (long long)c[0];
    contacts[k].b = (long long)c[1];
    for (int m = 0; m < 3; m++) contacts[k].n[m] = c[2 + m];
    contacts[k].nodes = 1;
  }
  const std::vector<peridem::GrainContact> merged = peridem::merge_grain_contacts(contacts);

  // grains with nodes in the group
  std::set<tagint> grains_here;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) grains_here.insert(mol[i]);
  const std::vector<double> ids =
      PERIDEM_NS::gather_all(lmp, std::vector<double>(grains_here.begin(), grains_here.end()));
  const long long ngrains = (long long)std::set<double>(ids.begin(), ids.end()).size();

  stats[NCONTACT] = double(merged.size());
  stats[NGRAIN] = double(ngrains);
  stats[NNODE] = double(contacts.size());
  stats[Z] = peridem::coordination_number((long long)merged.size(), ngrains);
  const std::array<double, 6> f = peridem::fabric_tensor(merged);
  for (int k = 0; k < 6; k++) stats[FABRIC + k] = f[k];
}

double ComputePeridemContacts::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  if (invoked_vector != invoked_scalar) compute_vector();
  scalar = stats[Z];
  return scalar;
}
