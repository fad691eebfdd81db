/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: bond_style peridem/lps, the linear peridynamic solid of
   Jha, Desai, Bhattacharya & Lipton (PeriDEM, eq. 5-10, 33-34) on LAMMPS's
   bond list. The physics is in peridem_lps_law.h; the shared keywords, the
   bond list by pieces and its refresh rule, the ghost cutoff, validation,
   the breakage decision and the one break path are the base's
   (bond_peridem_base.h).

   Per step: (1) dilation pass over the bonds: extension of each bond,
   breakage (unless break_order after_force), sum_j omega beta r e V_j into
   both nodes; (2) the ghosts' shares go home (newton_bond on), each local
   node forms theta/m and 1/m, and both go out to the ghosts; (3) force pass
   over the bonds with the lengths of pass (1).
------------------------------------------------------------------------- */

#include "bond_peridem_lps.h"
#include "lmp_peridem_citations.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_peridem_bonds.h"
#include "fix_peridem_lps.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"

#include "lmp_peridem_bond_loop.h"
#include "lmp_peridem_material.h"
#include "lmp_peridem_own_fix.h"
#include "lmp_peridem_parse.h"
#include "lmp_peridem_restart.h"
#include "peridem_lps_law.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;

namespace {
const char *const STYLE = "bond_style peridem/lps";
const char *const COEFF = "bond_coeff";
const char *const INFLUENCE[] = {"conic", "constant", "inverse"};
const char *const PLANE[] = {"strain", "stress", "3d"};
} // namespace

/* ---------------------------------------------------------------------- */

BondPeridemLPS::BondPeridemLPS(LAMMPS *lmp)
    : BondPeridemBase(lmp), bulk(nullptr), shear(nullptr), influence(nullptr),
      plane(peridem::LpsPlane::PlaneStrain), dfac(3.0), sum(nullptr), theta_over_m(nullptr),
      inv_m(nullptr), theta(nullptr), nmax_lps(0), check_wvolume(1), lps_fix(nullptr)
{
  PERIDEM_NS::cite_peridem(lmp);
}

BondPeridemLPS::~BondPeridemLPS()
{
  memory->destroy(bulk);
  memory->destroy(shear);
  memory->destroy(influence);
  memory->destroy(sum);
  memory->destroy(theta_over_m);
  memory->destroy(inv_m);
  memory->destroy(theta);
}

void BondPeridemLPS::allocate_model(int np1)
{
  memory->create(bulk, np1, "bond:bulk");
  memory->create(shear, np1, "bond:shear");
  memory->create(influence, np1, "bond:influence");
  for (int i = 0; i < np1; i++) {
    bulk[i] = shear[i] = 0.0;
    influence[i] = 0;
  }
}

void BondPeridemLPS::grow_lps()
{
  if (atom->nmax <= nmax_lps) return;
  nmax_lps = atom->nmax;
  memory->destroy(sum);
  memory->destroy(theta_over_m);
  memory->destroy(inv_m);
  memory->destroy(theta);
  memory->create(sum, nmax_lps, "bond:sum");
  memory->create(theta_over_m, nmax_lps, "bond:theta_over_m");
  memory->create(inv_m, nmax_lps, "bond:inv_m");
  memory->create(theta, nmax_lps, "bond:theta");
}

/* ----------------------------------------------------------------------
   per entry of the bond list: r0, omega beta V_i V_j and the weights of
   the extension in the two dilations; refreshed as bond_style peridem's
------------------------------------------------------------------------- */

void BondPeridemLPS::fill_cache()
{
  fill_reference_lengths(lcache.r0, nullptr);
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;
  const double *vfrac = atom->vfrac;
  lcache.k.resize(nbondlist);
  lcache.wi.resize(nbondlist);
  lcache.wj.resize(nbondlist);
  current_length.resize(nbondlist);
  for (int n = 0; n < nbondlist; n++) {
    const int type = bondlist[n][2];
    if (type <= 0) continue;
    const int i1 = bondlist[n][0], i2 = bondlist[n][1];
    const double r0 = lcache.r0[n];
    const double w =
        peridem::influence_value(peridem::Influence(influence[type]), r0, horizon[type]);
    const double beta = volume_correction
                            ? peridem::volume_factor(peridem::VolumeCorrection::PeriDEM, r0,
                                                     horizon[type], spacing[type])
                            : 1.0;
    lcache.k[n] = w * beta * vfrac[i1] * vfrac[i2];
    lcache.wi[n] = w * beta * r0 * vfrac[i2];
    lcache.wj[n] = w * beta * r0 * vfrac[i1];
  }
}

/* ----------------------------------------------------------------------
   m_i = sum_j omega beta r^2 V_j over the intact bonds (Jha et al. 2021, eq. 8), in
   the reference configuration, once per node: kept by fix peridem/lps
   through migration and restarts, so that later breakage lowers theta but
   not m (as LAMMPS peri/lps's wvolume). A node without bonds (m = 0) is
   looked at again at the next run.
------------------------------------------------------------------------- */

void BondPeridemLPS::compute_weighted_volume()
{
  check_wvolume = 0;
  double *m = lps_fix->weighted_volume();
  const int nlocal = atom->nlocal;
  int pending = 0;
  for (int i = 0; i < nlocal; i++)
    if (!(m[i] > 0.0)) pending = 1;
  int any = 0;
  MPI_Allreduce(&pending, &any, 1, MPI_INT, MPI_MAX, world);
  if (!any) return;

  const int nall = nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) sum[i] = 0.0;
  int **bondlist = neighbor->bondlist;
  const int newton_bond = force->newton_bond;
  for (int n = 0; n < neighbor->nbondlist; n++) {
    if (bondlist[n][2] <= 0) continue;
    const int i1 = bondlist[n][0], i2 = bondlist[n][1];
    sum[i1] += lcache.wi[n] * lcache.r0[n];
    if (newton_bond || i2 < nlocal) sum[i2] += lcache.wj[n] * lcache.r0[n];
  }
  if (newton_bond) lps_fix->reverse_sum(sum);
  const double *nbroken = bonds_fix->broken_count();
  bigint damaged = 0, damaged_all = 0;
  for (int i = 0; i < nlocal; i++)
    if (!(m[i] > 0.0)) {
      m[i] = sum[i];
      if (nbroken[i] > 0.0) damaged++;
    }
  // m belongs to the reference configuration: a node that lost bonds before this style knew
  // it (a state of bond_style peridem, a data file without peridem_wvolume) gets a smaller m
  MPI_Allreduce(&damaged, &damaged_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (damaged_all > 0 && comm->me == 0)
    error->warning(FLERR,
                   "bond_style peridem/lps: {} nodes with broken bonds have no weighted volume "
                   "of the reference configuration (a state of bond_style peridem, or a data "
                   "file without peridem_wvolume): their m is summed over the intact bonds "
                   "only, so their dilation is not that of the undamaged grain",
                   damaged_all);
}

/* ---------------------------------------------------------------------- */

void BondPeridemLPS::compute(int eflag, int vflag)
{
  begin_compute(eflag, vflag);
  grow_lps();
  if (check_wvolume) compute_weighted_volume();

  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int newton_bond = force->newton_bond;

  // (1) dilation pass
  for (int i = 0; i < nall; i++) sum[i] = 0.0;
  const bool planar = domain->dimension == 2, one_type = bond_pieces.type_all > 0;
  if (one_type)
    planar ? dilation_pass<2, true>() : dilation_pass<3, true>();
  else
    planar ? dilation_pass<2, false>() : dilation_pass<3, false>();

  // (2) theta_i = (d/m_i) sum (Jha et al. 2021, eq. 34), complete on owners and ghosts
  if (newton_bond) lps_fix->reverse_sum(sum);
  const double *m = lps_fix->weighted_volume();
  for (int i = 0; i < nlocal; i++) {
    if (m[i] > 0.0) {
      inv_m[i] = 1.0 / m[i];
      theta[i] = dfac * sum[i] * inv_m[i];
      theta_over_m[i] = theta[i] * inv_m[i];
    } else
      inv_m[i] = theta[i] = theta_over_m[i] = 0.0;
  }
  lps_fix->forward(theta_over_m, inv_m);

  // (3) force pass: steps with energy or virial, and LAMMPS's break order, one bond at a time
  // with z; the others without z in 2d (the same forces, to the bit)
  if (evflag || (break_after_force && break_flag)) {
    if (one_type)
      force_pass_one_by_one<true>(eflag);
    else
      force_pass_one_by_one<false>(eflag);
  } else if (one_type)
    planar ? force_pass<2, true>() : force_pass<3, true>();
  else
    planar ? force_pass<2, false>() : force_pass<3, false>();
}

/* ----------------------------------------------------------------------
   pass (1): extension e = |y| - r0 of each bond, breakage (unless
   break_order after_force), sum omega beta r0 e V into both nodes, the sum on
   i1 in a register while i1 repeats. The list is read by pieces with one i1
   (bond_style peridem's fill_pieces: i2 per entry, i1 and x1 once per piece, a broken
   entry has partner i1; ONE_TYPE: one bond type for the list). DIM 2 leaves z out: 2d nodes
   lie in one plane, so |y| is the same IEEE result without it. (Chunks with vectorised
   square roots, as bond_style peridem's loop, made both LPS passes slower: bench/README.md.)
------------------------------------------------------------------------- */

template <int DIM, bool ONE_TYPE> void BondPeridemLPS::dilation_pass()
{
  if (neighbor->nbondlist == 0) return; // the bond list may not exist yet on this rank
  struct Dilation {
    const double *x;
    int nlocal, newton_bond;
    const double *r0c, *wic, *wjc;
    double *len, *sum;
    int current = -1;
    double acc = 0.0;
    double x10 = 0.0, x11 = 0.0, x12 = 0.0, r = 0.0, ext = 0.0;
    void piece(int i1)
    {
      // the sums of the previous i1 are complete: LAMMPS lists the bonds of one i1 in one
      // run, so only pieces of one i1 follow each other (the same additions, in the same
      // order, as one entry at a time; a piece whose entries all broke adds 0 to its i1)
      if (i1 != current) {
        if (current >= 0) sum[current] += acc;
        current = i1;
        acc = 0.0;
      }
      const double *x1 = x + 3 * i1;
      x10 = x1[0];
      x11 = x1[1];
      x12 = DIM == 3 ? x1[2] : 0.0;
    }
    void measure(int n, int, int i2)
    {
      const double *x2 = x + 3 * i2;
      const double delx = x10 - x2[0], dely = x11 - x2[1];
      double rsq = delx * delx + dely * dely;
      if (DIM == 3) {
        const double delz = x12 - x2[2];
        rsq += delz * delz;
      }
      r = std::sqrt(rsq);
      ext = r - r0c[n];
    }
    double stretch(int n) const { return ext / r0c[n]; }
    double r0(int n) const { return r0c[n]; }
    void bond(int n, int, int i2, int)
    {
      len[n] = r;
      acc += wic[n] * ext;
      if (newton_bond || i2 < nlocal) sum[i2] += wjc[n] * ext;
    }
  } kernel{atom->x[0],       atom->nlocal,     force->newton_bond,    lcache.r0.data(),
           lcache.wi.data(), lcache.wj.data(), current_length.data(), sum};
  const PieceView pc = pieces();
  // a bond that breaks now takes no part in this step (default order)
  for_each_intact_bond<BREAK_BEFORE_FORCE, ONE_TYPE>(pc, 0, pc.npieces, kernel);
  if (kernel.current >= 0) sum[kernel.current] += kernel.acc;
}

/* ----------------------------------------------------------------------
   pass (3) of most steps (no energy or virial, default break order): the
   force of each intact bond with the lengths of pass (1), by pieces as pass (1);
   DIM 2 leaves z out (the same forces to the bit as force_pass_one_by_one(), which takes z
   and one entry at a time: tested, PlainForcePassEqualsOneByOne)
------------------------------------------------------------------------- */

template <int DIM, bool ONE_TYPE> void BondPeridemLPS::force_pass()
{
  if (neighbor->nbondlist == 0) return; // the bond list may not exist yet on this rank
  struct Forces {
    PERIDEM_NS::BondForces out;
    const double *x, *r0c, *kc, *len, *theta_over_m, *inv_m;
    const peridem::LpsConstants *lc;
    double x10 = 0.0, x11 = 0.0, x12 = 0.0, tm1 = 0.0, im1 = 0.0;
    void piece(int i1)
    {
      const double *x1 = x + 3 * i1;
      x10 = x1[0];
      x11 = x1[1];
      x12 = DIM == 3 ? x1[2] : 0.0;
      tm1 = theta_over_m[i1];
      im1 = inv_m[i1];
    }
    void measure(int, int, int) {}
    void bond(int n, int i1, int i2, int type)
    {
      const double *x2 = x + 3 * i2;
      const double r = len[n];
      const double F = peridem::lps_bond_force(lc[type], kc[n], r0c[n], r - r0c[n], tm1,
                                               theta_over_m[i2], im1, inv_m[i2]);
      const double fbond = r > 0.0 ? -F / r : 0.0;
      if (DIM == 3)
        out.add(i1, i2, x10 - x2[0], x11 - x2[1], x12 - x2[2], fbond);
      else
        out.add_2d(i1, i2, x10 - x2[0], x11 - x2[1], fbond);
    }
  } kernel{{atom->f[0], atom->nlocal, force->newton_bond},
           atom->x[0],
           lcache.r0.data(),
           lcache.k.data(),
           current_length.data(),
           theta_over_m,
           inv_m,
           constants.data()};
  const PieceView pc = pieces();
  for_each_intact_bond<NO_BREAK, ONE_TYPE>(pc, 0, pc.npieces, kernel);
  kernel.out.finish();
}

/* ----------------------------------------------------------------------
   pass (3) one bond at a time, with energy and virial and either break order
------------------------------------------------------------------------- */

template <bool ONE_TYPE> void BondPeridemLPS::force_pass_one_by_one(int eflag)
{
  struct OneByOne {
    PERIDEM_NS::BondForces out;
    BondPeridemLPS *self;
    const double *x;
    int eflag;
    const double *r0c, *kc, *len, *theta, *theta_over_m, *inv_m;
    const peridem::LpsConstants *lc;
    double del[3] = {0.0, 0.0, 0.0}, r = 0.0, e = 0.0, ebond = 0.0;
    // volumetric energy density needs theta on ghosts too: theta = (theta/m)/(1/m)
    double theta_of(int i) const
    {
      return i < out.nlocal ? theta[i] : (inv_m[i] > 0.0 ? theta_over_m[i] / inv_m[i] : 0.0);
    }
    void piece(int) {}
    void measure(int n, int i1, int i2)
    {
      PERIDEM_NS::separation(x, i1, i2, del);
      r = len[n];
      e = r - r0c[n];
    }
    double stretch(int n) const { return e / r0c[n]; }
    double r0(int n) const { return r0c[n]; }
    void bond(int n, int i1, int i2, int type)
    {
      const double F = peridem::lps_bond_force(lc[type], kc[n], r0c[n], e, theta_over_m[i1],
                                               theta_over_m[i2], inv_m[i1], inv_m[i2]);
      // a positive F pulls i1 towards i2; LAMMPS's fbond multiplies x1 - x2
      const double fbond = r > 0.0 ? -F / r : 0.0;
      out.add(i1, i2, del[0], del[1], del[2], fbond);
      if (self->evflag) {
        if (eflag)
          ebond = peridem::lps_bond_energy(lc[type], kc[n], r0c[n], e, theta_of(i1), theta_of(i2),
                                           inv_m[i1], inv_m[i2]);
        self->ev_tally(i1, i2, out.nlocal, out.newton_bond, ebond, fbond, del[0], del[1], del[2]);
      }
    }
  } kernel{{atom->f[0], atom->nlocal, force->newton_bond},
           this,
           atom->x[0],
           eflag,
           lcache.r0.data(),
           lcache.k.data(),
           current_length.data(),
           theta,
           theta_over_m,
           inv_m,
           constants.data()};
  // the bonds that break now broke in pass (1), unless the order is after_force: then here
  const PieceView pc = pieces();
  for_each_intact_bond<BREAK_AFTER_FORCE, ONE_TYPE>(pc, 0, pc.npieces, kernel);
  kernel.out.finish();
}

/* ----------------------------------------------------------------------
   bond_style peridem/lps [plane strain|stress|3d] and bond_style peridem's
   keywords
------------------------------------------------------------------------- */

bool BondPeridemLPS::settings_keyword(int iarg, int narg, char **arg)
{
  if (strcmp(arg[iarg], "plane") != 0) return false;
  if (iarg + 1 >= narg) error->all(FLERR, "{}: keyword plane needs a value", STYLE);
  plane = peridem::LpsPlane(
      PERIDEM_NS::choice(lmp, STYLE, "plane", arg[iarg + 1], {PLANE[0], PLANE[1], PLANE[2]}));
  plane_given = true;
  return true;
}

std::string BondPeridemLPS::plane_description() const
{
  if (domain->dimension == 3) return "3d";
  return std::string("plane ") + PLANE[int(plane)];
}

/* ----------------------------------------------------------------------
   bond_coeff N K value G value (Gc value | s0 value) horizon eps
              [influence conic|constant|inverse] [spacing h] [break yes|no]
   bond_coeff N material FILE NAME [horizon eps] [Gc value | s0 value] [influence w]
              [spacing h] [break yes|no]
------------------------------------------------------------------------- */

bool BondPeridemLPS::coeff_keyword(const std::string &key, const char *value, const char *style)
{
  ModelArgs &m = margs;
  if (key == "K") {
    m.K = coeff_positive("K (bulk modulus)", value, style);
    m.haveK = true;
  } else if (key == "G") {
    m.G = coeff_positive("G (shear modulus)", value, style);
    m.haveG = true;
  } else if (key == "influence") {
    m.influence = value;
    m.haveInfluence = true;
  } else if (key == "c") {
    coeff_positive("c (spring constant)", value, style);
    m.haveC = true;
  } else if (key == "E") {
    coeff_positive("E (Young's modulus)", value, style);
    m.haveE = true;
  } else if (key == "micromodulus") {
    PERIDEM_NS::parse_micromodulus(lmp, COEFF, value);
    m.haveMicro = true;
  } else
    return false;
  return true;
}

void BondPeridemLPS::coeff(int narg, char **arg)
{
  margs = ModelArgs();
  CoeffArgs a = parse_coeff(narg, arg, STYLE);
  const ModelArgs &m = margs;
  if (m.haveC || m.haveE || m.haveMicro)
    error->all(FLERR,
               "{}: {} is a bond-based coefficient; {} is state-based and takes K, G, Gc or s0, "
               "horizon and influence (use bond_style peridem for {})",
               COEFF, m.haveC ? "c" : (m.haveE ? "E" : "micromodulus"), STYLE,
               m.haveC ? "c" : (m.haveE ? "E" : "micromodulus"));
  if (a.haveMaterial && (m.haveK || m.haveG))
    error->all(FLERR, "{}: {} takes material FILE NAME or K and G, not both", COEFF, STYLE);
  if (a.haveGc && a.haveS0) error->all(FLERR, "{}: give Gc or s0, not both", COEFF);

  double K = m.K, G = m.G, s0val = 0.0, eps = a.eps;
  int infl = 0; // the paper's 1 - r/eps
  if (a.haveMaterial) {
    const peridem::Material &mat = a.material;
    K = mat.elastic.K;
    G = mat.elastic.G;
    if (!(K > 0.0) || !(G > 0.0))
      error->all(FLERR, "{}: {} needs K and G (or any two of E, nu, K, G); {} has not both", COEFF,
                 STYLE, a.origin);
    if (!(eps > 0.0)) eps = mat.horizon;
    if (!(eps > 0.0))
      error->all(FLERR, "{}: {} has no horizon: add horizon to the file or the command", COEFF,
                 a.origin);
    infl = mat.micromodulus == peridem::Micromodulus::Conic ? 0 : 1;
    // Gc or s0 in the command overrides the file's Gc (s0: a critical stretch from a strength)
    if (!a.haveGc && !a.haveS0) {
      if (!(mat.G_c > 0.0)) error->all(FLERR, "{}: {} has no Gc", COEFF, a.origin);
      a.Gc = mat.G_c;
      a.haveGc = true;
    }
  } else {
    if (!m.haveK) error->all(FLERR, "{}: {} needs K (bulk modulus)", COEFF, STYLE);
    if (!m.haveG) error->all(FLERR, "{}: {} needs G (shear modulus)", COEFF, STYLE);
    if (!(eps > 0.0)) error->all(FLERR, "{}: {} needs a horizon", COEFF, STYLE);
    if (!a.haveGc && !a.haveS0)
      error->all(FLERR, "{}: {} needs Gc (fracture energy, PeriDEM eq. 10) or s0, one of them",
                 COEFF, STYLE);
  }
  if (m.haveInfluence)
    infl = PERIDEM_NS::choice(lmp, COEFF, "influence", m.influence,
                              {INFLUENCE[0], INFLUENCE[1], INFLUENCE[2]});
  try {
    // Jha et al. 2021, eq. 10 (Zhu & Zhao's 3D LPS value; used in 2D too, as the paper does)
    s0val = a.haveGc ? peridem::lps_critical_stretch(K, G, a.Gc, eps) : a.s0;
    peridem::lps_constants(domain->dimension, plane, K, G); // validates K, G
  } catch (peridem::ParameterError &e) {
    error->all(FLERR, "{}: {}", COEFF, e.what());
  }
  for (int i = a.ilo; i <= a.ihi; i++) {
    set_shared_type(i, s0val, eps, a.h, a.breakable);
    bulk[i] = K;
    shear[i] = G;
    influence[i] = infl;
  }
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "{} type {}: K = {:.10g}, G = {:.10g}, s0 = {:.10g}{}, horizon = {:.10g}, "
                   "influence {}, {}{}\n",
                   STYLE, arg[0], K, G, s0val, a.haveGc ? " (PeriDEM eq. 10)" : "", eps,
                   INFLUENCE[infl], plane_description(), a.breakable ? "" : ", unbreakable");
}

/* ---------------------------------------------------------------------- */

void BondPeridemLPS::init_style()
{
  BondPeridemBase::init_style();
  const int dimension = domain->dimension;
  // checked here, not in settings(): bond_style may come before the dimension command
  if (dimension == 3 && plane_given && plane != peridem::LpsPlane::ThreeD)
    error->all(FLERR,
               "{}: plane {} is a 2d model; a 3d simulation always uses the 3d constants (drop "
               "the keyword)",
               STYLE, PLANE[int(plane)]);
  constants.assign(atom->nbondtypes + 1, peridem::LpsConstants());
  for (int i = 1; i <= atom->nbondtypes; i++) {
    if (!setflag[i]) continue;
    constants[i] = peridem::lps_constants(dimension, plane, bulk[i], shear[i]);
  }
  dfac = (dimension == 3 || plane == peridem::LpsPlane::ThreeD) ? 3.0 : 2.0;
  // after the base's fixes: fix peridem/bonds may hold m of an older restart file for it
  lps_fix = PERIDEM_NS::own_fix<FixPeridemLPS>(lmp, "peridem/lps", STYLE);
  check_wvolume = 1;
}

/* ---------------------------------------------------------------------- */

void BondPeridemLPS::write_restart(FILE *fp)
{
  PERIDEM_NS::write_restart_tag(fp, PERIDEM_NS::RESTART_BOND_PERIDEM_LPS);
  write_restart_settings(fp); // LAMMPS calls it only under bond_style hybrid
  for (double *arr : {bulk, shear, s0, horizon, spacing}) write_types(fp, arr);
  write_types(fp, influence);
  write_types(fp, breakable);
}

void BondPeridemLPS::read_restart(FILE *fp)
{
  PERIDEM_NS::check_restart_tag(lmp, fp, PERIDEM_NS::RESTART_BOND_PERIDEM_LPS,
                                "bond_style peridem/lps");
  read_restart_settings(fp);
  if (!allocated) allocate();
  const int n = atom->nbondtypes;
  for (double *arr : {bulk, shear, s0, horizon, spacing}) read_types(fp, arr);
  for (int *arr : {influence, breakable}) read_types(fp, arr);
  const char *style = "bond_style peridem/lps";
  constexpr double big = std::numeric_limits<double>::max();
  PERIDEM_NS::check_restart_values(lmp, style, "bulk modulus", &bulk[1], n, 1e-300, big);
  PERIDEM_NS::check_restart_values(lmp, style, "shear modulus", &shear[1], n, 0.0, big);
  PERIDEM_NS::check_restart_values(lmp, style, "critical stretch", &s0[1], n, 1e-300, big);
  PERIDEM_NS::check_restart_values(lmp, style, "horizon", &horizon[1], n, 1e-300, big);
  PERIDEM_NS::check_restart_values(lmp, style, "spacing", &spacing[1], n, 0.0, big);
  PERIDEM_NS::check_restart_values(lmp, style, "influence function", &influence[1], n, 0,
                                   int(sizeof(INFLUENCE) / sizeof(INFLUENCE[0])) - 1);
  PERIDEM_NS::check_restart_values(lmp, style, "break flag", &breakable[1], n, 0, 1);
  for (int i = 1; i <= n; i++) setflag[i] = 1;
}

void BondPeridemLPS::write_restart_settings(FILE *fp)
{
  BondPeridemBase::write_restart_settings(fp);
  const int p = int(plane);
  fwrite(&p, sizeof(int), 1, fp);
}

void BondPeridemLPS::read_restart_settings(FILE *fp)
{
  BondPeridemBase::read_restart_settings(fp);
  int p = 0;
  if (comm->me == 0) utils::sfread(FLERR, &p, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&p, 1, MPI_INT, 0, world);
  PERIDEM_NS::check_restart_values(lmp, "bond_style peridem/lps", "plane mode", &p, 1, 0, 2);
  plane = peridem::LpsPlane(p);
}

void BondPeridemLPS::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->nbondtypes; i++) {
    const std::string line =
        fmt::format("{} K {:.17g} G {:.17g} s0 {:.17g} horizon {:.17g} influence {}", i, bulk[i],
                    shear[i], s0[i], horizon[i], INFLUENCE[influence[i]]) +
        data_tail(i);
    fprintf(fp, "%s\n", line.c_str());
  }
}

/* ----------------------------------------------------------------------
   force of one bond from the nodes' theta/m and 1/m of the last force
   computation (compute bond/local); the energy of a state-based bond is
   not its own, so single() returns the bond's share as compute() tallies it
------------------------------------------------------------------------- */

double BondPeridemLPS::single(int type, double rsq, int i, int j, double &fforce)
{
  fforce = 0.0;
  if (type <= 0 || !inv_m || std::max(i, j) >= nmax_lps || constants.empty()) return 0.0;
  const double r0 = reference_length(i, j);
  const double w = peridem::influence_value(peridem::Influence(influence[type]), r0, horizon[type]);
  const double beta = volume_correction ? peridem::volume_factor(peridem::VolumeCorrection::PeriDEM,
                                                                 r0, horizon[type], spacing[type])
                                        : 1.0;
  const double k = w * beta * atom->vfrac[i] * atom->vfrac[j];
  const double r = std::sqrt(rsq);
  const double e = r - r0;
  const double F = peridem::lps_bond_force(constants[type], k, r0, e, theta_over_m[i],
                                           theta_over_m[j], inv_m[i], inv_m[j]);
  fforce = r > 0.0 ? -F / r : 0.0;
  const double ti = inv_m[i] > 0.0 ? theta_over_m[i] / inv_m[i] : 0.0;
  const double tj = inv_m[j] > 0.0 ? theta_over_m[j] / inv_m[j] : 0.0;
  return peridem::lps_bond_energy(constants[type], k, r0, e, ti, tj, inv_m[i], inv_m[j]);
}

/* ---------------------------------------------------------------------- */

void *BondPeridemLPS::extract(const char *str, int &dim)
{
  dim = 1;
  if (strcmp(str, "K") == 0) return (void *)bulk;
  if (strcmp(str, "G") == 0) return (void *)shear;
  return BondPeridemBase::extract(str, dim);
}

double BondPeridemLPS::memory_usage()
{
  return BondPeridemBase::memory_usage() +
         (lcache.r0.capacity() + lcache.k.capacity() + lcache.wi.capacity() +
          lcache.wj.capacity()) *
             sizeof(double) +
         current_length.capacity() * sizeof(double) + 4.0 * nmax_lps * sizeof(double);
}

/* ----------------------------------------------------------------------
   LPS: k_n = (a d^2 + b) omega beta V_i V_j (1/m_i + 1/m_j), the bound of
   lps_spring_constant() (peridem_lps_law.h). m is summed here over the
   intact bonds of the bond list (owned and ghost ends): a node whose bonds
   are partly stored on another rank gets a smaller m, hence a stiffer,
   still bounding spring; after breakage the force uses the reference m,
   which is larger than the intact sum, so the bound holds too. The stored
   m of fix peridem/lps is not used: the estimate is made in the pair
   style's setup, before the first bond computation of the first run has
   summed it, and it is kept for owned nodes only (ghosts would need a
   communication). On one rank, before breakage and without bonds across a
   periodic boundary, both are the same sum to round-off, so the bisected
   case of timestep_estimate_vs_threshold_bed would not move.
------------------------------------------------------------------------- */

void BondPeridemLPS::stability_springs(std::vector<double> &k)
{
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;
  const int nall = atom->nlocal + atom->nghost;
  const double *vfrac = atom->vfrac;
  k.assign(nbondlist, 0.0);
  std::vector<double> r0(nbondlist, 0.0), wb(nbondlist, 0.0), m(nall, 0.0);
  for (int n = 0; n < nbondlist; n++) {
    const int type = bondlist[n][2];
    if (type <= 0) continue;
    const int i1 = bondlist[n][0], i2 = bondlist[n][1];
    r0[n] = reference_length(i1, i2);
    const double w =
        peridem::influence_value(peridem::Influence(influence[type]), r0[n], horizon[type]);
    const double beta = volume_correction
                            ? peridem::volume_factor(peridem::VolumeCorrection::PeriDEM, r0[n],
                                                     horizon[type], spacing[type])
                            : 1.0;
    wb[n] = w * beta;
    m[i1] += wb[n] * r0[n] * r0[n] * vfrac[i2];
    m[i2] += wb[n] * r0[n] * r0[n] * vfrac[i1];
  }
  for (int n = 0; n < nbondlist; n++) {
    const int type = bondlist[n][2];
    if (type <= 0 || !(wb[n] > 0.0)) continue;
    const int i1 = bondlist[n][0], i2 = bondlist[n][1];
    k[n] = peridem::lps_spring_constant(constants[type]) * wb[n] * vfrac[i1] * vfrac[i2] *
           (1.0 / m[i1] + 1.0 / m[i2]);
  }
}
