/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/contacts. See doc/compute_peridem_contacts.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(peridem/contacts,ComputePeridemContacts);
// clang-format on
#else

#ifndef LMP_COMPUTE_PERIDEM_CONTACTS_H
#define LMP_COMPUTE_PERIDEM_CONTACTS_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputePeridemContacts : public Compute {
 public:
  ComputePeridemContacts(class LAMMPS *, int, char **);
  void init() override;
  double compute_scalar() override;
  void compute_vector() override;

 private:
  class PairPeridemContact *pair;
  double stats[10]; // Z, grain contacts, grains, node contacts, fabric (6)
};

} // namespace LAMMPS_NS

#endif
#endif
