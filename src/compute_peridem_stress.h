/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/stress. See doc/compute_peridem_stress.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(peridem/stress,ComputePeridemStress);
// clang-format on
#else

#ifndef LMP_COMPUTE_PERIDEM_STRESS_H
#define LMP_COMPUTE_PERIDEM_STRESS_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputePeridemStress : public Compute {
 public:
  ComputePeridemStress(class LAMMPS *, int, char **);
  ~ComputePeridemStress() override;
  void init() override;
  double compute_scalar() override;
  void compute_vector() override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

 private:
  enum { VOLUME_NUMBER, VOLUME_VARIABLE, VOLUME_BOX };
  int volume_kind;
  double volume_value;
  char *id_variable;
  int ivariable;
  std::vector<class Fix *> walls; // fix peridem/wall instances
  int nmax;
  double **vir;      // per atom and ghost: contact, bond, wall virial (18)
  double stress[30]; // total, kinetic, contact, bond, wall (6 each)

  double volume() const;
};

} // namespace LAMMPS_NS

#endif
#endif
