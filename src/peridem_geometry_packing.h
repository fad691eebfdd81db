/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Jammed polydisperse disk (2D) and sphere (3D) packings of a rectangular
// container: the "security disks" of Bhattacharya & Lipton 2023, §7-7.1.
//
// Bhattacharya and Lipton 2023 (§7) start a bed from disks that
// are jammed (Definition 7.1: no disk can be displaced without overlapping
// another disk or a wall), shrinks them by R_c/2 so nothing touches at t = 0,
// and inscribes one randomly rotated grain in each. Its §7.1 gets the disks
// from a triangle mesh (radii come out of the optimisation). Here the radii
// are drawn from a given distribution and the disks are jammed by energy
// minimisation of soft disks under a vertical pressure (the jamming protocol
// of O'Hern, Silbert, Liu and Nagel, PRE 68, 011306 (2003), with the FIRE
// minimiser of Bitzek et al., PRL 97, 170201 (2006), and an affine
// Berendsen-type barostat on the bed height); see pack_spheres().
#ifndef PERIDEM_GEOMETRY_PACKING_H
#define PERIDEM_GEOMETRY_PACKING_H

#include "peridem_geometry_error.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace peridem {

// Radius distribution of the security disks.
struct RadiusDistribution {
  enum class Kind { Uniform, Normal, List };
  Kind kind = Kind::Uniform;
  double lo = 0.0, hi = 0.0;   // range (uniform; clip range of normal)
  double mean = 0.0, sd = 0.0; // normal
  std::vector<double> values;  // list: drawn with equal probability
  static RadiusDistribution uniform(double lo, double hi);
  // normal(mean, sd) truncated to [lo, hi] by rejection (no mass piles up at
  // the bounds, unlike clamping)
  static RadiusDistribution normal(double mean, double sd, double lo, double hi);
  static RadiusDistribution list(std::vector<double> values);
  // throws GeometryError for a zero/negative radius, an inverted range, a
  // normal whose range is beyond 8 sd of the mean (practically never drawn)
  void validate() const;
  double smallest() const;
  double largest() const;
};

// n radii, reproducible on every platform for a given seed (own 64-bit
// uniform and Box-Muller normal, not the implementation-defined std ones).
std::vector<double> draw_radii(const RadiusDistribution &dist, std::size_t n, std::uint64_t seed);

// std::mt19937_64 (its output is fixed by the C++ standard) with its own
// uniform and normal, so that a seed gives the same numbers everywhere.
struct PackingRandom {
  explicit PackingRandom(std::uint64_t seed) : gen(seed) {}
  double uniform() { return static_cast<double>(gen() >> 11) * 0x1.0p-53; } // [0, 1)
  double normal();                                                          // Box-Muller
  std::mt19937_64 gen;
};

struct PackingOptions {
  int dimension = 2;        // 2: disks in x-y (y up); 3: spheres (z up)
  double lo[3] = {0, 0, 0}; // container: floor at lo[dim-1], side walls at lo/hi
  double hi[3] = {1, 1, 1}; // hi[dim-1] is the highest the bed may reach
  std::uint64_t seed = 1;   // initial positions
  // Relative contact tolerance tau: the minimiser works with radii r (1 + tau/2) and
  // stops when no overlap of those exceeds tau r / 2, so true gaps of touching disks
  // are in [0, tau (r_i + r_j) / 2] (walls: [0, tau r_i]) and none is negative.
  double tolerance = 1e-3;
  int max_iterations = 200000;
  // 2d beds of more than 3 * tile disks are packed tile by tile, about `tile`
  // disks a tile (near-linear time; see pack_spheres); 0: always as one bed
  std::size_t tile = 2000;
};

struct Packing {
  int dimension = 2;
  std::vector<std::array<double, 3>> centre;
  std::vector<double> radius;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}; // the jammed bed: hi[dim-1] = its lid
  double fraction = 0.0;                       // disk area / bed area (volumes in 3D)
  int iterations = 0; // FIRE iterations used (tiled: whole-bed equivalents)
};

// Jams the disks of the given radii in the container: side walls and floor
// fixed, the lid (bed height) found by the minimisation. A cell grid gives
// Verlet lists; 2d beds of more than 3 * opt.tile disks are packed tile by tile
// (rows of tiles from the floor up, the packed disks around a tile held, one
// strip on top), so the time grows near-linearly with N (see the .cpp). Throws GeometryError if the
// container cannot hold the disks (a disk wider than the container, or the jammed bed higher than
// the container) or if the minimisation does not converge.
Packing pack_spheres(const std::vector<double> &radii, const PackingOptions &opt);

// Before any radius is drawn: throws GeometryError if `count` disks of dist, each at least of
// its smallest radius, could not fit in the container of opt even at the densest packing. After
// it passes, count is at most the number of smallest disks the container holds, so drawing
// count radii costs no more memory than a bed that fits.
void check_count_fits(const RadiusDistribution &dist, std::size_t count, const PackingOptions &opt);

// Smallest gap (distance minus radii) over all disk pairs and all walls of box
// lo/hi (negative: overlap or wall crossing); exact, cell grid.
struct GapReport {
  double pair = 0.0, wall = 0.0; // smallest pair gap, smallest wall gap
  std::size_t pair_i = 0, pair_j = 0, wall_i = 0;
};
GapReport smallest_gaps(const Packing &p);

// Fraction of the box lo/hi covered by disks, by the midpoint rule on
// samples^D points: the bulk fraction, away from the wall layers, where
// packings are looser (walls order the first layer).
double fraction_inside(const Packing &p, const double *lo, const double *hi, int samples);

// Local jamming (Bhattacharya & Lipton 2023, Definition 7.1 applied to one disk, the others fixed):
// disk i cannot move iff the unit directions to its contacts (disks with gap
// <= tau (r_i + r_j) / 2, walls with gap <= tau r_i) lie in no closed half-plane
// (half-space in 3D), i.e. every displacement u has u . n_k > 0 for some k.
// Disks that fail are "rattlers": caged in a hole of the jammed backbone,
// they carry no load; jammed packings always have a few (O'Hern et al. 2003).
bool directions_block_every_move(const std::vector<std::array<double, 3>> &dirs, int dimension);
struct JammingReport {
  std::size_t jammed = 0, rattlers = 0;
  double mean_contacts = 0.0; // contacts per backbone disk (walls included)
  std::vector<std::size_t> rattler_index;
};
JammingReport jamming_report(const Packing &p, double tolerance);

// Rattler growth: Bhattacharya & Lipton (2023) §7.1 step 4 in spirit (each nodal circle gets the
// largest radius its neighbours and the walls allow, centre free). Each
// rattler, the other disks fixed, moves to the centre of the largest disk
// that fits in its cage (a local maximum over c of the distance to the
// nearest disk surface or wall, reached by a smoothed ascent) and takes that
// radius, capped at `cap` (the distribution's upper bound). At the maximum
// its contact directions lie in no closed half-plane (half-space), so it is
// jammed unless capped. Passes repeat while the rattler count falls (a
// grown rattler can jam a neighbouring one, a moved one can free a disk
// that leaned on it). Disks only grow: the bed's sizes shift up (reported).
struct RattlerGrowth {
  std::size_t before = 0, after = 0; // rattlers before and after
  std::size_t grown = 0;             // disks given a new centre and radius (all passes)
  std::size_t capped = 0;            // remaining rattlers whose cage holds more than cap
  int passes = 0;
  std::vector<std::size_t> remaining; // rattler indices left
};
RattlerGrowth grow_rattlers(Packing &p, double cap, double tolerance, int max_passes = 8);

// Perturbed-row bed of Jha, Desai, Bhattacharya and
// Lipton (2021, §4.4 and Fig. 22): disks in rows on a "uniform grid", each
// centre shifted randomly in x so that centres do not line up vertically; a
// loose start that settles under gravity, not a jammed packing. Rows fill
// the container from the floor, alternately from the left and from the right
// wall (as the authors' setup script does); in a row the disks' bottoms are
// aligned and consecutive disks are gap + U(0, 2 perturb r) apart (the random
// x shift of the paper; never less than gap, so nothing overlaps); a row
// starts gap above the highest disk of the row below and gap from the wall;
// a row ends with the first disk that does not fit. Radii are drawn in order
// from draw_radii(dist, max_count, seed); at most max_count disks.
struct RowOptions {
  int dimension = 2; // 2 only
  double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  double gap = 0.0;     // >= 0: between disks, rows and walls
  double perturb = 0.1; // random extra spacing up to 2 perturb r
  std::uint64_t seed = 1;
  std::size_t max_count = 0; // 0: as many as fit
};
Packing row_packing(const RadiusDistribution &dist, const RowOptions &opt);

// Smallest circle enclosing the points (Welzl's algorithm, expected linear):
// the security disk of a 2D grain shape.
struct EnclosingCircle {
  double x = 0.0, y = 0.0, r = 0.0;
};
EnclosingCircle smallest_enclosing_circle(const std::vector<std::array<double, 2>> &points);

} // namespace peridem

#endif
