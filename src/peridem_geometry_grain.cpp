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

void checkSpacing(double h, double eps)
{
  if (!(h > 0.0) || !std::isfinite(h)) throw GeometryError("node spacing must be positive");
  if (!(eps > 0.0) || !std::isfinite(eps)) throw GeometryError("horizon must be positive");
  if (eps < h)
    throw GeometryError("horizon " + num(eps) + " is smaller than the node spacing " + num(h) +
                        "; nodes would have no bonds");
}

void checkNodeCount(std::size_t n, double h)
{
  if (n < 2)
    throw GeometryError("node spacing " + num(h) + " is larger than the grain: only " +
                        std::to_string(n) + " node(s) inside, need at least 2");
}

} // namespace

Grain2D discretizeGrain(const Polygon &shape, double h, double eps, const GrainOptions &opt)
{
  checkSpacing(h, eps);
  shape.validate();
  Grain2D g;
  g.nodes = latticeNodes(shape, h, opt.lattice);
  checkNodeCount(g.nodes.size(), h);
  g.bonds = createBonds(shape, g.nodes.x, eps, opt.pruning);
  removeBondsCrossing(g.bonds, g.nodes.x, opt.cuts);
  return g;
}

Grain2D discretizeShape(const std::string &name, const std::map<std::string, double> &params,
                        double h, double eps, const GrainOptions &opt)
{
  return discretizeGrain(makeShape(name, params), h, eps, opt);
}

Grain2D discretizePolygonFile(const std::string &path, double h, double eps,
                              const GrainOptions &opt)
{
  return discretizeGrain(readPolygonFile(path), h, eps, opt);
}

Grain2D meshGrain(const Mesh2D &mesh, double eps, const Polygon *shape,
                  const std::vector<CutSegment> &cuts)
{
  if (shape) shape->validate();
  Grain2D g;
  g.nodes = meshNodes(mesh);
  double hmin = INFINITY;
  for (const auto &t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      hmin = std::min(hmin, (mesh.vertices[t[k]] - mesh.vertices[t[(k + 1) % 3]]).norm());
  for (const auto &q : mesh.quads)
    for (int k = 0; k < 4; ++k)
      hmin = std::min(hmin, (mesh.vertices[q[k]] - mesh.vertices[q[(k + 1) % 4]]).norm());
  checkSpacing(hmin, eps);
  checkNodeCount(g.nodes.size(), hmin);
  g.bonds = shape ? createBonds(*shape, g.nodes.x, eps, Pruning::Seed)
                  : pairsWithinHorizon(g.nodes.x, eps);
  removeBondsCrossing(g.bonds, g.nodes.x, cuts);
  return g;
}

Grain3D discretizeGrain3D(const Shape3D &shape, double h, double eps, Pruning pruning,
                          const Vec3 &offset)
{
  checkSpacing(h, eps);
  Grain3D g;
  g.nodes = latticeNodes3D(shape, h, offset);
  checkNodeCount(g.nodes.size(), h);
  g.bonds = createBonds3D(shape, g.nodes.x, eps, pruning);
  return g;
}

} // namespace peridem
