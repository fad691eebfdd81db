/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Grain construction with input validation (bad input gets a clear
// error); the LAMMPS glue turns GeometryError into a LAMMPS error.
#include "peridem_geometry_grain.h"
#include "peridem_geometry_shapes.h"

#include <cmath>
#include <cstdio>

namespace peridem {

namespace {

std::string num(double v)
{
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g", v);
  return buf;
}

void check_spacing(double h, double eps)
{
  if (!(h > 0.0) || !std::isfinite(h)) throw GeometryError("node spacing must be positive");
  if (!(eps > 0.0) || !std::isfinite(eps)) throw GeometryError("horizon must be positive");
  if (eps < h)
    throw GeometryError("horizon " + num(eps) + " is smaller than the node spacing " + num(h) +
                        "; nodes would have no bonds");
}

void check_node_count(std::size_t n, double h)
{
  if (n < 2)
    throw GeometryError("node spacing " + num(h) + " is larger than the grain: only " +
                        std::to_string(n) + " node(s) inside, need at least 2");
}

} // namespace

Grain2D discretize_grain(const Polygon &shape, double h, double eps, const GrainOptions &opt)
{
  check_spacing(h, eps);
  shape.validate();
  Grain2D g;
  g.nodes = lattice_nodes(shape, h, opt.lattice);
  check_node_count(g.nodes.size(), h);
  g.bonds = create_bonds(shape, g.nodes.x, eps, opt.pruning);
  remove_bonds_crossing(g.bonds, g.nodes.x, opt.cuts);
  return g;
}

Grain2D discretize_shape(const std::string &name, const std::map<std::string, double> &params,
                         double h, double eps, const GrainOptions &opt)
{
  return discretize_grain(make_shape(name, params), h, eps, opt);
}

Grain2D discretize_polygon_file(const std::string &path, double h, double eps,
                                const GrainOptions &opt)
{
  return discretize_grain(read_polygon_file(path), h, eps, opt);
}

Grain2D mesh_grain(const Mesh2D &mesh, double eps, const Polygon *shape,
                   const std::vector<CutSegment> &cuts)
{
  if (shape) shape->validate();
  Grain2D g;
  g.nodes = mesh_nodes(mesh);
  double hmin = INFINITY;
  for (const auto &t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      hmin = std::min(hmin, (mesh.vertices[t[k]] - mesh.vertices[t[(k + 1) % 3]]).norm());
  for (const auto &q : mesh.quads)
    for (int k = 0; k < 4; ++k)
      hmin = std::min(hmin, (mesh.vertices[q[k]] - mesh.vertices[q[(k + 1) % 4]]).norm());
  check_spacing(hmin, eps);
  check_node_count(g.nodes.size(), hmin);
  g.bonds = shape ? create_bonds(*shape, g.nodes.x, eps, Pruning::ExtendedBoundary)
                  : pairs_within_horizon(g.nodes.x, eps);
  remove_bonds_crossing(g.bonds, g.nodes.x, cuts);
  return g;
}

Grain3D discretize_grain_3d(const Shape3D &shape, double h, double eps, Pruning pruning,
                            const Vec3 &offset)
{
  check_spacing(h, eps);
  Grain3D g;
  g.nodes = lattice_nodes_3d(shape, h, offset);
  check_node_count(g.nodes.size(), h);
  g.bonds = create_bonds_3d(shape, g.nodes.x, eps, pruning);
  return g;
}

} // namespace peridem
