/* ----------------------------------------------------------------------
   PERIDEM: pair_style peridem/contact.

   The contact law (repulsion, damping, friction, self-contact) lives in
   peridem_contact_law.h (grain-shape seed §4.1-4.4, PeriDEM seed §2.2-2.3);
   this file applies it to LAMMPS's neighbour list. Nodes joined by an
   intact bond are excluded through the special list (special_bonds lj 0.0
   for 1-2 pairs); fix peridem/bonds removes a broken bond's nodes from each
   other's special lists, so the pieces of a broken grain touch again.
------------------------------------------------------------------------- */

#include "pair_peridem_contact.h"

#include "atom.h"
#include "bond.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include "lmp_peridem_compat.h"

#include <cmath>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;

namespace {
const char *const STYLE = "pair_style peridem/contact";
}

/* ---------------------------------------------------------------------- */

PairPeridemContact::PairPeridemContact(LAMMPS *lmp)
    : Pair(lmp), cut(nullptr), self_contact(1), dissipated(0.0)
{
  restartinfo = 1;
  single_enable = 0;
  writedata = 0;
  // compute pair ... returns the dissipated energy as its vector
  nextra = 1;
  pvector = new double[1];
  pvector[0] = 0.0;
}

PairPeridemContact::~PairPeridemContact()
{
  delete[] pvector;
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(cut);
  }
}

/* ---------------------------------------------------------------------- */

void PairPeridemContact::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  double **x0 = atom->x0;
  const double *vfrac = atom->vfrac;
  const double *rmass = atom->rmass;
  const tagint *molecule = atom->molecule;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton = force->newton_pair;
  const double dt = update->dt;

  const int inum = list->inum;
  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  double dissipated_now = 0.0;
  peridem::ContactInput in;
  in.dt = dt;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int itype = type[i];
    const int *jlist = firstneigh[i];
    for (int jj = 0; jj < numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const int jtype = type[j];
      const double dx = x[j][0] - x[i][0];
      const double dy = x[j][1] - x[i][1];
      const double dz = x[j][2] - x[i][2];
      if (dx * dx + dy * dy + dz * dz >= cutsq[itype][jtype]) continue;

      // same grain, no intact bond (bonded pairs are not in the list):
      // self-contact with the reference distance (grain-shape seed §4.4)
      in.ref_dist = -1.0;
      if (molecule[i] == molecule[j]) {
        if (!self_contact) continue;
        double d0[3] = {x0[j][0] - x0[i][0], x0[j][1] - x0[i][1], x0[j][2] - x0[i][2]};
        domain->minimum_image(d0[0], d0[1], d0[2]);
        in.ref_dist = std::sqrt(d0[0] * d0[0] + d0[1] * d0[1] + d0[2] * d0[2]);
      }
      in.sep[0] = dx;
      in.sep[1] = dy;
      in.sep[2] = dz;
      in.vrel[0] = v[i][0] - v[j][0];
      in.vrel[1] = v[i][1] - v[j][1];
      in.vrel[2] = v[i][2] - v[j][2];
      in.vol_i = vfrac[i];
      in.vol_j = vfrac[j];
      in.mass_i = rmass[i];
      in.mass_j = rmass[j];

      const peridem::ContactResult res = peridem::contact_force(in, spec[itype][jtype].params);
      if (!res.contact) continue;

      f[i][0] += res.f[0];
      f[i][1] += res.f[1];
      f[i][2] += res.f[2];
      const bool both = newton || j < nlocal;
      if (both) {
        f[j][0] -= res.f[0];
        f[j][1] -= res.f[1];
        f[j][2] -= res.f[2];
      }
      // a pair across ranks with newton off is computed on both ranks
      dissipated_now -= res.power * dt * (both ? 1.0 : 0.5);
      if (evflag)
        ev_tally_xyz(i, j, nlocal, newton, res.energy, 0.0, res.f[0], res.f[1], res.f[2], -dx, -dy,
                     -dz);
    }
  }
  dissipated += dissipated_now;
  pvector[0] = dissipated;
}

/* ----------------------------------------------------------------------
   pair_style peridem/contact [self yes|no]
------------------------------------------------------------------------- */

void PairPeridemContact::settings(int narg, char **arg)
{
  for (int iarg = 0; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (iarg + 1 >= narg) error->all(FLERR, "{}: keyword {} needs a value", STYLE, key);
    const std::string value = arg[iarg + 1];
    if (key == "self") {
      if (value == "yes")
        self_contact = 1;
      else if (value == "no")
        self_contact = 0;
      else
        error->all(FLERR, "{}: self must be yes or no, not {}", STYLE, value);
    } else
      error->all(FLERR, "{}: unknown keyword {}", STYLE, key);
  }
}

/* ---------------------------------------------------------------------- */

void PairPeridemContact::allocate()
{
  allocated = 1;
  const int n = atom->ntypes + 1;
  memory->create(setflag, n, n, "pair:setflag");
  memory->create(cutsq, n, n, "pair:cutsq");
  memory->create(cut, n, n, "pair:cut");
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      setflag[i][j] = 0;
      cut[i][j] = 0.0;
    }
  spec.assign(n, std::vector<PERIDEM::ContactSpec>(n));
}

/* ----------------------------------------------------------------------
   pair_coeff I J contact-keywords (see lmp_peridem_contact.h)
------------------------------------------------------------------------- */

void PairPeridemContact::coeff(int narg, char **arg)
{
  if (narg < 3)
    error->all(FLERR, "pair_coeff: {} needs two atom types and contact keywords", STYLE);
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const PERIDEM::ContactSpec s =
      PERIDEM::parse_contact(lmp, "pair_coeff", narg - 2, &arg[2], domain->dimension);
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      spec[i][j] = spec[j][i] = s;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "pair_coeff: no type pairs in {} {}", arg[0], arg[1]);
  if (comm->me == 0)
    utils::logmesg(lmp, "{} {} {}: {}\n", STYLE, arg[0], arg[1], PERIDEM::describe_contact(s));
}

/* ----------------------------------------------------------------------
   unlike types without their own pair_coeff: the harmonic mean of the two
   bulk moduli gives K_n (both seeds), the mean of the contact radii, and
   the damping and friction of the two types, which must agree
------------------------------------------------------------------------- */

void PairPeridemContact::mix(int i, int j)
{
  if (!setflag[i][i] || !setflag[j][j])
    error->all(FLERR, "{}: pair_coeff {} {} is not set and cannot be mixed from {} {} and {} {}",
               STYLE, i, j, i, i, j, j);
  const PERIDEM::ContactSpec &a = spec[i][i], &b = spec[j][j];
  PERIDEM::ContactSpec m = a;
  peridem::ContactParams &p = m.params;
  if (a.params.damping != b.params.damping || a.params.friction != b.params.friction)
    error->all(FLERR,
               "{}: types {} and {} use different damping or friction laws: give pair_coeff {} "
               "{} explicitly",
               STYLE, i, j, i, j);
  if (a.bulk_modulus > 0.0 && b.bulk_modulus > 0.0 && a.horizon > 0.0 && b.horizon > 0.0) {
    p.Kn = (a.horizon == b.horizon)
               ? peridem::contact_stiffness(a.bulk_modulus, b.bulk_modulus, a.horizon)
               : peridem::contact_stiffness_mixed(a.bulk_modulus, a.horizon, b.bulk_modulus,
                                                  b.horizon);
    m.bulk_modulus = peridem::harmonic_mean(a.bulk_modulus, b.bulk_modulus);
  } else {
    p.Kn = peridem::harmonic_mean(a.params.Kn, b.params.Kn);
  }
  p.kappa_eff = peridem::harmonic_mean(a.params.kappa_eff > 0 ? a.params.kappa_eff : 1.0,
                                       b.params.kappa_eff > 0 ? b.params.kappa_eff : 1.0);
  p.Rc = 0.5 * (a.params.Rc + b.params.Rc);
  p.r_d = 0.5 * (a.params.r_d + b.params.r_d);
  p.eps_n = 0.5 * (a.params.eps_n + b.params.eps_n);
  p.C = 0.5 * (a.params.C + b.params.C);
  p.mu = 0.5 * (a.params.mu + b.params.mu);
  m.origin = fmt::format("mixed from types {} and {}", i, j);
  spec[i][j] = spec[j][i] = m;
  if (comm->me == 0)
    utils::logmesg(lmp, "{} {} {}: {}\n", STYLE, i, j, PERIDEM::describe_contact(m));
}

double PairPeridemContact::init_one(int i, int j)
{
  if (!setflag[i][j]) mix(i, j);
  cut[i][j] = cut[j][i] = spec[i][j].params.Rc;
  return cut[i][j];
}

/* ---------------------------------------------------------------------- */

void PairPeridemContact::init_style()
{
  if (!atom->vfrac_flag || !atom->x0_flag || !atom->molecule_flag || !atom->rmass_flag)
    error->all(FLERR,
               "{} requires atom style peridem (per-atom volume, mass, reference position and "
               "grain ID)",
               STYLE);
  if (force->special_lj[1] != 0.0)
    error->all(FLERR,
               "{} requires special_bonds lj 0.0 for 1-2 pairs: nodes joined by an intact bond "
               "feel no contact (use special_bonds lj/coul 0.0 1.0 1.0)",
               STYLE);
  if (atom->nbonds > 0 && (force->special_lj[2] != 1.0 || force->special_lj[3] != 1.0))
    error->all(FLERR,
               "{} requires special_bonds lj weights 1.0 for 1-3 and 1-4 pairs: they are nodes "
               "that may touch (use special_bonds lj/coul 0.0 1.0 1.0)",
               STYLE);
  bool dissipative = false;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && (spec[i][j].params.damping != peridem::ContactDamping::None ||
                            spec[i][j].params.friction != peridem::ContactFriction::None))
        dissipative = true;
  if (dissipative && !comm->ghost_velocity)
    error->all(FLERR, "{} with damping or friction needs ghost velocities: use comm_modify vel yes",
               STYLE);
  PERIDEM::request_half_neighbor_list(neighbor, this, instance_me);
  report_time_step();
}

/* ----------------------------------------------------------------------
   the recommended time step from K_n, the bond constant and the smallest
   node mass (stable_time_step in peridem_contact_law.h); warn if exceeded
------------------------------------------------------------------------- */

void PairPeridemContact::report_time_step()
{
  double mine[3] = {std::numeric_limits<double>::max(), 0.0, 0.0}; // min mass, max V, max rho
  for (int i = 0; i < atom->nlocal; i++) {
    mine[0] = std::min(mine[0], atom->rmass[i]);
    mine[1] = std::max(mine[1], atom->vfrac[i]);
    mine[2] = std::max(mine[2], atom->rmass[i] / atom->vfrac[i]);
  }
  double minmass, maxvals[2];
  MPI_Allreduce(&mine[0], &minmass, 1, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(&mine[1], maxvals, 2, MPI_DOUBLE, MPI_MAX, world);
  if (atom->natoms == 0) return;

  peridem::TimeStepInput in;
  in.dimension = domain->dimension;
  in.min_node_mass = minmass;
  in.node_volume = maxvals[0];
  in.rho = minmass / maxvals[0];
  int dim = 0;
  const double *c = force->bond ? (double *)force->bond->extract("c", dim) : nullptr;
  const double *eps = force->bond ? (double *)force->bond->extract("horizon", dim) : nullptr;
  if (c && eps)
    for (int t = 1; t <= atom->nbondtypes; t++)
      if (c[t] > in.c) {
        in.c = c[t];
        in.horizon = eps[t];
      }
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      const peridem::ContactParams &p = spec[i][j].params;
      if (p.Kn > in.Kn) {
        in.Kn = p.Kn;
        in.Rc = p.Rc;
        in.damping_ratio = p.damping == peridem::ContactDamping::Nodal
                               ? p.r_d
                               : (p.damping == peridem::ContactDamping::Restitution
                                      ? peridem::damping_ratio_from_restitution(p.eps_n)
                                      : 0.0);
      }
    }
  const peridem::TimeStepEstimate est = peridem::stable_time_step(in);
  if (comm->me != 0) return;
  utils::logmesg(lmp, "{}: recommended time step {:.4g} (bonds {:.4g}, contact {:.4g})\n", STYLE,
                 est.dt_recommended, est.dt_bond, est.dt_contact);
  if (update->dt > est.dt_recommended)
    error->warning(FLERR, "{}: time step {} exceeds the recommended {:.4g}", STYLE, update->dt,
                   est.dt_recommended);
}

/* ---------------------------------------------------------------------- */

void PairPeridemContact::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (!setflag[i][j]) continue;
      const PERIDEM::ContactSpec &s = spec[i][j];
      fwrite(&s.params, sizeof(peridem::ContactParams), 1, fp);
      const double extra[3] = {s.bulk_modulus, s.horizon, s.density};
      fwrite(extra, sizeof(double), 3, fp);
    }
}

void PairPeridemContact::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (comm->me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (!setflag[i][j]) continue;
      PERIDEM::ContactSpec &s = spec[i][j];
      double extra[3];
      if (comm->me == 0) {
        utils::sfread(FLERR, &s.params, sizeof(peridem::ContactParams), 1, fp, nullptr, error);
        utils::sfread(FLERR, extra, sizeof(double), 3, fp, nullptr, error);
      }
      MPI_Bcast(&s.params, sizeof(peridem::ContactParams), MPI_BYTE, 0, world);
      MPI_Bcast(extra, 3, MPI_DOUBLE, 0, world);
      s.bulk_modulus = extra[0];
      s.horizon = extra[1];
      s.density = extra[2];
      s.origin = "restart file";
      spec[j][i] = s;
    }
}

void PairPeridemContact::write_restart_settings(FILE *fp)
{
  fwrite(&self_contact, sizeof(int), 1, fp);
  fwrite(&dissipated, sizeof(double), 1, fp);
}

void PairPeridemContact::read_restart_settings(FILE *fp)
{
  double total = 0.0;
  if (comm->me == 0) {
    utils::sfread(FLERR, &self_contact, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &total, sizeof(double), 1, fp, nullptr, error);
  }
  MPI_Bcast(&self_contact, 1, MPI_INT, 0, world);
  MPI_Bcast(&total, 1, MPI_DOUBLE, 0, world);
  // the dissipated energy so far continues on rank 0
  dissipated = comm->me == 0 ? total : 0.0;
  pvector[0] = dissipated;
}

/* ---------------------------------------------------------------------- */

void *PairPeridemContact::extract(const char *str, int &dim)
{
  dim = 0;
  if (strcmp(str, "dissipated") == 0) return (void *)&dissipated;
  return nullptr;
}

double PairPeridemContact::memory_usage()
{
  return Pair::memory_usage() + spec.size() * spec.size() * sizeof(PERIDEM::ContactSpec);
}
