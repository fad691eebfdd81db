/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: fix peridem/bonds, the bookkeeping of broken bonds.
------------------------------------------------------------------------- */

#include "fix_peridem_bonds.h"
#include "lmp_peridem_compat.h"
#include "lmp_peridem_damage_column.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "lmp_peridem_grains.h"
#include "lmp_peridem_own_fix.h"
#include "lmp_peridem_topology.h"
#include "memory.h"
#include "modify.h"
#include "pair.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
enum { COUNTS, PARTNERS };
}

/* ---------------------------------------------------------------------- */

FixPeridemBonds::FixPeridemBonds(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg), nbroken(nullptr), zbroken(nullptr), broken_here(0), comm_mode(0)
{
  PERIDEM_NS::check_own_fix(lmp, narg, this, ID, "bond_style peridem");
  restart_peratom = 1;
  comm_reverse = 2;
  // LAMMPS 29Sep2021 lists the fixes that may force a rebuild in
  // Neighbor::init(), at the start of each run: declare it now, not at the
  // first break, or the first run that breaks bonds never rebuilds early.
  // next_reneighbor names a step only after a break (collect()).
  force_reneighbor = 1;
  next_reneighbor = -1;
  maxexchange = 2;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nmax; i++) nbroken[i] = zbroken[i] = 0.0;
  adopt_data_file_damage();
}

FixPeridemBonds::~FixPeridemBonds()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(nbroken);
  memory->destroy(zbroken);
}

int FixPeridemBonds::setmask()
{
  return POST_NEIGHBOR | MIN_POST_NEIGHBOR | PRE_FORCE | POST_FORCE | MIN_PRE_FORCE |
         MIN_POST_FORCE;
}

void FixPeridemBonds::init()
{
  broken_here = 0;
  // write_data (which calls init first) writes the damage section only
  // when there is damage, so undamaged data files stay plain LAMMPS files
  int any = 0, any_all = 0;
  for (int i = 0; i < atom->nlocal && !any; i++) any = nbroken[i] > 0.0;
  MPI_Allreduce(&any, &any_all, 1, MPI_INT, MPI_MAX, world);
  wd_section = any_all;
  wd_columns.clear();
  for (int i = 0; i < modify->nfix; i++) {
    auto *column = dynamic_cast<PERIDEM_NS::DamageSectionColumn *>(modify->fix[i]);
    if (column && column->column_written()) wd_columns.push_back(column);
  }
  // pair_style peridem/contact takes the nodes of a broken bond into its pair list at once
  // (it holds each pair once with newton_pair on; with newton_bond on, or on one rank, one
  // rank sees each break): no rebuild of the neighbour lists per break. Otherwise LAMMPS
  // rebuilds them at the next step (collect()).
  broken_pair_sink = nullptr;
  Pair *contact = force->pair ? force->pair_match("^peridem/contact", 0) : nullptr;
  if (contact && force->newton_pair && (force->newton_bond || comm->nprocs == 1)) {
    int dim = 0;
    broken_pair_sink =
        static_cast<std::function<void(int, int)> *>(contact->extract("peridem_broken_pair", dim));
  }
}

/* ----------------------------------------------------------------------
   ghost entries collect the breaks of bonds whose partner is owned
   elsewhere: clear them before the forces, send them home after
------------------------------------------------------------------------- */

void FixPeridemBonds::clear_ghosts()
{
  const int nall = atom->nlocal + atom->nghost;
  for (int i = atom->nlocal; i < nall; i++) nbroken[i] = zbroken[i] = 0.0;
}

void FixPeridemBonds::collect()
{
  bigint all = 0;
  MPI_Allreduce(&broken_here, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  broken_here = 0;
  if (all == 0) return; // nothing to send home: ghost entries are still zero
  comm_mode = COUNTS;
  PERIDEM_NS::reverse_comm(comm, this);
  clear_ghosts();
  // every broken bond was counted once (see bond_broken): keep the global
  // bond count of write_data and thermo right
  atom->nbonds -= all;

  // the special lists of both nodes forget each other, so the next
  // neighbour list holds the pair and contact acts between the pieces
  if (force->newton_bond) {
    comm_mode = PARTNERS;
    PERIDEM_NS::reverse_comm_variable(comm, this);
  }
  const int nlocal = atom->nlocal;
  for (const auto &[i, partners] : lost_partners)
    if (i < nlocal)
      for (tagint p : partners) forget_partner(i, p);
  lost_partners.clear();
  // with a pair style that cannot take the pairs (init()), rebuild the neighbour lists at
  // the next step (Neighbor::decide() compares next_reneighbor with the step)
  if (force->pair && !broken_pair_sink) next_reneighbor = update->ntimestep + 1;
}

/* ----------------------------------------------------------------------
   remove a partner from the 1-2 part of atom i's special list
------------------------------------------------------------------------- */

void FixPeridemBonds::forget_partner(int i, tagint partner)
{
  int *nspecial = atom->nspecial[i];
  tagint *special = atom->special[i];
  for (int k = 0; k < nspecial[0]; k++) {
    if (special[k] != partner) continue;
    for (int m = k; m < nspecial[2] - 1; m++) special[m] = special[m + 1];
    nspecial[0]--;
    nspecial[1]--;
    nspecial[2]--;
    return;
  }
}

void FixPeridemBonds::setup_pre_force(int)
{
  clear_ghosts();
}
void FixPeridemBonds::pre_force(int)
{
  clear_ghosts();
}
void FixPeridemBonds::min_pre_force(int)
{
  clear_ghosts();
}
void FixPeridemBonds::setup(int)
{
  stamp++;
  collect();
}
void FixPeridemBonds::min_setup(int)
{
  stamp++;
  clear_ghosts();
  collect();
}
void FixPeridemBonds::post_force(int)
{
  collect();
}
void FixPeridemBonds::min_post_force(int)
{
  collect();
}

/* ---------------------------------------------------------------------- */

void FixPeridemBonds::remove_bond(Atom *atom, int i, tagint partner)
{
  int &n = atom->num_bond[i];
  for (int m = 0; m < n; m++) {
    if (atom->bond_atom[i][m] != partner) continue;
    atom->bond_atom[i][m] = atom->bond_atom[i][n - 1];
    atom->bond_type[i][m] = atom->bond_type[i][n - 1];
    n--;
    return;
  }
}

void FixPeridemBonds::bond_broken(int i1, int i2, double z)
{
  stamp++;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;
  // i1 stores the bond and is local. With newton_bond on, the partner's
  // share goes to its ghost entry and home by reverse communication; with
  // newton_bond off, the partner's own rank breaks its copy and credits it.
  nbroken[i1] += 1.0;
  zbroken[i1] = std::max(zbroken[i1], z);
  remove_bond(atom, i1, tag[i2]);
  forget_partner(i1, tag[i2]);
  if (newton_bond || i2 < nlocal) {
    nbroken[i2] += 1.0;
    zbroken[i2] = std::max(zbroken[i2], z);
  }
  if (i2 < nlocal) {
    remove_bond(atom, i2, tag[i1]);
    forget_partner(i2, tag[i1]);
  } else if (newton_bond) {
    lost_partners[i2].push_back(tag[i1]);
  }
  // count each bond once: with newton_bond off and the partner on another
  // rank, both ranks see it; the one holding the smaller ID counts it
  if (newton_bond || i2 < nlocal || tag[i1] < tag[i2]) broken_here++;
  if (broken_pair_sink) (*broken_pair_sink)(i1, i2);
}

/* ---------------------------------------------------------------------- */

int FixPeridemBonds::pack_reverse_comm_size(int n, int first)
{
  int size = 0;
  for (int i = first; i < first + n; i++) {
    const auto found = lost_partners.find(i);
    size += 1 + (found == lost_partners.end() ? 0 : int(found->second.size()));
  }
  return size;
}

int FixPeridemBonds::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    if (comm_mode == COUNTS) {
      buf[m++] = nbroken[i];
      buf[m++] = zbroken[i];
      continue;
    }
    const auto found = lost_partners.find(i);
    if (found == lost_partners.end()) {
      buf[m++] = 0.0;
      continue;
    }
    buf[m++] = double(found->second.size());
    for (tagint p : found->second) buf[m++] = ubuf(p).d;
    lost_partners.erase(found);
  }
  return m;
}

void FixPeridemBonds::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    if (comm_mode == COUNTS) {
      nbroken[j] += buf[m++];
      zbroken[j] = std::max(zbroken[j], buf[m++]);
      continue;
    }
    const int count = static_cast<int>(buf[m++]);
    for (int c = 0; c < count; c++) lost_partners[j].push_back((tagint)ubuf(buf[m++]).i);
  }
}

/* ---------------------------------------------------------------------- */

void FixPeridemBonds::grow_arrays(int nmax)
{
  memory->grow(nbroken, nmax, "peridem/bonds:nbroken");
  memory->grow(zbroken, nmax, "peridem/bonds:zbroken");
}

void FixPeridemBonds::set_arrays(int i)
{
  nbroken[i] = zbroken[i] = 0.0;
}

void FixPeridemBonds::copy_arrays(int i, int j, int)
{
  nbroken[j] = nbroken[i];
  zbroken[j] = zbroken[i];
}

int FixPeridemBonds::pack_exchange(int i, double *buf)
{
  buf[0] = nbroken[i];
  buf[1] = zbroken[i];
  return 2;
}

int FixPeridemBonds::unpack_exchange(int nlocal, double *buf)
{
  nbroken[nlocal] = buf[0];
  zbroken[nlocal] = buf[1];
  return 2;
}

int FixPeridemBonds::pack_restart(int i, double *buf)
{
  buf[0] = 3;
  buf[1] = nbroken[i];
  buf[2] = zbroken[i];
  return 3;
}

void FixPeridemBonds::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  nbroken[nlocal] = extra[nlocal][m + 1];
  zbroken[nlocal] = extra[nlocal][m + 2];
  // the older layout (4 values): see take_old_restart_m()
  if (static_cast<int>(extra[nlocal][m]) == 4) {
    if (static_cast<int>(old_restart_m.size()) < atom->nlocal)
      old_restart_m.resize(atom->nlocal, -1.0);
    old_restart_m[nlocal] = extra[nlocal][m + 3];
  }
  // a damaged file stops here, not in compute peridem/damage
  const double nb = nbroken[nlocal], z = zbroken[nlocal];
  if (!(nb >= 0.0 && nb <= 1e9 && nb == std::floor(nb)) || !(z >= 0.0 && std::isfinite(z)))
    error->one(FLERR,
               "fix {}: invalid damage state of atom {} in restart file (broken bonds {}, Z {}; "
               "damaged file?)",
               ID, atom->tag[nlocal], nb, z);
}

std::vector<double> FixPeridemBonds::take_old_restart_m()
{
  return std::exchange(old_restart_m, {});
}

int FixPeridemBonds::size_restart(int)
{
  return 3;
}

int FixPeridemBonds::maxsize_restart()
{
  return 3;
}

double FixPeridemBonds::memory_usage()
{
  return 2.0 * atom->nmax * sizeof(double);
}

/* ----------------------------------------------------------------------
   data files: the broken bonds are gone from the Bonds section,
   so write_data adds a section "PeridemDamage" with one line per node:
   ID, number of broken bonds, Z of the broken bonds, the columns other
   fixes add (fix peridem/lps: m). read_data reads it into a fix
   property/atom d_peridem_nbroken d_peridem_zbroken (and the columns'
   vectors), which this fix (and the columns' fixes) adopt when the bond
   style creates them.
------------------------------------------------------------------------- */

void FixPeridemBonds::adopt_data_file_damage()
{
  int flag = 0, cols = 0;
  const int inb = atom->find_custom("peridem_nbroken", flag, cols);
  if (inb < 0) {
    refuse_misnamed_damage();
    return;
  }
  if (flag != 1 || cols != 0)
    error->all(FLERR, "fix {}: per-atom property peridem_nbroken must be a d_ vector", ID);
  const int iz = atom->find_custom("peridem_zbroken", flag, cols);
  if (iz < 0 || flag != 1 || cols != 0)
    error->all(FLERR,
               "fix {}: per-atom property peridem_nbroken needs peridem_zbroken (define both: fix "
               "ID all property/atom d_peridem_nbroken d_peridem_zbroken)",
               ID);
  const double *nb = atom->dvector[inb], *zb = atom->dvector[iz];
  bigint here = 0, all = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(nb[i] >= 0.0 && nb[i] <= 1e9) || nb[i] != std::floor(nb[i]) || !(zb[i] >= 0.0) ||
        !std::isfinite(zb[i]))
      error->one(FLERR,
                 "fix {}: invalid damage of atom {} in the data file: broken count {} and Z {} "
                 "(need a whole number >= 0 and Z >= 0)",
                 ID, atom->tag[i], nb[i], zb[i]);
    nbroken[i] = nb[i];
    zbroken[i] = zb[i];
    here += static_cast<bigint>(nb[i]);
  }
  check_damage_per_grain(nb);
  MPI_Allreduce(&here, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "fix {}: {} broken bond ends (per-node counts) taken from property/atom "
                   "peridem_nbroken, peridem_zbroken\n",
                   ID, all);
}

/* ----------------------------------------------------------------------
   per-atom vectors named like PERIDEM's damage but not as it reads them
   (d_nbroken instead of d_peridem_nbroken): the section went into them and
   the damage would be 0 without a word
------------------------------------------------------------------------- */

void FixPeridemBonds::refuse_misnamed_damage()
{
  for (int k = 0; k < atom->ndvector; k++) {
    const std::string name = atom->dvname[k] ? atom->dvname[k] : "";
    if (name.find("broken") == std::string::npos) continue;
    if (comm->me == 0)
      error->warning(FLERR,
                     "fix {}: per-atom property {} looks like the damage of a {} section but is "
                     "not read, so the nodes start undamaged: name the vectors d_peridem_nbroken "
                     "d_peridem_zbroken",
                     ID, name, DATA_SECTION);
  }
}

/* ----------------------------------------------------------------------
   a broken bond is counted at both of its nodes, which lie in one grain:
   no node can have lost more bonds than its grain has other nodes, and
   the counts of a grain sum to an even number unless nodes with bonds to
   it were deleted (lost delete) or bonds joined grains (cohesive). A line
   of the section given twice, or one missing, shows as an odd sum.
------------------------------------------------------------------------- */

void FixPeridemBonds::check_damage_per_grain(const double *nb)
{
  const int nlocal = atom->nlocal;
  const tagint *molecule = atom->molecule;
  // per grain: nodes, broken bond ends
  const tagint maxmol = PERIDEM_NS::max_grain_id(lmp);
  const std::vector<double> grains =
      PERIDEM_NS::grain_reduce(lmp, groupbit, maxmol, 2, [&](int i, double *row) {
        row[0] += 1.0;
        row[1] += nb[i];
      });
  for (int i = 0; i < nlocal; i++) {
    const double others = grains[2 * molecule[i]] - 1.0;
    if (nb[i] > others)
      error->one(FLERR,
                 "fix {}: atom {} has {} broken bonds in the data file, more than the {} other "
                 "nodes of its grain {}",
                 ID, atom->tag[i], nb[i], others, molecule[i]);
  }
  bigint odd = 0;
  tagint first = 0;
  for (tagint g = 1; g <= maxmol; g++)
    if (std::fmod(grains[2 * g + 1], 2.0) != 0.0 && odd++ == 0) first = g;
  if (odd > 0 && comm->me == 0)
    error->warning(FLERR,
                   "fix {}: the broken bond counts of {} grains (first: grain {}) in the data "
                   "file sum to an odd number, but each broken bond counts at both its nodes: a "
                   "line of the {} section is missing or given twice, unless nodes with bonds "
                   "were deleted (lost delete) or bonds joined grains",
                   ID, odd, first, DATA_SECTION);
}

void FixPeridemBonds::write_data_section_size(int, int &nx, int &ny)
{
  nx = atom->nlocal;
  ny = 3 + static_cast<int>(wd_columns.size());
}

void FixPeridemBonds::write_data_section_pack(int, double **buf)
{
  for (int i = 0; i < atom->nlocal; i++) {
    buf[i][0] = ubuf(atom->tag[i]).d;
    buf[i][1] = nbroken[i];
    buf[i][2] = zbroken[i];
    for (std::size_t c = 0; c < wd_columns.size(); c++)
      buf[i][3 + c] = wd_columns[c]->column_value(i);
  }
}

void FixPeridemBonds::write_data_section_keyword(int, FILE *fp)
{
  // the column hint names the property/atom vectors that read it back
  std::string props = "d_peridem_nbroken d_peridem_zbroken", what;
  for (const auto *column : wd_columns) {
    props += std::string(" d_") + column->column_property();
    what += std::string(", ") + column->column_description();
  }
  fmt::print(fp, "\n{} # {}\n\n", DATA_SECTION, props);
  utils::logmesg(lmp,
                 "fix {}: the data file has a {} section (broken bonds per node{}); read it "
                 "back with\n  fix damage all property/atom {}\n"
                 "  read_data FILE fix damage NULL {}\n",
                 ID, DATA_SECTION, what, props, DATA_SECTION);
}

void FixPeridemBonds::write_data_section(int, FILE *fp, int n, double **buf, int)
{
  const int ncol = 3 + static_cast<int>(wd_columns.size());
  for (int i = 0; i < n; i++) {
    fmt::print(fp, "{} {} {:.17g}", (tagint)ubuf(buf[i][0]).i, buf[i][1], buf[i][2]);
    for (int c = 3; c < ncol; c++) fmt::print(fp, " {:.17g}", buf[i][c]);
    fmt::print(fp, "\n");
  }
}
