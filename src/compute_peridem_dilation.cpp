/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/dilation (per-atom theta of bond_style
   peridem/lps, Jha et al. 2021, eq. 34, as computed in the last force evaluation).
------------------------------------------------------------------------- */

#include "compute_peridem_dilation.h"

#include "atom.h"
#include "bond_peridem_lps.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
const char *const STYLE = "compute peridem/dilation";
}

ComputePeridemDilation::ComputePeridemDilation(LAMMPS *lmp, int narg, char **arg)
    : Compute(lmp, narg, arg), nmax(0), dilation(nullptr), bond(nullptr)
{
  if (narg != 3) error->all(FLERR, "Illegal {} command: it takes no arguments", STYLE);
  peratom_flag = 1;
  size_peratom_cols = 0;
}

ComputePeridemDilation::~ComputePeridemDilation()
{
  memory->destroy(dilation);
}

void ComputePeridemDilation::init()
{
  bond = dynamic_cast<BondPeridemLPS *>(force->bond);
  if (!bond) error->all(FLERR, "{} needs bond_style peridem/lps", STYLE);
}

void ComputePeridemDilation::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(dilation);
    nmax = atom->nmax;
    memory->create(dilation, nmax, "peridem/dilation:dilation");
    vector_atom = dilation;
  }
  const double *theta = bond->dilation();
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    dilation[i] = (theta && (mask[i] & groupbit)) ? theta[i] : 0.0;
}

double ComputePeridemDilation::memory_usage()
{
  return double(nmax) * sizeof(double);
}
