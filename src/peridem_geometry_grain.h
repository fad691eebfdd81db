/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// One-call grain construction for the LAMMPS commands: shape + spacing +
// horizon -> nodes (reference positions, volumes) and bonds, with the input
// checks ("spacing larger than the grain", "horizon smaller than
// the spacing", unknown shape or file, invalid polygon) reported as
// GeometryError with a clear message.
#ifndef PERIDEM_GEOMETRY_GRAIN_H
#define PERIDEM_GEOMETRY_GRAIN_H

#include "peridem_geometry_3d.h"
#include "peridem_geometry_bonds.h"
#include "peridem_geometry_discretize.h"

#include <map>
#include <string>
#include <vector>

namespace peridem {

struct GrainOptions {
  LatticeOptions lattice;                      // offset and nodal volume rule
  Pruning pruning = Pruning::ExtendedBoundary; // Bhattacharya & Lipton 2023, §5 by default
  std::vector<CutSegment> cuts;                // pre-notches / cracks (grain frame)
};

struct Grain2D {
  Nodes2D nodes;
  std::vector<Bond> bonds;
};

struct Grain3D {
  Nodes3D nodes;
  std::vector<Bond> bonds;
};

// Lattice grain of an arbitrary (validated) polygon.
Grain2D discretize_grain(const Polygon &shape, double h, double eps, const GrainOptions &opt = {});
// Built-in shape by name (see builtin_shapes()).
Grain2D discretize_shape(const std::string &name, const std::map<std::string, double> &params,
                         double h, double eps, const GrainOptions &opt = {});
// User polygon file (doc/peridem_polygon_format.rst).
Grain2D discretize_polygon_file(const std::string &path, double h, double eps,
                                const GrainOptions &opt = {});
// Gmsh mesh grain: nodes/volumes from eq. 31. Bonds are pruned against
// `shape` if given (mesh of a nonconvex polygon), else not pruned. The
// horizon must not be smaller than the shortest mesh edge.
Grain2D mesh_grain(const Mesh2D &mesh, double eps, const Polygon *shape = nullptr,
                   const std::vector<CutSegment> &cuts = {});
// 3D lattice grain.
Grain3D discretize_grain_3d(const Shape3D &shape, double h, double eps,
                            Pruning pruning = Pruning::ExtendedBoundary,
                            const Vec3 &offset = Vec3());

} // namespace peridem

#endif
