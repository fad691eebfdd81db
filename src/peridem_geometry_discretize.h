/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Discretization of a 2D grain into peridynamic nodes with nodal volumes.
//
// (a) Regular square lattice clipped to the shape (Bhattacharya & Lipton 2023, §6-7 use
//     uniform mesh size h); the nodal volume is the cell area h^2 or,
//     optionally, the exact area of the lattice cell clipped to the shape.
//     Optionally the nodes of the cells that the boundary crosses are moved
//     onto the boundary, as a mesher puts its boundary nodes (Jha et al. 2021).
// (b) Gmsh meshes (Jha et al. 2021, §3.1): nodes at the mesh vertices, nodal
//     volume V_i = sum over elements T_e containing i of int_{T_e} phi_i dx
//     (eq. 31) with the P1 (triangle) / Q1 (quad) interpolation functions.
#ifndef PERIDEM_GEOMETRY_DISCRETIZE_H
#define PERIDEM_GEOMETRY_DISCRETIZE_H

#include "peridem_geometry_polygon.h"

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

namespace peridem {

// Nodes of one grain: reference positions and nodal volumes (areas in 2D).
struct Nodes2D {
  std::vector<Vec2> x;
  std::vector<double> volume;
  std::size_t size() const { return x.size(); }
};

enum class NodalVolume {
  CellArea,  // V = h^2 for every node (default)
  ExactClip, // V = |cell cap D|; sums to |D| to round-off
};

enum class NodePlacement {
  Lattice, // the lattice points inside D (default)
  Outline, // the node of every cell that the boundary crosses moved onto the boundary
};

struct LatticeOptions {
  // Lattice points are offset + (i h, j h) for integers i, j.
  Vec2 offset{0.0, 0.0};
  NodalVolume volume = NodalVolume::CellArea;
  NodePlacement placement = NodePlacement::Lattice;
};

// Outline (see lattice_nodes): a moved node closer than this (in units of h) to a
// node already placed is merged into it. Interior nodes are h apart and at least
// h/2 from the boundary, and a node is only ever placed that far from the others,
// so no two nodes of an Outline grain are closer than outline_merge_fraction * h.
constexpr double outline_merge_fraction = 0.5;
// Outline: a cell with less than this fraction of h^2 in D is light (a corner or
// an edge just reaching into it); below the h^2 / 4 of a cell at a right-angle
// corner on a lattice point.
constexpr double outline_small_fraction = 0.2;
// Outline: a vertex of D where the outline turns by more than this (radians, 20
// degrees) is a corner; not the vertices of a polygon standing for a curve, whose
// nodes would crowd the vertices and leave gaps between them.
constexpr double outline_corner_angle = 0.3490658503988659;

// Square lattice of spacing h clipped to D. A lattice point is kept if it is
// inside the closed shape up to 1e-9 h (so points meant to lie on the boundary
// survive round-off); such a point that is exactly outside is moved onto/inside
// the boundary by a few ulps, so every node satisfies D.contains_exact().
// With ExactClip, the area of a cell whose centre is outside D is given to the
// nearest node, so the volumes sum to |D|.
//
// With Outline (requires ExactClip, else GeometryError) the node of every cell
// (closed h x h square) that the boundary of any ring meets is moved onto the
// boundary, with the cell's area in D as its volume: onto the corner in the cell
// nearest to its lattice point, else onto the nearest boundary point (a few ulps
// inward where round-off puts it outside). Cells the boundary does not meet keep
// their lattice point. The moved nodes are placed in turn, corners of cells that
// are not light first, then by decreasing volume:
//  * one closer than outline_merge_fraction * h to a placed node is merged into
//    it (volume added): cells at a convex corner, an arm thinner than h/2;
//  * a light one else joins the nearest node within h, which moves onto the
//    light node's point if it was an interior node or the light node is on a
//    corner, so that an edge just beyond a lattice row moves that row onto it
//    instead of adding light nodes;
//  * a node moves only to a point no other node is closer to than
//    outline_merge_fraction * h.
// A cell with less than 1e-12 of its area in D (round-off) gives it to the
// nearest node. The volumes sum to |D|. Nodes keep the lattice's row-major order.
Nodes2D lattice_nodes(const Polygon &D, double h, const LatticeOptions &opt = {});

// True if the closed segment [a, b] meets the closed box [lo, hi] (Liang-Barsky).
bool segment_meets_box(const Vec2 &a, const Vec2 &b, const Vec2 &lo, const Vec2 &hi);

// Exact area of the axis-aligned box [lo, hi] intersected with D
// (Sutherland-Hodgman clipping of every ring against the box; hole rings are
// clockwise and subtract themselves).
double clipped_box_area(const Polygon &D, const Vec2 &lo, const Vec2 &hi);

// A 2D mesh as read from Gmsh: vertex coordinates (z dropped) and linear
// elements, 0-based vertex indices.
struct Mesh2D {
  std::vector<Vec2> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::array<int, 4>> quads;
  double area() const;
};

// Reads an ASCII Gmsh file, format 2.2 or 4.1, keeping 3-node triangles
// (type 2) and 4-node quads (type 3); lines and points are ignored. Errors
// (missing file, binary or other versions, malformed lines, unknown node tags,
// higher-order elements, no 2D element) name the file and line.
Mesh2D read_gmsh_mesh(const std::string &path);
// The same from a stream (e.g. a file read on one MPI rank and broadcast); `path` names it in
// messages.
Mesh2D parse_gmsh_mesh(std::istream &in, const std::string &path);

// Nodes at mesh vertices with volumes from eq. 31: each triangle gives |T|/3 to
// each of its vertices, each quad the integrals of its bilinear shape
// functions (2x2 Gauss, exact). Vertices used by no element are dropped.
Nodes2D mesh_nodes(const Mesh2D &mesh);

} // namespace peridem

#endif
