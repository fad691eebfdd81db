/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Jammed polydisperse disk/sphere packings (Bhattacharya & Lipton 2023, §7-7.1); see the
// header for the method and its references.
#include "peridem_geometry_packing.h"
#include "peridem_math.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace peridem {

namespace {

// A generator of its own for one use of a packing seed (salt tells the uses
// apart, so e.g. radii and positions drawn from one seed do not correlate): the
// seed plus the salt through the splitmix64 finaliser (Steele et al. 2014).
PackingRandom random_stream(std::uint64_t seed, std::uint64_t salt)
{
  std::uint64_t z = seed + salt;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return PackingRandom(z ^ (z >> 31));
}

std::string str(double v)
{
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

double ball_volume(double r, int dim)
{
  return dim == 2 ? kPi * r * r : 4.0 / 3.0 * kPi * r * r * r;
}

// Densest packings: hexagonal (2D), fcc (3D); a bed needing more cannot fit. `bound` and
// `why` qualify a lower bound ("at least ", " (N disks of radius >= r)").
void check_fraction(double fraction, int dim, const std::string &bound = "",
                    const std::string &why = "")
{
  const double densest = dim == 2 ? kPi / (2.0 * std::sqrt(3.0)) : kPi / (3.0 * std::sqrt(2.0));
  if (fraction > densest)
    throw GeometryError("the disks need a packing fraction of " + bound + str(fraction) + why +
                        " to fit in the container, beyond the densest packing (" + str(densest) +
                        ")");
}

// Every extent of the container must hold a disk of radius r, with the minimiser's
// tolerance (the radii grow by tau/2 there); `note` qualifies r in the message.
void check_extents(const PackingOptions &opt, double r, const std::string &note = "")
{
  const double alpha = 0.5 * opt.tolerance;
  for (int d = 0; d < opt.dimension; d++)
    if (!(opt.hi[d] - opt.lo[d] >= 2.0 * r * (1.0 + alpha)))
      throw GeometryError("container " + std::string(1, "xyz"[d]) + " extent " +
                          str(opt.hi[d] - opt.lo[d]) + " is too small for a disk of radius " +
                          str(r) + note);
}

/* Cell grid over [lo, hi] (cells of side >= `size`; points outside are put in
   the border cells). Cells are sorted by a counting sort, so building is O(N).
   for_each_pair visits each unordered pair of points in the same or adjacent
   cells once (half stencil). */
class CellGrid {
 public:
  CellGrid(int dim, const double *lo, const double *hi, double size) : dim(dim)
  {
    for (int d = 0; d < 3; d++) {
      const double w = d < dim ? hi[d] - lo[d] : 0.0;
      n[d] = d < dim ? std::max(1, static_cast<int>(w / size)) : 1;
      base[d] = lo[d];
      inv[d] = d < dim ? n[d] / std::max(w, 1e-300) : 0.0;
    }
  }
  void build(const std::vector<std::array<double, 3>> &x)
  {
    const std::size_t np = x.size();
    cell_of.resize(np);
    start.assign(static_cast<std::size_t>(n[0]) * n[1] * n[2] + 1, 0);
    for (std::size_t i = 0; i < np; i++) {
      int c[3] = {0, 0, 0};
      for (int d = 0; d < dim; d++)
        c[d] = std::min(n[d] - 1, std::max(0, static_cast<int>((x[i][d] - base[d]) * inv[d])));
      cell_of[i] = (static_cast<std::size_t>(c[2]) * n[1] + c[1]) * n[0] + c[0];
      start[cell_of[i] + 1]++;
    }
    for (std::size_t c = 1; c < start.size(); c++) start[c] += start[c - 1];
    order.resize(np);
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < np; i++) order[fill[cell_of[i]]++] = i;
  }
  // point indices sorted by cell (after build)
  const std::vector<std::size_t> &sorted() const { return order; }
  template <class F> void for_each_pair(F &&f) const
  {
    // half stencil: the cell itself (j > i) and the neighbours "after" it
    static const int off2[4][3] = {{1, 0, 0}, {-1, 1, 0}, {0, 1, 0}, {1, 1, 0}};
    static const int off3[13][3] = {{1, 0, 0},  {-1, 1, 0}, {0, 1, 0},  {1, 1, 0}, {-1, -1, 1},
                                    {0, -1, 1}, {1, -1, 1}, {-1, 0, 1}, {0, 0, 1}, {1, 0, 1},
                                    {-1, 1, 1}, {0, 1, 1},  {1, 1, 1}};
    const int noff = dim == 2 ? 4 : 13;
    const int(*off)[3] = dim == 2 ? off2 : off3;
    for (int cz = 0; cz < n[2]; cz++)
      for (int cy = 0; cy < n[1]; cy++)
        for (int cx = 0; cx < n[0]; cx++) {
          const std::size_t c = (static_cast<std::size_t>(cz) * n[1] + cy) * n[0] + cx;
          for (std::size_t a = start[c]; a < start[c + 1]; a++) {
            for (std::size_t b = a + 1; b < start[c + 1]; b++) f(order[a], order[b]);
            for (int k = 0; k < noff; k++) {
              const int ox = cx + off[k][0], oy = cy + off[k][1], oz = cz + off[k][2];
              if (ox < 0 || oy < 0 || oz < 0 || ox >= n[0] || oy >= n[1] || oz >= n[2]) continue;
              const std::size_t o = (static_cast<std::size_t>(oz) * n[1] + oy) * n[0] + ox;
              for (std::size_t b = start[o]; b < start[o + 1]; b++) f(order[a], order[b]);
            }
          }
        }
  }

 private:
  int dim;
  int n[3];
  double base[3], inv[3];
  std::vector<std::size_t> cell_of, start, order;
};

} // namespace

/* ---------------------------------------------------------------------- */

RadiusDistribution RadiusDistribution::uniform(double lo, double hi)
{
  RadiusDistribution d;
  d.kind = Kind::Uniform;
  d.lo = lo;
  d.hi = hi;
  return d;
}

RadiusDistribution RadiusDistribution::normal(double mean, double sd, double lo, double hi)
{
  RadiusDistribution d;
  d.kind = Kind::Normal;
  d.mean = mean;
  d.sd = sd;
  d.lo = lo;
  d.hi = hi;
  return d;
}

RadiusDistribution RadiusDistribution::list(std::vector<double> values)
{
  RadiusDistribution d;
  d.kind = Kind::List;
  d.values = std::move(values);
  return d;
}

void RadiusDistribution::validate() const
{
  if (kind == Kind::List) {
    if (values.empty()) throw GeometryError("radius list is empty");
    for (double v : values)
      if (!(v > 0.0)) throw GeometryError("radius " + str(v) + " in the list must be > 0");
    return;
  }
  if (!(lo > 0.0)) throw GeometryError("smallest radius " + str(lo) + " must be > 0");
  if (!(hi >= lo)) throw GeometryError("inverted radius range: " + str(lo) + " > " + str(hi));
  if (kind == Kind::Normal) {
    if (!(sd >= 0.0)) throw GeometryError("standard deviation " + str(sd) + " must be >= 0");
    if (sd == 0.0 ? (mean < lo || mean > hi) : (mean + 8 * sd < lo || mean - 8 * sd > hi))
      throw GeometryError("normal radius distribution (mean " + str(mean) + ", sd " + str(sd) +
                          ") has no mass in the range [" + str(lo) + ", " + str(hi) + "]");
  }
}

double RadiusDistribution::smallest() const
{
  return kind == Kind::List ? *std::min_element(values.begin(), values.end()) : lo;
}

double RadiusDistribution::largest() const
{
  return kind == Kind::List ? *std::max_element(values.begin(), values.end()) : hi;
}

double PackingRandom::normal()
{
  // Box-Muller; 1 - u keeps the logarithm finite
  const double u1 = 1.0 - uniform(), u2 = uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}

std::vector<double> draw_radii(const RadiusDistribution &dist, std::size_t n, std::uint64_t seed)
{
  dist.validate();
  PackingRandom rng(seed);
  std::vector<double> r(n);
  for (auto &v : r) {
    switch (dist.kind) {
    case RadiusDistribution::Kind::Uniform:
      v = dist.lo + (dist.hi - dist.lo) * rng.uniform();
      break;
    case RadiusDistribution::Kind::List:
      v = dist.values[std::min(dist.values.size() - 1,
                               static_cast<std::size_t>(rng.uniform() * dist.values.size()))];
      break;
    case RadiusDistribution::Kind::Normal:
      if (dist.sd == 0.0) {
        v = dist.mean;
        break;
      }
      // truncation by rejection; validate() ensured the range has mass
      do {
        v = dist.mean + dist.sd * rng.normal();
      } while (v < dist.lo || v > dist.hi);
      break;
    }
  }
  return r;
}

/* FIRE + barostat state of pack_spheres (lengths in mean radii) */
struct Minimiser {
  double lo[3], hi[3];   // walls (a wall far outside the grid never acts)
  double glo[3], ghi[3]; // cell grid bounds (ghi[top] follows H)
  // a low side wall acts only on disks higher than this (tiles: above the
  // neighbouring tile's lid, so the loose start does not spill over it)
  double above[3] = {-1e300, -1e300, -1e300};
  double H, alpha, amax, area;
  int max_iterations;

  // x: positions in, jammed positions out (original order); returns iterations.
  // held (optional, 0/1 per disk): obstacles that neither move nor follow the
  // barostat, the neighbouring tiles' disks of pack_spheres' tiling; with them
  // the Verlet list counts the affine motion of the others as motion.
  template <int D>
  int run(std::vector<std::array<double, 3>> &xin, const std::vector<double> &ain,
          const std::vector<double> &held = {})
  {
    constexpr int top = D - 1;
    const std::size_t N = xin.size();
    // working arrays, reordered by cell at each list build for locality
    std::vector<double> x(D * N), v(D * N, 0.0), f(D * N, 0.0), xb(D * N), a(ain);
    std::vector<double> fixed = held.empty() ? std::vector<double>(N, 0.0) : held;
    const bool any_held = !held.empty(); // keeps the untiled loops free of the test
    std::vector<std::size_t> id(N);
    for (std::size_t i = 0; i < N; i++) {
      id[i] = i;
      for (int d = 0; d < D; d++) x[D * i + d] = xin[i][d];
    }

    // Verlet list from a cell grid; the list's reference positions follow the
    // affine part of the motion, so only the non-affine motion and the strain
    // since the build eat into the skin
    const double skin = 0.3;
    std::vector<std::uint32_t> pairs;
    double strain = 1.0;
    std::vector<std::array<double, 3>> cellx(N);
    std::vector<double> tmp;
    auto permute = [&](std::vector<double> &arr, int width, const std::vector<std::size_t> &order) {
      tmp.resize(arr.size());
      for (std::size_t k = 0; k < N; k++)
        for (int d = 0; d < width; d++) tmp[width * k + d] = arr[width * order[k] + d];
      arr.swap(tmp);
    };
    auto rebuild = [&]() {
      double gh[3] = {ghi[0], ghi[1], ghi[2]};
      gh[top] = H;
      CellGrid grid(D, glo, gh, 2.0 * amax + skin);
      for (std::size_t i = 0; i < N; i++)
        for (int d = 0; d < D; d++) cellx[i][d] = x[D * i + d];
      grid.build(cellx);
      // reorder every array by cell
      const std::vector<std::size_t> &order = grid.sorted();
      permute(x, D, order);
      permute(v, D, order);
      permute(a, 1, order);
      if (any_held) permute(fixed, 1, order);
      std::vector<std::size_t> nid(N);
      for (std::size_t k = 0; k < N; k++) nid[k] = id[order[k]];
      id.swap(nid);
      std::vector<std::size_t> rank(N);
      for (std::size_t k = 0; k < N; k++) rank[order[k]] = k;
      pairs.clear();
      grid.for_each_pair([&](std::size_t i0, std::size_t j0) {
        const std::size_t i = rank[i0], j = rank[j0];
        if (any_held && fixed[i] != 0.0 && fixed[j] != 0.0) return;
        double d2 = 0.0;
        for (int d = 0; d < D; d++)
          d2 += (x[D * i + d] - x[D * j + d]) * (x[D * i + d] - x[D * j + d]);
        const double c = a[i] + a[j] + skin;
        if (d2 < c * c) {
          pairs.push_back(static_cast<std::uint32_t>(std::min(i, j)));
          pairs.push_back(static_cast<std::uint32_t>(std::max(i, j)));
        }
      });
      xb = x;
      strain = 1.0;
    };

    // forces (f must be zero on entry: the update loop clears it), vertical
    // virial stress and the FIRE sums in two passes; returns the largest
    // overlap ratio (overlap of the a_i over alpha r; > 1: the true disks overlap)
    double Pint = 0.0, fmax2 = 0.0, power = 0.0, vnorm2 = 0.0, fnorm2 = 0.0;
    const double inv_alpha = (1.0 + alpha) / alpha; // r = a / (1 + alpha)
    auto forces = [&]() {
      double virial = 0.0, worst = 0.0;
      for (std::size_t p = 0; p < pairs.size(); p += 2) {
        const std::size_t i = pairs[p], j = pairs[p + 1];
        double dx[D], d2 = 0.0;
        for (int d = 0; d < D; d++) {
          dx[d] = x[D * j + d] - x[D * i + d];
          d2 += dx[d] * dx[d];
        }
        const double sum = a[i] + a[j];
        if (d2 >= sum * sum) continue;
        const double dist = std::sqrt(d2), delta = sum - dist, k = delta / std::max(dist, 1e-300);
        for (int d = 0; d < D; d++) {
          f[D * i + d] -= k * dx[d];
          f[D * j + d] += k * dx[d];
        }
        virial += k * dx[top] * dx[top];
        worst = std::max(worst, delta / sum);
      }
      fmax2 = power = vnorm2 = fnorm2 = 0.0;
      for (std::size_t i = 0; i < N; i++)
        for (int d = 0; d < D; d++) {
          const std::size_t k = D * i + d;
          if (any_held && fixed[i] != 0.0) {
            f[k] = 0.0;
            continue;
          }
          const double l = lo[d], h = d == top ? H : hi[d], xi = x[k];
          const double dl = a[i] - (xi - l), dh = a[i] - (h - xi);
          if (dl > 0.0 && (d == top || x[D * i + top] > above[d])) {
            f[k] += dl;
            if (d == top) virial += dl * (xi - l);
            worst = std::max(worst, dl / a[i]);
          }
          if (dh > 0.0) {
            f[k] -= dh;
            if (d == top) virial += dh * (h - xi);
            worst = std::max(worst, dh / a[i]);
          }
          fmax2 = std::max(fmax2, f[k] * f[k]);
          power += f[k] * v[k];
          vnorm2 += v[k] * v[k];
          fnorm2 += f[k] * f[k];
        }
      Pint = virial / (area * H);
      return worst * inv_alpha;
    };

    // FIRE parameters of Bitzek et al. (2006); unit masses, stiffness 1. The
    // largest step is near the stability limit of the semi-implicit Euler
    // step, dt < 2 / sqrt(lambda_max) with lambda_max <~ 2 z for z contacts
    // (z ~ 6 in 2D: 0.58; ~ 12 in 3D: 0.41); FIRE halves dt when the power
    // turns negative. Measured (bench/packing): dtmax 0.5 instead of 0.2 needs
    // 2.4x fewer iterations at 20,000 disks (4990 vs 12083), 1.4x at 1500.
    const double dtmax = D == 2 ? 0.5 : 0.35, finc = 1.1, fdec = 0.5, astart = 0.1, falpha = 0.99;
    const int nmin = 5;
    double dt = 0.05, afire = astart;
    int npos = 0;
    // pressure schedule: compress at 1e-2, then lower by 4x to the final pressure
    // (mean contact force ~ P d^(D-1) = mean overlap, here alpha / 10 in 2D)
    double Pfinal = D == 2 ? alpha / 20.0 : alpha / 80.0;
    double Ptarget = 1e-2;
    const double gamma = 0.1, epsmax = 2e-3;

    rebuild();
    int it = 0;
    for (; it < max_iterations; it++) {
      const double worst = forces();
      // convergence of the current stage
      const double fscale = (D == 2 ? 2.0 : 4.0) * Ptarget; // mean contact force ~ P d^(D-1)
      if (std::sqrt(fmax2) < 0.1 * fscale && std::fabs(Pint - Ptarget) < 0.05 * Ptarget) {
        if (Ptarget <= Pfinal && worst < 1.0) break;
        // a few contacts carry forces well above the mean: lower the pressure
        if (Ptarget <= Pfinal) Pfinal /= 2.0 * worst;
        Ptarget = std::max(Pfinal, 0.25 * Ptarget);
      }

      // FIRE: velocity mixing, then a semi-implicit Euler step
      double keep = 1.0, mix = 0.0;
      if (power > 0.0) {
        keep = 1.0 - afire;
        mix = afire * std::sqrt(vnorm2 / std::max(fnorm2, 1e-300));
        if (++npos > nmin) {
          dt = std::min(dt * finc, dtmax);
          afire *= falpha;
        }
      } else {
        keep = 0.0;
        dt *= fdec;
        afire = astart;
        npos = 0;
      }
      // affine barostat on the bed height
      const double eps = std::max(-epsmax, std::min(epsmax, gamma * (Pint - Ptarget)));
      H *= 1.0 + eps;
      strain *= 1.0 + eps;
      double move2 = 0.0;
      for (std::size_t i = 0; i < N; i++) {
        if (any_held && fixed[i] != 0.0) continue;
        double m2 = 0.0;
        for (int d = 0; d < D; d++) {
          const std::size_t k = D * i + d;
          v[k] = keep * v[k] + mix * f[k] + f[k] * dt;
          f[k] = 0.0;
          x[k] += v[k] * dt;
          if (d == top) {
            x[k] *= 1.0 + eps;
            if (!any_held) xb[k] *= 1.0 + eps;
          }
          m2 += (x[k] - xb[k]) * (x[k] - xb[k]);
        }
        move2 = std::max(move2, m2);
      }
      if (2.0 * std::sqrt(move2) + std::fabs(strain - 1.0) * (2.0 * amax + skin) > skin) rebuild();
    }
    for (std::size_t k = 0; k < N; k++)
      for (int d = 0; d < D; d++) xin[id[k]][d] = x[D * k + d];
    return it;
  }
};

/* ----------------------------------------------------------------------
   Jamming by pressure-controlled energy minimisation.

   Soft disks of radii a_i = r_i (1 + alpha), alpha = tau / 2, repel with the
   harmonic energy (1/2) delta^2 (delta = overlap; lengths in units of the
   mean radius), and so do the walls. FIRE (Bitzek et al. 2006) relaxes the
   positions; after each step the bed height H and all vertical coordinates
   are scaled affinely by 1 + eps, eps ~ (P_int - P) (Berendsen-type
   barostat), where P_int is the vertical virial stress. The bed is first
   compressed at a high pressure and then brought to a pressure at which the
   mean overlap is ~alpha / 10, so the jammed contact network of O'Hern et al.
   (2003) is kept while no overlap of the a_i exceeds alpha r: the disks of
   radii r_i then do not overlap and touching ones have gaps below tau r.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Tile by tile (beds of more than 3 tiles). One minimisation of the whole
   bed needs a number of FIRE iterations that grows with the bed's largest
   extent (force balance must cross it: 4990 iterations at 20,000 disks in a
   square bed, 20,858 in a bed 4x as wide), so its time grew as N^1.4-1.6.
   Here the container is cut into columns of about `tile` disks' width and the
   bed is packed in rows of tiles from the floor up, each tile by the same
   minimisation with the disks already packed around it (the tiles below and
   to its left) held as obstacles, a temporary wall on its right, and its own
   barostat lid; the next row packs on those disks, and a tile's right
   neighbour against its disks, so every seam is made of real contacts. The
   top row is one strip across the container, so the bed has one flat lid.
   Each tile costs what a bed of `tile` disks costs, the top strip grows as
   the container's width times its own disks: near-linear in N. A domain
   decomposition in the spirit of sequential (layer-by-layer) packing
   generators; the jamming and overlap criteria of the result are the
   minimisation's own, checked by jamming_report and smallest_gaps.
   Returns the FIRE iterations weighted by disks / N (whole-bed equivalents);
   m.H: the lid; x: all positions (scaled units).
------------------------------------------------------------------------- */
int pack_tiles(int D, std::vector<std::array<double, 3>> &x, const std::vector<double> &a,
               double volume, const double *lo, const double *hi, const PackingOptions &opt,
               Minimiser &m)
{
  const int top = D - 1;
  const std::size_t N = a.size();
  const double amax = m.amax, margin = 4.0 * amax;
  // tile side: `tile` disks at the jammed fraction (~0.84 disks, ~0.64 spheres);
  // columns over the floor, rows up to the estimated bed height; the top row
  // (one strip) holds as many disks as a row of tiles
  const double phi = D == 2 ? 0.84 : 0.64;
  const double side = std::pow(static_cast<double>(opt.tile) * volume / N / phi, 1.0 / D);
  int nt[2] = {1, 1};
  double base = 1.0;
  for (int d = 0; d < top; d++) {
    nt[d] = std::max(1, static_cast<int>(std::lround((hi[d] - lo[d]) / side)));
    base *= hi[d] - lo[d];
  }
  const std::size_t ncol = static_cast<std::size_t>(nt[0]) * nt[1];
  const int rows = std::max(2, static_cast<int>(std::lround(volume / (phi * base) / side)));
  const std::size_t per_tile = N / (ncol * rows);

  // disks in a seeded random order (a sorted radius list must not fill the floor first)
  PackingRandom rng = random_stream(opt.seed, 0x5851f42d4c957f2dULL);
  std::vector<std::size_t> order(N);
  for (std::size_t i = 0; i < N; i++) order[i] = i;
  for (std::size_t i = N; i > 1; i--)
    std::swap(order[i - 1], order[static_cast<std::size_t>(rng.uniform() * i)]);

  std::vector<std::size_t> placed;        // disks packed so far
  std::vector<double> lid(ncol, lo[top]); // lid of the last tile of each column
  std::size_t next = 0;
  double work = 0.0;
  std::vector<std::array<double, 3>> xs;
  std::vector<double> as, held;
  std::vector<std::size_t> mine;
  for (int row = 0; row < rows; row++) {
    const bool strip = row == rows - 1;
    for (std::size_t c = 0; c < (strip ? 1 : ncol); c++) {
      // the tile's extent over the floor
      double tlo[3], thi[3];
      const int cc[2] = {static_cast<int>(c % nt[0]), static_cast<int>(c / nt[0])};
      for (int d = 0; d < top; d++) {
        const double w = (hi[d] - lo[d]) / nt[d];
        tlo[d] = strip ? lo[d] : lo[d] + cc[d] * w;
        thi[d] = strip ? hi[d] : (cc[d] == nt[d] - 1 ? hi[d] : lo[d] + (cc[d] + 1) * w);
      }
      const double yref = strip ? *std::max_element(lid.begin(), lid.end()) : lid[c];
      const std::size_t n = strip ? N - next : per_tile;
      mine.assign(order.begin() + next, order.begin() + next + n);
      next += n;
      // the tile's disks at a loose start without overlaps, one per cell of a
      // grid (cells wider than the largest disk, fraction <= 0.35), each at a
      // random place in its cell: a random start with overlaps pushes disks
      // hard enough to squeeze between the held ones below; then the obstacles
      double width = 1.0, vol = 0.0;
      for (int d = 0; d < top; d++) width *= thi[d] - tlo[d];
      for (std::size_t i : mine) vol += ball_volume(a[i], D);
      const double cell = std::max(2.02 * amax, std::pow(vol / n / 0.35, 1.0 / D));
      int nc[2] = {1, 1};
      double cw[2] = {cell, cell};
      for (int d = 0; d < top; d++) {
        nc[d] = std::max(1, static_cast<int>((thi[d] - tlo[d]) / cell));
        cw[d] = (thi[d] - tlo[d]) / nc[d];
      }
      const std::size_t per_layer = static_cast<std::size_t>(nc[0]) * nc[1];
      const std::size_t layers = (n + per_layer - 1) / per_layer;
      const std::size_t last = n - (layers - 1) * per_layer; // cells used in the top layer
      const double H0 = layers * cell;
      xs.clear();
      as.clear();
      held.clear();
      for (std::size_t k = 0; k < n; k++) {
        const std::size_t i = mine[k], layer = k / per_layer;
        std::size_t q = k % per_layer;
        if (layer == layers - 1) q = q * per_layer / last; // spread over the top layer
        const std::size_t qc[2] = {q % nc[0], q / nc[0]};
        std::array<double, 3> p = {0.0, 0.0, 0.0};
        for (int d = 0; d < top; d++)
          p[d] = tlo[d] + qc[d] * cw[d] + a[i] + (cw[d] - 2 * a[i]) * rng.uniform();
        p[top] = layer * cell + a[i] + (cell - 2 * a[i]) * rng.uniform();
        xs.push_back(p);
        as.push_back(a[i]);
        held.push_back(0.0);
      }
      // obstacles down to the lowest lid: a neighbouring column lower than this
      // tile's floor leaves a trench its disks can fill
      const double deepest = std::min(yref, *std::min_element(lid.begin(), lid.end())) - margin;
      for (std::size_t j : placed) {
        bool near = x[j][top] >= deepest;
        for (int d = 0; d < top; d++)
          near = near && x[j][d] >= tlo[d] - margin && x[j][d] <= thi[d] + margin;
        if (!near) continue;
        std::array<double, 3> p = x[j];
        p[top] -= yref;
        xs.push_back(p);
        as.push_back(a[j]);
        held.push_back(1.0);
      }
      // walls: the container's where the tile meets it, a temporary one on the
      // high side, on the low side one above the packed neighbour only
      Minimiser t = m;
      for (int d = 0; d < top; d++) {
        const bool at_lo = tlo[d] <= lo[d];
        // below the top layer of the tile before this one along d its disks bound
        // the tile; above, a wall keeps this tile's disks off that layer's
        // valleys, where a lid lower than the neighbour's would crush them
        t.lo[d] = at_lo ? lo[d] : tlo[d];
        t.above[d] = at_lo ? -1e300 : lid[c - (d == 0 ? 1 : nt[0])] - yref - 2.0 * amax;
        t.hi[d] = thi[d];
        t.glo[d] = at_lo ? lo[d] : tlo[d] - margin;
        t.ghi[d] = thi[d];
      }
      t.lo[top] = row == 0 ? 0.0 : -1e30;
      t.glo[top] = row == 0 ? 0.0 : -margin;
      t.H = H0;
      t.area = width;
      const int it = D == 2 ? t.run<2>(xs, as, held) : t.run<3>(xs, as, held);
      if (it >= m.max_iterations) return it;
      work += static_cast<double>(it) * static_cast<double>(xs.size());
      for (std::size_t k = 0; k < n; k++) {
        x[mine[k]] = xs[k];
        x[mine[k]][top] += yref;
        placed.push_back(mine[k]);
      }

      if (strip) {
        m.H = yref + t.H;
      } else {
        lid[c] = yref + t.H;
      }
    }
  }
  return static_cast<int>(std::lround(work / N));
}

void check_count_fits(const RadiusDistribution &dist, std::size_t count, const PackingOptions &opt)
{
  dist.validate();
  check_extents(opt, dist.smallest(), ", the smallest of the distribution");
  double container = 1.0;
  for (int d = 0; d < opt.dimension; d++) container *= opt.hi[d] - opt.lo[d];
  // every disk is at least as large as the smallest radius: a lower bound of their volume
  const double least = static_cast<double>(count) * ball_volume(dist.smallest(), opt.dimension);
  check_fraction(least / container, opt.dimension, "at least ",
                 " (" + std::to_string(count) + " disks of radius >= " + str(dist.smallest()) +
                     ")");
}

Packing pack_spheres(const std::vector<double> &radii, const PackingOptions &opt)
{
  const int D = opt.dimension;
  if (D != 2 && D != 3) throw GeometryError("packing dimension must be 2 or 3");
  if (radii.empty()) throw GeometryError("no disks to pack");
  if (!(opt.tolerance > 0.0 && opt.tolerance < 0.1))
    throw GeometryError("packing tolerance " + str(opt.tolerance) + " must be in (0, 0.1)");
  const int top = D - 1;
  double rmax = 0.0, rsum = 0.0, volume = 0.0;
  for (double r : radii) {
    if (!(r > 0.0)) throw GeometryError("disk radius " + str(r) + " must be > 0");
    rmax = std::max(rmax, r);
    rsum += r;
    volume += ball_volume(r, D);
  }
  const double alpha = 0.5 * opt.tolerance;
  check_extents(opt, rmax);
  double base = 1.0; // floor area (width in 2D)
  for (int d = 0; d < top; d++) base *= opt.hi[d] - opt.lo[d];
  check_fraction(volume / (base * (opt.hi[top] - opt.lo[top])), D);

  // scaled units: lengths / mean radius, floor at 0
  const std::size_t N = radii.size();
  const double L = rsum / N;
  std::vector<double> a(N);
  for (std::size_t i = 0; i < N; i++) a[i] = radii[i] / L * (1.0 + alpha);
  const double amax = rmax / L * (1.0 + alpha);
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int d = 0; d < D; d++) {
    lo[d] = (opt.lo[d] - opt.lo[top] * (d == top)) / L;
    hi[d] = (opt.hi[d] - opt.lo[top] * (d == top)) / L;
    if (d == top) lo[d] = 0.0;
  }
  const double Hmax = hi[top];
  double area = base / std::pow(L, D - 1);

  // random loose start at packing fraction 0.5 (the overlaps are pushed apart first)
  // a stream of its own: draw_radii with the same seed must not correlate radii and positions
  PackingRandom rng = random_stream(opt.seed, 0x9e3779b97f4a7c15ULL);
  double H = std::max(volume / std::pow(L, D) / (0.5 * area), 2.0 * amax);
  std::vector<std::array<double, 3>> x0(N);
  for (std::size_t i = 0; i < N; i++) {
    x0[i] = {0.0, 0.0, 0.0};
    for (int d = 0; d < D; d++) {
      const double l = d == top ? 0.0 : lo[d], h = d == top ? H : hi[d];
      x0[i][d] = l + a[i] + (h - l - 2 * a[i]) * rng.uniform();
    }
  }
  Minimiser m;
  for (int d = 0; d < 3; d++) {
    m.lo[d] = m.glo[d] = lo[d];
    m.hi[d] = m.ghi[d] = hi[d];
  }
  m.H = H;
  m.alpha = alpha;
  m.amax = amax;
  m.area = area;
  m.max_iterations = opt.max_iterations;
  int it = 0;
  // 2d only: in 3d a tile of the bench's 10,000-sphere bed did not converge (the
  // fallback then cost 3.4x the untiled time); spheres are packed as one bed
  if (D == 2 && opt.tile > 0 && N > 3 * opt.tile) {
    std::vector<std::array<double, 3>> xt = x0;
    Minimiser mt = m;
    it = pack_tiles(D, xt, a, volume / std::pow(L, D), lo, hi, opt, mt);
    if (it < opt.max_iterations) {
      x0.swap(xt);
      m = mt;
    }
  }
  // untiled, or a tile did not converge (not seen; a safety net): the bed as one
  if (it == 0 || it >= opt.max_iterations) it = D == 2 ? m.run<2>(x0, a) : m.run<3>(x0, a);
  H = m.H;
  const auto &x = x0;
  if (it >= opt.max_iterations)
    throw GeometryError("packing did not converge in " + std::to_string(opt.max_iterations) +
                        " iterations");
  if (H > Hmax * (1.0 + 1e-12))
    throw GeometryError("the jammed bed of " + std::to_string(N) + " disks is " + str(H * L) +
                        " high, more than the container's " + str(Hmax * L) +
                        " (jammed packing fraction " + str(volume / (base * H * L)) +
                        "; filling the container would need " + str(volume / (base * Hmax * L)) +
                        ")");

  Packing out;
  out.dimension = D;
  out.radius = radii;
  out.centre.resize(N);
  for (std::size_t i = 0; i < N; i++) {
    out.centre[i] = {0.0, 0.0, 0.0};
    for (int d = 0; d < D; d++) out.centre[i][d] = x[i][d] * L + (d == top ? opt.lo[top] : 0.0);
  }
  for (int d = 0; d < 3; d++) {
    out.lo[d] = d < D ? opt.lo[d] : 0.0;
    out.hi[d] = d < D ? opt.hi[d] : 0.0;
  }
  out.hi[top] = std::min(opt.hi[top], opt.lo[top] + H * L);
  out.fraction = volume / (base * (out.hi[top] - out.lo[top]));
  out.iterations = it;
  return out;
}

/* ---------------------------------------------------------------------- */

double fraction_inside(const Packing &p, const double *lo, const double *hi, int samples)
{
  const int D = p.dimension;
  double rmax = 0.0;
  for (double r : p.radius) rmax = std::max(rmax, r);
  // bucket the disks once: a sample point looks at its cell and the neighbours
  const double cs = 2.0 * rmax;
  int n[3] = {1, 1, 1};
  for (int d = 0; d < D; d++) n[d] = std::max(1, static_cast<int>((p.hi[d] - p.lo[d]) / cs));
  std::vector<std::vector<std::size_t>> cell(static_cast<std::size_t>(n[0]) * n[1] * n[2]);
  auto index = [&](const double *x, int *c) {
    for (int d = 0; d < 3; d++)
      c[d] = d < D ? std::min(n[d] - 1, std::max(0, static_cast<int>((x[d] - p.lo[d]) /
                                                                     (p.hi[d] - p.lo[d]) * n[d])))
                   : 0;
  };
  for (std::size_t i = 0; i < p.centre.size(); i++) {
    int c[3];
    index(p.centre[i].data(), c);
    cell[(static_cast<std::size_t>(c[2]) * n[1] + c[1]) * n[0] + c[0]].push_back(i);
  }
  std::size_t hit = 0, total = 0;
  int m[3] = {samples, samples, D == 3 ? samples : 1};
  for (int k = 0; k < m[2]; k++)
    for (int j = 0; j < m[1]; j++)
      for (int i = 0; i < m[0]; i++) {
        const int ijk[3] = {i, j, k};
        double x[3] = {0, 0, 0};
        for (int d = 0; d < D; d++) x[d] = lo[d] + (hi[d] - lo[d]) * (ijk[d] + 0.5) / samples;
        int c[3];
        index(x, c);
        bool covered = false;
        for (int dz = (D == 3 ? -1 : 0); dz <= (D == 3 ? 1 : 0) && !covered; dz++)
          for (int dy = -1; dy <= 1 && !covered; dy++)
            for (int dx = -1; dx <= 1 && !covered; dx++) {
              const int o[3] = {c[0] + dx, c[1] + dy, c[2] + dz};
              if (o[0] < 0 || o[1] < 0 || o[2] < 0 || o[0] >= n[0] || o[1] >= n[1] || o[2] >= n[2])
                continue;
              for (std::size_t q :
                   cell[(static_cast<std::size_t>(o[2]) * n[1] + o[1]) * n[0] + o[0]]) {
                double d2 = 0.0;
                for (int d = 0; d < D; d++) d2 += (x[d] - p.centre[q][d]) * (x[d] - p.centre[q][d]);
                if (d2 < p.radius[q] * p.radius[q]) {
                  covered = true;
                  break;
                }
              }
            }
        hit += covered;
        total++;
      }
  return static_cast<double>(hit) / total;
}

GapReport smallest_gaps(const Packing &p)
{
  const int D = p.dimension;
  GapReport g;
  g.pair = g.wall = std::numeric_limits<double>::infinity();
  double rmax = 0.0;
  for (double r : p.radius) rmax = std::max(rmax, r);
  CellGrid grid(D, p.lo, p.hi, 2.0 * rmax);
  grid.build(p.centre);
  grid.for_each_pair([&](std::size_t i, std::size_t j) {
    double d2 = 0.0;
    for (int d = 0; d < D; d++)
      d2 += (p.centre[i][d] - p.centre[j][d]) * (p.centre[i][d] - p.centre[j][d]);
    const double gap = std::sqrt(d2) - p.radius[i] - p.radius[j];
    if (gap < g.pair) {
      g.pair = gap;
      g.pair_i = i;
      g.pair_j = j;
    }
  });
  for (std::size_t i = 0; i < p.centre.size(); i++)
    for (int d = 0; d < D; d++) {
      const double gap = std::min(p.centre[i][d] - p.lo[d], p.hi[d] - p.centre[i][d]) - p.radius[i];
      if (gap < g.wall) {
        g.wall = gap;
        g.wall_i = i;
      }
    }
  return g;
}

bool directions_block_every_move(const std::vector<std::array<double, 3>> &n, int dimension)
{
  const std::size_t k = n.size();
  if (k < static_cast<std::size_t>(dimension + 1)) return false;
  const double eps = 1e-9;
  if (dimension == 2) {
    // blocked iff the largest angular gap between contact directions is < pi
    std::vector<double> ang(k);
    for (std::size_t i = 0; i < k; i++) ang[i] = std::atan2(n[i][1], n[i][0]);
    std::sort(ang.begin(), ang.end());
    double gap = ang.front() + 2.0 * kPi - ang.back();
    for (std::size_t i = 1; i < k; i++) gap = std::max(gap, ang[i] - ang[i - 1]);
    return gap < kPi - eps;
  }
  // 3D: the cone {u : u . n_k <= 0 for all k} is {0} iff no candidate works.
  // A nonzero cone has an extreme ray normal to two contact directions
  // (+-n_a x n_b), or, if all directions are collinear, contains -n_a or a
  // perpendicular.
  auto movable = [&](const double *u) {
    for (const auto &m : n)
      if (u[0] * m[0] + u[1] * m[1] + u[2] * m[2] > eps) return false;
    return true;
  };
  bool independent = false;
  for (std::size_t a = 0; a < k; a++) {
    const double u[3] = {-n[a][0], -n[a][1], -n[a][2]};
    if (movable(u)) return false;
    for (std::size_t b = a + 1; b < k; b++) {
      double c[3] = {n[a][1] * n[b][2] - n[a][2] * n[b][1], n[a][2] * n[b][0] - n[a][0] * n[b][2],
                     n[a][0] * n[b][1] - n[a][1] * n[b][0]};
      const double norm = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      if (norm < 1e-12) continue;
      independent = true;
      for (double &ci : c) ci /= norm;
      const double m[3] = {-c[0], -c[1], -c[2]};
      if (movable(c) || movable(m)) return false;
    }
  }
  return independent;
}

JammingReport jamming_report(const Packing &p, double tolerance)
{
  const int D = p.dimension;
  const std::size_t N = p.centre.size();
  std::vector<std::vector<std::array<double, 3>>> dirs(N);
  double rmax = 0.0;
  for (double r : p.radius) rmax = std::max(rmax, r);
  CellGrid grid(D, p.lo, p.hi, 2.0 * rmax * (1.0 + tolerance));
  grid.build(p.centre);
  grid.for_each_pair([&](std::size_t i, std::size_t j) {
    std::array<double, 3> u = {0, 0, 0};
    double d2 = 0.0;
    for (int d = 0; d < D; d++) {
      u[d] = p.centre[j][d] - p.centre[i][d];
      d2 += u[d] * u[d];
    }
    const double dist = std::sqrt(d2);
    if (dist - p.radius[i] - p.radius[j] > 0.5 * tolerance * (p.radius[i] + p.radius[j])) return;
    for (double &c : u) c /= dist;
    dirs[i].push_back(u);
    for (double &c : u) c = -c;
    dirs[j].push_back(u);
  });
  JammingReport rep;
  std::size_t contacts = 0;
  for (std::size_t i = 0; i < N; i++) {
    for (int d = 0; d < D; d++) {
      std::array<double, 3> u = {0, 0, 0};
      if (p.centre[i][d] - p.lo[d] - p.radius[i] <= tolerance * p.radius[i]) {
        u[d] = -1.0;
        dirs[i].push_back(u);
      }
      if (p.hi[d] - p.centre[i][d] - p.radius[i] <= tolerance * p.radius[i]) {
        u[d] = 1.0;
        dirs[i].push_back(u);
      }
    }
    if (directions_block_every_move(dirs[i], D)) {
      rep.jammed++;
      contacts += dirs[i].size();
    } else {
      rep.rattlers++;
      rep.rattler_index.push_back(i);
    }
  }
  rep.mean_contacts = rep.jammed ? static_cast<double>(contacts) / rep.jammed : 0.0;
  return rep;
}

/* ----------------------------------------------------------------------
   Rattler growth (see the header). For one disk the others are fixed
   obstacles with surface distances g_j(c) = |c - x_j| - r_j (walls: the
   distance of c to the wall plane); the largest disk centred at c has radius
   f(c) = min_j g_j(c). Its local maximum (Bhattacharya & Lipton 2023, §7.1 step 4, radius
   maximisation of one nodal circle) is found by gradient steps on the
   smoothed energy (1/2) sum_j (f + delta - g_j)_+^2 with delta lowered from
   r_i / 5 to 1e-9 r_i: coarse delta pulls the centre towards the middle of
   the hole, fine delta settles it where the active normals balance (a
   positive combination of them vanishes), i.e. where f is maximal.
------------------------------------------------------------------------- */

namespace {
// Shortest vector of the convex hull of the unit vectors n (Wolfe's
// optimality test: v is it iff v . n_k >= v . v for all k), by trying the
// affine hulls of subsets of 1 to D + 1 vectors; a few vectors only.
std::array<double, 3> shortest_in_hull(const std::vector<std::array<double, 3>> &n, int D)
{
  const std::size_t k = n.size();
  std::array<double, 3> best = {0, 0, 0};
  double best2 = std::numeric_limits<double>::infinity();
  auto dot = [&](const std::array<double, 3> &a, const std::array<double, 3> &b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  };
  std::size_t idx[4];
  const std::size_t mmax = std::min<std::size_t>(k, D + 1);
  for (std::size_t m = 1; m <= mmax; m++) {
    // subsets of size m in lexicographic order
    for (std::size_t q = 0; q < m; q++) idx[q] = q;
    while (true) {
      // weights l minimising |sum l_a n_a|^2 with sum l = 1: [G 1; 1 0] (l, mu) = (0, 1)
      double A[5][6] = {};
      for (std::size_t a = 0; a < m; a++) {
        for (std::size_t b = 0; b < m; b++) A[a][b] = dot(n[idx[a]], n[idx[b]]);
        A[a][m] = 1.0;
        A[m][a] = 1.0;
      }
      A[m][m + 1] = 1.0;
      bool ok = true;
      const std::size_t s = m + 1;
      for (std::size_t col = 0; col < s && ok; col++) { // Gauss-Jordan, partial pivoting
        std::size_t piv = col;
        for (std::size_t r = col + 1; r < s; r++)
          if (std::fabs(A[r][col]) > std::fabs(A[piv][col])) piv = r;
        if (std::fabs(A[piv][col]) < 1e-12) {
          ok = false;
          break;
        }
        for (std::size_t c = 0; c <= s; c++) std::swap(A[col][c], A[piv][c]);
        for (std::size_t r = 0; r < s; r++)
          if (r != col) {
            const double fct = A[r][col] / A[col][col];
            for (std::size_t c = col; c <= s; c++) A[r][c] -= fct * A[col][c];
          }
      }
      if (ok) {
        std::array<double, 3> v = {0, 0, 0};
        bool inside = true;
        for (std::size_t a = 0; a < m; a++) {
          const double l = A[a][s] / A[a][a];
          if (l < -1e-12) inside = false;
          for (int d = 0; d < 3; d++) v[d] += l * n[idx[a]][d];
        }
        const double v2 = dot(v, v);
        if (inside && v2 < best2) {
          bool optimal = true;
          for (const auto &w : n)
            if (dot(v, w) < v2 - 1e-12) optimal = false;
          if (optimal) {
            best = v;
            best2 = v2;
          }
        }
      }
      // next subset
      std::size_t q = m;
      while (q > 0 && idx[q - 1] == k - m + q - 1) q--;
      if (q == 0) break;
      idx[q - 1]++;
      for (std::size_t r = q; r < m; r++) idx[r] = idx[r - 1] + 1;
    }
  }
  return best2 < std::numeric_limits<double>::infinity() ? best : std::array<double, 3>{0, 0, 0};
}
} // namespace

RattlerGrowth grow_rattlers(Packing &p, double cap, double tolerance, int max_passes)
{
  const int D = p.dimension;
  const std::size_t N = p.centre.size();
  RattlerGrowth out;
  JammingReport rep = jamming_report(p, tolerance);
  out.before = rep.rattlers;
  double rmax = 0.0;
  for (double r : p.radius) rmax = std::max(rmax, r);
  const double R = std::max(rmax, cap);
  // buckets of side 2R: +-2 buckets reach 4R, beyond any obstacle of a cage
  // (the grown disk has radius <= R and stays within R of its hole)
  int n[3] = {1, 1, 1};
  for (int d = 0; d < D; d++) n[d] = std::max(1, static_cast<int>((p.hi[d] - p.lo[d]) / (2.0 * R)));
  auto bucket = [&](const std::array<double, 3> &x, int *c) {
    for (int d = 0; d < 3; d++)
      c[d] = d < D ? std::min(n[d] - 1, std::max(0, static_cast<int>((x[d] - p.lo[d]) /
                                                                     (p.hi[d] - p.lo[d]) * n[d])))
                   : 0;
  };
  std::vector<std::array<double, 3>> ox; // obstacle centres
  std::vector<double> orad, g;
  std::vector<std::array<double, 3>> nrm;
  for (; out.passes < max_passes && rep.rattlers > 0; out.passes++) {
    std::vector<std::vector<std::size_t>> cell(static_cast<std::size_t>(n[0]) * n[1] * n[2]);
    for (std::size_t j = 0; j < N; j++) {
      int c[3];
      bucket(p.centre[j], c);
      cell[(static_cast<std::size_t>(c[2]) * n[1] + c[1]) * n[0] + c[0]].push_back(j);
    }
    bool changed = false;
    for (std::size_t i : rep.rattler_index) {
      ox.clear();
      orad.clear();
      int c0[3];
      bucket(p.centre[i], c0);
      for (int dz = (D == 3 ? -2 : 0); dz <= (D == 3 ? 2 : 0); dz++)
        for (int dy = -2; dy <= 2; dy++)
          for (int dx = -2; dx <= 2; dx++) {
            const int o[3] = {c0[0] + dx, c0[1] + dy, c0[2] + dz};
            if (o[0] < 0 || o[1] < 0 || o[2] < 0 || o[0] >= n[0] || o[1] >= n[1] || o[2] >= n[2])
              continue;
            for (std::size_t j : cell[(static_cast<std::size_t>(o[2]) * n[1] + o[1]) * n[0] + o[0]])
              if (j != i) {
                ox.push_back(p.centre[j]);
                orad.push_back(p.radius[j]);
              }
          }
      const std::size_t M = ox.size();
      g.resize(M + 2 * D);
      nrm.resize(M + 2 * D);
      // g_j(c) and the unit normals grad g_j; returns f(c)
      auto eval = [&](const std::array<double, 3> &c) {
        double f = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < M; j++) {
          double d2 = 0.0;
          std::array<double, 3> u = {0, 0, 0};
          for (int d = 0; d < D; d++) {
            u[d] = c[d] - ox[j][d];
            d2 += u[d] * u[d];
          }
          const double dist = std::sqrt(d2);
          for (int d = 0; d < D; d++) u[d] /= std::max(dist, 1e-300);
          g[j] = dist - orad[j];
          nrm[j] = u;
          f = std::min(f, g[j]);
        }
        for (int d = 0; d < D; d++) {
          std::array<double, 3> u = {0, 0, 0};
          u[d] = 1.0;
          g[M + 2 * d] = c[d] - p.lo[d];
          nrm[M + 2 * d] = u;
          u[d] = -1.0;
          g[M + 2 * d + 1] = p.hi[d] - c[d];
          nrm[M + 2 * d + 1] = u;
          f = std::min(f, std::min(g[M + 2 * d], g[M + 2 * d + 1]));
        }
        return f;
      };
      std::array<double, 3> c = p.centre[i];
      double f = eval(c);
      const double r0 = p.radius[i];
      double eps = 0.1 * r0;
      std::vector<std::array<double, 3>> act;
      for (int it = 0; it < 1000 && eps > 1e-10 * r0; it++) {
        // steepest ascent of f over the eps-active obstacles: the direction of
        // the shortest vector v of the convex hull of their normals (v = 0: c
        // is a maximum for them; then only closer contacts may count)
        act.clear();
        for (std::size_t j = 0; j < g.size(); j++)
          if (g[j] <= f + eps) act.push_back(nrm[j]);
        const std::array<double, 3> v = shortest_in_hull(act, D);
        const double vn = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (vn < 1e-9) {
          eps *= 0.25;
          continue;
        }
        // line search: halve from eps until f rises, then double while it rises
        auto at = [&](double t) {
          std::array<double, 3> y = c;
          for (int d = 0; d < D; d++) y[d] += t * v[d] / vn;
          return y;
        };
        double t = eps, ft = eval(at(t));
        while (!(ft > f) && t > 1e-14 * r0) ft = eval(at(t *= 0.5));
        if (!(ft > f)) {
          eps *= 0.25;
          f = eval(c);
          continue;
        }
        for (double f2; t < 4.0 * r0 && (f2 = eval(at(2.0 * t))) > ft;) {
          t *= 2.0;
          ft = f2;
        }
        c = at(t);
        f = eval(c);
      }
      f = eval(c);
      const double rnew = std::min(cap, f) * (1.0 - 1e-12);
      if (rnew > p.radius[i]) {
        p.centre[i] = c;
        p.radius[i] = rnew;
        out.grown++;
        changed = true;
      }
    }
    const std::size_t last = rep.rattlers;
    rep = jamming_report(p, tolerance);
    if (!changed || rep.rattlers >= last) {
      out.passes++;
      break;
    }
  }
  out.after = rep.rattlers;
  out.remaining = rep.rattler_index;
  for (std::size_t i : rep.rattler_index)
    if (p.radius[i] >= cap * (1.0 - 1e-9)) out.capped++;
  // the bed's packing fraction with the new radii
  double vol = 0.0, box = 1.0;
  for (double r : p.radius) vol += ball_volume(r, D);
  for (int d = 0; d < D; d++) box *= p.hi[d] - p.lo[d];
  p.fraction = vol / box;
  return out;
}

/* ---------------------------------------------------------------------- */

Packing row_packing(const RadiusDistribution &dist, const RowOptions &opt)
{
  if (opt.dimension != 2) throw GeometryError("row layout is 2d only");
  dist.validate();
  if (!(opt.gap >= 0.0)) throw GeometryError("gap " + str(opt.gap) + " must be >= 0");
  if (!(opt.perturb >= 0.0)) throw GeometryError("perturb " + str(opt.perturb) + " must be >= 0");
  const double W = opt.hi[0] - opt.lo[0], H = opt.hi[1] - opt.lo[1];
  const double rmax = dist.largest(), rmin = dist.smallest();
  if (!(W >= 2.0 * rmax + 2.0 * opt.gap) || !(H >= 2.0 * rmax + 2.0 * opt.gap))
    throw GeometryError("container " + str(W) + " x " + str(H) +
                        " is too small for a disk of radius " + str(rmax) + " with gap " +
                        str(opt.gap));
  // at most one disk per (2 rmin + gap)^2 square of the container
  std::size_t nmax = static_cast<std::size_t>((W / (2.0 * rmin + opt.gap) + 1.0) *
                                              (H / (2.0 * rmin + opt.gap) + 1.0));
  if (opt.max_count > 0) nmax = std::min(nmax, opt.max_count);
  const std::vector<double> radii = draw_radii(dist, nmax, opt.seed);
  // the spacings from a stream of their own (see pack_spheres)
  PackingRandom rng = random_stream(opt.seed, 0x7f4a7c159e3779b9ULL);
  Packing out;
  out.dimension = 2;
  for (int d = 0; d < 3; d++) {
    out.lo[d] = d < 2 ? opt.lo[d] : 0.0;
    out.hi[d] = d < 2 ? opt.hi[d] : 0.0;
  }
  std::size_t k = 0;
  double floor = opt.lo[1]; // bottom of the current row, before its gap
  for (int row = 0; k < nmax; row++) {
    const bool from_left = row % 2 == 0;
    double edge = from_left ? opt.lo[0] : opt.hi[0]; // last occupied x
    double top = floor;
    std::size_t in_row = 0;
    while (k < nmax) {
      const double r = radii[k];
      const double y = floor + opt.gap + r;
      if (y + r > opt.hi[1] - opt.gap) break; // the row does not fit in height
      const double step = opt.gap + 2.0 * opt.perturb * r * rng.uniform() + r;
      const double x = from_left ? edge + step : edge - step;
      if (x - r < opt.lo[0] + opt.gap || x + r > opt.hi[0] - opt.gap) break;
      out.centre.push_back({x, y, 0.0});
      out.radius.push_back(r);
      edge = from_left ? x + r : x - r;
      top = std::max(top, y + r);
      k++;
      in_row++;
    }
    if (in_row == 0) break; // not even one more disk fits
    floor = top;
  }
  double area = 0.0;
  for (double r : out.radius) area += ball_volume(r, 2);
  out.fraction = area / (W * H);
  return out;
}

/* ---------------------------------------------------------------------- */

EnclosingCircle smallest_enclosing_circle(const std::vector<std::array<double, 2>> &points)
{
  // Welzl (1991), iterative form; points shuffled with a fixed seed so the
  // expected time is linear and the result reproducible.
  std::vector<std::array<double, 2>> P = points;
  PackingRandom rng(12345);
  for (std::size_t i = P.size(); i > 1; i--)
    std::swap(P[i - 1], P[static_cast<std::size_t>(rng.uniform() * i)]);
  auto inside = [](const EnclosingCircle &c, const std::array<double, 2> &p) {
    return std::hypot(p[0] - c.x, p[1] - c.y) <= c.r * (1.0 + 1e-12) + 1e-300;
  };
  auto two = [](const std::array<double, 2> &a, const std::array<double, 2> &b) {
    EnclosingCircle c;
    c.x = 0.5 * (a[0] + b[0]);
    c.y = 0.5 * (a[1] + b[1]);
    c.r = 0.5 * std::hypot(a[0] - b[0], a[1] - b[1]);
    return c;
  };
  auto three = [&](const std::array<double, 2> &a, const std::array<double, 2> &b,
                   const std::array<double, 2> &c) {
    const double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    const double d = 2.0 * (bx * cy - by * cx);
    if (std::fabs(d) < 1e-300) { // collinear: the widest pair
      EnclosingCircle e = two(a, b), f = two(a, c), g = two(b, c);
      return e.r >= f.r && e.r >= g.r ? e : (f.r >= g.r ? f : g);
    }
    const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    EnclosingCircle e;
    e.x = a[0] + (cy * b2 - by * c2) / d;
    e.y = a[1] + (bx * c2 - cx * b2) / d;
    e.r = std::hypot(e.x - a[0], e.y - a[1]);
    return e;
  };
  EnclosingCircle c;
  if (P.empty()) return c;
  c.x = P[0][0];
  c.y = P[0][1];
  for (std::size_t i = 1; i < P.size(); i++) {
    if (inside(c, P[i])) continue;
    c = {P[i][0], P[i][1], 0.0};
    for (std::size_t j = 0; j < i; j++) {
      if (inside(c, P[j])) continue;
      c = two(P[i], P[j]);
      for (std::size_t k = 0; k < j; k++)
        if (!inside(c, P[k])) c = three(P[i], P[j], P[k]);
    }
  }
  return c;
}

} // namespace peridem
