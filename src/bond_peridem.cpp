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
#include "bond_peridem_chunked.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"

#include "lmp_peridem_bond_loop.h"
#include "lmp_peridem_citations.h"
#include "lmp_peridem_material.h"
#include "lmp_peridem_restart.h"

#include <cmath>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;

namespace {
const char *const STYLE = "bond_style peridem";
const char *const COEFF = "bond_coeff";
} // namespace

/* ---------------------------------------------------------------------- */

BondPeridem::BondPeridem(LAMMPS *lmp) : BondPeridemBase(lmp), c(nullptr), conic(nullptr)
{
  PERIDEM_NS::cite_grain_shape(lmp);
}

BondPeridem::~BondPeridem()
{
  memory->destroy(c);
  memory->destroy(conic);
}

void BondPeridem::allocate_model(int np1)
{
  memory->create(c, np1, "bond:c");
  memory->create(conic, np1, "bond:conic");
  for (int i = 0; i < np1; i++) {
    c[i] = 0.0;
    conic[i] = 0;
  }
}

/* ----------------------------------------------------------------------
   F = c w(|xi|) s V_i V_j along the current bond (Bhattacharya & Lipton 2023, eq. 3.2 times the
   nodal volumes); the bond breaks for good once s > s0 (§3.1)
------------------------------------------------------------------------- */

void BondPeridem::compute(int eflag, int vflag)
{
  begin_compute(eflag, vflag);
  if (neighbor->nbondlist == 0) return;
  // steps with energy or virial, and LAMMPS's break order, go one bond at a
  // time; the others in chunks (the same forces, to the bit)
  if (evflag || (break_flag && break_after_force)) {
    if (bond_pieces.type_all > 0)
      compute_one_by_one<true>(eflag);
    else
      compute_one_by_one<false>(eflag);
  } else
    compute_chunked();
}

/* ----------------------------------------------------------------------
   the force loop of ordinary steps (bond_peridem_chunked.h) in portable C++,
   compiled with the build's flags; bond_style peridem/opt compiles the same
   loop for the vector units of the machine (bond_peridem_opt.cpp)
------------------------------------------------------------------------- */

namespace {
struct Portable {}; // the tag of this file's copy of the chunked passes
} // namespace

void BondPeridem::compute_chunked()
{
  chunked_passes<Portable>();
}

/* ----------------------------------------------------------------------
   one bond at a time, with energy and virial and either break order
------------------------------------------------------------------------- */

template <bool ONE_TYPE> void BondPeridem::compute_one_by_one(int eflag)
{
  struct OneByOne {
    PERIDEM_NS::BondForces out;
    BondPeridem *self;
    const double *x;
    int eflag;
    const double *r0c, *inv_r0, *kb;
    bool k_uniform;
    double k_value;
    double del[3] = {0.0, 0.0, 0.0}, r = 0.0, s = 0.0, ebond = 0.0;
    void piece(int) {}
    void measure(int n, int i1, int i2)
    {
      PERIDEM_NS::separation(x, i1, i2, del);
      r = std::sqrt(del[0] * del[0] + del[1] * del[1] + del[2] * del[2]);
      s = peridem::stretch_from_inverse(r, inv_r0[n]);
    }
    double stretch(int) const { return s; }
    double r0(int n) const { return r0c[n]; }
    void bond(int n, int i1, int i2, int)
    {
      // F/|y| of bond_force(c, w, s, V_i, V_j), with c w V_i V_j (and the
      // volume factor) in k; a positive force pulls i1 towards i2, and
      // LAMMPS's fbond multiplies x1 - x2
      const double k = k_uniform ? k_value : kb[n];
      const double fbond = r > 0.0 ? -peridem::bond_force_per_length(k, inv_r0[n], 1.0 / r) : 0.0;
      out.add(i1, i2, del[0], del[1], del[2], fbond);
      if (eflag) ebond = peridem::bond_energy(k, 1.0, s, r0c[n], 1.0, 1.0);
      if (self->evflag)
        self->ev_tally(i1, i2, out.nlocal, out.newton_bond, ebond, fbond, del[0], del[1], del[2]);
    }
  } kernel{{atom->f[0], atom->nlocal, force->newton_bond},
           this,
           atom->x[0],
           eflag,
           cache.r0.data(),
           cache.inv_r0.data(),
           cache.k.data(),
           cache.k_uniform,
           cache.k_value};

  // a bond that breaks now carries no force now, unless the user asked for the order of
  // LAMMPS's peri styles: force first, then break
  const PieceView pc = pieces();
  for_each_intact_bond<BREAK_EITHER, ONE_TYPE>(pc, 0, pc.npieces, kernel);
  kernel.out.finish();
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

void BondPeridem::fill_cache()
{
  // once per rebuild of the bond list (41 times in in.peri_impact's 1000 steps)
  fill_reference_lengths(cache.r0, &cache.inv_r0);
  const int nbondlist = neighbor->nbondlist;
  const int *bl = nbondlist > 0 ? neighbor->bondlist[0] : nullptr;
  const double *vfrac = atom->vfrac;
  const double *r0c = cache.r0.data();
  // k is often one value for the whole list (one material, equal node volumes, constant
  // micromodulus, no volume correction: the beds): then the force loop reads that value
  // instead of streaming 8 bytes per bond (28 -> 20 bytes per bond with the bond list and
  // 1/r0); the same double, so the same forces to the bit
  bool uniform = true, found = false;
  cache.k_value = 0.0;
  for (int n = 0; n < nbondlist && uniform; n++) {
    const int *b = bl + 3 * n;
    if (b[2] <= 0) continue;
    const double k = stiffness(b[2], r0c[n], vfrac[b[0]], vfrac[b[1]]);
    if (!found) {
      found = true;
      cache.k_value = k;
    } else if (k != cache.k_value)
      uniform = false;
  }
  cache.k_uniform = uniform; // also with no intact bond at all (k_value 0)
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
}

/* ----------------------------------------------------------------------
   bond-based: the bond force c w s V_i V_j (times the volume factor) is
   linear in the extension e = r - |xi| with slope c w V_i V_j/|xi|: the
   spring is exact, not a bound
------------------------------------------------------------------------- */

void BondPeridem::stability_springs(std::vector<double> &k)
{
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;
  k.assign(nbondlist, 0.0);
  for (int n = 0; n < nbondlist; n++) {
    const int type = bondlist[n][2];
    if (type <= 0) continue;
    const int i1 = bondlist[n][0], i2 = bondlist[n][1];
    const double r0 = reference_length(i1, i2);
    if (r0 > 0.0) k[n] = bond_stiffness(type, r0, i1, i2) / r0;
  }
}

/* ----------------------------------------------------------------------
   bond_coeff N material FILE NAME [horizon eps] [Gc value | s0 value] [micromodulus m]
              [spacing h] [break yes|no]
   bond_coeff N E|K value Gc value horizon eps [micromodulus m] [spacing h] [break yes|no]
   bond_coeff N c value s0 value horizon eps [micromodulus m] [spacing h] [break yes|no]
------------------------------------------------------------------------- */

bool BondPeridem::coeff_keyword(const std::string &key, const char *value, const char *style)
{
  ModelArgs &m = margs;
  if (key == "micromodulus") {
    m.micro = PERIDEM_NS::parse_micromodulus(lmp, COEFF, value);
    m.haveMicro = true;
  } else if (key == "E") {
    m.E = coeff_positive("E (Young's modulus)", value, style);
    m.haveE = true;
  } else if (key == "K") {
    m.K = coeff_positive("K (bulk modulus)", value, style);
    m.haveK = true;
  } else if (key == "c") {
    m.cval = coeff_positive("c (spring constant)", value, style);
    m.haveC = true;
  } else if (key == "G") {
    coeff_positive("G (shear modulus)", value, style);
    m.haveG = true;
  } else if (key == "influence") {
    m.haveInfluence = true;
  } else
    return false;
  return true;
}

void BondPeridem::coeff(int narg, char **arg)
{
  margs = ModelArgs();
  const CoeffArgs a = parse_coeff(narg, arg, STYLE);
  const ModelArgs &m = margs;
  const int dimension = domain->dimension;
  if (m.haveG || m.haveInfluence)
    error->all(FLERR,
               "{}: {} is a state-based coefficient; {} is bond-based (use bond_style "
               "peridem/lps for K and G)",
               COEFF, m.haveG ? "G" : "influence", STYLE);
  const double E = m.E, K = m.K, Gc = a.Gc, cval = m.cval, s0val = a.s0, eps = a.eps, h = a.h;
  const bool haveE = m.haveE, haveK = m.haveK, haveGc = a.haveGc, haveC = m.haveC,
             haveS0 = a.haveS0, haveMaterial = a.haveMaterial, haveMicro = m.haveMicro;
  const peridem::Micromodulus micro = m.micro;
  peridem::Material material = a.material;
  std::string origin = a.origin;
  const int ilo = a.ilo, ihi = a.ihi;

  // with a material, s0 (like Gc) overrides the file's: a critical stretch from a strength
  const int nsources =
      int(haveMaterial) + int(haveE || haveK) + int(haveC || (haveS0 && !haveMaterial));
  if (nsources != 1)
    error->all(FLERR,
               "{}: {} needs exactly one of: material FILE NAME; E or K with Gc and horizon; "
               "c with s0 and horizon",
               COEFF, STYLE);
  if (haveE && haveK) error->all(FLERR, "{}: give E or K, not both", COEFF);

  // the coefficients of the types, as derived from the keywords
  struct {
    double c = 0.0, s0 = 0.0, horizon = 0.0;
    peridem::Micromodulus micromodulus = peridem::Micromodulus::Constant;
    int breakable = 1;
  } p;
  try {
    if (haveMaterial) {
      p.micromodulus = haveMicro ? micro : material.micromodulus;
      material.micromodulus = p.micromodulus;
      // Gc overrides the file's, as horizon does (Bhattacharya & Lipton 2023 §6.4 vary only
      // G_c of their M1); it used to be ignored without a word
      if (haveGc && haveS0) error->all(FLERR, "{}: give Gc or s0, not both", COEFF);
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
      p.s0 = haveS0 ? s0val : bc.s0;
      if (haveS0) origin += fmt::format(", s0 = {}", s0val);
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
  p.breakable = a.breakable;
  for (int i = ilo; i <= ihi; i++) {
    set_shared_type(i, p.s0, p.horizon, h, p.breakable);
    c[i] = p.c;
    conic[i] = p.micromodulus == peridem::Micromodulus::Conic;
  }
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "{} type {}: c = {:.10g}, s0 = {:.10g}, horizon = {:.10g}, {} micromodulus, "
                   "{}d ({}){}\n",
                   STYLE, arg[0], p.c, p.s0, p.horizon,
                   PERIDEM_NS::micromodulus_name(p.micromodulus), dimension, origin,
                   p.breakable ? "" : ", unbreakable");
}

/* ----------------------------------------------------------------------
   restart: tag, the shared settings, then per type c, s0, horizon, spacing,
   micromodulus and break flag
------------------------------------------------------------------------- */

void BondPeridem::write_restart(FILE *fp)
{
  PERIDEM_NS::write_restart_tag(fp, PERIDEM_NS::RESTART_BOND_PERIDEM);
  write_restart_settings(fp);
  for (double *a : {c, s0, horizon, spacing}) write_types(fp, a);
  write_types(fp, conic);
  write_types(fp, breakable);
}

void BondPeridem::read_restart(FILE *fp)
{
  PERIDEM_NS::check_restart_tag(lmp, fp, PERIDEM_NS::RESTART_BOND_PERIDEM, "bond_style peridem");
  read_restart_settings(fp);
  allocate();
  const int n = atom->nbondtypes;
  for (double *a : {c, s0, horizon, spacing}) read_types(fp, a);
  read_types(fp, conic);
  read_types(fp, breakable);
  constexpr double big = std::numeric_limits<double>::max();
  PERIDEM_NS::check_restart_values(lmp, STYLE, "bond constant c", &c[1], n, 1e-300, big);
  PERIDEM_NS::check_restart_values(lmp, STYLE, "critical stretch", &s0[1], n, 1e-300, big);
  PERIDEM_NS::check_restart_values(lmp, STYLE, "horizon", &horizon[1], n, 1e-300, big);
  PERIDEM_NS::check_restart_values(lmp, STYLE, "spacing", &spacing[1], n, 0.0, big);
  PERIDEM_NS::check_restart_values(lmp, STYLE, "micromodulus", &conic[1], n, 0, 1);
  PERIDEM_NS::check_restart_values(lmp, STYLE, "break flag", &breakable[1], n, 0, 1);
  for (int i = 1; i <= n; i++) setflag[i] = 1;
}

/* ----------------------------------------------------------------------
   Bond Coeffs in the direct form, so a data file reproduces c and s0
------------------------------------------------------------------------- */

void BondPeridem::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->nbondtypes; i++) {
    const std::string line =
        fmt::format("{} c {:.17g} s0 {:.17g} horizon {:.17g} micromodulus {}", i, c[i], s0[i],
                    horizon[i], conic[i] ? "conic" : "constant") +
        data_tail(i);
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
  if (strcmp(str, "conic") == 0) return (void *)conic; // int per type: 1 conic micromodulus
  return BondPeridemBase::extract(str, dim);
}

/* ---------------------------------------------------------------------- */

double BondPeridem::memory_usage()
{
  return BondPeridemBase::memory_usage() +
         (cache.r0.capacity() + cache.inv_r0.capacity() + cache.k.capacity()) * sizeof(double);
}
