/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: bond_style peridem, bond-based peridynamics with breakage.

   The physics lives in peridem_bond_law.h (Bhattacharya & Lipton 2023, eq. 3.2,
   Table 1, §3.1); this file applies it to LAMMPS's bond list.
------------------------------------------------------------------------- */

#include "bond_peridem.h"
#include "lmp_peridem_citations.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "lmp_peridem_restart.h"
#include "lmp_peridem_bond_loop.h"
#include "lmp_peridem_image.h"
#include "error.h"
#include "fix_peridem_bonds.h"
#include "force.h"
#include "lattice.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include "lmp_peridem_material.h"
#include "lmp_peridem_parse.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstring>

using namespace LAMMPS_NS;

namespace {
const char *const STYLE = "bond_style peridem";
const char *const COEFF = "bond_coeff";
} // namespace

/* ---------------------------------------------------------------------- */

BondPeridem::BondPeridem(LAMMPS *lmp)
    : Bond(lmp), c(nullptr), s0(nullptr), horizon(nullptr), spacing(nullptr), conic(nullptr),
      breakable(nullptr), breakage(peridem::BreakageMode::Tension), break_flag(1),
      break_after_force(0), volume_correction(0), cohesive(0), validate_next(1), bonds_fix(nullptr),
      cache_ncalls(-1), cache_generation(-1), cache_bondlist(nullptr)
{
  peridem_lmp::cite_grain_shape(lmp);
  writedata = 1;
}

BondPeridem::~BondPeridem()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(c);
    memory->destroy(s0);
    memory->destroy(horizon);
    memory->destroy(spacing);
    memory->destroy(conic);
    memory->destroy(breakable);
    memory->destroy(s0_break);
  }
}

/* ----------------------------------------------------------------------
   reference bond length |x0_i - x0_j|; x0 of a ghost atom is its owner's,
   not shifted by the periodic image, hence the minimum image convention
------------------------------------------------------------------------- */

double BondPeridem::reference_length(int i1, int i2) const
{
  return reference_length_flat(atom->x0[0], i1, i2);
}

// x0 flat from x0[0] (LAMMPS's per-atom arrays are contiguous, memory->grow), so that
// fill_cache() reads it without a row pointer per atom
inline double BondPeridem::reference_length_flat(const double *x0, int i1, int i2) const
{
  const double *a = x0 + 3 * i1, *b = x0 + 3 * i2;
  double dx = a[0] - b[0];
  double dy = a[1] - b[1];
  double dz = a[2] - b[2];
  peridem_lmp::minimum_image(domain, dx, dy, dz);
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

/* ----------------------------------------------------------------------
   F = c w(|xi|) s V_i V_j along the current bond (Bhattacharya & Lipton 2023, eq. 3.2 times the
   nodal volumes); the bond breaks for good once s > s0 (§3.1)
------------------------------------------------------------------------- */

void BondPeridem::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (validate_next) validate_bonds();
  if (bond_list_is_new(cache.size())) fill_cache();
  if (neighbor->nbondlist == 0) return;
  // steps with energy or virial, and LAMMPS's break order, go one bond at a
  // time; the others in chunks (the same forces, to the bit)
  if (evflag || (break_flag && break_after_force))
    compute_one_by_one(eflag);
  else
    compute_chunked();
}

/* ----------------------------------------------------------------------
   the force loop of most steps: bonds in chunks of at most CHUNK list
   entries, in three passes. (a) gathers the separations x1 - x2 into short
   arrays; (b) computes |y|, the stretch and F/|y| for the whole chunk
   without branches, so that the compiler vectorises the square roots and
   divisions (SSE2: two bonds per instruction; this file is compiled with
   -fno-math-errno, cmake/PeridemLAMMPS.cmake, without which GCC keeps each
   sqrt scalar for errno); (c) breaks bonds and adds the forces in list
   order, summing those on i1 in registers while i1 repeats. LAMMPS lists the
   bonds of one atom one after the other, so the loop reads the list as
   pieces with one i1 each (fill_pieces): per entry it streams i2 and 1/r0 only
   (12 bytes; and k when the bonds' stiffnesses differ, the type when their types do;
   LAMMPS's list entry is 12 bytes on its own), and x1 once per piece. Each force is the same
   expression as in compute_one_by_one(), so the results are the same to
   the bit (tested: chunked_equals_one_by_one).
------------------------------------------------------------------------- */

// one chunked pass over the bond list; DIM 2 leaves z out: in 2d every node lies in one
// plane (LAMMPS's 2d model), so z1 - z2 = 0 and |y|, the stretch and the force are the same
// IEEE results without it (to the bit: tested, chunked_equals_one_by_one, 2d), and f_z gets
// nothing. The 2d bed then gathers, sums and scatters two components instead of three.
// ONE_TYPE: every intact entry has type cache.type_all (no per-entry type to stream).
template <int DIM, bool UNIFORM_K, bool ONE_TYPE>
inline __attribute__((always_inline)) void BondPeridem::chunked_pass()
{
  // LAMMPS's per-atom arrays are contiguous (memory->create): index them flat, as LAMMPS's
  // OPT styles do
  const double *x = atom->x[0];
  double *f = atom->f[0];
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;
  const double *inv_r0 = cache.inv_r0.data();
  const double *kb = cache.k.data();
  const double k_all = cache.k_value;
  const PieceView pc = pieces();

  alignas(64) double dx[CHUNK], dy[CHUNK], dz[CHUNK], rv[CHUNK], sv[CHUNK], fb[CHUNK];
  int current = -1;
  double fsum[3] = {0.0, 0.0, 0.0};

  for (int c = 0; c < pc.nchunks; c++) {
    const int p0 = pc.chunk[c], p1 = pc.chunk[c + 1];
    const int n0 = pc.start[p0], m = pc.start[p1] - n0;
    // (a) gather, x1 once per piece
    for (int p = p0; p < p1; p++) {
      const double *x1 = x + 3 * pc.atom[p];
      const double x10 = x1[0], x11 = x1[1], x12 = DIM == 3 ? x1[2] : 0.0;
      for (int n = pc.start[p], e = pc.start[p + 1]; n < e; n++) {
        const double *x2 = x + 3 * pc.partner[n];
        const int j = n - n0;
        dx[j] = x10 - x2[0];
        dy[j] = x11 - x2[1];
        if (DIM == 3) dz[j] = x12 - x2[2];
      }
    }
    // (b) no branches: vectorised. An entry with r = 0 (coinciding nodes, or a broken entry,
    // whose partner is i1) gets an infinite or undefined fb here, and no force in (c); so
    // this pass raises the divide-by-zero and invalid flags whenever a bond has broken (a
    // run with floating-point traps, feenableexcept, stops here)
    const double *ir = inv_r0 + n0, *kk = UNIFORM_K ? nullptr : kb + n0;
    for (int j = 0; j < m; j++) {
      const double rsq =
          DIM == 3 ? dx[j] * dx[j] + dy[j] * dy[j] + dz[j] * dz[j] : dx[j] * dx[j] + dy[j] * dy[j];
      const double r = std::sqrt(rsq);
      rv[j] = r;
      sv[j] = peridem::stretch_from_inverse(r, ir[j]);
      fb[j] = -peridem::bond_force_per_length(UNIFORM_K ? k_all : kk[j], ir[j], 1.0 / r);
    }
    // (c) forces in list order
    for (int p = p0; p < p1; p++) {
      const int i1 = pc.atom[p];
      for (int n = pc.start[p], e = pc.start[p + 1]; n < e; n++) {
        const int i2 = pc.partner[n];
        if (i2 == i1) continue; // broken
        const int type = pc.type_of<ONE_TYPE>(n);
        const int j = n - n0;
        if (break_flag && peridem::bond_breaks(sv[j], s0_break[type], breakage)) {
          break_bond(n, i1, i2, cache.r0[n], s0[type]);
          continue;
        }
        const double fbond = rv[j] > 0.0 ? fb[j] : 0.0;
        if (DIM == 3)
          peridem_lmp::add_bond_force(f, current, fsum, i1, i2, newton_bond || i2 < nlocal, dx[j],
                                      dy[j], dz[j], fbond);
        else
          peridem_lmp::add_bond_force_2d(f, current, fsum, i1, i2, newton_bond || i2 < nlocal,
                                         dx[j], dy[j], fbond);
      }
    }
  }
  if (current >= 0) peridem_lmp::add_force(f, current, fsum[0], fsum[1], fsum[2]);
}

// built three times, for AVX-512, AVX2 and the baseline x86-64 (SSE2), chosen when the
// library loads: pass (b) then takes eight or four bonds per instruction. Without FMA
// contraction (-ffp-contract=off, cmake/PeridemLAMMPS.cmake), so each result is the same
// IEEE operation as in compute_one_by_one(), to the bit. in.peri_impact, CPU time of the Bond
// section, median of 6 interleaved runs: 5.0 (SSE2), 4.0-4.3 (AVX2), 3.6-4.4 ns per bond
// (AVX-512)
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
void BondPeridem::compute_chunked()
{
  const bool planar = domain->dimension == 2, one_type = cache.type_all > 0;
  if (cache.k_uniform) {
    if (one_type)
      planar ? chunked_pass<2, true, true>() : chunked_pass<3, true, true>();
    else
      planar ? chunked_pass<2, true, false>() : chunked_pass<3, true, false>();
  } else {
    if (one_type)
      planar ? chunked_pass<2, false, true>() : chunked_pass<3, false, true>();
    else
      planar ? chunked_pass<2, false, false>() : chunked_pass<3, false, false>();
  }
}

/* ----------------------------------------------------------------------
   one bond at a time, with energy and virial and either break order
------------------------------------------------------------------------- */

void BondPeridem::compute_one_by_one(int eflag)
{
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;
  const double *x = atom->x[0];
  double *f = atom->f[0];
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;
  const double *r0c = cache.r0.data(), *inv_r0 = cache.inv_r0.data(), *kb = cache.k.data();
  const bool k_uniform = cache.k_uniform;
  double ebond = 0.0;

  // forces on i1 summed in registers (lmp_peridem_bond_loop.h)
  int current = -1;
  double fsum[3] = {0.0, 0.0, 0.0};

  for (int n = 0; n < nbondlist; n++) {
    const int type = bondlist[n][2];
    if (type <= 0) continue;
    const int i1 = bondlist[n][0];
    const int i2 = bondlist[n][1];
    const double *x1 = x + 3 * i1, *x2 = x + 3 * i2;

    const double r0 = r0c[n];
    const double delx = x1[0] - x2[0];
    const double dely = x1[1] - x2[1];
    const double delz = x1[2] - x2[2];
    const double r = std::sqrt(delx * delx + dely * dely + delz * delz);
    const double s = peridem::stretch_from_inverse(r, inv_r0[n]);

    // a bond that breaks now carries no force now, unless the user asked
    // for the order of LAMMPS's peri styles: force first, then break
    const bool breaks = break_flag && peridem::bond_breaks(s, s0_break[type], breakage);
    if (breaks && !break_after_force) {
      break_bond(n, i1, i2, r0, s0[type]);
      continue;
    }

    // F/|y| of bond_force(c, w, s, V_i, V_j), with c w V_i V_j (and the
    // volume factor) in k; a positive force pulls i1 towards i2, and
    // LAMMPS's fbond multiplies x1 - x2
    const double k = k_uniform ? cache.k_value : kb[n];
    const double fbond = r > 0.0 ? -peridem::bond_force_per_length(k, inv_r0[n], 1.0 / r) : 0.0;

    peridem_lmp::add_bond_force(f, current, fsum, i1, i2, newton_bond || i2 < nlocal, delx, dely,
                                delz, fbond);

    if (eflag) ebond = peridem::bond_energy(k, 1.0, s, r0, 1.0, 1.0);
    if (evflag) ev_tally(i1, i2, nlocal, newton_bond, ebond, fbond, delx, dely, delz);
    if (breaks) break_bond(n, i1, i2, r0, s0[type]);
  }
  if (current >= 0) peridem_lmp::add_force(f, current, fsum[0], fsum[1], fsum[2]);
}

/* ----------------------------------------------------------------------
   per entry of the bond list: reference length and the stiffness
   k = c w(|xi|) V_i V_j (times the volume factor), which change only when
   LAMMPS rebuilds the bond list
------------------------------------------------------------------------- */

double BondPeridem::bond_stiffness(int type, double r0, int i1, int i2) const
{
  return stiffness(type, r0, atom->vfrac[i1], atom->vfrac[i2]);
}

inline double BondPeridem::stiffness(int type, double r0, double vol1, double vol2) const
{
  const double w = peridem::micromodulus_value(conic[type] ? peridem::Micromodulus::Conic
                                                           : peridem::Micromodulus::Constant,
                                               r0, horizon[type]);
  const double vscale = volume_correction
                            ? peridem::volume_factor(peridem::VolumeCorrection::PeriDEM, r0,
                                                     horizon[type], spacing[type])
                            : 1.0;
  return peridem::bond_force(c[type], w, 1.0, vol1, vol2 * vscale);
}

// LAMMPS rebuilt the bond list since the caches were filled: fix peridem/bonds counts the
// rebuilds (neighbor->ncalls alone returns to 0 at every setup, and rerun sets up every
// snapshot without a new init)
bool BondPeridem::bond_list_is_new(std::size_t cached_entries) const
{
  return bonds_fix->bond_list_generation() != cache_generation ||
         neighbor->ncalls != cache_ncalls || neighbor->nbondlist != int(cached_entries) ||
         neighbor->bondlist != cache_bondlist;
}

void BondPeridem::remember_bond_list()
{
  cache_generation = bonds_fix->bond_list_generation();
  cache_ncalls = neighbor->ncalls;
  cache_bondlist = neighbor->bondlist;
}

void BondPeridem::fill_cache()
{
  // once per rebuild of the bond list (41 times in in.peri_impact's 1000 steps): a tight
  // loop over flat arrays, 4.5 % of that run's samples before (session 7)
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;
  remember_bond_list();
  if (nbondlist == 0) { // the bond list and x0 may not exist yet on this rank
    cache.r0.clear();
    cache.inv_r0.clear();
    cache.k.clear();
    cache.k_uniform = true;
    cache.k_value = 0.0;
    fill_pieces();
    return;
  }
  const int *bl = bondlist[0];
  const double *x0 = atom->x0[0];
  const double *vfrac = atom->vfrac;
  // resize, not assign: every intact entry is written below, and clearing 16 bytes per bond
  // at each rebuild was a quarter of this function's time; the entries of broken bonds
  // (type <= 0) keep old finite values that the chunked loop computes with and discards
  cache.r0.resize(nbondlist, 0.0);
  cache.inv_r0.resize(nbondlist, 0.0);
  double *r0c = cache.r0.data(), *inv_r0 = cache.inv_r0.data();
  // k is often one value for the whole list (one material, equal node volumes, constant
  // micromodulus, no volume correction: the beds): then the force loop reads that value
  // instead of streaming 8 bytes per bond (28 -> 20 bytes per bond with the bond list and
  // 1/r0); the same double, so the same forces to the bit
  int mismatch = -1;
  bool found = false;
  cache.k_value = 0.0;
  for (int n = 0; n < nbondlist; n++) {
    const int *b = bl + 3 * n;
    const int type = b[2];
    if (type <= 0) continue;
    const int i1 = b[0], i2 = b[1];
    const double r0 = reference_length_flat(x0, i1, i2);
    r0c[n] = r0;
    inv_r0[n] = 1.0 / r0;
    if (mismatch >= 0) continue;
    const double k = stiffness(type, r0, vfrac[i1], vfrac[i2]);
    if (!found) {
      found = true;
      cache.k_value = k;
    } else if (k != cache.k_value)
      mismatch = n;
  }
  cache.k_uniform = mismatch < 0; // also with no intact bond at all (k_value 0)
  if (cache.k_uniform) {
    std::vector<double>().swap(cache.k);
  } else {
    cache.k.resize(nbondlist, 0.0);
    double *k = cache.k.data();
    for (int n = 0; n < nbondlist; n++) {
      const int *b = bl + 3 * n;
      if (b[2] > 0) k[n] = stiffness(b[2], r0c[n], vfrac[b[0]], vfrac[b[1]]);
    }
  }
  fill_pieces();
}

// the bond list as the chunked loop reads it (BondCache): i2 per entry, i1 per piece of
// consecutive entries with one i1, the pieces grouped into chunks of at most CHUNK entries,
// and one type for the whole list when the intact entries share it
void BondPeridem::fill_pieces()
{
  const int nbondlist = neighbor->nbondlist;
  cache.partner.resize(nbondlist);
  cache.piece_atom.clear();
  cache.piece_start.clear();
  cache.chunk_piece.clear();
  cache.type.clear();
  cache.type_all = 1; // any valid type when no entry is intact: no intact entry reads it
  if (nbondlist == 0) {
    cache.piece_start.push_back(0);
    cache.chunk_piece.push_back(0);
    return;
  }
  const int *bl = neighbor->bondlist[0];
  int *partner = cache.partner.data();
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
    if (cache.piece_atom.empty() || cache.piece_atom.back() != i1 ||
        n - cache.piece_start.back() == CHUNK) {
      cache.piece_atom.push_back(i1);
      cache.piece_start.push_back(n);
    }
  }
  const int npieces = int(cache.piece_atom.size());
  cache.piece_start.push_back(nbondlist);
  const int *start = cache.piece_start.data();
  for (int p = 0; p < npieces; p++)
    if (cache.chunk_piece.empty() || start[p + 1] - start[cache.chunk_piece.back()] > CHUNK)
      cache.chunk_piece.push_back(p);
  cache.chunk_piece.push_back(npieces);
  if (mixed) {
    cache.type_all = 0;
    cache.type.resize(nbondlist);
    for (int n = 0; n < nbondlist; n++) cache.type[n] = bl[3 * n + 2];
  } else if (first_type > 0)
    cache.type_all = first_type;
}

/* ----------------------------------------------------------------------
   bond n broke: type 0 in this step's bond list, and out of the bond
   arrays (fix peridem/bonds keeps count), so that its nodes may separate
   without LAMMPS missing a bond partner. Another rank that holds the bond
   (newton_bond off, partner owned there) computes the same stretch from
   the same positions and breaks it too.
------------------------------------------------------------------------- */

void BondPeridem::break_bond(int n, int i1, int i2, double r0, double s0type)
{
  neighbor->bondlist[n][2] = 0;
  // the list by pieces, which both bond styles read (fill_pieces()): partner i1 marks the
  // entry broken (after a fill, partner has one entry per entry of the bond list)
  if (std::size_t(n) < cache.partner.size()) cache.partner[n] = i1;
  double **x = atom->x;
  double dy[3];
  for (int d = 0; d < 3; d++) dy[d] = x[i2][d] - x[i1][d];
  domain->minimum_image(dy[0], dy[1], dy[2]);
  // the damage Z a broken bond leaves at its nodes: the stretch that broke it over s0 (>= 1;
  // compute peridem/damage explains the choice)
  const double z = peridem::z_stretch_term(
      peridem::stretch(std::sqrt(dy[0] * dy[0] + dy[1] * dy[1] + dy[2] * dy[2]), r0), s0type);
  bonds_fix->bond_broken(i1, i2, z);
}

/* ----------------------------------------------------------------------
   once per run: bonds must join nodes of one grain and be no longer than
   the horizon of their type
------------------------------------------------------------------------- */

void BondPeridem::validate_bonds()
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
------------------------------------------------------------------------- */

void BondPeridem::settings(int narg, char **arg)
{
  for (int iarg = 0; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (iarg + 1 >= narg) error->all(FLERR, "{}: keyword {} needs a value", STYLE, key);
    const std::string value = arg[iarg + 1];
    if (key == "break") {
      const int mode = peridem_lmp::choice(lmp, STYLE, key, value, {"tension", "absolute", "off"});
      break_flag = mode != 2;
      if (mode == 1)
        breakage = peridem::BreakageMode::Absolute;
      else
        breakage = peridem::BreakageMode::Tension;
    } else if (key == "break_order") {
      break_after_force =
          peridem_lmp::choice(lmp, STYLE, key, value, {"before_force", "after_force"});
    } else if (key == "volume_correction") {
      volume_correction = peridem_lmp::choice(lmp, STYLE, key, value, {"none", "linear"});
    } else if (key == "cohesive") {
      cohesive = peridem_lmp::yes_no(lmp, STYLE, key, value);
    } else
      error->all(FLERR, "{}: unknown keyword {}", STYLE, key);
  }
}

/* ---------------------------------------------------------------------- */

void BondPeridem::allocate()
{
  allocated = 1;
  const int np1 = atom->nbondtypes + 1;
  memory->create(setflag, np1, "bond:setflag");
  memory->create(c, np1, "bond:c");
  memory->create(s0, np1, "bond:s0");
  memory->create(horizon, np1, "bond:horizon");
  memory->create(spacing, np1, "bond:spacing");
  memory->create(conic, np1, "bond:conic");
  memory->create(breakable, np1, "bond:breakable");
  memory->create(s0_break, np1, "bond:s0_break");
  for (int i = 0; i < np1; i++) {
    setflag[i] = 0;
    c[i] = s0[i] = horizon[i] = spacing[i] = s0_break[i] = 0.0;
    conic[i] = 0;
    breakable[i] = 1;
  }
}

void BondPeridem::set_type(int type, const TypeParams &p)
{
  c[type] = p.c;
  s0[type] = p.s0;
  horizon[type] = p.horizon;
  spacing[type] = p.spacing;
  conic[type] = p.micromodulus == peridem::Micromodulus::Conic;
  breakable[type] = p.breakable;
  setflag[type] = 1;
}

/* ----------------------------------------------------------------------
   bond_coeff N material FILE NAME [horizon eps] [Gc value] [micromodulus m] [spacing h]
   bond_coeff N E|K value Gc value horizon eps [micromodulus m] [spacing h]
   bond_coeff N c value s0 value horizon eps [micromodulus m] [spacing h]
------------------------------------------------------------------------- */

BondPeridem::CoeffArgs BondPeridem::parse_coeff(int narg, char **arg, const char *style)
{
  if (narg < 2) error->all(FLERR, "{}: {} needs a bond type and its parameters", COEFF, style);
  if (!allocated) allocate();
  CoeffArgs a;
  utils::bounds(FLERR, arg[0], 1, atom->nbondtypes, a.ilo, a.ihi, error);

  auto positive = [&](int iarg, const char *what) {
    if (iarg + 1 >= narg) error->all(FLERR, "{}: keyword {} needs a value", COEFF, what);
    const double v = peridem_lmp::number(lmp, COEFF, what, arg[iarg + 1]);
    if (!(v > 0.0))
      error->all(FLERR, "{}: {} must be > 0 for {}, not {}", COEFF, what, style, arg[iarg + 1]);
    return v;
  };

  for (int iarg = 1; iarg < narg;) {
    const std::string key = arg[iarg];
    if (key == "material") {
      if (iarg + 2 >= narg)
        error->all(FLERR, "{}: material needs a file name and a material name", COEFF);
      a.material = peridem_lmp::load_material(lmp, COEFF, arg[iarg + 1], arg[iarg + 2]);
      a.haveMaterial = true;
      a.origin = fmt::format("material {} of {}", arg[iarg + 2], arg[iarg + 1]);
      iarg += 3;
      continue;
    }
    if (iarg + 1 >= narg) error->all(FLERR, "{}: keyword {} needs a value", COEFF, key);
    if (key == "micromodulus") {
      a.micro = peridem_lmp::parse_micromodulus(lmp, COEFF, arg[iarg + 1]);
      a.haveMicro = true;
    } else if (key == "influence") {
      a.influence = arg[iarg + 1];
      a.haveInfluence = true;
    } else if (key == "break") {
      a.breakable = peridem_lmp::yes_no(lmp, COEFF, key, arg[iarg + 1]);
    } else if (key == "E") {
      a.E = positive(iarg, "E (Young's modulus)");
      a.haveE = true;
    } else if (key == "K") {
      a.K = positive(iarg, "K (bulk modulus)");
      a.haveK = true;
    } else if (key == "G") {
      a.G = positive(iarg, "G (shear modulus)");
      a.haveG = true;
    } else if (key == "Gc") {
      a.Gc = positive(iarg, "Gc (fracture energy)");
      a.haveGc = true;
    } else if (key == "c") {
      a.cval = positive(iarg, "c (spring constant)");
      a.haveC = true;
    } else if (key == "s0") {
      a.s0 = positive(iarg, "s0 (critical stretch)");
      a.haveS0 = true;
    } else if (key == "horizon") {
      a.eps = positive(iarg, "horizon");
    } else if (key == "spacing") {
      a.h = positive(iarg, "spacing");
    } else
      error->all(FLERR, "{}: unknown keyword {} for {}", COEFF, key, style);
    iarg += 2;
  }
  return a;
}

/* ----------------------------------------------------------------------
   bond_coeff N material FILE NAME [horizon eps] [Gc value] [micromodulus m] [spacing h]
              [break yes|no]
   bond_coeff N E|K value Gc value horizon eps [micromodulus m] [spacing h] [break yes|no]
   bond_coeff N c value s0 value horizon eps [micromodulus m] [spacing h] [break yes|no]
------------------------------------------------------------------------- */

void BondPeridem::coeff(int narg, char **arg)
{
  const CoeffArgs a = parse_coeff(narg, arg, STYLE);
  const int dimension = domain->dimension;
  if (a.haveG || a.haveInfluence)
    error->all(FLERR,
               "{}: {} is a state-based coefficient; {} is bond-based (use bond_style "
               "peridem/lps for K and G)",
               COEFF, a.haveG ? "G" : "influence", STYLE);
  const double E = a.E, K = a.K, Gc = a.Gc, cval = a.cval, s0val = a.s0, eps = a.eps, h = a.h;
  const bool haveE = a.haveE, haveK = a.haveK, haveGc = a.haveGc, haveC = a.haveC,
             haveS0 = a.haveS0, haveMaterial = a.haveMaterial, haveMicro = a.haveMicro;
  const peridem::Micromodulus micro = a.micro;
  peridem::Material material = a.material;
  std::string origin = a.origin;
  const int ilo = a.ilo, ihi = a.ihi;

  const int nsources = int(haveMaterial) + int(haveE || haveK) + int(haveC || haveS0);
  if (nsources != 1)
    error->all(FLERR,
               "{}: {} needs exactly one of: material FILE NAME; E or K with Gc and horizon; "
               "c with s0 and horizon",
               COEFF, STYLE);
  if (haveE && haveK) error->all(FLERR, "{}: give E or K, not both", COEFF);

  TypeParams p;
  try {
    if (haveMaterial) {
      p.micromodulus = haveMicro ? micro : material.micromodulus;
      material.micromodulus = p.micromodulus;
      // Gc overrides the file's, as horizon does (Bhattacharya & Lipton 2023 §6.4 vary only
      // G_c of their M1); it used to be ignored without a word
      if (haveGc) {
        material.G_c = Gc;
        origin += fmt::format(", Gc = {}", Gc);
      }
      p.horizon = eps > 0.0 ? eps : material.horizon;
      if (!(p.horizon > 0.0))
        error->all(FLERR, "{}: {} has no horizon: add horizon to the file or the command", COEFF,
                   origin);
      const peridem::BondConstants bc =
          peridem::material_bond_constants(material, dimension, p.horizon);
      p.c = bc.c;
      p.s0 = bc.s0;
    } else if (haveE || haveK) {
      if (!haveGc)
        error->all(FLERR, "{}: {} with {} needs Gc (fracture energy)", COEFF, STYLE,
                   haveE ? "E" : "K");
      if (!(eps > 0.0)) error->all(FLERR, "{}: {} needs a horizon", COEFF, STYLE);
      p.micromodulus = micro;
      p.horizon = eps;
      const peridem::BondConstants bc = peridem::derive_bond_constants(
          dimension, micro,
          haveE ? peridem::ElasticInput::YoungsModulus : peridem::ElasticInput::BulkModulus,
          haveE ? E : K, Gc, eps);
      p.c = bc.c;
      p.s0 = bc.s0;
      origin = fmt::format("{} = {}, Gc = {}", haveE ? "E" : "K", haveE ? E : K, Gc);
    } else {
      if (!haveC || !haveS0) error->all(FLERR, "{}: give both c and s0", COEFF);
      if (!(eps > 0.0)) error->all(FLERR, "{}: {} needs a horizon", COEFF, STYLE);
      if (haveGc) error->all(FLERR, "{}: Gc does not go with c and s0 (s0 is given)", COEFF);
      p.micromodulus = micro;
      p.horizon = eps;
      p.c = cval;
      p.s0 = s0val;
      origin = "c and s0 given";
    }
  } catch (peridem::ParameterError &e) {
    error->all(FLERR, "{}: {}", COEFF, e.what());
  }
  p.spacing = h;
  p.breakable = a.breakable;
  for (int i = ilo; i <= ihi; i++) set_type(i, p);
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "{} type {}: c = {:.10g}, s0 = {:.10g}, horizon = {:.10g}, {} micromodulus, "
                   "{}d ({}){}\n",
                   STYLE, arg[0], p.c, p.s0, p.horizon,
                   peridem_lmp::micromodulus_name(p.micromodulus), dimension, origin,
                   p.breakable ? "" : ", unbreakable");
}

/* ---------------------------------------------------------------------- */

void BondPeridem::init_style()
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
  // the bookkeeping of broken bonds
  const int ifix = modify->find_fix(FixPeridemBonds::ID);
  if (ifix < 0)
    bonds_fix = dynamic_cast<FixPeridemBonds *>(
        modify->add_fix(fmt::format("{} all peridem/bonds", FixPeridemBonds::ID)));
  else
    bonds_fix = dynamic_cast<FixPeridemBonds *>(modify->fix[ifix]);
  if (!bonds_fix)
    error->all(FLERR, "{}: fix {} is not a fix peridem/bonds", STYLE, FixPeridemBonds::ID);

  // Nodes in memory grain by grain, in the order of creation (peridem_atom_order.h: the
  // 2000-grain bed's bond loop 4.8 -> 3.6 ns per bond), at the frequency of LAMMPS's sort
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
  bonds_fix->set_grain_order(grain_order);
  validate_next = 1;
  cache_ncalls = cache_generation = -1;
}

/* ---------------------------------------------------------------------- */

// LAMMPS uses this only to estimate the communication cutoff (1.5 x this +
// skin, Comm::get_comm_cutoff; it warns when the cutoff in use is shorter):
// return the reach of a bond of this type over 1.5, so that the estimate is
// the cutoff init_style() sets.
double BondPeridem::equilibrium_distance(int i)
{
  return horizon[i] * (1.0 + stretch_allowance) / 1.5;
}

/* ---------------------------------------------------------------------- */

// LAMMPS calls write/read_restart_settings() of a bond style only under
// bond_style hybrid: without these calls the settings (volume_correction,
// break_order, ...) were lost in a restart
void BondPeridem::write_restart(FILE *fp)
{
  peridem_lmp::write_restart_tag(fp, peridem_lmp::RESTART_BOND_PERIDEM);
  write_restart_settings(fp);
  const int n = atom->nbondtypes;
  for (double *a : {c, s0, horizon, spacing}) fwrite(&a[1], sizeof(double), n, fp);
  fwrite(&conic[1], sizeof(int), n, fp);
  fwrite(&breakable[1], sizeof(int), n, fp);
}

void BondPeridem::read_restart(FILE *fp)
{
  peridem_lmp::check_restart_tag(lmp, fp, peridem_lmp::RESTART_BOND_PERIDEM, "bond_style peridem");
  read_restart_settings(fp);
  allocate();
  const int n = atom->nbondtypes;
  for (double *a : {c, s0, horizon, spacing}) {
    if (comm->me == 0) utils::sfread(FLERR, &a[1], sizeof(double), n, fp, nullptr, error);
    MPI_Bcast(&a[1], n, MPI_DOUBLE, 0, world);
  }
  if (comm->me == 0) utils::sfread(FLERR, &conic[1], sizeof(int), n, fp, nullptr, error);
  MPI_Bcast(&conic[1], n, MPI_INT, 0, world);
  if (comm->me == 0) utils::sfread(FLERR, &breakable[1], sizeof(int), n, fp, nullptr, error);
  MPI_Bcast(&breakable[1], n, MPI_INT, 0, world);
  constexpr double big = std::numeric_limits<double>::max();
  peridem_lmp::check_restart_values(lmp, STYLE, "bond constant c", &c[1], n, 1e-300, big);
  peridem_lmp::check_restart_values(lmp, STYLE, "critical stretch", &s0[1], n, 1e-300, big);
  peridem_lmp::check_restart_values(lmp, STYLE, "horizon", &horizon[1], n, 1e-300, big);
  peridem_lmp::check_restart_values(lmp, STYLE, "spacing", &spacing[1], n, 0.0, big);
  peridem_lmp::check_restart_values(lmp, STYLE, "micromodulus", &conic[1], n, 0, 1);
  peridem_lmp::check_restart_values(lmp, STYLE, "break flag", &breakable[1], n, 0, 1);
  for (int i = 1; i <= n; i++) setflag[i] = 1;
}

void BondPeridem::write_restart_settings(FILE *fp)
{
  const int settings[5] = {break_flag, breakage == peridem::BreakageMode::Absolute,
                           volume_correction, cohesive, break_after_force};
  fwrite(settings, sizeof(int), 5, fp);
}

void BondPeridem::read_restart_settings(FILE *fp)
{
  int settings[5];
  if (comm->me == 0) utils::sfread(FLERR, settings, sizeof(int), 5, fp, nullptr, error);
  MPI_Bcast(settings, 5, MPI_INT, 0, world);
  peridem_lmp::check_restart_values(lmp, STYLE, "setting", settings, 5, 0, 1);
  break_flag = settings[0];
  breakage = settings[1] ? peridem::BreakageMode::Absolute : peridem::BreakageMode::Tension;
  volume_correction = settings[2];
  cohesive = settings[3];
  break_after_force = settings[4];
}

/* ----------------------------------------------------------------------
   Bond Coeffs in the direct form, so a data file reproduces c and s0
------------------------------------------------------------------------- */

void BondPeridem::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->nbondtypes; i++) {
    std::string line = fmt::format("{} c {:.17g} s0 {:.17g} horizon {:.17g} micromodulus {}", i,
                                   c[i], s0[i], horizon[i], conic[i] ? "conic" : "constant");
    if (spacing[i] > 0.0) line += fmt::format(" spacing {:.17g}", spacing[i]);
    if (!breakable[i]) line += " break no";
    fprintf(fp, "%s\n", line.c_str());
  }
}

/* ---------------------------------------------------------------------- */

double BondPeridem::single(int type, double rsq, int i, int j, double &fforce)
{
  fforce = 0.0;
  if (type <= 0) return 0.0;
  const double r0 = reference_length(i, j);
  const double k = bond_stiffness(type, r0, i, j);
  const double r = std::sqrt(rsq);
  const double s = peridem::stretch(r, r0);
  fforce = r > 0.0 ? -peridem::bond_force(k, 1.0, s, 1.0, 1.0) / r : 0.0;
  return peridem::bond_energy(k, 1.0, s, r0, 1.0, 1.0);
}

/* ---------------------------------------------------------------------- */

void *BondPeridem::extract(const char *str, int &dim)
{
  dim = 1;
  if (strcmp(str, "c") == 0) return (void *)c;
  if (strcmp(str, "s0") == 0) return (void *)s0;
  if (strcmp(str, "horizon") == 0) return (void *)horizon;
  if (strcmp(str, "conic") == 0) return (void *)conic; // int per type: 1 conic micromodulus
  dim = 0;
  return nullptr;
}

/* ---------------------------------------------------------------------- */

double BondPeridem::memory_usage()
{
  return Bond::memory_usage() +
         (cache.r0.capacity() + cache.inv_r0.capacity() + cache.k.capacity()) * sizeof(double) +
         pieces_memory();
}

double BondPeridem::pieces_memory() const
{
  return double(cache.partner.capacity() + cache.piece_atom.capacity() +
                cache.piece_start.capacity() + cache.chunk_piece.capacity() +
                cache.type.capacity()) *
         sizeof(int);
}
