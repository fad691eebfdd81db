/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Robust geometric predicates for the grain geometry library.
//
// Bond pruning (Bhattacharya & Lipton 2023, §5) is decided by the sign of small
// determinants. Bonds that start or end on the boundary, run along an edge or
// pass exactly through a corner are common on a lattice, and a naive double
// evaluation can give the wrong sign there. orient2d() is therefore exact for
// double inputs: a floating-point filter first, then an exact expansion
// evaluation (Shewchuk-style TwoSum/TwoProduct) when the filter cannot decide.
#ifndef PERIDEM_GEOMETRY_PREDICATES_H
#define PERIDEM_GEOMETRY_PREDICATES_H

namespace peridem {

struct Vec2;

// Sign (-1, 0, +1) of the 2x2 determinant |b-a, c-a|: +1 if c lies left of the
// directed line a->b (counter-clockwise turn), exact for any double input
// (barring overflow/underflow).
int orient2d(const Vec2 &a, const Vec2 &b, const Vec2 &c);

// True if c lies on the closed segment [a, b] (exact).
bool on_segment(const Vec2 &a, const Vec2 &b, const Vec2 &c);

// Closed segment [a,b] and closed segment [c,d] share at least one point (exact).
bool segments_intersect_closed(const Vec2 &a, const Vec2 &b, const Vec2 &c, const Vec2 &d);

// Closed segment [a,b] meets the OPEN segment (c,d) (endpoints c, d excluded).
bool segment_hits_open_segment(const Vec2 &a, const Vec2 &b, const Vec2 &c, const Vec2 &d);

// Open segments (a,b) and (c,d) cross at a single point interior to both
// (a "proper" crossing; touching or collinear overlap does not count).
bool segments_cross_properly(const Vec2 &a, const Vec2 &b, const Vec2 &c, const Vec2 &d);

} // namespace peridem

#endif
