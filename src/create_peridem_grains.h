/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: command create_peridem_grains, see
   doc/create_peridem_grains.rst.

   Turns a grain shape (built-in 2D shape, polygon file, Gmsh mesh, or a
   3D sphere, box, cylinder or extrusion) into peridynamic nodes with
   volumes and bonds (within the horizon, same grain only, pruned so no
   bond leaves the shape) and places one grain per requested position.
   Every rank builds the whole grain from the same input, keeps the nodes
   inside its subdomain and attaches the bonds to them by atom ID, so the
   result does not depend on the number of ranks or the decomposition.
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(create_peridem_grains,CreatePeridemGrains);
// clang-format on
#else

#ifndef LMP_CREATE_PERIDEM_GRAINS_H
#define LMP_CREATE_PERIDEM_GRAINS_H

#include "command.h"

#include <array>
#include <vector>

namespace LAMMPS_NS {

class CreatePeridemGrains : public Command {
 public:
  CreatePeridemGrains(class LAMMPS *);
  void command(int, char **) override;

  // parsed arguments and the discretized grain (defined in the .cpp)
  struct Options;
  struct Grain;

 private:
  void parse(int, char **, Options &);
  void check(const Options &);
  void build(const Options &, Grain &);
  void check_bonds_per_atom(const Grain &);
  double smallest_node_distance(const Options &, const Grain &);
  void place(const Options &, const std::vector<const Grain *> &);
  void read_positions(const char *, Options &);
  void report_bed_fraction(const Options &, double);
};

} // namespace LAMMPS_NS

#endif
#endif
