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

#include "atom.h"
#include "neighbor.h"

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
