/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: command create_peridem_grains, see
   doc/create_peridem_grains.rst.
------------------------------------------------------------------------- */

#include "create_peridem_grains.h"
#include "lmp_peridem_citations.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "math_const.h"
#include "lmp_peridem_material.h"
#include "lmp_peridem_parse.h"
#include "lmp_peridem_topology.h"

#include "peridem_geometry_grain.h"
#include "peridem_geometry_packing.h"
#include "peridem_geometry_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <unordered_map>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

namespace {
constexpr const char *CMD = "create_peridem_grains";

// 3D primitives and their size parameters (defaults: unit size)
const std::map<std::string, std::map<std::string, double>> &solid_shapes()
{
  static const std::map<std::string, std::map<std::string, double>> shapes = {
      {"sphere", {{"radius", 1.0}}},
      {"box", {{"lx", 1.0}, {"ly", 1.0}, {"lz", 1.0}}},
      {"cylinder", {{"radius", 1.0}, {"height", 1.0}}}};
  return shapes;
}

const peridem::ShapeInfo *builtin_shape(const std::string &name)
{
  for (const auto &s : peridem::builtin_shapes())
    if (s.name == name) return &s;
  return nullptr;
}

// uniform double in [0, 1) from the raw 64-bit output (same on every platform)
double uniform(std::mt19937_64 &gen)
{
  return static_cast<double>(gen() >> 11) * 0x1.0p-53;
}

struct Rotation {
  double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  static Rotation about_z(double angle)
  {
    Rotation r;
    const double c = std::cos(angle), s = std::sin(angle);
    r.m[0][0] = c;
    r.m[0][1] = -s;
    r.m[1][0] = s;
    r.m[1][1] = c;
    return r;
  }
  // by angle about the unit vector a (Rodrigues' formula)
  static Rotation about_axis(double angle, const double a[3])
  {
    const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
    Rotation r;
    r.m[0][0] = c + t * a[0] * a[0];
    r.m[0][1] = t * a[0] * a[1] - s * a[2];
    r.m[0][2] = t * a[0] * a[2] + s * a[1];
    r.m[1][0] = t * a[1] * a[0] + s * a[2];
    r.m[1][1] = c + t * a[1] * a[1];
    r.m[1][2] = t * a[1] * a[2] - s * a[0];
    r.m[2][0] = t * a[2] * a[0] - s * a[1];
    r.m[2][1] = t * a[2] * a[1] + s * a[0];
    r.m[2][2] = c + t * a[2] * a[2];
    return r;
  }
  // uniformly random orientation (Shoemake's unit quaternion)
  static Rotation random3d(double u1, double u2, double u3)
  {
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    const double w = b * std::cos(2 * MY_PI * u3), x = a * std::sin(2 * MY_PI * u2),
                 y = a * std::cos(2 * MY_PI * u2), z = b * std::sin(2 * MY_PI * u3);
    Rotation r;
    r.m[0][0] = 1 - 2 * (y * y + z * z);
    r.m[0][1] = 2 * (x * y - w * z);
    r.m[0][2] = 2 * (x * z + w * y);
    r.m[1][0] = 2 * (x * y + w * z);
    r.m[1][1] = 1 - 2 * (x * x + z * z);
    r.m[1][2] = 2 * (y * z - w * x);
    r.m[2][0] = 2 * (x * z - w * y);
    r.m[2][1] = 2 * (y * z + w * x);
    r.m[2][2] = 1 - 2 * (x * x + y * y);
    return r;
  }
};

/* Owned atoms in cells of size >= the overlap distance, for the test
   "does a new node come closer than d to an existing atom" in O(1) per node.
   Periodic dimensions wrap, distances are minimum-image. */
class OverlapGrid {
 public:
  OverlapGrid(Domain *domain, double d) : domain(domain), d(d)
  {
    const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
    for (int k = 0; k < 3; k++) {
      wrap[k] = periodic[k];
      ncell[k] = wrap[k] ? std::max(1, static_cast<int>(domain->prd[k] / d)) : 0;
      size[k] = wrap[k] ? domain->prd[k] / ncell[k] : d;
    }
  }

  void insert(const double *x, tagint tag)
  {
    int c[3];
    cell(x, c);
    cells[key(c)].push_back({{x[0], x[1], x[2]}, tag});
  }

  // smallest ID of an atom closer than d to x, 0 if none
  tagint closest_tag(const double *x)
  {
    int c[3];
    cell(x, c);
    tagint found = 0;
    std::vector<long long> seen;
    for (int i = -1; i <= 1; i++)
      for (int j = -1; j <= 1; j++)
        for (int k = -1; k <= 1; k++) {
          int n[3] = {c[0] + i, c[1] + j, c[2] + k};
          for (int m = 0; m < 3; m++)
            if (wrap[m]) n[m] = ((n[m] % ncell[m]) + ncell[m]) % ncell[m];
          const long long kk = key(n);
          if (std::find(seen.begin(), seen.end(), kk) != seen.end()) continue;
          seen.push_back(kk);
          auto it = cells.find(kk);
          if (it == cells.end()) continue;
          for (const auto &e : it->second) {
            double dx = x[0] - e.x[0], dy = x[1] - e.x[1], dz = x[2] - e.x[2];
            domain->minimum_image(dx, dy, dz);
            if (dx * dx + dy * dy + dz * dz < d * d && (found == 0 || e.tag < found)) found = e.tag;
          }
        }
    return found;
  }

 private:
  struct Entry {
    double x[3];
    tagint tag;
  };
  Domain *domain;
  double d;
  int wrap[3], ncell[3];
  double size[3];
  std::unordered_map<long long, std::vector<Entry>> cells;

  void cell(const double *x, int *c) const
  {
    for (int k = 0; k < 3; k++) {
      c[k] = static_cast<int>(std::floor((x[k] - domain->boxlo[k]) / size[k]));
      if (wrap[k]) c[k] = std::min(std::max(c[k], 0), ncell[k] - 1);
    }
  }
  static long long key(const int *c)
  {
    const long long off = 1 << 20, m = 1 << 21;
    return ((c[0] + off) * m + (c[1] + off)) * m + (c[2] + off);
  }
};

// smallest circle enclosing the outer ring: the grain's security disk (Bhattacharya & Lipton 2023,
// §7.1 step 6)
peridem::EnclosingCircle security_disk(const peridem::Ring &ring)
{
  std::vector<std::array<double, 2>> pts;
  for (const auto &v : ring) pts.push_back({v.x, v.y});
  return peridem::smallest_enclosing_circle(pts);
}

// a parameter of a built-in 2d shape: the value given, else the shape table's default; 0 for
// shapes without it
double shape_parameter(const std::string &shape, const std::map<std::string, double> &params,
                       const std::string &name)
{
  for (const auto &info : peridem::builtin_shapes())
    if (info.name == shape)
      for (const auto &par : info.parameters)
        if (par.name == name) {
          const auto given = params.find(name);
          return given != params.end() ? given->second : par.default_value;
        }
  return 0.0;
}

} // namespace

/* parsed arguments of one create_peridem_grains command */
struct CreatePeridemGrains::Options {
  int type = 0;
  std::string shape;                    // built-in 2D name, sphere/box/cylinder, file, gmsh
  std::map<std::string, double> params; // shape parameters given
  std::string file;                     // polygon file or mesh
  std::string boundary;                 // polygon that prunes the bonds of a mesh
  // their text, read once on rank 0 and broadcast (found as LAMMPS finds potential files)
  std::string file_text, boundary_text;
  std::vector<std::array<double, 3>> at;
  // bed files (create_peridem_bed): per-position radius and angle (radians); empty unless
  // the positions file has those columns
  std::vector<double> at_radius, at_angle;
  std::string label; // keep only the positions-file lines with this label
  std::vector<std::string> labels_of_lines;
  std::vector<double> bed; // "# bed xlo xhi ylo yhi zlo zhi" of the positions file
  double fit_radius = 0.0; // > 0: scale the shape to this security-disk radius
  // fit radius: the shape's radius parameter becomes the security disk's radius, the shape
  // centred on the disk (the authors' perigrain scales its shapes so); else the smallest
  // enclosing circle is the disk (fit enclosing, the text's "diameters match")
  bool fit_by_radius = false, fit_given = false;
  bool rotate_given = false;
  // perturbed_disk: each grain its own outline (seed S + k for the k-th position: Bhattacharya
  // & Lipton 2023, §7.2 draw one per grain) or all the outline of seed S (outlines same)
  bool outlines_each = true, outlines_given = false;
  double spacing = 0.0, horizon = 0.0, density = 0.0, scale = 1.0, extrude = 0.0;
  double overlap = 0.0;
  double angle = 0.0; // radians
  double axis[3] = {0.0, 0.0, 1.0};
  bool axis_given = false;
  long long rotate_seed = 0; // > 0: random rotation
  int bond_type = 1;
  peridem::NodalVolume volume = peridem::NodalVolume::CellArea;
  bool volume_given = false;
  peridem::NodePlacement nodes = peridem::NodePlacement::Lattice;
  peridem::Pruning pruning = peridem::Pruning::ExtendedBoundary;
  std::vector<peridem::CutSegment> notches;
  bool is_solid() const { return solid_shapes().count(shape) > 0; }
};

/* the discretized grain in its own frame (centred at its placement point) */
struct CreatePeridemGrains::Grain {
  std::vector<std::array<double, 3>> x;
  std::vector<double> volume;
  std::vector<peridem::Bond> bonds;
};

/* ---------------------------------------------------------------------- */

CreatePeridemGrains::CreatePeridemGrains(LAMMPS *lmp) : Command(lmp)
{
  PERIDEM_NS::cite_grain_shape(lmp);
}

/* ---------------------------------------------------------------------- */

void CreatePeridemGrains::command(int narg, char **arg)
{
  if (domain->box_exist == 0) error->all(FLERR, "{} command before simulation box is defined", CMD);
  if (!atom->x0_flag || !atom->vfrac_flag || !atom->molecule_flag || !atom->rmass_flag ||
      atom->molecular != Atom::MOLECULAR)
    error->all(FLERR, "{} requires atom style peridem", CMD);
  if (domain->triclinic) error->all(FLERR, "{} does not support triclinic boxes", CMD);

  const double time0 = MPI_Wtime();
  Options opt;
  parse(narg, arg, opt);
  check(opt);
  if (opt.shape == "gmsh" || opt.shape == "file")
    opt.file_text = PERIDEM_NS::read_text_file(lmp, CMD, opt.shape == "gmsh" ? "Gmsh" : "polygon",
                                               opt.file, true);
  if (!opt.boundary.empty())
    opt.boundary_text = PERIDEM_NS::read_text_file(lmp, CMD, "polygon", opt.boundary, true);
  std::vector<const Grain *> per_grain;
  // one discretization per security-disk radius (bed files), and per grain where each grain
  // has its own outline
  const bool each = opt.shape == "perturbed_disk" && opt.outlines_each;
  // the seed given, else the shape table's default
  const double seed0 = each ? shape_parameter(opt.shape, opt.params, "seed") : 0.0;
  std::map<std::pair<double, std::size_t>, Grain> built;
  double closest = std::numeric_limits<double>::infinity(); // over the grains built
  for (std::size_t ig = 0; ig < opt.at.size(); ig++) {
    const double r = opt.at_radius.empty() ? 0.0 : opt.at_radius[ig];
    const std::pair<double, std::size_t> key(r, each ? ig : 0);
    auto it = built.find(key);
    if (it == built.end()) {
      Options o = opt;
      o.fit_radius = r;
      if (each) o.params["seed"] = seed0 + static_cast<double>(ig);
      it = built.emplace(key, Grain()).first;
      build(o, it->second);
      check_bonds_per_atom(it->second);
      closest = std::min(closest, smallest_node_distance(o, it->second));
    }
    per_grain.push_back(&it->second);
  }
  place(opt, per_grain);

  // the contact radius is commonly chosen from it (the PeriDEM authors: R_c = 0.95 x it)
  if (comm->me == 0)
    utils::logmesg(lmp, "  smallest node distance in a grain: {:.8g} (nodes {})\n", closest,
                   opt.nodes == peridem::NodePlacement::Outline ? "outline" : "lattice");
  if (comm->me == 0)
    utils::logmesg(lmp, "  {} wall time = {:.3f} seconds\n", CMD, MPI_Wtime() - time0);
}

/* ----------------------------------------------------------------------
   create_peridem_grains type shape-style [shape args] keyword value ...
------------------------------------------------------------------------- */

void CreatePeridemGrains::parse(int narg, char **arg, Options &o)
{
  if (narg < 2) error->all(FLERR, "Illegal {} command: expected atom type and shape", CMD);
  // types are checked here against the box, before they are stored in an int
  o.type = PERIDEM_NS::integer(lmp, CMD, "atom type", arg[0], 1, atom->ntypes);
  if (atom->nbondtypes == 0)
    error->all(FLERR, "{}: the box has no bond types; set bond/types in create_box", CMD);
  o.shape = arg[1];
  int iarg = 2;

  auto need = [&](int n, const char *what) {
    if (iarg + n > narg)
      error->all(FLERR, "Illegal {} command: {} needs {} value(s)", CMD, what, n);
  };
  auto positive = [&](const char *str, const char *what) {
    const double v = PERIDEM_NS::number(lmp, CMD, what, str);
    if (!(v > 0.0)) error->all(FLERR, "{}: {} must be > 0, got {}", CMD, what, str);
    return v;
  };

  // shape arguments
  const peridem::ShapeInfo *info = builtin_shape(o.shape);
  if (info || o.is_solid()) {
    while (iarg + 1 < narg) {
      const std::string key = arg[iarg];
      bool known =
          info ? std::any_of(info->parameters.begin(), info->parameters.end(),
                             [&](const peridem::ShapeParameter &p) { return p.name == key; })
               : solid_shapes().at(o.shape).count(key) > 0;
      if (!known) break;
      o.params[key] = PERIDEM_NS::number(lmp, CMD, key, arg[iarg + 1]);
      iarg += 2;
    }
  } else if (o.shape == "file" || o.shape == "gmsh") {
    need(1, o.shape.c_str());
    o.file = arg[iarg++];
  } else {
    error->all(FLERR,
               "{}: unknown shape '{}'; use one of {}, sphere, box, cylinder, file FILE or "
               "gmsh FILE",
               CMD, o.shape, peridem::builtin_shape_list());
  }

  bool have_material = false;
  peridem::Material material;
  while (iarg < narg) {
    const std::string key = arg[iarg++];
    if (key == "at") {
      need(3, "at");
      o.at.push_back({PERIDEM_NS::number(lmp, CMD, key, arg[iarg]),
                      PERIDEM_NS::number(lmp, CMD, key, arg[iarg + 1]),
                      PERIDEM_NS::number(lmp, CMD, key, arg[iarg + 2])});
      iarg += 3;
    } else if (key == "positions") {
      need(1, "positions");
      read_positions(arg[iarg++], o);
    } else if (key == "outlines") {
      need(1, "outlines");
      o.outlines_each =
          PERIDEM_NS::choice(lmp, CMD, "outlines", arg[iarg++], {"each", "same"}) == 0;
      o.outlines_given = true;
    } else if (key == "fit") {
      need(1, "fit");
      o.fit_by_radius =
          PERIDEM_NS::choice(lmp, CMD, "fit", arg[iarg++], {"enclosing", "radius"}) == 1;
      o.fit_given = true;
    } else if (key == "label") {
      need(1, "label");
      o.label = arg[iarg++];
    } else if (key == "spacing") {
      need(1, "spacing");
      o.spacing = positive(arg[iarg++], "spacing");
    } else if (key == "horizon") {
      need(1, "horizon");
      o.horizon = positive(arg[iarg++], "horizon");
    } else if (key == "density") {
      need(1, "density");
      o.density = positive(arg[iarg++], "density");
    } else if (key == "material") {
      need(2, "material");
      material = PERIDEM_NS::load_material(lmp, CMD, arg[iarg], arg[iarg + 1]);
      have_material = true;
      iarg += 2;
    } else if (key == "bond/type") {
      need(1, "bond/type");
      o.bond_type = PERIDEM_NS::integer(lmp, CMD, key, arg[iarg++], 1, atom->nbondtypes);
    } else if (key == "rotate") {
      need(1, "rotate");
      o.rotate_given = true;
      if (strcmp(arg[iarg], "random") == 0) {
        need(2, "rotate random");
        o.rotate_seed = PERIDEM_NS::integer(lmp, CMD, "rotate random", arg[iarg + 1]);
        if (o.rotate_seed <= 0) error->all(FLERR, "{}: rotate random seed must be > 0", CMD);
        iarg += 2;
      } else {
        o.angle = PERIDEM_NS::number(lmp, CMD, key, arg[iarg++]) * MY_PI / 180.0;
      }
    } else if (key == "axis") {
      need(3, "axis");
      for (int k = 0; k < 3; k++) o.axis[k] = PERIDEM_NS::number(lmp, CMD, key, arg[iarg + k]);
      const double norm =
          std::sqrt(o.axis[0] * o.axis[0] + o.axis[1] * o.axis[1] + o.axis[2] * o.axis[2]);
      if (!(norm > 0.0)) error->all(FLERR, "{}: rotation axis must not be zero", CMD);
      for (double &a : o.axis) a /= norm;
      o.axis_given = true;
      iarg += 3;
    } else if (key == "scale") {
      need(1, "scale");
      o.scale = positive(arg[iarg++], "scale");
    } else if (key == "extrude") {
      need(1, "extrude");
      o.extrude = positive(arg[iarg++], "extrude height");
    } else if (key == "volume") {
      need(1, "volume");
      o.volume_given = true;
      const std::string v = arg[iarg++];
      if (v == "cell")
        o.volume = peridem::NodalVolume::CellArea;
      else if (v == "exact")
        o.volume = peridem::NodalVolume::ExactClip;
      else
        error->all(FLERR, "{}: unknown volume mode '{}' (use cell or exact)", CMD, v);
    } else if (key == "nodes") {
      need(1, "nodes");
      o.nodes = PERIDEM_NS::choice(lmp, CMD, "nodes", arg[iarg++], {"lattice", "outline"}) == 1
                    ? peridem::NodePlacement::Outline
                    : peridem::NodePlacement::Lattice;
    } else if (key == "pruning") {
      need(1, "pruning");
      const std::string v = arg[iarg++];
      // "seed": the keyword's first name, still accepted
      if (v == "extended" || v == "seed")
        o.pruning = peridem::Pruning::ExtendedBoundary;
      else if (v == "exact")
        o.pruning = peridem::Pruning::Exact;
      else if (v == "off")
        o.pruning = peridem::Pruning::None;
      else
        error->all(FLERR, "{}: unknown pruning '{}' (use extended, exact or off)", CMD, v);
    } else if (key == "notch") {
      need(4, "notch");
      double v[4];
      for (int k = 0; k < 4; k++) v[k] = PERIDEM_NS::number(lmp, CMD, key, arg[iarg + k]);
      o.notches.push_back({{v[0], v[1]}, {v[2], v[3]}});
      iarg += 4;
    } else if (key == "overlap") {
      need(1, "overlap");
      o.overlap = positive(arg[iarg++], "overlap distance");
    } else if (key == "boundary") {
      need(1, "boundary");
      o.boundary = arg[iarg++];
    } else {
      error->all(FLERR, "{}: unknown keyword or shape parameter '{}'", CMD, key);
    }
  }

  // a positions file with labels: keep the lines of this command's label (label *: all)
  if (!o.at_radius.empty() && o.at.size() != o.at_radius.size())
    error->all(FLERR, "{}: a positions file with radii cannot be mixed with at or other positions",
               CMD);
  if (!o.label.empty() && o.labels_of_lines.empty())
    error->all(FLERR, "{}: label {} needs a positions file with a label column", CMD, o.label);
  if (!o.labels_of_lines.empty()) {
    if (o.label.empty()) o.label = o.shape;
    std::vector<std::array<double, 3>> at;
    std::vector<double> radius, angle;
    for (std::size_t k = 0; k < o.at.size(); k++)
      if (o.label == "*" || o.labels_of_lines[k] == o.label) {
        at.push_back(o.at[k]);
        radius.push_back(o.at_radius[k]);
        angle.push_back(o.at_angle[k]);
      }
    if (at.empty())
      error->all(FLERR, "{}: no line of the positions file has label '{}' (use label NAME)", CMD,
                 o.label);
    o.at = at;
    o.at_radius = radius;
    o.at_angle = angle;
  }
  if (!o.at_radius.empty() && o.scale != 1.0)
    error->all(FLERR, "{}: scale cannot be used with a positions file that gives radii", CMD);
  if (!o.at_angle.empty() && o.rotate_given)
    error->all(FLERR, "{}: rotate cannot be used with a positions file that gives angles", CMD);

  // the material gives what the command does not repeat
  if (have_material) {
    if (o.density == 0.0) o.density = material.density;
    if (o.horizon == 0.0) o.horizon = material.horizon;
  }
}

/* ---------------------------------------------------------------------- */

void CreatePeridemGrains::check(const Options &o)
{
  if (o.at.empty()) error->all(FLERR, "{}: no grain position given (use at x y z)", CMD);
  if (o.outlines_given && o.shape != "perturbed_disk")
    error->all(FLERR, "{}: outlines applies to perturbed_disk grains, not {}", CMD, o.shape);
  if (o.fit_by_radius && (shape_parameter(o.shape, o.params, "radius") <= 0.0 || o.extrude > 0.0))
    error->all(FLERR,
               "{}: fit radius needs a built-in 2d shape with a radius parameter (disk, polygon, "
               "hexagon, plus, ring, perturbed_disk), not {}{}",
               CMD, o.shape, o.extrude > 0.0 ? " extruded" : "");
  if (o.fit_given && o.at_radius.empty())
    error->all(FLERR,
               "{}: fit applies to grains placed from a bed file (positions FILE with radii)", CMD);
  if (o.axis_given && o.rotate_seed > 0)
    error->all(FLERR, "{}: axis applies to a fixed rotate angle, not to rotate random", CMD);
  if (o.axis_given && domain->dimension == 2 && (o.axis[0] != 0.0 || o.axis[1] != 0.0))
    error->all(FLERR, "{}: a 2d grain rotates about z only; axis {} {} {} needs dimension 3", CMD,
               o.axis[0], o.axis[1], o.axis[2]);
  if (!(o.density > 0.0))
    error->all(FLERR, "{}: no density: give density or material FILE NAME", CMD);
  if (!(o.horizon > 0.0))
    error->all(FLERR, "{}: no horizon: give horizon, or a material whose file sets it", CMD);
  if (o.shape == "gmsh") {
    if (o.spacing > 0.0) error->all(FLERR, "{}: gmsh grains take the spacing from the mesh", CMD);
  } else if (!(o.spacing > 0.0)) {
    error->all(FLERR, "{}: no node spacing given (use spacing h)", CMD);
  }
  if (!o.boundary.empty() && o.shape != "gmsh")
    error->all(FLERR, "{}: boundary is only used with gmsh meshes", CMD);
  if (o.nodes == peridem::NodePlacement::Outline) {
    if (o.shape == "gmsh")
      error->all(FLERR,
                 "{}: nodes outline is for lattice grains; gmsh nodes are where the mesh "
                 "puts them",
                 CMD);
    if (o.is_solid() || o.extrude > 0.0)
      error->all(FLERR, "{}: nodes outline is 2d only, not {}", CMD,
                 o.extrude > 0.0 ? "extrude" : o.shape);
    // a boundary node keeps the part of its cell inside the shape; h^2 would add material
    if (o.volume_given && o.volume == peridem::NodalVolume::CellArea)
      error->all(FLERR,
                 "{}: volume cell cannot be used with nodes outline (its volumes are the cells "
                 "clipped to the shape, as volume exact)",
                 CMD);
  }

  const bool solid = o.is_solid() || o.extrude > 0.0;
  if (domain->dimension == 2) {
    if (solid)
      error->all(FLERR, "{}: shape {} needs a 3D box", CMD, o.extrude > 0.0 ? "extrude" : o.shape);
    for (const auto &p : o.at)
      if (p[2] != 0.0) error->all(FLERR, "{}: a 2D grain needs z = 0 in at, got {}", CMD, p[2]);
  } else {
    if (!solid) error->all(FLERR, "{}: 2D shape {} in a 3D box needs extrude HEIGHT", CMD, o.shape);
    if (o.shape == "gmsh") error->all(FLERR, "{}: gmsh meshes are 2D only", CMD);
    if (o.volume == peridem::NodalVolume::ExactClip)
      error->all(FLERR, "{}: volume exact is 2D only (3D nodes have volume h^3)", CMD);
  }
}

/* ----------------------------------------------------------------------
   discretize the grain once, in its own frame (shape centre at the origin)
------------------------------------------------------------------------- */

void CreatePeridemGrains::build(const Options &o, Grain &g)
{
  try {
    if (o.shape == "gmsh") {
      std::istringstream mesh_text(o.file_text);
      peridem::Mesh2D mesh = peridem::parse_gmsh_mesh(mesh_text, o.file);
      double scale = o.scale;
      peridem::Vec2 c;
      if (o.fit_radius > 0.0) { // centre of the security disk, diameter matched
        const peridem::EnclosingCircle e = security_disk(mesh.vertices);
        c = peridem::Vec2(e.x, e.y);
        scale = o.fit_radius / e.r;
        c = c * scale;
      }
      for (auto &v : mesh.vertices) v = v * scale;
      if (o.fit_radius == 0.0) {
        peridem::Nodes2D nodes = peridem::mesh_nodes(mesh);
        double area = 0.0;
        for (std::size_t i = 0; i < nodes.size(); i++) {
          c = c + nodes.x[i] * nodes.volume[i];
          area += nodes.volume[i];
        }
        c = c / area;
      }
      for (auto &v : mesh.vertices) v = v - c;
      peridem::Polygon boundary;
      if (!o.boundary.empty()) {
        std::istringstream boundary_text(o.boundary_text);
        boundary = peridem::parse_polygon(boundary_text, o.boundary);
        boundary.scale(scale).translate(c * -1.0);
      }
      const peridem::Grain2D grain =
          peridem::mesh_grain(mesh, o.horizon, o.boundary.empty() ? nullptr : &boundary, o.notches);
      for (std::size_t i = 0; i < grain.nodes.size(); i++)
        g.x.push_back({grain.nodes.x[i].x, grain.nodes.x[i].y, 0.0});
      g.volume = grain.nodes.volume;
      g.bonds = grain.bonds;
      return;
    }

    if (o.is_solid()) {
      std::map<std::string, double> p = solid_shapes().at(o.shape);
      for (const auto &kv : o.params) p[kv.first] = kv.second * o.scale;
      if (o.fit_radius > 0.0) { // circumscribed sphere of the solid = security sphere
        const double r =
            o.shape == "sphere" ? p["radius"]
            : o.shape == "box"
                ? 0.5 * std::sqrt(p["lx"] * p["lx"] + p["ly"] * p["ly"] + p["lz"] * p["lz"])
                : std::sqrt(p["radius"] * p["radius"] + 0.25 * p["height"] * p["height"]);
        for (auto &kv : p) kv.second *= o.fit_radius / r;
      }
      for (const auto &kv : p)
        if (!(kv.second > 0.0))
          throw peridem::GeometryError(o.shape + " " + kv.first + " must be > 0");
      peridem::Shape3D s = o.shape == "sphere" ? peridem::Shape3D::sphere(p["radius"])
                           : o.shape == "box"
                               ? peridem::Shape3D::box(p["lx"], p["ly"], p["lz"])
                               : peridem::Shape3D::cylinder(p["radius"], p["height"]);
      const peridem::Grain3D grain =
          peridem::discretize_grain_3d(s, o.spacing, o.horizon, o.pruning);
      for (const auto &v : grain.nodes.x) g.x.push_back({v.x, v.y, v.z});
      g.volume = grain.nodes.volume;
      g.bonds = grain.bonds;
      return;
    }

    // polygon: built-in shapes are centred by construction, files by centroid
    peridem::Polygon shape;
    if (o.shape == "file") {
      std::istringstream shape_text(o.file_text);
      shape = peridem::parse_polygon(shape_text, o.file);
      shape.translate(shape.centroid() * -1.0);
    } else {
      shape = peridem::make_shape(o.shape, o.params);
    }
    shape.scale(o.scale);
    double extrude = o.extrude;
    if (o.fit_radius > 0.0 && o.fit_by_radius) { // radius parameter = security-disk radius
      shape.scale(o.fit_radius / (o.scale * shape_parameter(o.shape, o.params, "radius")));
    } else if (o.fit_radius > 0.0) { // security disk (sphere of an extrusion), diameter matched
      const peridem::EnclosingCircle e = security_disk(shape.outer());
      shape.translate(peridem::Vec2(-e.x, -e.y));
      const double s = o.fit_radius / std::sqrt(e.r * e.r + 0.25 * extrude * extrude);
      shape.scale(s);
      extrude *= s;
    }

    if (extrude > 0.0) {
      const peridem::Shape3D s = peridem::Shape3D::extrusion(shape, extrude);
      peridem::Grain3D grain = peridem::discretize_grain_3d(s, o.spacing, o.horizon, o.pruning);
      std::vector<peridem::Vec2> xy;
      for (const auto &v : grain.nodes.x) {
        g.x.push_back({v.x, v.y, v.z});
        xy.emplace_back(v.x, v.y);
      }
      peridem::remove_bonds_crossing(grain.bonds, xy, o.notches);
      g.volume = grain.nodes.volume;
      g.bonds = grain.bonds;
      return;
    }

    peridem::GrainOptions gopt;
    gopt.lattice.volume = o.volume;
    gopt.lattice.placement = o.nodes;
    if (o.nodes == peridem::NodePlacement::Outline)
      gopt.lattice.volume = peridem::NodalVolume::ExactClip;
    gopt.pruning = o.pruning;
    gopt.cuts = o.notches;
    const peridem::Grain2D grain = peridem::discretize_grain(shape, o.spacing, o.horizon, gopt);
    for (const auto &v : grain.nodes.x) g.x.push_back({v.x, v.y, 0.0});
    g.volume = grain.nodes.volume;
    g.bonds = grain.bonds;
  } catch (peridem::GeometryError &e) {
    error->all(FLERR, "{}: {}", CMD, e.what());
  }
}

/* ----------------------------------------------------------------------
   smallest distance between two nodes of a grain (lattice: the spacing
   unless the shape is thinner; outline: at least half of it)
------------------------------------------------------------------------- */

double CreatePeridemGrains::smallest_node_distance(const Options &o, const Grain &g)
{
  std::vector<double> coords;
  coords.reserve(3 * g.x.size());
  for (const auto &x : g.x) coords.insert(coords.end(), x.begin(), x.end());
  return peridem::smallest_pair_distance(coords, 3, o.spacing > 0.0 ? o.spacing : o.horizon);
}

/* ----------------------------------------------------------------------
   every grain has the same bonds: check the per-atom bond capacity once
------------------------------------------------------------------------- */

void CreatePeridemGrains::check_bonds_per_atom(const Grain &g)
{
  std::vector<int> count(g.x.size(), 0);
  for (const auto &b : g.bonds) {
    count[b.first]++; // stored on the atom with the smaller ID
    if (!force->newton_bond) count[b.second]++;
  }
  const int most = count.empty() ? 0 : *std::max_element(count.begin(), count.end());
  if (most > atom->bond_per_atom)
    error->all(FLERR,
               "{}: a grain node needs {} bonds but atoms can hold {}; set extra/bond/per/atom "
               "to at least {} in create_box or read_data",
               CMD, most, atom->bond_per_atom, most);
}

/* ----------------------------------------------------------------------
   one grain per position: nodes inside my subdomain become my atoms,
   with atom IDs tag0 + node index so bonds attach by ID on any rank
------------------------------------------------------------------------- */

void CreatePeridemGrains::place(const Options &o, const std::vector<const Grain *> &grains)
{
  const int nlocal_previous = atom->nlocal;
  const bigint natoms_previous = atom->natoms;
  const bigint ngrains = static_cast<bigint>(o.at.size());
  bigint nnodes = 0;
  for (const Grain *g : grains) nnodes += static_cast<bigint>(g->x.size());
  if (natoms_previous + nnodes >= MAXTAGINT)
    error->all(FLERR, "{}: too many atoms for 32-bit atom IDs", CMD);

  tagint maxtag = 0, maxmol = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    maxtag = std::max(maxtag, atom->tag[i]);
    maxmol = std::max(maxmol, atom->molecule[i]);
  }
  tagint tag0, mol;
  MPI_Allreduce(&maxtag, &tag0, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  MPI_Allreduce(&maxmol, &mol, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  tag0 += 1;
  mol += 1;
  const tagint first_mol = mol;

  OverlapGrid *grid = nullptr;
  if (o.overlap > 0.0) {
    grid = new OverlapGrid(domain, o.overlap);
    for (int i = 0; i < atom->nlocal; i++) {
      double xi[3] = {atom->x[i][0], atom->x[i][1], atom->x[i][2]};
      domain->remap(xi);
      grid->insert(xi, atom->tag[i]);
    }
  }

  const double *lo = domain->sublo, *hi = domain->subhi;
  const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  auto mine = [&](const double *x) {
    for (int k = 0; k < 3; k++) {
      if (x[k] < lo[k]) return false;
      if (x[k] >= hi[k] && !(x[k] == hi[k] && hi[k] == domain->boxhi[k] && !periodic[k]))
        return false;
    }
    return true;
  };

  std::mt19937_64 gen(static_cast<std::uint64_t>(o.rotate_seed));
  std::vector<std::array<double, 3>> X;
  std::vector<int> local;
  double volume_created = 0.0;
  for (bigint ig = 0; ig < ngrains; ig++) {
    const Grain &g = *grains[ig];
    const int n = static_cast<int>(g.x.size());
    X.resize(n);
    local.resize(n);
    const double angle = o.at_angle.empty() ? o.angle : o.at_angle[ig];
    Rotation R = o.axis_given ? Rotation::about_axis(angle, o.axis) : Rotation::about_z(angle);
    if (o.rotate_seed > 0) {
      const double u1 = uniform(gen), u2 = uniform(gen), u3 = uniform(gen);
      R = domain->dimension == 2 ? Rotation::about_z(2 * MY_PI * u1)
                                 : Rotation::random3d(u1, u2, u3);
    }
    const auto &c = o.at[ig];
    for (int k = 0; k < n; k++)
      for (int d = 0; d < 3; d++)
        X[k][d] = c[d] + R.m[d][0] * g.x[k][0] + R.m[d][1] * g.x[k][1] + R.m[d][2] * g.x[k][2];

    if (grid) {
      tagint hit = MAXTAGINT, all_hit;
      int node = -1;
      for (int k = 0; k < n && hit == MAXTAGINT; k++) {
        double xk[3] = {X[k][0], X[k][1], X[k][2]};
        domain->remap(xk);
        const tagint t = grid->closest_tag(xk);
        if (t) {
          hit = t;
          node = k;
        }
      }
      MPI_Allreduce(&hit, &all_hit, 1, MPI_LMP_TAGINT, MPI_MIN, world);
      if (all_hit != MAXTAGINT) {
        int all_node;
        if (hit != all_hit) node = n;
        MPI_Allreduce(&node, &all_node, 1, MPI_INT, MPI_MIN, world);
        error->all(FLERR,
                   "{}: grain {} at ({}, {}, {}) overlaps existing atoms: its node at ({:.6g}, "
                   "{:.6g}, {:.6g}) is closer than the overlap distance {} to atom {}",
                   CMD, ig + 1, c[0], c[1], c[2], X[all_node][0], X[all_node][1], X[all_node][2],
                   o.overlap, all_hit);
      }
    }

    for (int k = 0; k < n; k++) {
      double xk[3] = {X[k][0], X[k][1], X[k][2]};
      imageint image = ((imageint)IMGMAX << IMG2BITS) | ((imageint)IMGMAX << IMGBITS) | IMGMAX;
      domain->remap(xk, image);
      local[k] = -1;
      if (!mine(xk)) continue;
      atom->avec->create_atom(o.type, xk);
      const int i = atom->nlocal - 1;
      local[k] = i;
      atom->tag[i] = tag0 + k;
      atom->image[i] = image;
      atom->molecule[i] = mol;
      atom->vfrac[i] = g.volume[k];
      volume_created += g.volume[k];
      atom->rmass[i] = o.density * g.volume[k];
      for (int d = 0; d < 3; d++) atom->x0[i][d] = X[k][d]; // unwrapped reference
      if (grid) grid->insert(xk, atom->tag[i]);
    }

    for (const auto &b : g.bonds) {
      const int ends[2][2] = {{b.first, b.second}, {b.second, b.first}};
      for (int e = 0; e < (force->newton_bond ? 1 : 2); e++) {
        const int i = local[ends[e][0]];
        if (i < 0) continue;
        const int m = atom->num_bond[i]++;
        atom->bond_type[i][m] = o.bond_type;
        atom->bond_atom[i][m] = tag0 + ends[e][1];
      }
    }
    tag0 += n;
    mol++;
  }
  delete grid;

  // every node must have found an owner
  bigint nblocal = atom->nlocal;
  MPI_Allreduce(&nblocal, &atom->natoms, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  const bigint expected = natoms_previous + nnodes;
  if (atom->natoms != expected)
    error->all(FLERR, "{}: {} of {} grain nodes are outside the simulation box", CMD,
               expected - atom->natoms, nnodes);

  atom->data_fix_compute_variable(nlocal_previous, atom->nlocal);
  atom->tag_check();
  if (atom->map_style != Atom::MAP_NONE) {
    atom->map_init();
    atom->map_set();
  }
  const bigint nbonds_previous = atom->nbonds;
  const bigint nbonds = PERIDEM_NS::finish_bond_edit(lmp);

  if (comm->me == 0) {
    if (o.at_radius.empty())
      utils::logmesg(lmp,
                     "Created {} peridem grains (IDs {} to {}) of {} nodes and {} bonds each: {} "
                     "atoms, {} bonds added\n",
                     ngrains, first_mol, mol - 1, grains[0]->x.size(), grains[0]->bonds.size(),
                     atom->natoms - natoms_previous, nbonds - nbonds_previous);
    else
      utils::logmesg(lmp,
                     "Created {} peridem grains (IDs {} to {}) sized to their security disks: {} "
                     "atoms, {} bonds added\n",
                     ngrains, first_mol, mol - 1, atom->natoms - natoms_previous,
                     nbonds - nbonds_previous);
  }
  double vsum = 0.0;
  MPI_Allreduce(&volume_created, &vsum, 1, MPI_DOUBLE, MPI_SUM, world);
  report_bed_fraction(o, vsum);
}

/* ----------------------------------------------------------------------
   positions file: one "x y z" per line, or "x y z radius [angle [label]]"
   (a bed file of create_peridem_bed: radius of the security disk, angle in
   degrees); '#' starts a comment; "# bed xlo xhi ylo yhi zlo zhi" gives the
   bed for the packing-fraction report
------------------------------------------------------------------------- */

void CreatePeridemGrains::read_positions(const char *file, Options &o)
{
  std::istringstream in(PERIDEM_NS::read_text_file(lmp, CMD, "positions", file, false));
  std::string line;
  int columns = 0;
  for (int lineno = 1; std::getline(in, line); lineno++) {
    if (line.rfind("# bed ", 0) == 0) {
      std::istringstream b(line.substr(6));
      double v;
      o.bed.clear();
      while (b >> v) o.bed.push_back(v);
    }
    line = line.substr(0, line.find('#'));
    std::istringstream s(line);
    std::vector<std::string> words;
    std::string w;
    while (s >> w) words.push_back(w);
    if (words.empty()) continue;
    const int n = static_cast<int>(words.size());
    if (n < 3 || n > 6 || (columns > 0 && n != columns))
      error->all(FLERR,
                 "{}: positions file {}:{}: expected 'x y z [radius [angle [label]]]' with the "
                 "same columns on every line",
                 CMD, file, lineno);
    columns = n;
    double v[5] = {0, 0, 0, 0, 0};
    for (int k = 0; k < std::min(n, 5); k++) {
      if (!utils::is_double(words[k]))
        error->all(FLERR, "{}: positions file {}:{}: '{}' is not a number", CMD, file, lineno,
                   words[k]);
      v[k] = std::stod(words[k]);
    }
    o.at.push_back({v[0], v[1], v[2]});
    if (n >= 4) {
      if (!(v[3] > 0.0))
        error->all(FLERR, "{}: positions file {}:{}: radius {} must be > 0", CMD, file, lineno,
                   words[3]);
      o.at_radius.push_back(v[3]);
    }
    if (n >= 5) o.at_angle.push_back(v[4] * MY_PI / 180.0);
    if (n == 6) o.labels_of_lines.push_back(words[5]);
  }
}

/* ----------------------------------------------------------------------
   grains of a bed file: their volume against the bed's (Bhattacharya & Lipton 2023, §7.3
   volume fraction), and that of all atoms so far (several labels, one bed)
------------------------------------------------------------------------- */

void CreatePeridemGrains::report_bed_fraction(const Options &o, double created)
{
  if (o.bed.size() != 6) return;
  double vbed = 1.0;
  for (int k = 0; k < domain->dimension; k++) vbed *= o.bed[2 * k + 1] - o.bed[2 * k];
  double mine = 0.0, all;
  for (int i = 0; i < atom->nlocal; i++) mine += atom->vfrac[i];
  MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, world);
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "  grain volume fraction of the bed: {:.4f} of these grains, {:.4f} of all "
                   "atoms\n",
                   created / vbed, all / vbed);
}
