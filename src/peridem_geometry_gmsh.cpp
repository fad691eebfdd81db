/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Gmsh .msh import (ASCII 2.2 and 4.1) and nodal volumes from the P1/Q1
// interpolation functions, Jha et al. 2021, §3.1 eq. 31.
#include "peridem_geometry_discretize.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <unordered_map>

namespace peridem {

namespace {

// Line-oriented tokenizer that remembers the line number for messages.
class MshReader {
 public:
  MshReader(std::istream &in, std::string name) : in_(in), name_(std::move(name)) {}
  [[noreturn]] void fail(const std::string &msg) const
  {
    throw GeometryError("Gmsh file " + name_ + ":" + std::to_string(line_) + ": " + msg);
  }
  // Next non-empty line split into tokens; false at end of file.
  bool next(std::vector<std::string> &tok)
  {
    std::string s;
    while (std::getline(in_, s)) {
      ++line_;
      std::istringstream ls(s);
      tok.clear();
      for (std::string t; ls >> t;) tok.push_back(t);
      if (!tok.empty()) return true;
    }
    return false;
  }
  std::vector<std::string> require(const char *what)
  {
    std::vector<std::string> tok;
    if (!next(tok)) fail(std::string("unexpected end of file, expected ") + what);
    return tok;
  }
  long to_long(const std::string &s) const
  {
    return parse<long>(s, "an integer",
                       [](const std::string &t, std::size_t *pos) { return std::stol(t, pos); });
  }
  double to_double(const std::string &s) const
  {
    const double v = parse<double>(
        s, "a number", [](const std::string &t, std::size_t *pos) { return std::stod(t, pos); });
    if (!std::isfinite(v)) fail("expected a finite number, got '" + s + "'");
    return v;
  }
  // Whole-token conversion; anything left over or out of range is an error.
  template <class T, class Conv> T parse(const std::string &s, const char *what, Conv conv) const
  {
    std::size_t pos = 0;
    T v{};
    try {
      v = conv(s, &pos);
    } catch (...) {
      pos = 0;
    }
    if (pos != s.size()) fail(std::string("expected ") + what + ", got '" + s + "'");
    return v;
  }
  void need(const std::vector<std::string> &tok, std::size_t n, const char *what) const
  {
    if (tok.size() < n) fail(std::string("too few entries for ") + what);
  }

 private:
  std::istream &in_;
  std::string name_;
  long line_ = 0;
};

struct MshData {
  std::unordered_map<long, int> tag_to_index;
  Mesh2D mesh;
};

void add_node(MshReader &r, MshData &d, long tag, const std::vector<std::string> &xyz,
              std::size_t first)
{
  r.need(xyz, first + 3, "a node (x y z)");
  if (!d.tag_to_index.emplace(tag, static_cast<int>(d.mesh.vertices.size())).second)
    r.fail("duplicate node tag " + std::to_string(tag));
  d.mesh.vertices.emplace_back(r.to_double(xyz[first]), r.to_double(xyz[first + 1]));
}

// Adds an element of Gmsh type `type` whose node tags start at tok[first].
void add_element(MshReader &r, MshData &d, long type, const std::vector<std::string> &tok,
                 std::size_t first)
{
  if (type == 1 || type == 15) return; // lines and points: boundary tags only
  if (type != 2 && type != 3)
    r.fail("unsupported element type " + std::to_string(type) +
           " (only linear triangles, type 2, and quads, type 3)");
  const std::size_t nn = type == 2 ? 3 : 4;
  r.need(tok, first + nn, "an element's node list");
  std::array<int, 4> v{};
  for (std::size_t k = 0; k < nn; ++k) {
    const auto it = d.tag_to_index.find(r.to_long(tok[first + k]));
    if (it == d.tag_to_index.end()) r.fail("element refers to unknown node " + tok[first + k]);
    v[k] = it->second;
  }
  if (type == 2)
    d.mesh.triangles.push_back({v[0], v[1], v[2]});
  else
    d.mesh.quads.push_back(v);
}

void read_nodes22(MshReader &r, MshData &d)
{
  const long n = r.to_long(r.require("node count")[0]);
  for (long i = 0; i < n; ++i) {
    const auto tok = r.require("a node line");
    r.need(tok, 4, "a node line (tag x y z)");
    add_node(r, d, r.to_long(tok[0]), tok, 1);
  }
}

void read_elements22(MshReader &r, MshData &d)
{
  const long n = r.to_long(r.require("element count")[0]);
  for (long i = 0; i < n; ++i) {
    const auto tok = r.require("an element line");
    r.need(tok, 3, "an element line (tag type ntags ...)");
    const long ntags = r.to_long(tok[2]);
    if (ntags < 0) r.fail("negative tag count");
    add_element(r, d, r.to_long(tok[1]), tok, 3 + static_cast<std::size_t>(ntags));
  }
}

void read_nodes41(MshReader &r, MshData &d)
{
  const auto head = r.require("node section header");
  r.need(head, 4, "the $Nodes header (numEntityBlocks numNodes minTag maxTag)");
  const long blocks = r.to_long(head[0]);
  for (long b = 0; b < blocks; ++b) {
    const auto bh = r.require("a node block header");
    r.need(bh, 4, "a node block header (dim tag parametric numNodes)");
    const long cnt = r.to_long(bh[3]);
    std::vector<long> tags;
    for (long i = 0; i < cnt; ++i) tags.push_back(r.to_long(r.require("a node tag")[0]));
    for (long i = 0; i < cnt; ++i) add_node(r, d, tags[i], r.require("node coordinates"), 0);
  }
}

void read_elements41(MshReader &r, MshData &d)
{
  const auto head = r.require("element section header");
  r.need(head, 4, "the $Elements header (numEntityBlocks numElements minTag maxTag)");
  const long blocks = r.to_long(head[0]);
  for (long b = 0; b < blocks; ++b) {
    const auto bh = r.require("an element block header");
    r.need(bh, 4, "an element block header (dim tag type numElements)");
    const long type = r.to_long(bh[2]), cnt = r.to_long(bh[3]);
    for (long i = 0; i < cnt; ++i) add_element(r, d, type, r.require("an element line"), 1);
  }
}

} // namespace

double Mesh2D::area() const
{
  double a = 0.0;
  for (const auto &t : triangles)
    a += 0.5 * std::fabs(cross(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]]));
  for (const auto &q : quads)
    a += 0.5 * std::fabs(cross(vertices[q[2]] - vertices[q[0]], vertices[q[3]] - vertices[q[1]]));
  return a;
}

Mesh2D read_gmsh_mesh(const std::string &path)
{
  std::ifstream in(path);
  if (!in) throw GeometryError("cannot open Gmsh file '" + path + "'");
  return parse_gmsh_mesh(in, path);
}

Mesh2D parse_gmsh_mesh(std::istream &in, const std::string &path)
{
  MshReader r(in, path);
  MshData d;
  std::string version;
  bool have_nodes = false;
  std::vector<std::string> tok;
  while (r.next(tok)) {
    const std::string sec = tok[0];
    if (sec.empty() || sec[0] != '$')
      r.fail("expected a section such as $Nodes, got '" + sec + "'");
    if (sec == "$MeshFormat") {
      const auto f = r.require("the format line");
      r.need(f, 3, "the format line (version file-type data-size)");
      version = f[0];
      if (f[1] != "0") r.fail("binary Gmsh files are not supported; save as ASCII");
      if (version != "2.2" && version != "4.1" && version != "4")
        r.fail("unsupported Gmsh format " + version + " (use 2.2 or 4.1)");
    } else if (sec == "$Nodes" || sec == "$Elements") {
      if (version.empty()) r.fail(sec + " before $MeshFormat");
      const bool v2 = version == "2.2";
      if (sec == "$Nodes") {
        v2 ? read_nodes22(r, d) : read_nodes41(r, d);
        have_nodes = true;
      } else {
        if (!have_nodes) r.fail("$Elements before $Nodes");
        v2 ? read_elements22(r, d) : read_elements41(r, d);
      }
    }
    // Skip to the end of this section (also skips $PhysicalNames, $Entities...).
    const std::string end = "$End" + sec.substr(1);
    for (;;) {
      if (!r.next(tok)) r.fail("missing " + end);
      if (tok[0] == end) break;
      if (sec == "$Nodes" || sec == "$Elements" || sec == "$MeshFormat")
        r.fail("expected " + end + ", got '" + tok[0] + "'");
    }
  }
  if (version.empty()) throw GeometryError("Gmsh file " + path + ": no $MeshFormat section");
  if (d.mesh.triangles.empty() && d.mesh.quads.empty())
    throw GeometryError("Gmsh file " + path + ": no triangle (type 2) or quad (type 3) elements");
  return d.mesh;
}

Nodes2D mesh_nodes(const Mesh2D &m)
{
  std::vector<double> vol(m.vertices.size(), 0.0);
  // eq. 31 with P1 functions: int_T phi_i = |T| / 3 for each vertex of T.
  for (const auto &t : m.triangles) {
    const double a = 0.5 * std::fabs(cross(m.vertices[t[1]] - m.vertices[t[0]],
                                           m.vertices[t[2]] - m.vertices[t[0]]));
    for (int v : t) vol[v] += a / 3.0;
  }
  // Q1 (bilinear) functions: int_Q phi_i = sum_g phi_i(g) |det J(g)| w_g with
  // 2x2 Gauss points, exact because phi_i * det J is at most biquadratic.
  const double g = 1.0 / std::sqrt(3.0);
  const double xi[4] = {-1, 1, 1, -1}, eta[4] = {-1, -1, 1, 1};
  for (const auto &q : m.quads) {
    for (int gp = 0; gp < 4; ++gp) {
      const double s = xi[gp] * g, t = eta[gp] * g;
      Vec2 dxds, dxdt;
      for (int k = 0; k < 4; ++k) {
        dxds = dxds + m.vertices[q[k]] * (0.25 * xi[k] * (1 + eta[k] * t));
        dxdt = dxdt + m.vertices[q[k]] * (0.25 * eta[k] * (1 + xi[k] * s));
      }
      const double detJ = std::fabs(cross(dxds, dxdt));
      for (int k = 0; k < 4; ++k) vol[q[k]] += 0.25 * (1 + xi[k] * s) * (1 + eta[k] * t) * detJ;
    }
  }
  Nodes2D n;
  for (std::size_t i = 0; i < vol.size(); ++i)
    if (vol[i] > 0.0) {
      n.x.push_back(m.vertices[i]);
      n.volume.push_back(vol[i]);
    }
  return n;
}

} // namespace peridem
