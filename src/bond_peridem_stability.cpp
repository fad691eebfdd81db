/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: the bonds' share of the time-step estimate of
   pair_style peridem/contact. Each bond style gives, per entry
   of LAMMPS's bond list, a spring constant k_n whose pair-spring network
   bounds the linearised bond energy from above; the pair style then bounds
   the highest frequency by the Rayleigh quotient (stable_time_step in
   peridem_contact_law.h, after Silling & Askari 2005).
------------------------------------------------------------------------- */

#include "bond_peridem.h"
#include "bond_peridem_lps.h"

#include "lmp_peridem_image.h"
#include "peridem_contact_law.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

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
   LPS: k_n = (a d^2 + b) omega beta V_i V_j (1/m_i + 1/m_j), the bound of
   lps_spring_constant() (peridem_lps_law.h). m is summed here over the
   intact bonds of the bond list (owned and ghost ends): a node whose bonds
   are partly stored on another rank gets a smaller m, hence a stiffer,
   still bounding spring; after breakage the force uses the reference m,
   which is larger than the intact sum, so the bound holds too. The stored
   m of fix peridem/bonds is not used: the estimate is made in the pair
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

/* ----------------------------------------------------------------------
   the bonds' part of the time-step bound (peridem_contact_law.h): for
   each node the tensor A_i = sum of k_b e e over its bonds, with the
   spring constants k_b of the bond style (BondPeridem::stability_springs:
   c w V_i V_j/|xi| for bond_style peridem, the bound of
   lps_spring_constant() for peridem/lps), reference geometry, and per atom
   type the largest 2 lambda_max(A_i)/m_i. Bonds stored on another rank
   are not seen here (newton_bond): a node at a rank boundary may miss
   some, the interior nodes that set the maximum do not.
------------------------------------------------------------------------- */

std::vector<double> BondPeridem::stability_omega2_of_types()
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
      peridem_lmp::minimum_image(domain, e[0], e[1], e[2]);
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

void BondPeridem::report_time_step()
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
