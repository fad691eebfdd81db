/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: a per-node column that a fix adds to the PeridemDamage section
   fix peridem/bonds writes into data files (fix peridem/lps: the weighted
   volume m), so that one section and one read_data keyword carry a node's
   whole damage state. read_data puts the column into fix property/atom
   d_<property>, from which the owning fix takes it back.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_DAMAGE_COLUMN_H
#define LMP_PERIDEM_DAMAGE_COLUMN_H

namespace LAMMPS_NS {
namespace PERIDEM_NS {

class DamageSectionColumn {
 public:
  // the fix property/atom vector that reads the column back, without d_ ("peridem_wvolume")
  virtual const char *column_property() const = 0;
  // what the column holds, for the log of write_data ("weighted volume m")
  virtual const char *column_description() const = 0;
  // whether write_data writes the column; called by every rank (it may reduce over them)
  virtual bool column_written() = 0;
  // the value of local atom i
  virtual double column_value(int i) const = 0;

 protected:
  // not deleted through this interface: no virtual destructor, whose exception specification
  // would clash with that of LAMMPS's Fix (noexcept(false) where LAMMPS throws)
  ~DamageSectionColumn() = default;
};

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
