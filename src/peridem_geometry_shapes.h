/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Built-in parametric grain shapes and the user polygon file reader.
//
// The shapes are those of Bhattacharya & Lipton 2023, §6.2-6.4 and §7.2 (perturbed
// disks, squares, plus shapes, rings, notched plates) plus a few common extras
// (rectangle, regular polygon/hexagon, concave "neck"). Every shape is centred
// at the origin; place it with Polygon::rotate()/translate().
#ifndef PERIDEM_GEOMETRY_SHAPES_H
#define PERIDEM_GEOMETRY_SHAPES_H

#include "peridem_geometry_polygon.h"

#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace peridem {

Polygon make_disk(double radius, int segments);
Polygon make_rectangle(double width, double height);
Polygon make_regular_polygon(double radius, int sides);
// Plus/cross (§6.3, §7.2): arm tips at distance `radius` (the half length R)
// from the centre, arms of full width `arm_width`.
Polygon make_plus(double radius, double arm_width);
// Annulus (§7.2): inner radius tau * outer radius, tau = 0.6 in Bhattacharya & Lipton 2023.
Polygon make_ring(double outer_radius, double inner_radius, int segments);
// Randomly perturbed disk (§7.2): vertices (r_i cos t_i, r_i sin t_i),
// t_i = 2 pi i / N, r_i = R (1 - X_i), X_i iid uniform on [0, 1 - phi]
// (phi = roundness). Deterministic for a given seed on every platform.
Polygon make_perturbed_disk(double radius, int vertices, double roundness, std::uint64_t seed);
// Concave hourglass: length x width rectangle pinched to neck_width at x = 0.
Polygon make_neck(double length, double width, double neck_width);
// Plate width x height with a notch cut from the middle of the left edge
// (§6.4: square plate, notch of length 0.5 reaching the centre). Rectangular
// notch of the given width, or a V notch whose opening at the edge is notch_width.
Polygon make_notched_plate(double width, double height, double notch_length, double notch_width,
                           bool v_notch);

// Parameter table of a built-in shape (names as in Bhattacharya & Lipton 2023, defaults for a
// grain of characteristic size 1).
struct ShapeParameter {
  std::string name;
  double default_value;
  std::string description;
};
struct ShapeInfo {
  std::string name;
  std::string description;
  std::vector<ShapeParameter> parameters;
};
const std::vector<ShapeInfo> &builtin_shapes();
std::vector<std::string> builtin_shape_names();
// Comma-separated list of the built-in shape names, for error messages.
std::string builtin_shape_list();

// Builds a built-in shape by name. Parameters not given take their defaults;
// unknown shape or parameter names and bad values throw GeometryError listing
// the valid choices. The result is validated.
Polygon make_shape(const std::string &name, const std::map<std::string, double> &params = {});

// User polygon files (format: doc/peridem_polygon_format.rst). Errors name the
// file and the line. The result is validated.
Polygon read_polygon_file(const std::string &path);
Polygon parse_polygon(std::istream &in, const std::string &source_name);

} // namespace peridem

#endif
