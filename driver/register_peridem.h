/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: the list of all PERIDEM styles with their creators, for the
   routes that register them without LAMMPS's style headers (lmp_peridem,
   libperidem: driver/register_driver.h; peridemplugin.so).
------------------------------------------------------------------------- */

#ifndef LMP_REGISTER_PERIDEM_H
#define LMP_REGISTER_PERIDEM_H

namespace LAMMPS_NS {
class LAMMPS;
class AtomVec;
class Bond;
class Pair;
class Fix;
class Compute;
class Command;
} // namespace LAMMPS_NS

namespace LAMMPS_NS {
namespace PERIDEM_NS {

/* The creators LAMMPS's style maps hold (Atom::AtomVecCreator, Force::BondCreator, ...). */
using AtomVecCreator = LAMMPS_NS::AtomVec *(*)(LAMMPS_NS::LAMMPS *);
using BondCreator = LAMMPS_NS::Bond *(*)(LAMMPS_NS::LAMMPS *);
using PairCreator = LAMMPS_NS::Pair *(*)(LAMMPS_NS::LAMMPS *);
using FixCreator = LAMMPS_NS::Fix *(*)(LAMMPS_NS::LAMMPS *, int, char **);
using ComputeCreator = LAMMPS_NS::Compute *(*)(LAMMPS_NS::LAMMPS *, int, char **);
using CommandCreator = LAMMPS_NS::Command *(*)(LAMMPS_NS::LAMMPS *);

/* Receives every PERIDEM style with its creator, one call per style. */
class StyleSink {
 public:
  virtual ~StyleSink() = default;
  virtual void atom(const char *name, AtomVecCreator creator) = 0;
  virtual void bond(const char *name, BondCreator creator) = 0;
  virtual void pair(const char *name, PairCreator creator) = 0;
  virtual void fix(const char *name, FixCreator creator) = 0;
  virtual void compute(const char *name, ComputeCreator creator) = 0;
  virtual void command(const char *name, CommandCreator creator) = 0;
};

/* The list of PERIDEM styles, shared by register_styles() and the plugin. */
void for_each_style(StyleSink &sink);

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
