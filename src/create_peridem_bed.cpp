/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: command create_peridem_bed, see doc/create_peridem_bed.rst.
------------------------------------------------------------------------- */

#include "create_peridem_bed.h"
#include "lmp_peridem_citations.h"
#include "lmp_peridem_parse.h"

#include "comm.h"
#include "domain.h"
#include "error.h"
#include "input.h"
#include "math_const.h"
#include "variable.h"

#include "peridem_geometry_packing.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

namespace {
constexpr const char *CMD = "create_peridem_bed";
}

CreatePeridemBed::CreatePeridemBed(LAMMPS *lmp) : Command(lmp)
{
  PERIDEM_NS::cite_grain_shape(lmp);
}

/* ----------------------------------------------------------------------
   create_peridem_bed FILE count N radius STYLE args seed S keyword value ...
------------------------------------------------------------------------- */

void CreatePeridemBed::command(int narg, char **arg)
{
  if (domain->box_exist == 0) error->all(FLERR, "{} command before simulation box is defined", CMD);
  if (narg < 1) error->all(FLERR, "Illegal {} command: expected an output file", CMD);
  const double time0 = MPI_Wtime();
  const int dim = domain->dimension;
  const std::string file = arg[0];

  long long count = 0, seed = 0;
  bool have_radius = false;
  peridem::RadiusDistribution dist;
  double rc = 0.0, tolerance = 1e-3;
  bool grow = true;  // rattlers grow (default) or keep
  bool rows = false; // layout rows: Jha et al.'s (2021) perturbed rows (§4.4)
  double gap = 0.0, perturb = 0.1;
  std::string lid_variable; // lid NAME: the bed's lid height as an internal-style variable
  double lo[3], hi[3];
  for (int k = 0; k < 3; k++) {
    lo[k] = domain->boxlo[k];
    hi[k] = domain->boxhi[k];
  }
  std::vector<std::string> labels;
  std::vector<double> weights;

  int iarg = 1;
  auto need = [&](int n, const char *what) {
    if (iarg + n > narg)
      error->all(FLERR, "Illegal {} command: {} needs {} value(s)", CMD, what, n);
  };
  while (iarg < narg) {
    const std::string key = arg[iarg++];
    auto num = [&](int k) { return PERIDEM_NS::number(lmp, CMD, key, arg[k]); };
    if (key == "count") {
      need(1, "count");
      // every disk becomes a grain of at least one node, and this LAMMPS numbers atoms in
      // 32 bits (LAMMPS_SMALLBIG): more disks than MAXTAGINT could never be placed
      count = PERIDEM_NS::integer(lmp, CMD, key, arg[iarg++], 1, MAXTAGINT);
    } else if (key == "radius") {
      need(1, "radius");
      const std::string style = arg[iarg++];
      if (style == "uniform") {
        need(2, "radius uniform");
        dist = peridem::RadiusDistribution::uniform(num(iarg), num(iarg + 1));
        iarg += 2;
      } else if (style == "normal") {
        need(4, "radius normal");
        dist = peridem::RadiusDistribution::normal(num(iarg), num(iarg + 1), num(iarg + 2),
                                                   num(iarg + 3));
        iarg += 4;
      } else if (style == "list") {
        std::vector<double> values;
        while (iarg < narg && utils::is_double(arg[iarg])) values.push_back(num(iarg++));
        dist = peridem::RadiusDistribution::list(values);
      } else {
        error->all(FLERR, "{}: unknown radius distribution '{}' (use uniform, normal or list)", CMD,
                   style);
      }
      have_radius = true;
    } else if (key == "seed") {
      need(1, "seed");
      seed = PERIDEM_NS::integer(lmp, CMD, key, arg[iarg++]);
      if (seed <= 0) error->all(FLERR, "{}: seed must be > 0, got {}", CMD, seed);
    } else if (key == "box") {
      need(2 * dim, "box");
      for (int k = 0; k < dim; k++) {
        lo[k] = num(iarg + 2 * k);
        hi[k] = num(iarg + 2 * k + 1);
        if (!(hi[k] > lo[k]))
          error->all(FLERR, "{}: box {} {} is empty or inverted", CMD, arg[iarg + 2 * k],
                     arg[iarg + 2 * k + 1]);
      }
      iarg += 2 * dim;
    } else if (key == "contact_radius") {
      need(1, "contact_radius");
      rc = num(iarg++);
      if (!(rc >= 0.0)) error->all(FLERR, "{}: contact_radius must be >= 0, got {}", CMD, rc);
    } else if (key == "tolerance") {
      need(1, "tolerance");
      tolerance = num(iarg++);
    } else if (key == "layout") {
      need(1, "layout");
      const std::string v = arg[iarg++];
      if (v != "jammed" && v != "rows")
        error->all(FLERR, "{}: layout must be jammed or rows, got '{}'", CMD, v);
      rows = v == "rows";
    } else if (key == "gap") {
      need(1, "gap");
      gap = num(iarg++);
      if (!(gap >= 0.0)) error->all(FLERR, "{}: gap must be >= 0, got {}", CMD, gap);
    } else if (key == "perturb") {
      need(1, "perturb");
      perturb = num(iarg++);
      if (!(perturb >= 0.0)) error->all(FLERR, "{}: perturb must be >= 0, got {}", CMD, perturb);
    } else if (key == "lid") {
      need(1, "lid");
      lid_variable = arg[iarg++];
      if (!utils::is_id(lid_variable))
        error->all(FLERR, "{}: lid needs a variable name (letters, digits, _), got '{}'", CMD,
                   lid_variable);
    } else if (key == "rattlers") {
      need(1, "rattlers");
      const std::string v = arg[iarg++];
      if (v != "grow" && v != "keep")
        error->all(FLERR, "{}: rattlers must be grow or keep, got '{}'", CMD, v);
      grow = v == "grow";
    } else if (key == "labels") {
      while (iarg + 1 < narg && !utils::is_double(arg[iarg]) && utils::is_double(arg[iarg + 1])) {
        labels.emplace_back(arg[iarg]);
        weights.push_back(num(iarg + 1));
        if (!(weights.back() > 0.0))
          error->all(FLERR, "{}: proportion of label {} must be > 0, got {}", CMD, arg[iarg],
                     arg[iarg + 1]);
        iarg += 2;
      }
      if (labels.empty())
        error->all(FLERR, "Illegal {} command: labels needs NAME PROPORTION pairs", CMD);
    } else {
      error->all(FLERR, "{}: unknown keyword '{}'", CMD, key);
    }
  }
  if (count == 0 && !rows) error->all(FLERR, "{}: no number of disks given (use count N)", CMD);
  if (rows && dim != 2) error->all(FLERR, "{}: layout rows is 2d only", CMD);
  if (!have_radius) error->all(FLERR, "{}: no radius distribution given (use radius ...)", CMD);
  if (seed == 0) error->all(FLERR, "{}: no random seed given (use seed S)", CMD);
  if (labels.empty()) {
    labels.emplace_back("grain");
    weights.push_back(1.0);
  }
  if (dim == 2) lo[2] = hi[2] = 0.0;

  // rank 0 packs and writes; every rank learns the outcome (same on any number of ranks)
  std::string message;
  char line[512];
  double lid = 0.0;
  if (comm->me == 0) {
    try {
      dist.validate();
      if (rc / 2.0 >= dist.smallest())
        throw peridem::GeometryError("contact_radius " + std::to_string(rc) +
                                     " leaves nothing of the smallest disk after shrinking by "
                                     "R_c/2 (radius " +
                                     std::to_string(dist.smallest()) + ")");
      // jam the security disks in the container inset by R_c/2: after shrinking them by
      // R_c/2 the grains are >= R_c from each other and from the walls (Bhattacharya & Lipton 2023,
      // §7.1 step 5)
      peridem::PackingOptions opt;
      opt.dimension = dim;
      for (int k = 0; k < 3; k++) {
        opt.lo[k] = lo[k] + (k < dim ? rc / 2 : 0.0);
        opt.hi[k] = hi[k] - (k < dim ? rc / 2 : 0.0);
      }
      opt.seed = static_cast<std::uint64_t>(seed);
      opt.tolerance = tolerance;
      peridem::Packing p;
      if (rows) {
        // Jha et al. (2021) §4.4: perturbed rows, loose (settles under gravity)
        peridem::RowOptions ro;
        for (int k = 0; k < 3; k++) {
          ro.lo[k] = opt.lo[k];
          ro.hi[k] = opt.hi[k];
        }
        ro.gap = gap;
        ro.perturb = perturb;
        ro.seed = opt.seed;
        ro.max_count = static_cast<std::size_t>(count);
        p = peridem::row_packing(dist, ro);
        grow = false;
        count = static_cast<long long>(p.radius.size());
      } else {
        // refuse a count the container cannot hold before drawing (and storing) its radii
        peridem::check_count_fits(dist, static_cast<std::size_t>(count), opt);
        const auto radii = peridem::draw_radii(dist, count, static_cast<std::uint64_t>(seed));
        p = peridem::pack_spheres(radii, opt);
      }
      // sizes before and after the rattler growth (it shifts them up)
      auto moments = [](const std::vector<double> &r, double &mean, double &sd) {
        mean = sd = 0.0;
        for (double v : r) mean += v / r.size();
        for (double v : r) sd += (v - mean) * (v - mean);
        sd = r.size() > 1 ? std::sqrt(sd / (r.size() - 1)) : 0.0;
      };
      double mean0, sd0, mean1, sd1;
      moments(p.radius, mean0, sd0);
      const double fraction0 = p.fraction;
      peridem::RattlerGrowth g;
      if (grow) {
        // Bhattacharya & Lipton (2023) §7.1 step 4: each rattler takes the largest disk its cage
        // holds, capped at the distribution's upper bound
        g = peridem::grow_rattlers(p, dist.largest(), tolerance);
      } else if (!rows) {
        const auto rep = peridem::jamming_report(p, tolerance);
        g.before = g.after = rep.rattlers;
      }
      moments(p.radius, mean1, sd1);

      // angles and labels from their own stream of the seed
      peridem::PackingRandom rng(static_cast<std::uint64_t>(seed) ^ 0x9e3779b97f4a7c15ULL);
      double wsum = 0.0;
      for (double w : weights) wsum += w;
      FILE *out = fopen(file.c_str(), "w");
      if (!out) throw peridem::GeometryError("cannot write bed file " + file);
      const int top = dim - 1;
      double bed[3][2] = {{lo[0], hi[0]}, {lo[1], hi[1]}, {lo[2], hi[2]}};
      bed[top][1] = p.hi[top] + rc / 2; // the bed's lid (container coordinates)
      lid = bed[top][1];
      double vbed = 1.0, vgrain = 0.0;
      for (int k = 0; k < dim; k++) vbed *= bed[k][1] - bed[k][0];
      for (double r : p.radius) {
        const double s = r - rc / 2;
        vgrain += dim == 2 ? MY_PI * s * s : 4.0 / 3.0 * MY_PI * s * s * s;
      }
      const char *kind = rows ? "perturbed-row" : "jammed";
      fprintf(out, "# create_peridem_bed: %lld %s security %s, seed %lld\n", count, kind,
              dim == 2 ? "disks" : "spheres", seed);
      fprintf(out, "# bed %.17g %.17g %.17g %.17g %.17g %.17g\n", bed[0][0], bed[0][1], bed[1][0],
              bed[1][1], bed[2][0], bed[2][1]);
      fprintf(out,
              "# %s packing fraction %.6f (of the bed inset by R_c/2 = %g); after shrinking "
              "by R_c/2: %.6f of the bed; rattlers %zu\n",
              kind, p.fraction, rc / 2, vgrain / vbed, g.after);
      if (!rows)
        fprintf(out,
                "# rattlers %s: %zu before, %zu after (%zu capped at radius %g); fraction %.6f "
                "before; radius mean %.6g sd %.6g before, mean %.6g sd %.6g after\n",
                grow ? "grown" : "kept", g.before, g.after, g.capped, dist.largest(), fraction0,
                mean0, sd0, mean1, sd1);
      fprintf(out, "# x y z radius angle(degrees) label   (radius: shrunk by R_c/2)\n");
      for (std::size_t i = 0; i < p.radius.size(); i++) {
        const double angle = 360.0 * rng.uniform();
        double u = rng.uniform() * wsum;
        std::size_t l = 0;
        while (l + 1 < labels.size() && u >= weights[l]) u -= weights[l++];
        fprintf(out, "%.17g %.17g %.17g %.17g %.17g %s\n", p.centre[i][0], p.centre[i][1],
                p.centre[i][2], p.radius[i] - rc / 2, angle, labels[l].c_str());
      }
      fclose(out);
      if (rows)
        snprintf(line, sizeof(line),
                 "Created a bed of %lld perturbed-row disks in %s: packing fraction %.4f of the "
                 "container (%.4f after shrinking by R_c/2 = %g)\n",
                 count, file.c_str(), p.fraction, vgrain / vbed, rc / 2);
      else
        snprintf(line, sizeof(line),
                 "Created a bed of %lld jammed %s in %s: bed height %.6g (container %.6g), "
                 "packing fraction %.4f of security %s (%.4f after shrinking by R_c/2 = %g), "
                 "%zu rattlers (%zu before growth), %d iterations\n",
                 count, dim == 2 ? "disks" : "spheres", file.c_str(), bed[top][1] - bed[top][0],
                 hi[top] - lo[top], p.fraction, dim == 2 ? "disks" : "spheres", vgrain / vbed,
                 rc / 2, g.after, g.before, p.iterations);
    } catch (peridem::GeometryError &e) {
      message = e.what();
    }
  }
  int len = static_cast<int>(message.size());
  MPI_Bcast(&len, 1, MPI_INT, 0, world);
  message.resize(len);
  MPI_Bcast(&message[0], len, MPI_CHAR, 0, world);
  if (len > 0) error->all(FLERR, "{}: {}", CMD, message);
  if (!lid_variable.empty()) {
    // an internal-style variable: a later create_peridem_bed with the same name resets it
    MPI_Bcast(&lid, 1, MPI_DOUBLE, 0, world);
    int ivar = input->variable->find(lid_variable.c_str());
    if (ivar >= 0 && !input->variable->internalstyle(ivar))
      error->all(FLERR, "{}: lid variable {} exists and is not internal-style", CMD, lid_variable);
    if (ivar < 0) {
      input->one(fmt::format("variable {} internal 0", lid_variable));
      ivar = input->variable->find(lid_variable.c_str());
    }
    input->variable->internal_set(ivar, lid);
  }
  if (comm->me == 0) {
    utils::logmesg(lmp, line);
    utils::logmesg(lmp, "  {} wall time = {:.3f} seconds\n", CMD, MPI_Wtime() - time0);
  }
}
