/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: the shared machinery of the peridynamic bond styles
   (bond_peridem_base.h): keywords, the bond list by pieces, the break path,
   the ghost cutoff, validation, restart of the shared settings and the
   bonds' time-step bound.
------------------------------------------------------------------------- */

#include "bond_peridem_base.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_peridem_bonds.h"
#include "fix_peridem_escapes.h"
#include "fix_peridem_order.h"
#include "lmp_peridem_own_fix.h"
#include "force.h"
#include "lattice.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include "lmp_peridem_image.h"
#include "lmp_peridem_material.h"
#include "lmp_peridem_parse.h"
#include "lmp_peridem_restart.h"
#include "peridem_contact_law.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;

namespace {
// the shared keywords keep bond_style peridem's name in their messages, for every model
const char *const STYLE = "bond_style peridem";
const char *const COEFF = "bond_coeff";
} // namespace

/* ---------------------------------------------------------------------- */

BondPeridemBase::BondPeridemBase(LAMMPS *lmp)
    : Bond(lmp), s0(nullptr), horizon(nullptr), spacing(nullptr), breakable(nullptr),
      s0_break(nullptr), breakage(peridem::BreakageMode::Tension), break_flag(1),
      break_after_force(0), volume_correction(0), cohesive(0), validate_next(1), bonds_fix(nullptr),
      cache_ncalls(-1), cache_generation(-1), cache_bondlist(nullptr), cache_nbondlist(-1)
{
  writedata = 1;
}

BondPeridemBase::~BondPeridemBase()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(s0);
    memory->destroy(horizon);
    memory->destroy(spacing);
    memory->destroy(breakable);
    memory->destroy(s0_break);
  }
}

void BondPeridemBase::allocate()
{
  allocated = 1;
  const int np1 = atom->nbondtypes + 1;
  memory->create(setflag, np1, "bond:setflag");
  memory->create(s0, np1, "bond:s0");
  memory->create(horizon, np1, "bond:horizon");
  memory->create(spacing, np1, "bond:spacing");
  memory->create(breakable, np1, "bond:breakable");
  memory->create(s0_break, np1, "bond:s0_break");
  for (int i = 0; i < np1; i++) {
    setflag[i] = 0;
    s0[i] = horizon[i] = spacing[i] = s0_break[i] = 0.0;
    breakable[i] = 1;
  }
  allocate_model(np1);
}

void BondPeridemBase::set_shared_type(int type, double s0type, double horizon_type,
                                      double spacing_type, int breakable_type)
{
  s0[type] = s0type;
  horizon[type] = horizon_type;
  spacing[type] = spacing_type;
  breakable[type] = breakable_type;
  setflag[type] = 1;
}

/* ----------------------------------------------------------------------
   reference bond length |x0_i - x0_j|; x0 of a ghost atom is its owner's,
   not shifted by the periodic image, hence the minimum image convention
------------------------------------------------------------------------- */

// x0 flat from x0[0] (LAMMPS's per-atom arrays are contiguous, memory->grow), so that
// fill_reference_lengths() reads it without a row pointer per atom
static inline double reference_length_flat(Domain *domain, const double *x0, int i1, int i2)
{
  const double *a = x0 + 3 * i1, *b = x0 + 3 * i2;
  double dx = a[0] - b[0];
  double dy = a[1] - b[1];
  double dz = a[2] - b[2];
  PERIDEM_NS::minimum_image(domain, dx, dy, dz);
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

double BondPeridemBase::reference_length(int i1, int i2) const
{
  return reference_length_flat(domain, atom->x0[0], i1, i2);
}

void BondPeridemBase::fill_reference_lengths(std::vector<double> &r0,
                                             std::vector<double> *inv_r0) const
{
  const int nbondlist = neighbor->nbondlist;
  // resize, not assign: every intact entry is written below, and clearing the arrays at each
  // rebuild was a quarter of the cache refill's time; the entries of broken bonds (type <= 0)
  // keep old finite values that the chunked loop computes with and discards
  r0.resize(nbondlist, 0.0);
  if (inv_r0) inv_r0->resize(nbondlist, 0.0);
  if (nbondlist == 0) return; // the bond list and x0 may not exist yet on this rank
  const int *bl = neighbor->bondlist[0];
  const double *x0 = atom->x0[0];
  double *r0c = r0.data(), *inv = inv_r0 ? inv_r0->data() : nullptr;
  for (int n = 0; n < nbondlist; n++) {
    const int *b = bl + 3 * n;
    if (b[2] <= 0) continue;
    const double r = reference_length_flat(domain, x0, b[0], b[1]);
    r0c[n] = r;
    if (inv) inv[n] = 1.0 / r;
  }
}

/* ----------------------------------------------------------------------
   the caches belong to one bond list: refilled when LAMMPS has rebuilt it
------------------------------------------------------------------------- */

void BondPeridemBase::begin_compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (validate_next) validate_bonds();
  if (bond_list_is_new()) {
    remember_bond_list();
    fill_cache();
    fill_pieces();
  }
}

// LAMMPS rebuilt the bond list since the caches were filled: fix peridem/bonds counts the
// rebuilds (neighbor->ncalls alone returns to 0 at every setup, and rerun sets up every
// snapshot without a new init)
bool BondPeridemBase::bond_list_is_new() const
{
  return bonds_fix->bond_list_generation() != cache_generation ||
         neighbor->ncalls != cache_ncalls || neighbor->nbondlist != cache_nbondlist ||
         neighbor->bondlist != cache_bondlist;
}

void BondPeridemBase::remember_bond_list()
{
  cache_generation = bonds_fix->bond_list_generation();
  cache_ncalls = neighbor->ncalls;
  cache_bondlist = neighbor->bondlist;
  cache_nbondlist = neighbor->nbondlist;
}

// the bond list as the piece loops read it (BondPieces): i2 per entry, i1 per piece of
// consecutive entries with one i1, the pieces grouped into chunks of at most CHUNK entries,
// and one type for the whole list when the intact entries share it
void BondPeridemBase::fill_pieces()
{
  BondPieces &bp = bond_pieces;
  const int nbondlist = neighbor->nbondlist;
  bp.partner.resize(nbondlist);
  bp.piece_atom.clear();
  bp.piece_start.clear();
  bp.chunk_piece.clear();
  bp.type.clear();
  bp.type_all = 1; // any valid type when no entry is intact: no intact entry reads it
  if (nbondlist == 0) {
    bp.piece_start.push_back(0);
    bp.chunk_piece.push_back(0);
    return;
  }
  const int *bl = neighbor->bondlist[0];
  int *partner = bp.partner.data();
  int first_type = 0;
  bool mixed = false;
  for (int n = 0; n < nbondlist; n++) {
    const int *b = bl + 3 * n;
    const int i1 = b[0];
    partner[n] = b[2] > 0 ? b[1] : i1;
    if (b[2] > 0) {
      if (first_type == 0) first_type = b[2];
      mixed = mixed || b[2] != first_type;
    }
    if (bp.piece_atom.empty() || bp.piece_atom.back() != i1 || n - bp.piece_start.back() == CHUNK) {
      bp.piece_atom.push_back(i1);
      bp.piece_start.push_back(n);
    }
  }
  const int npieces = int(bp.piece_atom.size());
  bp.piece_start.push_back(nbondlist);
  const int *start = bp.piece_start.data();
  for (int p = 0; p < npieces; p++)
    if (bp.chunk_piece.empty() || start[p + 1] - start[bp.chunk_piece.back()] > CHUNK)
      bp.chunk_piece.push_back(p);
  bp.chunk_piece.push_back(npieces);
  if (mixed) {
    bp.type_all = 0;
    bp.type.resize(nbondlist);
    for (int n = 0; n < nbondlist; n++) bp.type[n] = bl[3 * n + 2];
  } else if (first_type > 0)
    bp.type_all = first_type;
}

double BondPeridemBase::pieces_memory() const
{
  const BondPieces &bp = bond_pieces;
  return double(bp.partner.capacity() + bp.piece_atom.capacity() + bp.piece_start.capacity() +
                bp.chunk_piece.capacity() + bp.type.capacity()) *
         sizeof(int);
}

/* ----------------------------------------------------------------------
   bond n broke: type 0 in this step's bond list, and out of the bond
   arrays (fix peridem/bonds keeps count), so that its nodes may separate
   without LAMMPS missing a bond partner. Another rank that holds the bond
   (newton_bond off, partner owned there) computes the same stretch from
   the same positions and breaks it too.
------------------------------------------------------------------------- */

void BondPeridemBase::break_bond(int n, int i1, int i2, double r0, int type)
{
  neighbor->bondlist[n][2] = 0;
  // partner i1 marks the entry broken for the piece loops (after a fill, partner has one
  // entry per entry of the bond list)
  if (std::size_t(n) < bond_pieces.partner.size()) bond_pieces.partner[n] = i1;
  double **x = atom->x;
  double dy[3];
  for (int d = 0; d < 3; d++) dy[d] = x[i2][d] - x[i1][d];
  domain->minimum_image(dy[0], dy[1], dy[2]);
  // the damage Z a broken bond leaves at its nodes: the stretch that broke it over s0 (>= 1;
  // compute peridem/damage explains the choice)
  const double z = peridem::z_stretch_term(
      peridem::stretch(std::sqrt(dy[0] * dy[0] + dy[1] * dy[1] + dy[2] * dy[2]), r0), s0[type]);
  bonds_fix->bond_broken(i1, i2, z);
}

/* ----------------------------------------------------------------------
   once per run: bonds must join nodes of one grain and be no longer than
   the horizon of their type
------------------------------------------------------------------------- */

void BondPeridemBase::validate_bonds()
{
  validate_next = 0;
  int **bondlist = neighbor->bondlist;
  const tagint *tag = atom->tag;
  const tagint *molecule = atom->molecule;
  for (int n = 0; n < neighbor->nbondlist; n++) {
    const int type = bondlist[n][2];
    if (type <= 0) continue;
    const int i1 = bondlist[n][0];
    const int i2 = bondlist[n][1];
    if (!cohesive && molecule[i1] != molecule[i2])
      error->one(FLERR,
                 "{}: bond between atoms {} and {} joins grains {} and {}; peridynamic bonds "
                 "join nodes of one grain (use bond_style peridem cohesive yes to allow this)",
                 STYLE, tag[i1], tag[i2], molecule[i1], molecule[i2]);
    const double r0 = reference_length(i1, i2);
    if (!(r0 <= horizon[type] * (1.0 + 1e-10))) // NaN too
      error->one(FLERR,
                 "{}: bond between atoms {} and {} (type {}) has reference length {} longer "
                 "than the horizon {}",
                 STYLE, tag[i1], tag[i2], type, r0, horizon[type]);
    if (r0 <= 0.0)
      error->one(FLERR, "{}: atoms {} and {} are bonded but have the same reference position",
                 STYLE, tag[i1], tag[i2]);
  }
  report_time_step();
}

/* ----------------------------------------------------------------------
   bond_style peridem [break tension|absolute|off] [break_order before_force|after_force]
                      [volume_correction none|linear] [cohesive no|yes]
   and the model's own keywords (settings_keyword)
------------------------------------------------------------------------- */

bool BondPeridemBase::settings_keyword(int, int, char **)
{
  return false;
}

void BondPeridemBase::settings(int narg, char **arg)
{
  for (int iarg = 0; iarg < narg; iarg += 2) {
    if (settings_keyword(iarg, narg, arg)) continue;
    const std::string key = arg[iarg];
    if (iarg + 1 >= narg) error->all(FLERR, "{}: keyword {} needs a value", STYLE, key);
    const std::string value = arg[iarg + 1];
    if (key == "break") {
      const int mode = PERIDEM_NS::choice(lmp, STYLE, key, value, {"tension", "absolute", "off"});
      break_flag = mode != 2;
      if (mode == 1)
        breakage = peridem::BreakageMode::Absolute;
      else
        breakage = peridem::BreakageMode::Tension;
    } else if (key == "break_order") {
      break_after_force =
          PERIDEM_NS::choice(lmp, STYLE, key, value, {"before_force", "after_force"});
    } else if (key == "volume_correction") {
      volume_correction = PERIDEM_NS::choice(lmp, STYLE, key, value, {"none", "linear"});
    } else if (key == "cohesive") {
      cohesive = PERIDEM_NS::yes_no(lmp, STYLE, key, value);
    } else
      error->all(FLERR, "{}: unknown keyword {}", STYLE, key);
  }
}

/* ----------------------------------------------------------------------
   the keywords of bond_coeff that every model takes:
     material FILE NAME, horizon eps, Gc value, s0 value, spacing h, break yes|no
   the others go to the model (coeff_keyword)
------------------------------------------------------------------------- */

double BondPeridemBase::coeff_positive(const char *what, const char *value, const char *style)
{
  const double v = PERIDEM_NS::number(lmp, COEFF, what, value);
  if (!(v > 0.0)) error->all(FLERR, "{}: {} must be > 0 for {}, not {}", COEFF, what, style, value);
  return v;
}

BondPeridemBase::CoeffArgs BondPeridemBase::parse_coeff(int narg, char **arg, const char *style)
{
  if (narg < 2) error->all(FLERR, "{}: {} needs a bond type and its parameters", COEFF, style);
  if (!allocated) allocate();
  CoeffArgs a;
  utils::bounds(FLERR, arg[0], 1, atom->nbondtypes, a.ilo, a.ihi, error);

  for (int iarg = 1; iarg < narg;) {
    const std::string key = arg[iarg];
    if (key == "material") {
      if (iarg + 2 >= narg)
        error->all(FLERR, "{}: material needs a file name and a material name", COEFF);
      a.material = PERIDEM_NS::load_material(lmp, COEFF, arg[iarg + 1], arg[iarg + 2]);
      a.haveMaterial = true;
      a.origin = fmt::format("material {} of {}", arg[iarg + 2], arg[iarg + 1]);
      iarg += 3;
      continue;
    }
    if (iarg + 1 >= narg) error->all(FLERR, "{}: keyword {} needs a value", COEFF, key);
    const char *value = arg[iarg + 1];
    if (key == "break") {
      a.breakable = PERIDEM_NS::yes_no(lmp, COEFF, key, value);
    } else if (key == "Gc") {
      a.Gc = coeff_positive("Gc (fracture energy)", value, style);
      a.haveGc = true;
    } else if (key == "s0") {
      a.s0 = coeff_positive("s0 (critical stretch)", value, style);
      a.haveS0 = true;
    } else if (key == "horizon") {
      a.eps = coeff_positive("horizon", value, style);
    } else if (key == "spacing") {
      a.h = coeff_positive("spacing", value, style);
    } else if (!coeff_keyword(key, value, style))
      error->all(FLERR, "{}: unknown keyword {} for {}", COEFF, key, style);
    iarg += 2;
  }
  return a;
}

/* ---------------------------------------------------------------------- */

void BondPeridemBase::init_style()
{
  if (!atom->vfrac_flag || !atom->x0_flag || !atom->molecule_flag || !atom->rmass_flag)
    error->all(FLERR,
               "{} requires atom style peridem (per-atom volume, reference position x0 and "
               "grain ID)",
               STYLE);

  for (int i = 1; i <= atom->nbondtypes; i++)
    s0_break[i] = breakable[i] ? s0[i] : std::numeric_limits<double>::infinity();
  for (int i = 1; i <= atom->nbondtypes; i++) {
    if (!setflag[i]) continue;
    if (volume_correction && spacing[i] <= 0.0) {
      if (domain->lattice && domain->lattice->style != Lattice::NONE)
        spacing[i] = domain->lattice->xlattice;
      else
        error->all(FLERR,
                   "{}: volume_correction linear needs the node spacing of bond type {}: add "
                   "spacing to its bond_coeff (or define a lattice)",
                   STYLE, i);
    }
  }

  // Ghost atoms must hold every bond partner when LAMMPS rebuilds its bond
  // list, whatever the pair cutoff. An intact bond (reference length <=
  // horizon) is stretched at most s0 plus one step's increment when bonds
  // break; without breakage it may stretch without bound and 50 % is assumed,
  // LAMMPS's own estimate (Comm::get_comm_cutoff). A tighter cutoff means
  // fewer ghosts: on 2 ranks of the in.peri.pmb impact 1.05 h instead of
  // 1.5 h (+ skin) saves a fifth of the ghost atoms.
  double max_s0 = 0.0;
  for (int i = 1; i <= atom->nbondtypes; i++)
    if (setflag[i]) max_s0 = std::max(max_s0, breakable[i] ? s0[i] : 1.0);
  stretch_allowance = break_flag ? std::min(0.5, max_s0 + 0.05) : 0.5;
  // computed as Comm::get_comm_cutoff computes its estimate from
  // equilibrium_distance(), so that the two agree to the last bit
  double longest = 0.0;
  for (int i = 1; i <= atom->nbondtypes; i++)
    if (setflag[i]) longest = std::max(longest, equilibrium_distance(i));
  const double needed = longest * 1.5 + neighbor->skin;
  if (comm->cutghostuser < needed) {
    comm->cutghostuser = needed;
    if (comm->me == 0)
      utils::logmesg(lmp,
                     "{}: communication cutoff set to {:.8g} (largest horizon x {:.4g} + skin)\n",
                     STYLE, needed, 1.0 + stretch_allowance);
  }
  // the bookkeeping of broken bonds, nodes that leave the box through a fixed boundary, the
  // order of the nodes in memory: one fix each, created once
  bonds_fix = PERIDEM_NS::own_fix<FixPeridemBonds>(lmp, "peridem/bonds", STYLE);
  PERIDEM_NS::own_fix<FixPeridemEscapes>(lmp, "peridem/escapes", STYLE);
  FixPeridemOrder *order = PERIDEM_NS::own_fix<FixPeridemOrder>(lmp, "peridem/order", STYLE);

  // Nodes in memory grain by grain, in the order of creation (peridem_atom_order.h says why),
  // at the frequency of LAMMPS's sort
  // (atom_modify sort N, 1000 by default), instead of LAMMPS's spatial sort, which a bin
  // size larger than any box turns into a no-op (Atom::sort() returns with one bin).
  // atom_modify sort 0 0 leaves the atoms as they are; a bin size given by the user
  // (atom_modify sort N binsize) keeps LAMMPS's spatial sort as asked.
  const bool user_bins = atom->userbinsize > 0.0 && atom->userbinsize != NO_SPATIAL_SORT;
  const bool grain_order = !user_bins && atom->sortfreq > 0;
  if (grain_order && atom->userbinsize != NO_SPATIAL_SORT) {
    atom->userbinsize = NO_SPATIAL_SORT;
    if (comm->me == 0)
      utils::logmesg(lmp,
                     "{}: nodes kept in memory grain by grain every {} steps, instead of "
                     "LAMMPS's spatial sort (atom_modify sort N binsize: that sort instead)\n",
                     STYLE, atom->sortfreq);
  }
  order->set_active(grain_order);
  validate_next = 1;
  cache_ncalls = cache_generation = -1;
}

/* ---------------------------------------------------------------------- */

// LAMMPS uses this only to estimate the communication cutoff (1.5 x this +
// skin, Comm::get_comm_cutoff; it warns when the cutoff in use is shorter):
// return the reach of a bond of this type over 1.5, so that the estimate is
// the cutoff init_style() sets.
double BondPeridemBase::equilibrium_distance(int i)
{
  return horizon[i] * (1.0 + stretch_allowance) / 1.5;
}

/* ----------------------------------------------------------------------
   LAMMPS calls write/read_restart_settings() of a bond style only under
   bond_style hybrid: each model's write/read_restart() calls them, or the
   settings (volume_correction, break_order, ...) were lost in a restart
------------------------------------------------------------------------- */

void BondPeridemBase::write_restart_settings(FILE *fp)
{
  const int settings[5] = {break_flag, breakage == peridem::BreakageMode::Absolute,
                           volume_correction, cohesive, break_after_force};
  fwrite(settings, sizeof(int), 5, fp);
}

void BondPeridemBase::read_restart_settings(FILE *fp)
{
  int settings[5];
  if (comm->me == 0) utils::sfread(FLERR, settings, sizeof(int), 5, fp, nullptr, error);
  MPI_Bcast(settings, 5, MPI_INT, 0, world);
  PERIDEM_NS::check_restart_values(lmp, STYLE, "setting", settings, 5, 0, 1);
  break_flag = settings[0];
  breakage = settings[1] ? peridem::BreakageMode::Absolute : peridem::BreakageMode::Tension;
  volume_correction = settings[2];
  cohesive = settings[3];
  break_after_force = settings[4];
}

void BondPeridemBase::write_types(FILE *fp, const double *a) const
{
  fwrite(&a[1], sizeof(double), atom->nbondtypes, fp);
}

void BondPeridemBase::write_types(FILE *fp, const int *a) const
{
  fwrite(&a[1], sizeof(int), atom->nbondtypes, fp);
}

void BondPeridemBase::read_types(FILE *fp, double *a)
{
  const int n = atom->nbondtypes;
  if (comm->me == 0) utils::sfread(FLERR, &a[1], sizeof(double), n, fp, nullptr, error);
  MPI_Bcast(&a[1], n, MPI_DOUBLE, 0, world);
}

void BondPeridemBase::read_types(FILE *fp, int *a)
{
  const int n = atom->nbondtypes;
  if (comm->me == 0) utils::sfread(FLERR, &a[1], sizeof(int), n, fp, nullptr, error);
  MPI_Bcast(&a[1], n, MPI_INT, 0, world);
}

std::string BondPeridemBase::data_tail(int type) const
{
  std::string tail;
  if (spacing[type] > 0.0) tail += fmt::format(" spacing {:.17g}", spacing[type]);
  if (!breakable[type]) tail += " break no";
  return tail;
}

/* ---------------------------------------------------------------------- */

void *BondPeridemBase::extract(const char *str, int &dim)
{
  dim = 1;
  if (strcmp(str, "s0") == 0) return (void *)s0;
  if (strcmp(str, "horizon") == 0) return (void *)horizon;
  dim = 0;
  return nullptr;
}

double BondPeridemBase::memory_usage()
{
  return Bond::memory_usage() + pieces_memory();
}

/* ----------------------------------------------------------------------
   the bonds' part of the time-step bound (peridem_contact_law.h): for
   each node the tensor A_i = sum of k_b e e over its bonds, with the
   spring constants k_b of the model (stability_springs: c w V_i V_j/|xi|
   for bond_style peridem, the bound of lps_spring_constant() for
   peridem/lps), reference geometry, and per atom type the largest
   2 lambda_max(A_i)/m_i. Bonds stored on another rank are not seen here
   (newton_bond): a node at a rank boundary may miss some, the interior
   nodes that set the maximum do not.
------------------------------------------------------------------------- */

std::vector<double> BondPeridemBase::stability_omega2_of_types()
{
  const int nt = atom->ntypes;
  std::vector<double> mine(nt + 1, 0.0), all(nt + 1, 0.0);
  const int nlocal = atom->nlocal;
  if (neighbor->nbondlist > 0) {
    const int d = domain->dimension;
    std::vector<double> kb;
    stability_springs(kb);
    std::vector<double> A(6 * (size_t)nlocal, 0.0);
    double **x0 = atom->x0;
    for (int n = 0; n < neighbor->nbondlist; n++) {
      const int *b = neighbor->bondlist[n];
      const int i1 = b[0], i2 = b[1];
      if (b[2] <= 0 || !(kb[n] > 0.0)) continue;
      double e[3] = {x0[i2][0] - x0[i1][0], x0[i2][1] - x0[i1][1], x0[i2][2] - x0[i1][2]};
      PERIDEM_NS::minimum_image(domain, e[0], e[1], e[2]);
      const double r0 = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
      if (!(r0 > 0.0)) continue;
      for (double &ek : e) ek /= r0;
      const double outer[6] = {e[0] * e[0], e[1] * e[1], e[2] * e[2],
                               e[0] * e[1], e[0] * e[2], e[1] * e[2]};
      for (const int i : {i1, i2}) {
        if (i >= nlocal) continue;
        for (int m = 0; m < 6; m++) A[6 * (size_t)i + m] += kb[n] * outer[m];
      }
    }
    for (int i = 0; i < nlocal; i++) {
      const double *a = &A[6 * (size_t)i];
      // 2D: (xx, yy, xy); 3D: (xx, yy, zz, xy, xz, yz)
      const double a2[3] = {a[0], a[1], a[3]};
      const double lambda = peridem::symmetric_max_eigenvalue(d == 2 ? a2 : a, d);
      mine[atom->type[i]] = std::max(mine[atom->type[i]], 2.0 * lambda / atom->rmass[i]);
    }
  }
  MPI_Allreduce(mine.data(), all.data(), nt + 1, MPI_DOUBLE, MPI_MAX, world);
  return all;
}

/* ----------------------------------------------------------------------
   at the setup of every run: the bonds' own time-step bound, printed, and
   a warning when the step exceeds it without pair_style peridem/contact
   (which prints and checks the bound of bonds and contact together). A
   single breakable grain run at 2.8x this bound broke 736 of its 740
   bonds without a word before.
------------------------------------------------------------------------- */

void BondPeridemBase::report_time_step()
{
  const std::vector<double> omega2 = stability_omega2_of_types();
  const double largest = *std::max_element(omega2.begin(), omega2.end());
  if (!(largest > 0.0)) return; // no intact bond anywhere
  peridem::TimeStepInput in;
  in.dimension = domain->dimension;
  in.bond_omega2 = largest;
  const peridem::TimeStepEstimate est = peridem::stable_time_step(in);
  const std::string style = std::string("bond_style ") + force->bond_style;
  const std::string line = fmt::format(
      "{}: time step estimate of the bonds {:.4g} (critical {:.4g}; contact not included)\n", style,
      est.dt_recommended, est.dt_critical);
  // runs in a loop would repeat it at every run: once per change (and time step)
  const std::string key = fmt::format("{}(time step {})", line, update->dt);
  if (key == last_time_step_report) return;
  last_time_step_report = key;
  if (comm->me == 0) utils::logmesg(lmp, line);
  if (update->dt > est.dt_recommended && !force->pair_match("peridem/contact", 0) && comm->me == 0)
    error->warning(FLERR, "{}: time step {} exceeds the bonds' recommended {:.4g}", style,
                   update->dt, est.dt_recommended);
}
