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

void requirePositive(double v, const char *what)
{
  if (!(v > 0.0) || !std::isfinite(v)) {
    std::ostringstream value; // the value as the user wrote it (up to 6 digits)
    value << v;
    throw GeometryError(std::string("shape parameter ") + what + " must be positive, not " +
                        value.str());
  }
}

void requireCount(int n, int minimum, const char *what)
{
  if (n < minimum)
    throw GeometryError(std::string("shape parameter ") + what + " must be at least " +
                        std::to_string(minimum));
}

Ring circleRing(double r, int n)
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
Polygon regularPolygon(double radius, int n, const char *countName)
{
  requirePositive(radius, "radius");
  requireCount(n, 3, countName);
  return Polygon(circleRing(radius, n));
}

} // namespace

Polygon makeDisk(double radius, int segments)
{
  return regularPolygon(radius, segments, "segments");
}

Polygon makeRectangle(double width, double height)
{
  requirePositive(width, "width");
  requirePositive(height, "height");
  const double a = 0.5 * width, b = 0.5 * height;
  return Polygon({{-a, -b}, {a, -b}, {a, b}, {-a, b}});
}

Polygon makeRegularPolygon(double radius, int sides)
{
  return regularPolygon(radius, sides, "sides");
}

Polygon makePlus(double radius, double armWidth)
{
  requirePositive(radius, "radius");
  requirePositive(armWidth, "arm_width");
  const double a = 0.5 * armWidth, r = radius;
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

Polygon makeRing(double outerRadius, double innerRadius, int segments)
{
  requirePositive(outerRadius, "radius");
  requirePositive(innerRadius, "inner_radius");
  requireCount(segments, 3, "segments");
  if (!(innerRadius < outerRadius * std::cos(kPi / segments)))
    throw GeometryError("ring needs inner_radius < radius (hole must be inside)");
  return Polygon(circleRing(outerRadius, segments), {circleRing(innerRadius, segments)});
}

Polygon makePerturbedDisk(double radius, int vertices, double roundness, std::uint64_t seed)
{
  requirePositive(radius, "radius");
  requireCount(vertices, 3, "vertices");
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

Polygon makeNeck(double length, double width, double neckWidth)
{
  requirePositive(length, "length");
  requirePositive(width, "width");
  requirePositive(neckWidth, "neck_width");
  if (!(neckWidth < width)) throw GeometryError("neck shape needs neck_width < width");
  const double a = 0.5 * length, b = 0.5 * width, c = 0.5 * neckWidth;
  return Polygon({{-a, -b}, {0.0, -c}, {a, -b}, {a, b}, {0.0, c}, {-a, b}});
}

Polygon makeNotchedPlate(double width, double height, double notchLength, double notchWidth,
                         bool vNotch)
{
  requirePositive(width, "width");
  requirePositive(height, "height");
  requirePositive(notchLength, "notch_length");
  requirePositive(notchWidth, "notch_width");
  if (!(notchLength < width)) throw GeometryError("notched plate needs notch_length < width");
  if (!(notchWidth < height)) throw GeometryError("notched plate needs notch_width < height");
  const double a = 0.5 * width, b = 0.5 * height, c = 0.5 * notchWidth;
  const double tip = -a + notchLength;
  Ring r = {{-a, -b}, {a, -b}, {a, b}, {-a, b}, {-a, c}};
  if (vNotch) {
    r.emplace_back(tip, 0.0);
  } else {
    r.emplace_back(tip, c);
    r.emplace_back(tip, -c);
  }
  r.emplace_back(-a, -c);
  return Polygon(r);
}

const std::vector<ShapeInfo> &builtinShapes()
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

std::vector<std::string> builtinShapeNames()
{
  std::vector<std::string> names;
  for (const auto &s : builtinShapes()) names.push_back(s.name);
  return names;
}

std::string builtinShapeList()
{
  std::string list;
  for (const auto &n : builtinShapeNames()) list += (list.empty() ? "" : ", ") + n;
  return list;
}

Polygon makeShape(const std::string &name, const std::map<std::string, double> &params)
{
  const ShapeInfo *info = nullptr;
  for (const auto &s : builtinShapes())
    if (s.name == name) info = &s;
  if (!info)
    throw GeometryError("unknown grain shape '" + name + "'; known shapes: " + builtinShapeList());

  std::map<std::string, double> v;
  for (const auto &p : info->parameters) v[p.name] = p.defaultValue;
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
    p = makeDisk(v["radius"], count("segments"));
  else if (name == "square")
    p = makeRectangle(v["side"], v["side"]);
  else if (name == "rectangle")
    p = makeRectangle(v["width"], v["height"]);
  else if (name == "polygon")
    p = makeRegularPolygon(v["radius"], count("sides"));
  else if (name == "hexagon")
    p = makeRegularPolygon(v["radius"], 6);
  else if (name == "plus")
    p = makePlus(v["radius"], v["arm_width"]);
  else if (name == "ring")
    p = makeRing(v["radius"], v["inner_radius"], count("segments"));
  else if (name == "perturbed_disk") {
    const int seed = count("seed");
    if (seed < 0) throw GeometryError("shape parameter seed must be >= 0");
    p = makePerturbedDisk(v["radius"], count("vertices"), v["roundness"],
                          static_cast<std::uint64_t>(seed));
  } else if (name == "neck")
    p = makeNeck(v["length"], v["width"], v["neck_width"]);
  else
    p = makeNotchedPlate(v["width"], v["height"], v["notch_length"], v["notch_width"],
                         name == "v_notched_plate");
  p.validate();
  return p;
}

Polygon parsePolygon(std::istream &in, const std::string &src)
{
  Ring outer;
  std::vector<Ring> holes;
  Ring *current = nullptr;
  bool haveOuter = false;
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
        if (haveOuter) fail("more than one 'outer' section");
        haveOuter = true;
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
  if (!haveOuter) throw GeometryError("polygon file " + src + ": no 'outer' section");
  Polygon p(outer, holes);
  const std::string err = p.validationError();
  if (!err.empty()) throw GeometryError("polygon file " + src + ": invalid polygon: " + err);
  return p;
}

Polygon readPolygonFile(const std::string &path)
{
  std::ifstream in(path);
  if (!in) throw GeometryError("cannot open polygon file '" + path + "'");
  return parsePolygon(in, path);
}

} // namespace peridem
