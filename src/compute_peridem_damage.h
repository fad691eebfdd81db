/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/damage. See doc/compute_peridem_damage.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(peridem/damage,ComputePeridemDamage);
// clang-format on
#else

#ifndef LMP_COMPUTE_PERIDEM_DAMAGE_H
#define LMP_COMPUTE_PERIDEM_DAMAGE_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputePeridemDamage : public Compute {
 public:
  ComputePeridemDamage(class LAMMPS *, int, char **);
  ~ComputePeridemDamage() override;
  void init() override;
  double compute_scalar() override;
  void compute_vector() override;
  void compute_peratom() override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

 private:
  int nmax;
  double **damage; // per atom: bond fraction, Z, grain mean of the bond fraction
  double *intact;  // per atom (and ghost): intact bonds
  double *zintact; // per atom (and ghost): largest Z term of an intact bond
  double *stats;   // bulk damage, broken bonds, reference bonds, grains
  double *s0;      // critical stretch per bond type, from the bond style
  class FixPeridemBonds *bonds_fix;
  int z_displacement; // 1: Z by eq. 14 as printed (|u_j - u_i|); 0: by the bond stretch

  void refresh();
  bool refreshed = false;     // the arrays hold the counts of refreshed_step and _stamp
  bigint refreshed_step = -1; // (fix peridem/bonds' change_stamp())
  bigint refreshed_stamp = -1;
  void count_bonds();
  void grain_means();
};

} // namespace LAMMPS_NS

#endif
#endif
