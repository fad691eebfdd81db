/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Built-in grain shapes (Bhattacharya & Lipton 2023, §6.2-6.4, §7.2) and the polygon file
// reader (format in doc/peridem_polygon_format.rst).
#include "peridem_geometry_shapes.h"
#include "peridem_math.h"

#include <cmath>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>

namespace peridem {

namespace {

void require_positive_parameter(double v, const char *what)
{
  if (!(v > 0.0) || !std::isfinite(v)) {
    std::ostringstream value; // the value as the user wrote it (up to 6 digits)
    value << v;
    throw GeometryError(std::string("shape parameter ") + what + " must be positive, not " +
                        value.str());
  }
}

void require_count(int n, int minimum, const char *what)
{
  if (n < minimum)
    throw GeometryError(std::string("shape parameter ") + what + " must be at least " +
                        std::to_string(minimum));
}

Ring circle_ring(double r, int n)
{
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * kPi * i / n;
    ring.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  return ring;
}

// Uniform double in [0, 1) from the 53 high bits: std::mt19937_64 output is
// fixed by the standard, std::uniform_real_distribution is not.
double uniform01(std::mt19937_64 &g)
{
  return static_cast<double>(g() >> 11) * 0x1.0p-53;
}

// A polygonal disk and a regular polygon are the same thing; only the name of
// the vertex-count parameter in error messages differs.
Polygon regular_polygon(double radius, int n, const char *count_name)
{
  require_positive_parameter(radius, "radius");
  require_count(n, 3, count_name);
  return Polygon(circle_ring(radius, n));
}

} // namespace

Polygon make_disk(double radius, int segments)
{
  return regular_polygon(radius, segments, "segments");
}

Polygon make_rectangle(double width, double height)
{
  require_positive_parameter(width, "width");
  require_positive_parameter(height, "height");
  const double a = 0.5 * width, b = 0.5 * height;
  return Polygon({{-a, -b}, {a, -b}, {a, b}, {-a, b}});
}

Polygon make_regular_polygon(double radius, int sides)
{
  return regular_polygon(radius, sides, "sides");
}

Polygon make_plus(double radius, double arm_width)
{
  require_positive_parameter(radius, "radius");
  require_positive_parameter(arm_width, "arm_width");
  const double a = 0.5 * arm_width, r = radius;
  if (!(a < r)) throw GeometryError("plus shape needs arm_width < 2 * radius");
  // 12 vertices, CCW, starting at the tip of the +x arm; the four reflex
  // corners (a, a), (-a, a), ... are Bhattacharya & Lipton's (2023) nonconvex cusps (§5).
  return Polygon({{r, -a},
                  {r, a},
                  {a, a},
                  {a, r},
                  {-a, r},
                  {-a, a},
                  {-r, a},
                  {-r, -a},
                  {-a, -a},
                  {-a, -r},
                  {a, -r},
                  {a, -a}});
}

Polygon make_ring(double outer_radius, double inner_radius, int segments)
{
  require_positive_parameter(outer_radius, "radius");
  require_positive_parameter(inner_radius, "inner_radius");
  require_count(segments, 3, "segments");
  if (!(inner_radius < outer_radius * std::cos(kPi / segments)))
    throw GeometryError("ring needs inner_radius < radius (hole must be inside)");
  return Polygon(circle_ring(outer_radius, segments), {circle_ring(inner_radius, segments)});
}

Polygon make_perturbed_disk(double radius, int vertices, double roundness, std::uint64_t seed)
{
  require_positive_parameter(radius, "radius");
  require_count(vertices, 3, "vertices");
  if (!(roundness > 0.0 && roundness <= 1.0))
    throw GeometryError("shape parameter roundness must be in (0, 1]");
  std::mt19937_64 gen(seed);
  Ring ring;
  for (int i = 0; i < vertices; ++i) {
    // §7.2: r_i = R (1 - X_i), X_i ~ U[0, 1 - phi]; equally spaced angles keep
    // the polygon star-shaped about the origin, hence simple.
    const double x = (1.0 - roundness) * uniform01(gen);
    const double r = radius * (1.0 - x);
    const double t = 2.0 * kPi * i / vertices;
    ring.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  return Polygon(ring);
}

Polygon make_neck(double length, double width, double neck_width)
{
  require_positive_parameter(length, "length");
  require_positive_parameter(width, "width");
  require_positive_parameter(neck_width, "neck_width");
  if (!(neck_width < width)) throw GeometryError("neck shape needs neck_width < width");
  const double a = 0.5 * length, b = 0.5 * width, c = 0.5 * neck_width;
  return Polygon({{-a, -b}, {0.0, -c}, {a, -b}, {a, b}, {0.0, c}, {-a, b}});
}

Polygon make_notched_plate(double width, double height, double notch_length, double notch_width,
                           bool v_notch)
{
  require_positive_parameter(width, "width");
  require_positive_parameter(height, "height");
  require_positive_parameter(notch_length, "notch_length");
  require_positive_parameter(notch_width, "notch_width");
  if (!(notch_length < width)) throw GeometryError("notched plate needs notch_length < width");
  if (!(notch_width < height)) throw GeometryError("notched plate needs notch_width < height");
  const double a = 0.5 * width, b = 0.5 * height, c = 0.5 * notch_width;
  const double tip = -a + notch_length;
  Ring r = {{-a, -b}, {a, -b}, {a, b}, {-a, b}, {-a, c}};
  if (v_notch) {
    r.emplace_back(tip, 0.0);
  } else {
    r.emplace_back(tip, c);
    r.emplace_back(tip, -c);
  }
  r.emplace_back(-a, -c);
  return Polygon(r);
}

const std::vector<ShapeInfo> &builtin_shapes()
{
  static const std::vector<ShapeInfo> shapes = {
      {"disk", "polygonal disk", {{"radius", 1.0, "radius R"}, {"segments", 64, "boundary edges"}}},
      {"square",
       "square inscribed in a disk of radius R: side sqrt(2) R (Bhattacharya & Lipton 2023, §7.2)",
       {{"side", std::sqrt(2.0), "side length"}}},
      {"rectangle",
       "axis-aligned rectangle",
       {{"width", 2.0, "x size"}, {"height", 1.0, "y size"}}},
      {"polygon",
       "regular polygon with a vertex on +x",
       {{"radius", 1.0, "circumradius"}, {"sides", 6, "number of sides"}}},
      {"hexagon", "regular hexagon with a vertex on +x", {{"radius", 1.0, "circumradius"}}},
      {"plus",
       "plus/cross shape (Bhattacharya & Lipton 2023, §6.3, §7.2): half length R, arm width 2cR, c "
       "= 0.2",
       {{"radius", 1.0, "half length R"}, {"arm_width", 0.4, "full arm width"}}},
      {"ring",
       "annulus (Bhattacharya & Lipton 2023, §7.2): inner radius tau R, tau = 0.6",
       {{"radius", 1.0, "outer radius R"},
        {"inner_radius", 0.6, "inner radius"},
        {"segments", 64, "edges per circle"}}},
      {"perturbed_disk",
       "randomly perturbed disk (Bhattacharya & Lipton 2023, §7.2): r_i = R(1 - X_i), X_i ~ U[0, 1 "
       "- phi]",
       {{"radius", 1.0, "radius R"},
        {"vertices", 20, "number of vertices N"},
        {"roundness", 0.6, "roundness phi"},
        {"seed", 1, "random seed"}}},
      {"neck",
       "concave hourglass pinched at x = 0 (cf. Jha et al. 2021, Fig. 18b: R = 1, half neck "
       "width w = 0.5 R)",
       {{"length", 2.0, "x size"}, {"width", 2.0, "y size"}, {"neck_width", 1.0, "width at x=0"}}},
      {"notched_plate",
       "plate with a rectangular notch from the middle of the left edge (Bhattacharya & Lipton "
       "2023, §6.4)",
       {{"width", 1.0, "x size"},
        {"height", 1.0, "y size"},
        {"notch_length", 0.5, "notch depth from the edge"},
        {"notch_width", 0.1, "notch width"}}},
      {"v_notched_plate",
       "plate with a V notch from the middle of the left edge",
       {{"width", 1.0, "x size"},
        {"height", 1.0, "y size"},
        {"notch_length", 0.5, "notch depth from the edge"},
        {"notch_width", 0.2, "notch opening at the edge"}}},
  };
  return shapes;
}

std::vector<std::string> builtin_shape_names()
{
  std::vector<std::string> names;
  for (const auto &s : builtin_shapes()) names.push_back(s.name);
  return names;
}

std::string builtin_shape_list()
{
  std::string list;
  for (const auto &n : builtin_shape_names()) list += (list.empty() ? "" : ", ") + n;
  return list;
}

Polygon make_shape(const std::string &name, const std::map<std::string, double> &params)
{
  const ShapeInfo *info = nullptr;
  for (const auto &s : builtin_shapes())
    if (s.name == name) info = &s;
  if (!info)
    throw GeometryError("unknown grain shape '" + name +
                        "'; known shapes: " + builtin_shape_list());

  std::map<std::string, double> v;
  for (const auto &p : info->parameters) v[p.name] = p.default_value;
  for (const auto &kv : params) {
    if (!v.count(kv.first)) {
      std::string known;
      for (const auto &p : info->parameters) known += (known.empty() ? "" : ", ") + p.name;
      throw GeometryError("unknown parameter '" + kv.first + "' for shape " + name +
                          "; known parameters: " + known);
    }
    v[kv.first] = kv.second;
  }
  auto count = [&](const char *key) {
    const double x = v[key];
    if (x != std::floor(x) || std::fabs(x) > 1e9)
      throw GeometryError(std::string("shape parameter ") + key + " must be an integer");
    return static_cast<int>(x);
  };

  Polygon p;
  if (name == "disk")
    p = make_disk(v["radius"], count("segments"));
  else if (name == "square")
    p = make_rectangle(v["side"], v["side"]);
  else if (name == "rectangle")
    p = make_rectangle(v["width"], v["height"]);
  else if (name == "polygon")
    p = make_regular_polygon(v["radius"], count("sides"));
  else if (name == "hexagon")
    p = make_regular_polygon(v["radius"], 6);
  else if (name == "plus")
    p = make_plus(v["radius"], v["arm_width"]);
  else if (name == "ring")
    p = make_ring(v["radius"], v["inner_radius"], count("segments"));
  else if (name == "perturbed_disk") {
    const int seed = count("seed");
    if (seed < 0) throw GeometryError("shape parameter seed must be >= 0");
    p = make_perturbed_disk(v["radius"], count("vertices"), v["roundness"],
                            static_cast<std::uint64_t>(seed));
  } else if (name == "neck")
    p = make_neck(v["length"], v["width"], v["neck_width"]);
  else
    p = make_notched_plate(v["width"], v["height"], v["notch_length"], v["notch_width"],
                           name == "v_notched_plate");
  p.validate();
  return p;
}

Polygon parse_polygon(std::istream &in, const std::string &src)
{
  Ring outer;
  std::vector<Ring> holes;
  Ring *current = nullptr;
  bool have_outer = false;
  std::string line;
  int lineno = 0;
  auto fail = [&](const std::string &msg) {
    throw GeometryError("polygon file " + src + ":" + std::to_string(lineno) + ": " + msg);
  };
  while (std::getline(in, line)) {
    ++lineno;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream ls(line);
    std::string first;
    if (!(ls >> first)) continue; // blank or comment-only line
    std::string extra;
    if (first == "outer" || first == "hole") {
      if (ls >> extra) fail("unexpected text '" + extra + "' after '" + first + "'");
      if (first == "outer") {
        if (have_outer) fail("more than one 'outer' section");
        have_outer = true;
        current = &outer;
      } else {
        holes.emplace_back();
        current = &holes.back();
      }
      continue;
    }
    std::istringstream ps(line);
    double x, y;
    if (!(ps >> x >> y) || (ps >> extra) || !std::isfinite(x) || !std::isfinite(y))
      fail("expected a vertex line 'x y' or a section keyword 'outer'/'hole', got '" + line + "'");
    if (!current) fail("vertex before any 'outer' or 'hole' section");
    current->emplace_back(x, y);
  }
  if (!have_outer) throw GeometryError("polygon file " + src + ": no 'outer' section");
  Polygon p(outer, holes);
  const std::string err = p.validation_error();
  if (!err.empty()) throw GeometryError("polygon file " + src + ": invalid polygon: " + err);
  return p;
}

Polygon read_polygon_file(const std::string &path)
{
  std::ifstream in(path);
  if (!in) throw GeometryError("cannot open polygon file '" + path + "'");
  return parse_polygon(in, path);
}

} // namespace peridem
