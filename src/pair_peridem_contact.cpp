/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: pair_style peridem/contact.

   The contact law (repulsion, damping, friction, self-contact) lives in
   peridem_contact_law.h (Bhattacharya & Lipton 2023, §4.1-4.4, Jha et al. 2021, §2.2-2.3);
   this file applies it to LAMMPS's neighbour list. Nodes joined by an
   intact bond are excluded through the special list (special_bonds lj 0.0
   for 1-2 pairs); fix peridem/bonds removes a broken bond's nodes from each
   other's special lists, so the pieces of a broken grain touch again.
   damping centroid (Jha et al. 2021, §2.3.2) acts between grain centres:
   compute_centroid_damping below.
------------------------------------------------------------------------- */

#include "pair_peridem_contact.h"
#include "lmp_peridem_citations.h"

#include "bond_peridem_base.h"
#include "fix_peridem_vhistory.h"

#include "atom.h"
#include "bond.h"
#include "comm.h"
#include "domain.h"
#include "lmp_peridem_restart.h"
#include "lmp_peridem_bond_loop.h"
#include "lmp_peridem_grains.h"
#include "lmp_peridem_image.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "output.h"
#include "update.h"

#include "lmp_peridem_compat.h"
#include "lmp_peridem_parse.h"
#include "lmp_peridem_startup.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;

namespace {
const char *const STYLE = "pair_style peridem/contact";
}

/* ---------------------------------------------------------------------- */

PairPeridemContact::PairPeridemContact(LAMMPS *lmp)
    : Pair(lmp), cut(nullptr), self_contact(1), dissipated(0.0), centroid_on(0), grains_stale(true)
{
  PERIDEM_NS::cite_grain_shape(lmp);
  PERIDEM_NS::cite_peridem(lmp);
  restartinfo = 1;
  single_enable = 1;
  writedata = 0;
  // compute pair ... returns the dissipated energy as its vector
  nextra = 1;
  pvector = new double[1];
  pvector[0] = 0.0;
  // a bond broken in this step's bond computation: its nodes are no longer 1-2 neighbours and
  // touch from the next step on. LAMMPS's list excluded them (special_bonds lj 0.0); the copy
  // takes the pair now, as a rebuild would (the loop checks the distance), so no rebuild of
  // the lists is needed for contact between the pieces (the special lists are edited for the
  // next one). Pairs are kept once, with newton_pair on (fix peridem/bonds decides).
  broken_pair_sink = [this](int i, int j) {
    if (pairs_copied) pairs.push_back(i < atom->nlocal ? NodePair{i, j} : NodePair{j, i});
  };
  // the ghosts' shares of the dissipative forces go home (newton_pair on)
  comm_reverse = 3;
  // a restart file holds rank 0's share: before one can be written (restart N in a run, or
  // write_restart after it), rank 0 takes the shares of all ranks
  step_end = [this]() {
    count_work();
    if (update->ntimestep == output->next_restart) fold_dissipated();
  };
  run_end = [this]() { fold_dissipated(); };
}

PairPeridemContact::~PairPeridemContact()
{
  delete[] pvector;
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(cut);
    memory->destroy(touchsq);
  }
}

/* ----------------------------------------------------------------------
   the pairs of LAMMPS's neighbour list in its order (so the sums are the
   same, to the bit), without the atoms that have none. The contact list of
   a bed is sparse (bonded pairs are not in it: 0.14 pairs per node in the
   2000-grain bed), and walking LAMMPS's list over every node each step, and
   then to the other grain's node, took twice as long per pair as this copy,
   made once per build (bench/README.md).
------------------------------------------------------------------------- */

void PairPeridemContact::copy_neighbour_pairs()
{
  pairs.clear();
  const int *ilist = list->ilist, *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = ilist[ii];
    const int *jlist = firstneigh[i];
    for (int jj = 0; jj < numneigh[i]; jj++) pairs.push_back({i, jlist[jj] & NEIGHMASK});
  }
  pairs_copied = true;
}

void PairPeridemContact::grain_node_contacts(std::vector<std::array<int, 2>> &out) const
{
  out.clear();
  const double *x = atom->x ? atom->x[0] : nullptr;
  for (const NodePair &p : pairs) {
    if (atom->molecule[p.i] == atom->molecule[p.j]) continue;
    const double *xi = x + 3 * p.i, *xj = x + 3 * p.j;
    const double d[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]};
    const double Rc = spec[atom->type[p.i]][atom->type[p.j]].params.Rc;
    if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < Rc * Rc) out.push_back({p.i, p.j});
  }
}

/* ----------------------------------------------------------------------
   the contact law's input for the pair i, j (any two atoms within the
   cutoff); false for nodes of one grain without self-contact. Nodes of one
   grain are never joined by an intact bond here (bonded pairs are not in
   the neighbour list): they touch with the self-contact law, whose radius
   depends on the reference distance (Bhattacharya & Lipton 2023, §4.4).
------------------------------------------------------------------------- */

bool PairPeridemContact::pair_input(int i, int j, peridem::ContactInput &in) const
{
  // flat from x[0], v[0], x0[0] (LAMMPS's per-atom arrays are contiguous): in a big bed the
  // few nodes in contact are far apart in memory, and each row pointer was one more cache
  // miss before the data
  const double *xi = atom->x[0] + 3 * i, *xj = atom->x[0] + 3 * j;
  const double *vi = vel + 3 * i, *vj = vel + 3 * j;
  in.ref_dist = -1.0;
  if (atom->molecule[i] == atom->molecule[j]) {
    if (!self_contact) return false;
    const double *x0i = atom->x0[0] + 3 * i, *x0j = atom->x0[0] + 3 * j;
    double d0[3] = {x0j[0] - x0i[0], x0j[1] - x0i[1], x0j[2] - x0i[2]};
    PERIDEM_NS::minimum_image(domain, d0[0], d0[1], d0[2]);
    in.ref_dist = std::sqrt(d0[0] * d0[0] + d0[1] * d0[1] + d0[2] * d0[2]);
  }
  for (int k = 0; k < 3; k++) {
    in.sep[k] = xj[k] - xi[k];
    in.vrel[k] = vi[k] - vj[k];
  }
  in.vol_i = atom->vfrac[i];
  in.vol_j = atom->vfrac[j];
  in.mass_i = atom->rmass[i];
  in.mass_j = atom->rmass[j];
  in.dt = update->dt;
  return true;
}

const double *PairPeridemContact::velocities() const
{
  const double *setup = history ? history->setup_velocities() : nullptr;
  return setup ? setup : (atom->v ? atom->v[0] : nullptr);
}

/* ----------------------------------------------------------------------
   one pair for compute pair/local and compute group/group: the normal
   part of the pair force (repulsion and normal damping; friction is
   tangential and the centroid dashpot acts between grain centres, so
   neither is in it) as fforce with F_i = fforce (x_i - x_j), and the
   repulsion energy
------------------------------------------------------------------------- */

double PairPeridemContact::single(int i, int j, int itype, int jtype, double rsq,
                                  double /*factor_coul*/, double /*factor_lj*/, double &fforce)
{
  fforce = 0.0;
  vel = atom->v[0];
  peridem::ContactInput in;
  if (rsq <= 0.0 || !pair_input(i, j, in)) return 0.0;
  const peridem::ContactResult res = peridem::contact_force(in, spec[itype][jtype].params);
  if (!res.contact) return 0.0;
  // in.sep = x_j - x_i
  fforce = -(res.f[0] * in.sep[0] + res.f[1] * in.sep[1] + res.f[2] * in.sep[2]) / rsq;
  return res.energy;
}

/* ---------------------------------------------------------------------- */

void PairPeridemContact::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  // flat (pair_input explains); a rank without atoms may have no arrays yet
  const double *x = atom->x ? atom->x[0] : nullptr;
  double *f = atom->f ? atom->f[0] : nullptr;
  vel = velocities();
  const tagint *molecule = atom->molecule;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton = force->newton_pair;

  // the pairs of the neighbour list, copied when LAMMPS has just built it (neighbor->ago is 0
  // in the step of every build: runs, minimisation, each snapshot of rerun)
  if (neighbor->ago == 0 || !pairs_copied) copy_neighbour_pairs();
  const int npairs = int(pairs.size());

  // the dissipative forces per node, for their work with the full-step velocities (count_work):
  // in every step of a run and in its setup (the first end of the trapezoid), not in a
  // minimisation. With newton_pair off a pair across ranks is computed on both ranks: each
  // gives its owned node its share.
  const bool keep_fdis = history && update->whichflag == 1;
  if (keep_fdis) start_fdis();
  touch_local.clear();
  peridem::ContactInput in;

  for (int p = 0; p < npairs; p++) {
    const int i = pairs[p].i, j = pairs[p].j;
    const int itype = type[i];
    const int jtype = type[j];
    const double *xi = x + 3 * i, *xj = x + 3 * j;
    const double dx = xj[0] - xi[0];
    const double dy = xj[1] - xi[1];
    const double dz = xj[2] - xi[2];
    const double rsq = dx * dx + dy * dy + dz * dz;
    if (rsq >= cutsq[itype][jtype]) continue;
    const PERIDEM_NS::ContactSpec &sp = spec[itype][jtype];

    // two grains touch (closer than R_c, or centroid_range): damping
    // centroid of this grain pair (Jha et al. 2021, eq. 27)
    if (sp.centroid && sp.centroid_bounding == 0.0 && molecule[i] != molecule[j] &&
        rsq < touchsq[itype][jtype]) {
      if (molecule[i] < molecule[j])
        touch_local.push_back({molecule[i], molecule[j], itype, jtype});
      else
        touch_local.push_back({molecule[j], molecule[i], jtype, itype});
    }

    if (!pair_input(i, j, in)) continue;
    const peridem::ContactResult res = peridem::contact_force(in, sp.params);
    if (!res.contact) continue;

    PERIDEM_NS::add_force(f, i, res.f[0], res.f[1], res.f[2]);
    const bool both = newton || j < nlocal;
    if (both) PERIDEM_NS::add_force(f, j, -res.f[0], -res.f[1], -res.f[2]);
    if (keep_fdis) {
      const double g[3] = {res.f_damp[0] + res.f_fric[0], res.f_damp[1] + res.f_fric[1],
                           res.f_damp[2] + res.f_fric[2]};
      add_fdis(i, g[0], g[1], g[2]);
      if (both) add_fdis(j, -g[0], -g[1], -g[2]);
    }
    if (evflag)
      ev_tally_xyz(i, j, nlocal, newton, res.energy, 0.0, res.f[0], res.f[1], res.f[2], -dx, -dy,
                   -dz);
  }
  // global virial as sum f . r of the node pairs (newton on); the centroid
  // dashpots below tally their own, from the unwrapped centres
  // (virial_fdotr_compute() clears vflag_fdotr: decide the centroid tally first, or
  // the centroid dashpots were left out of the virial with newton_pair on)
  const bool centroid_virial = vflag_global || vflag_fdotr;
  if (vflag_fdotr) virial_fdotr_compute();
  if (centroid_on) compute_centroid_damping(centroid_virial, keep_fdis);
  if (keep_fdis && newton) PERIDEM_NS::reverse_comm(comm, this);
  // a setup has v(n) already: the power of the step it continues, or of the state it starts from
  if (keep_fdis && update->setupflag) power_prev = dissipative_power();
  if (keep_fdis && !update->setupflag) fdis_step = update->ntimestep;
}

// clears the slots of the last call and makes room for every atom slot
void PairPeridemContact::start_fdis()
{
  for (const int i : fdis_slots)
    fdis[3 * std::size_t(i)] = fdis[3 * std::size_t(i) + 1] = fdis[3 * std::size_t(i) + 2] = 0.0;
  fdis_slots.clear();
  const std::size_t nmax = atom->nmax;
  if (fdis_mark.size() < nmax) {
    fdis.resize(3 * nmax, 0.0);
    fdis_mark.resize(nmax, 0);
  }
  if (++fdis_call == std::numeric_limits<int>::max()) {
    std::fill(fdis_mark.begin(), fdis_mark.end(), 0);
    fdis_call = 1;
  }
}

/* ----------------------------------------------------------------------
   the work of the dissipative forces (damping, friction, centroid dashpot)
   with the full-step velocities of velocity Verlet: with P(n) = sum_i
   F_i(n) . v_i(n), F_i(n) those forces on node i in step n (they take
   v(n - 1/2)) and v_i(n) its velocity after the second half-kick, each
   step adds -(P(n - 1) + P(n)) dt/2 (peridem::dissipated_in_step: the
   trapezoidal rule, by which the integrator changes the kinetic energy), so
   E + dissipated is as constant as E alone is without damping and
   friction. The power at the velocities the forces take, F(n) . v(n - 1/2),
   counts stuck contacts wrong: a friction force that reverses a node's
   velocity u in one step (v(n + 1/2) = -u) takes no energy, but
   -F . v(n - 1/2) dt = 2 m |u|^2 counts it as lost, at every step at a node
   held by several contacts, where the force flips while the node hardly
   moves (17x the energy balance in examples/sheared-fault); v(n + 1/2) would
   count it as gained. v(n) = 0 there; a force that stops a node
   (v(n + 1/2) = 0) counts the kinetic energy m |u|^2/2 it takes. The work
   is negative where the forces feed energy in, as the regularized stick
   branch does at a node stuck to three partners or more
   (peridem_contact_law.h). P(n - 1) of a run's first step is that of its
   setup, which computes the forces of the step it continues (the same
   P(n), so a split or restarted run adds up as one), or of a fresh start.
   Atoms do not change ranks or places between the force and here;
   power_prev is a rank's share of a sum, which migration does not change.
------------------------------------------------------------------------- */

double PairPeridemContact::dissipative_power() const
{
  const double *v = atom->v ? atom->v[0] : nullptr;
  const int nlocal = atom->nlocal;
  double power = 0.0;
  for (const int i : fdis_slots) {
    if (i >= nlocal) continue; // a ghost: its share went home
    const double *fd = &fdis[3 * std::size_t(i)], *vi = v + 3 * std::size_t(i);
    power += fd[0] * vi[0] + fd[1] * vi[1] + fd[2] * vi[2];
  }
  return power;
}

void PairPeridemContact::count_work()
{
  if (fdis_step != update->ntimestep) return;
  fdis_step = -1;
  dissipated += peridem::dissipated_in_step(power_prev, dissipative_power(), update->dt);
  pvector[0] = dissipated;
}

void PairPeridemContact::fold_dissipated()
{
  double total = 0.0;
  MPI_Allreduce(&dissipated, &total, 1, MPI_DOUBLE, MPI_SUM, world);
  dissipated = comm->me == 0 ? total : 0.0;
  pvector[0] = dissipated;
}

int PairPeridemContact::pack_reverse_comm(int n, int first, double *buf)
{
  const double *fd = fdis.data() + 3 * std::size_t(first);
  std::copy(fd, fd + 3 * n, buf);
  return 3 * n;
}

void PairPeridemContact::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int k = 0; k < n; k++) {
    const double *b = buf + 3 * k;
    if (b[0] != 0.0 || b[1] != 0.0 || b[2] != 0.0) add_fdis(list[k], b[0], b[1], b[2]);
  }
}

/* ----------------------------------------------------------------------
   damping centroid, Jha et al. 2021, §2.3.2: for every pair of grains p, p'
   with two nodes closer than R_c (eq. 27: dist(p, p') < R_c)
     F = -beta_bar max(0, (v_c - v_c') . e_c) e_c   on p,  -F on p'
   (centroid_damping_force, eq. 26-27), beta_bar from eq. 28 with
   M_eq = harmonic mean of the grain masses (eq. 29). Eq. 30 gives each
   node x of p the force density F/|Omega_p|, i.e. the force F V_x/|Omega_p|;
   we use the mass share F m_x/M_p, the same for a grain of uniform density,
   so that the dashpot only decelerates the centre (all nodes of the grain
   get the acceleration F/M_p) and its power is exactly F . (v_c - v_c').
   keep_fdis: the nodal shares are kept with the other dissipative forces,
   for their work at the end of the step (count_work).
------------------------------------------------------------------------- */

void PairPeridemContact::compute_centroid_damping(bool tally_virial, bool keep_fdis)
{
  // the grain pairs in contact, from all ranks, sorted and unique (one entry
  // per grain pair, the smallest type pair), so that every rank and every
  // rank count applies the same forces in the same order
  auto same_grains = [](const std::array<tagint, 4> &a, const std::array<tagint, 4> &b) {
    return a[0] == b[0] && a[1] == b[1];
  };
  std::sort(touch_local.begin(), touch_local.end());
  touch_local.erase(std::unique(touch_local.begin(), touch_local.end(), same_grains),
                    touch_local.end());
  const int mine = 4 * (int)touch_local.size();
  const int total = gather_counts(mine);
  // no grains in contact anywhere: nothing to do (unless grains touch by their bounding radii)
  if (total == 0 && !bounding_on) return;
  touch_all.resize(total / 4);
  if (total > 0)
    MPI_Allgatherv(touch_local.empty() ? nullptr : touch_local[0].data(), mine, MPI_LMP_TAGINT,
                   touch_all[0].data(), counts.data(), displs.data(), MPI_LMP_TAGINT, world);

  // centres of mass and velocities of all grains (eq. 26)
  sum_grain_centres();
  if (bounding_on) add_bounding_touches();
  std::sort(touch_all.begin(), touch_all.end());
  touch_all.erase(std::unique(touch_all.begin(), touch_all.end(), same_grains), touch_all.end());
  const int ngrains = (int)grain_ids.size();
  grain_force.assign(3 * ngrains, 0.0);
  const bool tally = tally_virial && comm->me == 0;
  for (const auto &t : touch_all) {
    const int a = grain_index(t[0]), b = grain_index(t[1]);
    if (a < 0 || b < 0) continue;
    const double *sa = &grain_sum[7 * a], *sb = &grain_sum[7 * b];
    if (!(sa[0] > 0.0) || !(sb[0] > 0.0)) continue;
    double sep[3], vrel[3], fc[3];
    for (int k = 0; k < 3; k++) {
      sep[k] = sb[1 + k] / sb[0] - sa[1 + k] / sa[0];  // z_c' - z_c
      vrel[k] = sa[4 + k] / sa[0] - sb[4 + k] / sb[0]; // v_c - v_c'
    }
    domain->minimum_image(sep[0], sep[1], sep[2]);
    const peridem::ContactParams &p = spec[t[2]][t[3]].params;
    const double m_eq = peridem::harmonic_mean(sa[0], sb[0]); // eq. 29
    const double beta =
        peridem::restitution_damping_coefficient(p.eps_n, p.C, p.kappa_eff, p.Rc, m_eq);
    peridem::centroid_damping_force(sep, vrel, beta, true, fc);
    for (int k = 0; k < 3; k++) {
      grain_force[3 * a + k] += fc[k];
      grain_force[3 * b + k] -= fc[k];
    }
    // virial of the pair of centre forces (F on z_c, -F on z_c'), once
    if (tally) {
      virial[0] -= fc[0] * sep[0];
      virial[1] -= fc[1] * sep[1];
      virial[2] -= fc[2] * sep[2];
      virial[3] -= fc[0] * sep[1];
      virial[4] -= fc[0] * sep[2];
      virial[5] -= fc[1] * sep[2];
    }
  }
  // eq. 30: the share m_x/M_p of the force on grain p to each of its nodes
  double **f = atom->f;
  const double *rmass = atom->rmass;
  for (int i = 0; i < atom->nlocal; i++) {
    const int g = grain_of[i];
    if (g < 0) continue;
    const double *fg = &grain_force[3 * g];
    if (fg[0] == 0.0 && fg[1] == 0.0 && fg[2] == 0.0) continue;
    const double share = rmass[i] / grain_sum[7 * g];
    f[i][0] += share * fg[0];
    f[i][1] += share * fg[1];
    f[i][2] += share * fg[2];
    if (keep_fdis) add_fdis(i, share * fg[0], share * fg[1], share * fg[2]);
  }
}

/* ----------------------------------------------------------------------
   centroid_bounding F (Jha et al.'s code, prashjha/PeriDEM demModel.cpp):
   two grains touch while their centres are closer than b + b' + F R_c, b
   the bounding radius of each grain. Every rank has all centres
   (grain_sum), so every rank finds the same pairs: sorted by the centres'
   x, each grain is checked against those within reach along x (all pairs
   when x is periodic)
------------------------------------------------------------------------- */

void PairPeridemContact::add_bounding_touches()
{
  if (bounding_stale) compute_bounding_radii();
  const int ngrains = (int)grain_ids.size();
  double reach_max = 0.0, b_max = 0.0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++)
      if (spec[i][j].centroid && spec[i][j].centroid_bounding > 0.0)
        reach_max = std::max(reach_max, spec[i][j].centroid_bounding * spec[i][j].params.Rc);
  order.clear();
  for (int g = 0; g < ngrains; g++)
    if (grain_sum[7 * g] > 0.0 && grain_type[g] > 0) {
      order.push_back(g);
      b_max = std::max(b_max, bounding[g]);
    }
  auto cx = [&](int g) { return grain_sum[7 * g + 1] / grain_sum[7 * g]; };
  const bool sweep = !domain->xperiodic;
  if (sweep) std::sort(order.begin(), order.end(), [&](int a, int b) { return cx(a) < cx(b); });
  const int n = (int)order.size();
  for (int u = 0; u < n; u++) {
    const int a = order[u];
    const double *sa = &grain_sum[7 * a];
    for (int w = u + 1; w < n; w++) {
      const int b = order[w];
      const double *sb = &grain_sum[7 * b];
      double sep[3];
      for (int k = 0; k < 3; k++) sep[k] = sb[1 + k] / sb[0] - sa[1 + k] / sa[0];
      if (sweep && sep[0] > bounding[a] + b_max + reach_max) break;
      const int ta = grain_type[a], tb = grain_type[b];
      const PERIDEM_NS::ContactSpec &sp = spec[ta][tb];
      if (!sp.centroid || !(sp.centroid_bounding > 0.0)) continue;
      domain->minimum_image(sep[0], sep[1], sep[2]);
      const double d = bounding[a] + bounding[b] + sp.centroid_bounding * sp.params.Rc;
      if (sep[0] * sep[0] + sep[1] * sep[1] + sep[2] * sep[2] >= d * d) continue;
      if (grain_ids[a] < grain_ids[b])
        touch_all.push_back({grain_ids[a], grain_ids[b], ta, tb});
      else
        touch_all.push_back({grain_ids[b], grain_ids[a], tb, ta});
    }
  }
}

/* ----------------------------------------------------------------------
   bounding radius of every grain: the largest distance of its nodes from
   its centre of mass in the reference configuration (x0), and the largest
   atom type of its nodes (the type pair of the dashpot); at each run and
   when the grains change
------------------------------------------------------------------------- */

void PairPeridemContact::compute_bounding_radii()
{
  if (grains_stale) build_grain_index();
  const int ngrains = (int)grain_ids.size();
  const int nlocal = atom->nlocal;
  double **x0 = atom->x0;
  const double *rmass = atom->rmass;
  const int *type = atom->type;
  std::vector<double> local(4 * ngrains, 0.0), centre(4 * ngrains);
  std::vector<int> gi(nlocal);
  for (int i = 0; i < nlocal; i++) {
    const int g = gi[i] = grain_index(atom->molecule[i]);
    if (g < 0) continue;
    local[4 * g] += rmass[i];
    for (int k = 0; k < 3; k++) local[4 * g + 1 + k] += rmass[i] * x0[i][k];
  }
  MPI_Allreduce(local.data(), centre.data(), 4 * ngrains, MPI_DOUBLE, MPI_SUM, world);
  std::vector<double> rmax(ngrains, 0.0);
  std::vector<int> tmax(ngrains, 0);
  for (int i = 0; i < nlocal; i++) {
    const int g = gi[i];
    if (g < 0 || !(centre[4 * g] > 0.0)) continue;
    double r2 = 0.0;
    for (int k = 0; k < 3; k++) {
      const double d = x0[i][k] - centre[4 * g + 1 + k] / centre[4 * g];
      r2 += d * d;
    }
    rmax[g] = std::max(rmax[g], std::sqrt(r2));
    tmax[g] = std::max(tmax[g], type[i]);
  }
  bounding.resize(ngrains);
  grain_type.resize(ngrains);
  MPI_Allreduce(rmax.data(), bounding.data(), ngrains, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(tmax.data(), grain_type.data(), ngrains, MPI_INT, MPI_MAX, world);
  bounding_stale = false;
}

/* ----------------------------------------------------------------------
   counts and displs of an MPI_Allgatherv of n items per rank; the total
------------------------------------------------------------------------- */

int PairPeridemContact::gather_counts(int n)
{
  return PERIDEM_NS::gather_counts(world, n, counts, displs);
}

/* ----------------------------------------------------------------------
   grain index of a grain (molecule) ID: a table when the IDs are dense,
   otherwise a binary search in the sorted list; -1 if unknown
------------------------------------------------------------------------- */

int PairPeridemContact::grain_index(tagint id) const
{
  if (!grain_table.empty())
    return (id >= 0 && id < (tagint)grain_table.size()) ? grain_table[id] : -1;
  const auto it = std::lower_bound(grain_ids.begin(), grain_ids.end(), id);
  return (it != grain_ids.end() && *it == id) ? (int)(it - grain_ids.begin()) : -1;
}

/* ----------------------------------------------------------------------
   the list of all grain IDs, gathered from all ranks; rebuilt at each run
   and when a node of an unknown grain appears (atoms created in a run)
------------------------------------------------------------------------- */

void PairPeridemContact::build_grain_index()
{
  const tagint *molecule = atom->molecule;
  std::vector<tagint> mine(molecule, molecule + atom->nlocal);
  std::sort(mine.begin(), mine.end());
  mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
  const int n = (int)mine.size();
  grain_ids.resize(gather_counts(n));
  MPI_Allgatherv(mine.data(), n, MPI_LMP_TAGINT, grain_ids.data(), counts.data(), displs.data(),
                 MPI_LMP_TAGINT, world);
  std::sort(grain_ids.begin(), grain_ids.end());
  grain_ids.erase(std::unique(grain_ids.begin(), grain_ids.end()), grain_ids.end());

  grain_table.clear();
  const tagint ngrains = (tagint)grain_ids.size();
  if (ngrains > 0 && grain_ids.front() >= 0 && grain_ids.back() < 4 * ngrains + 1024) {
    grain_table.assign(grain_ids.back() + 1, -1);
    for (tagint g = 0; g < ngrains; g++) grain_table[grain_ids[g]] = (int)g;
  }
  grains_stale = false;
  bounding_stale = true;
}

/* ----------------------------------------------------------------------
   grain_sum[7 g .. 7 g + 6] = M_p, M_p z_c, M_p v_c of every grain, summed
   over the owned nodes of all ranks (positions unwrapped with the image
   flags, so a grain across a periodic boundary has one centre)
------------------------------------------------------------------------- */

void PairPeridemContact::sum_grain_centres()
{
  const int nlocal = atom->nlocal;
  for (int attempt = 0; attempt < 2; attempt++) {
    if (grains_stale) build_grain_index();
    const int ngrains = (int)grain_ids.size();
    grain_local.assign(7 * ngrains + 1, 0.0);
    grain_of.resize(nlocal);
    double **x = atom->x;
    const double *rmass = atom->rmass;
    const tagint *molecule = atom->molecule;
    const imageint *image = atom->image;
    for (int i = 0; i < nlocal; i++) {
      const int g = grain_of[i] = grain_index(molecule[i]);
      if (g < 0) {
        grain_local[7 * ngrains] += 1.0; // a grain created since the last build
        continue;
      }
      double xu[3];
      domain->unmap(x[i], image[i], xu);
      double *s = &grain_local[7 * g];
      const double m = rmass[i];
      s[0] += m;
      for (int k = 0; k < 3; k++) {
        s[1 + k] += m * xu[k];
        s[4 + k] += m * vel[3 * i + k];
      }
    }
    grain_sum.resize(grain_local.size());
    MPI_Allreduce(grain_local.data(), grain_sum.data(), (int)grain_local.size(), MPI_DOUBLE,
                  MPI_SUM, world);
    if (grain_sum[7 * ngrains] == 0.0) return;
    grains_stale = true; // all ranks see the same sum and rebuild together
  }
  error->all(FLERR, "{}: internal error: grain list incomplete after rebuild", STYLE);
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
      self_contact = PERIDEM_NS::yes_no(lmp, STYLE, key, value);
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
  memory->create(touchsq, n, n, "pair:touchsq");
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      setflag[i][j] = 0;
      cut[i][j] = touchsq[i][j] = 0.0;
    }
  spec.assign(n, std::vector<PERIDEM_NS::ContactSpec>(n));
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
  const PERIDEM_NS::ContactSpec s =
      PERIDEM_NS::parse_contact(lmp, "pair_coeff", narg - 2, &arg[2], domain->dimension, true);
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      spec[i][j] = spec[j][i] = s;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "pair_coeff: no type pairs in {} {}", arg[0], arg[1]);
  if (comm->me == 0)
    utils::logmesg(lmp, "{} {} {}: {}\n", STYLE, arg[0], arg[1], PERIDEM_NS::describe_contact(s));
}

/* ----------------------------------------------------------------------
   unlike types without their own pair_coeff: the harmonic mean of the two
   bulk moduli gives K_n (both papers), the mean of the contact radii, and
   the damping and friction of the two types, which must agree
------------------------------------------------------------------------- */

void PairPeridemContact::mix(int i, int j)
{
  if (!setflag[i][i] || !setflag[j][j])
    error->all(FLERR, "{}: pair_coeff {} {} is not set and cannot be mixed from {} {} and {} {}",
               STYLE, i, j, i, i, j, j);
  const PERIDEM_NS::ContactSpec &a = spec[i][i], &b = spec[j][j];
  PERIDEM_NS::ContactSpec m = a;
  peridem::ContactParams &p = m.params;
  if (a.params.damping != b.params.damping || a.params.friction != b.params.friction ||
      a.centroid != b.centroid)
    error->all(FLERR,
               "{}: types {} and {} use different damping or friction laws: give pair_coeff {} "
               "{} explicitly",
               STYLE, i, j, i, j);
  if (a.kn_form != b.kn_form)
    error->all(FLERR,
               "{}: types {} and {} use different Kn_form ({} and {}): give pair_coeff {} {} "
               "explicitly",
               STYLE, i, j, peridem::kn_form_name(a.kn_form), peridem::kn_form_name(b.kn_form), i,
               j);
  if (a.bulk_modulus > 0.0 && b.bulk_modulus > 0.0 && a.horizon > 0.0 && b.horizon > 0.0) {
    p.Kn = (a.horizon == b.horizon)
               ? peridem::contact_stiffness(a.bulk_modulus, b.bulk_modulus, a.horizon, a.kn_form)
               : peridem::contact_stiffness_mixed(a.bulk_modulus, a.horizon, b.bulk_modulus,
                                                  b.horizon, a.kn_form);
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
  m.centroid_range = (a.centroid_range > 0.0 || b.centroid_range > 0.0)
                         ? 0.5 * (a.centroid_reach() + b.centroid_reach())
                         : 0.0;
  m.centroid_bounding = (a.centroid_bounding > 0.0 && b.centroid_bounding > 0.0)
                            ? 0.5 * (a.centroid_bounding + b.centroid_bounding)
                            : 0.0;
  m.origin = fmt::format("mixed from types {} and {}", i, j);
  m.kappa_origin = fmt::format("harmonic mean of types {} and {}, Jha et al. 2021 eq. 25", i, j);
  spec[i][j] = spec[j][i] = m;
  if (comm->me == 0)
    utils::logmesg(lmp, "{} {} {}: {}\n", STYLE, i, j, PERIDEM_NS::describe_contact(m));
}

double PairPeridemContact::init_one(int i, int j)
{
  if (!setflag[i][j]) mix(i, j);
  const PERIDEM_NS::ContactSpec &s = spec[i][j];
  const double touch = s.centroid && s.centroid_bounding == 0.0 ? s.centroid_reach() : 0.0;
  if (s.centroid && s.centroid_bounding > 0.0) bounding_on = 1;
  touchsq[i][j] = touchsq[j][i] = touch * touch;
  cut[i][j] = cut[j][i] = std::max(s.params.Rc, touch);
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
  // 'special_bonds lj 0.0 1.0 1.0' leaves the coul weights at 0, and LAMMPS
  // then builds 1-3 and 1-4 lists of every node's horizon neighbours' partners
  // (46 s for 2197 nodes, developer notes): refuse it
  if (atom->nbonds > 0 && (force->special_coul[2] != 1.0 || force->special_coul[3] != 1.0))
    error->all(FLERR,
               "{} requires special_bonds coul weights 1.0 for 1-3 and 1-4 pairs too (now {} "
               "and {}): 'special_bonds lj 0.0 1.0 1.0' leaves them at 0 and LAMMPS builds huge "
               "1-3/1-4 lists (use special_bonds lj/coul 0.0 1.0 1.0)",
               STYLE, force->special_coul[2], force->special_coul[3]);
  bool dissipative = false;
  centroid_on = 0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (setflag[i][j] && (spec[i][j].params.damping != peridem::ContactDamping::None ||
                            spec[i][j].params.friction != peridem::ContactFriction::None))
        dissipative = true;
      // unset unlike pairs are mixed later only from two centroid types
      if (setflag[i][j] && spec[i][j].centroid) centroid_on = 1;
    }
  // the grains (molecule IDs) may have changed since the last run
  grains_stale = true;
  bounding_on = 0; // set by init_one for type pairs with centroid_bounding
  if (dissipative && !comm->ghost_velocity)
    error->all(FLERR, "{} with damping or friction needs ghost velocities: use comm_modify vel yes",
               STYLE);
  // damping, friction and the centroid dashpot take v: a run's setup must see the v(n - 1/2)
  // of the step it continues (fix peridem/vhistory)
  history = dissipative || centroid_on ? FixPeridemVelocityHistory::instance(lmp, STYLE) : nullptr;
  PERIDEM_NS::request_half_neighbor_list(neighbor, this, instance_me);
  double reach = 0.0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j])
        reach = std::max(
            {reach, spec[i][j].params.Rc, spec[i][j].centroid ? spec[i][j].centroid_reach() : 0.0});
  PERIDEM_NS::check_neighbor_skin(lmp, STYLE, reach);
}

/* ----------------------------------------------------------------------
   after the first neighbour build of the first run: nodes of different
   grains already in contact (start-up check, lmp_peridem_startup.h)
------------------------------------------------------------------------- */

void PairPeridemContact::setup()
{
  // after the neighbour build: the bond list of this run is there
  report_time_step();
  if (start_checked) return;
  start_checked = true;
  report_start_overlaps();
}

void PairPeridemContact::report_start_overlaps()
{
  double **x = atom->x;
  const tagint *molecule = atom->molecule;
  const int *type = atom->type;
  PERIDEM_NS::OverlapReport overlaps;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (molecule[i] == molecule[j]) continue;
      const double Rc = spec[type[i]][type[j]].params.Rc;
      const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
      if (dx * dx + dy * dy + dz * dz < Rc * Rc)
        overlaps.add(molecule[i], fmt::format("grain {}", molecule[j]));
    }
  }
  double rc_max = 0.0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j]) rc_max = std::max(rc_max, spec[i][j].params.Rc);
  overlaps.report(lmp, STYLE, "node pairs of different grains", rc_max);
}

/* ----------------------------------------------------------------------
   the recommended time step from K_n, the bond constant and the smallest
   node mass (stable_time_step in peridem_contact_law.h); warn if exceeded
------------------------------------------------------------------------- */

void PairPeridemContact::report_time_step()
{
  // per atom type: smallest node mass, largest node volume, smallest density
  const int nt = atom->ntypes;
  std::vector<double> mine(3 * (nt + 1)), all(3 * (nt + 1));
  // the largest volume is stored negated, so that one MPI_MIN reduces all three
  for (double &v : mine) v = std::numeric_limits<double>::max();
  for (int i = 0; i < atom->nlocal; i++) {
    double *m = &mine[3 * atom->type[i]];
    m[0] = std::min(m[0], atom->rmass[i]);
    m[1] = std::min(m[1], -atom->vfrac[i]);
    m[2] = std::min(m[2], atom->rmass[i] / atom->vfrac[i]);
  }
  MPI_Allreduce(mine.data(), all.data(), (int)mine.size(), MPI_DOUBLE, MPI_MIN, world);
  if (atom->natoms == 0) return;

  // the bonds' part of the bound (BondPeridemBase::stability_omega2_of_types)
  auto *bonds = dynamic_cast<BondPeridemBase *>(force->bond);
  const std::vector<double> bond_omega2 =
      bonds ? bonds->stability_omega2_of_types() : std::vector<double>(nt + 1, 0.0);
  const std::vector<std::array<double, 2>> wall_laws = own_wall_laws();

  peridem::TimeStepEstimate overall;
  std::string lines;
  for (int i = 1; i <= nt; i++)
    for (int j = i; j <= nt; j++) {
      const double *a = &all[3 * i], *b = &all[3 * j];
      if (a[0] == std::numeric_limits<double>::max() || b[0] == std::numeric_limits<double>::max())
        continue; // a type without nodes
      if (!setflag[i][j] && !(setflag[i][i] && setflag[j][j])) continue;
      const peridem::ContactParams &p = spec[i][j].params;
      peridem::TimeStepInput in;
      in.dimension = domain->dimension;
      in.min_node_mass = std::min(a[0], b[0]);
      in.node_volume = std::max(-a[1], -b[1]);
      in.rho = std::min(a[2], b[2]);
      in.bond_omega2 = std::max(bond_omega2[i], bond_omega2[j]);
      in.walls = PERIDEM_NS::has_fix_style(modify, "^peridem/wall");
      in.wall_laws = wall_laws;
      in.Kn = p.Kn;
      in.Rc = p.Rc;
      in.damping_ratio = p.damping == peridem::ContactDamping::Nodal
                             ? p.r_d
                             : (p.damping == peridem::ContactDamping::Restitution
                                    ? peridem::damping_ratio_from_restitution(p.eps_n)
                                    : 0.0);
      peridem::TimeStepEstimate est;
      try {
        est = peridem::stable_time_step(in);
      } catch (peridem::ParameterError &e) {
        error->all(FLERR, "{}: time step estimate for types {} {}: {}", STYLE, i, j, e.what());
      }
      lines += fmt::format("{}: types {} {}: time step estimate {:.4g} (critical {:.4g}: bonds "
                           "{:.4g}, contact {:.4g} with damping ratio {:.3g}, {:.3g} pair springs "
                           "for contacts shallower than {:.3g})\n",
                           STYLE, i, j, est.dt_recommended, est.dt_critical, est.dt_bond,
                           est.dt_contact, in.damping_ratio, est.n_contacts, est.shallow_depth);
      if (!wall_laws.empty()) lines.insert(lines.size() - 2, wall_law_note(wall_laws));
      if (est.dt_recommended < overall.dt_recommended) overall = est;
    }
  if (comm->me != 0 || lines.empty()) return;
  lines += fmt::format("{}: recommended time step {:.4g} (critical {:.4g}: bonds {:.4g}, contact "
                       "{:.4g})\n",
                       STYLE, overall.dt_recommended, overall.dt_critical, overall.dt_bond,
                       overall.dt_contact);
  // runs in a loop would repeat it at every run: once per change (and time step)
  lines += fmt::format("(time step {})", update->dt);
  if (lines == last_time_step_report) return;
  last_time_step_report = lines;
  utils::logmesg(lmp, lines.substr(0, lines.rfind('(')));
  if (update->dt > overall.dt_recommended)
    error->warning(FLERR, "{}: time step {} exceeds the recommended {:.4g}", STYLE, update->dt,
                   overall.dt_recommended);
}

/* ----------------------------------------------------------------------
   {Kn, Rc} of each fix peridem/wall with a contact law of its own (not
   'contact pair'): a wall stiffer than the pair's contact sets the contact
   part of the time step (TimeStepInput::wall_laws)
------------------------------------------------------------------------- */

std::vector<std::array<double, 2>> PairPeridemContact::own_wall_laws() const
{
  std::vector<std::array<double, 2>> laws;
  for (int i = 0; i < modify->nfix; i++) {
    if (!utils::strmatch(modify->fix[i]->style, "^peridem/wall")) continue;
    int dim = 0;
    const auto *p = static_cast<const peridem::ContactParams *>(
        modify->fix[i]->extract("peridem_wall_contact", dim));
    if (p) laws.push_back({p->Kn, p->Rc});
  }
  return laws;
}

// "; walls with their own law: Kn = ..., Rc = ...", for the time-step line
std::string PairPeridemContact::wall_law_note(const std::vector<std::array<double, 2>> &laws)
{
  std::string note = "; walls with their own law:";
  for (const auto &w : laws) note += fmt::format(" Kn = {:.4g}, Rc = {:.4g};", w[0], w[1]);
  note.pop_back();
  return note;
}

/* ---------------------------------------------------------------------- */

void PairPeridemContact::write_restart(FILE *fp)
{
  PERIDEM_NS::write_restart_tag(fp, PERIDEM_NS::RESTART_PAIR_CONTACT);
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (!setflag[i][j]) continue;
      const PERIDEM_NS::ContactSpec &s = spec[i][j];
      PERIDEM_NS::write_contact_params(fp, s.params);
      const double extra[7] = {s.bulk_modulus,     s.horizon,
                               s.density,          s.centroid ? 1.0 : 0.0,
                               s.centroid_range,   (double)peridem::kn_exponent(s.kn_form),
                               s.centroid_bounding};
      fwrite(extra, sizeof(double), 7, fp);
    }
}

void PairPeridemContact::read_restart(FILE *fp)
{
  // format 2 writes the parameters field by field; format 3 adds centroid_bounding (0 in
  // files of format 2)
  const int format =
      PERIDEM_NS::read_restart_version(lmp, fp, PERIDEM_NS::RESTART_PAIR_CONTACT, 2, STYLE);
  read_restart_settings(fp);
  allocate();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (comm->me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (!setflag[i][j]) continue;
      PERIDEM_NS::ContactSpec &s = spec[i][j];
      s.params = PERIDEM_NS::read_contact_params(lmp, fp, STYLE);
      double extra[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      const int nextra = format >= 3 ? 7 : 6;
      if (comm->me == 0) utils::sfread(FLERR, extra, sizeof(double), nextra, fp, nullptr, error);
      MPI_Bcast(extra, nextra, MPI_DOUBLE, 0, world);
      constexpr double big = std::numeric_limits<double>::max();
      PERIDEM_NS::check_restart_values(lmp, STYLE, "material constants", extra, 3, 0.0, big);
      PERIDEM_NS::check_restart_values(lmp, STYLE, "centroid settings", extra + 3, 2, 0.0, big);
      PERIDEM_NS::check_restart_values(lmp, STYLE, "Kn form", extra + 5, 1, 4.0, 5.0);
      PERIDEM_NS::check_restart_values(lmp, STYLE, "centroid settings", extra + 6, 1, 0.0, big);
      s.bulk_modulus = extra[0];
      s.horizon = extra[1];
      s.density = extra[2];
      s.centroid = extra[3] != 0.0;
      s.centroid_range = extra[4];
      s.kn_form = extra[5] == 4.0 ? peridem::KnForm::Eps4 : peridem::KnForm::Eps5;
      s.centroid_bounding = extra[6];
      s.origin = s.kappa_origin = "restart file";
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
  start_checked = true; // a restarted bed is in contact: no start-up overlap report
  // the dissipated energy so far continues on rank 0
  dissipated = comm->me == 0 ? total : 0.0;
  pvector[0] = dissipated;
}

/* ---------------------------------------------------------------------- */

void *PairPeridemContact::extract(const char *str, int &dim)
{
  dim = 0;
  if (strcmp(str, "dissipated") == 0) return (void *)&dissipated;
  if (strcmp(str, "peridem_broken_pair") == 0) return (void *)&broken_pair_sink;
  // for fix peridem/vhistory: count_work at the end of each step, fold_dissipated at the end of
  // each run
  if (strcmp(str, "peridem_step_end") == 0) return (void *)&step_end;
  if (strcmp(str, "peridem_run_end") == 0) return (void *)&run_end;
  // per type t: the law of pair_coeff t t (Kn = 0 where it is not set), for fix peridem/wall
  // 'contact pair'
  if (strcmp(str, "peridem_contact_params") == 0) {
    dim = 1;
    diag_params.assign(atom->ntypes + 1, peridem::ContactParams());
    for (int t = 1; t <= atom->ntypes; t++)
      if (type_set(t, t)) diag_params[t] = spec[t][t].params;
    return (void *)diag_params.data();
  }
  // per type t: the reach of damping centroid of pair_coeff t t (0: none), for the dashpot
  // between grain centres and walls of fix peridem/wall 'contact pair'
  if (strcmp(str, "peridem_centroid_reach") == 0) {
    dim = 1;
    diag_reach.assign(atom->ntypes + 1, 0.0);
    for (int t = 1; t <= atom->ntypes; t++)
      if (type_set(t, t) && spec[t][t].centroid) diag_reach[t] = spec[t][t].centroid_reach();
    return (void *)diag_reach.data();
  }
  return nullptr;
}

double PairPeridemContact::memory_usage()
{
  return Pair::memory_usage() + spec.size() * spec.size() * sizeof(PERIDEM_NS::ContactSpec) +
         (grain_local.capacity() + grain_sum.capacity() + grain_force.capacity() +
          fdis.capacity()) *
             sizeof(double) +
         (grain_table.capacity() + grain_of.capacity() + fdis_mark.capacity() +
          fdis_slots.capacity()) *
             sizeof(int) +
         grain_ids.capacity() * sizeof(tagint);
}
