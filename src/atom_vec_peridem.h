/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: peridynamic grains for LAMMPS.
   atom_style peridem: peridynamic nodes grouped into grains.
------------------------------------------------------------------------- */

#ifdef ATOM_CLASS
// clang-format off
AtomStyle(peridem,AtomVecPeridem);
// clang-format on
#else

#ifndef LMP_ATOM_VEC_PERIDEM_H
#define LMP_ATOM_VEC_PERIDEM_H

#include "atom_vec.h"
#include "lmp_peridem_compat.h"

namespace LAMMPS_NS {

/* A peridynamic node: bond topology (the peridynamic bonds are LAMMPS
   bonds), grain ID (the molecule ID), nodal volume (vfrac), mass (rmass)
   and reference position x0. The Atoms line of a data file reads
     atom-ID grain-ID atom-type volume density x y z x0 y0 z0
   and the mass is density * volume. */
class AtomVecPeridem : public AtomVec {
 public:
  AtomVecPeridem(class LAMMPS *);
  ~AtomVecPeridem() override;

  void grow_pointers() override;
  void create_atom_post(int) override;
  void data_atom_post(int) override;
  void pack_data_pre(int) override;
  void pack_data_post(int) override;
  void pack_restart_pre(int) override;
  void pack_restart_post(int) override;
  void unpack_restart_init(int) override;
  int property_atom(PERIDEM_NS::PropertyAtomName) override;
  void pack_property_atom(int, double *, int, int) override;

 private:
  int *num_bond;
  int **bond_type;
  int **nspecial;
  double *rmass, *vfrac;
  double **x0;

  void check_reference_position(int i, const char *where);
  void check_restart_atom(int i);

  // pack_data writes density, not mass: the mass is kept here meanwhile
  double rmass_one;
  // restart files carry turned-off (negative type) bonds as positive types
  // plus this flag, as LAMMPS's bond atom style does
  int *bond_negative;
  int bond_negative_capacity;
  int any_bond_negative;
};

} // namespace LAMMPS_NS

#endif
#endif
