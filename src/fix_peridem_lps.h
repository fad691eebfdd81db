/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: fix peridem/lps, the per-node state of bond_style peridem/lps.

   Created by bond_style peridem/lps (ID PERIDEM_LPS); not meant to be
   defined in an input script. Keeps the weighted volume m of each node in
   the reference configuration through migration, restart files and data
   files (a column of fix peridem/bonds' PeridemDamage section), so that
   breakage lowers a node's dilation but not its m; and carries the per-atom
   sums of the style's dilation pass between ranks (bond styles have no
   communication hooks of their own).
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(peridem/lps,FixPeridemLPS);
// clang-format on
#else

#ifndef LMP_FIX_PERIDEM_LPS_H
#define LMP_FIX_PERIDEM_LPS_H

#include "fix.h"
#include "lmp_peridem_damage_column.h"

namespace LAMMPS_NS {

class FixPeridemLPS : public Fix, public PERIDEM_NS::DamageSectionColumn {
 public:
  static constexpr const char *ID = "PERIDEM_LPS";

  FixPeridemLPS(class LAMMPS *, int, char **);
  ~FixPeridemLPS() override;
  int setmask() override { return 0; }

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override { return 2; }
  int maxsize_restart() override { return 2; }
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

  // the m column of the PeridemDamage section (fix property/atom d_peridem_wvolume)
  const char *column_property() const override { return "peridem_wvolume"; }
  const char *column_description() const override { return "weighted volume m"; }
  bool column_written() override;
  double column_value(int i) const override { return wvolume[i]; }

  // the weighted volume m of each node in the reference configuration; < 0 until computed
  double *weighted_volume() { return wvolume; }
  // add the ghost entries of a per-atom array into their owners (newton_bond on)
  void reverse_sum(double *a);
  // copy two per-atom arrays from the owners to their ghosts
  void forward(double *a, double *b);

 private:
  double *wvolume;
  double *comm_a, *comm_b; // the arrays of reverse_sum() and forward()

  void adopt_data_file_m();
  void refuse_misnamed_m();
  void adopt_old_restart_m();
  void check_restart_m(int i);
};

} // namespace LAMMPS_NS

#endif
#endif
