/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   A LAMMPS host that loads plugins the way the PLUGIN package of LAMMPS
   29Sep2021 does ("plugin load FILE": dlopen with RTLD_NOW | RTLD_GLOBAL,
   lammpsplugin_init(lmp, handle, regfunc), and a regfunc that puts each
   creator into the style map of its kind), for testing peridemplugin.so on
   Debian's LAMMPS, which has no PLUGIN package. It does not link PERIDEM:
   every PERIDEM style it knows comes from the plugin.

   usage: plugin_host PLUGIN.so INPUT [LAMMPS command-line arguments]
------------------------------------------------------------------------- */

#include "lammpsplugin.h"

#include "atom.h"
#include "force.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"

#include <cstdio>
#include <cstring>
#include <dlfcn.h>
#include <mpi.h>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {

std::vector<std::string> loaded; // "style name" of every registered plugin style
bool unknown_kind = false;

// as PLUGIN/plugin.cpp plugin_register() of that version
void host_register(lammpsplugin_t *plugin, void *ptr)
{
  auto *lmp = static_cast<LAMMPS *>(ptr);
  const std::string style = plugin->style;
  if (std::strcmp(plugin->version, lmp->version) != 0)
    std::fprintf(stderr, "plugin %s compiled for LAMMPS %s, host is %s\n", plugin->name,
                 plugin->version, lmp->version);
  if (style == "pair")
    (*lmp->force->pair_map)[plugin->name] = (Force::PairCreator)plugin->creator.v1;
  else if (style == "bond")
    (*lmp->force->bond_map)[plugin->name] = (Force::BondCreator)plugin->creator.v1;
  else if (style == "compute")
    (*lmp->modify->compute_map)[plugin->name] = (Modify::ComputeCreator)plugin->creator.v2;
  else if (style == "fix")
    (*lmp->modify->fix_map)[plugin->name] = (Modify::FixCreator)plugin->creator.v2;
  else if (style == "command")
    (*lmp->input->command_map)[plugin->name] = (Input::CommandCreator)plugin->creator.v1;
  else
    unknown_kind = true; // the loader of that version ignores other kinds
  loaded.push_back(style + " " + plugin->name);
}

} // namespace

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  if (argc < 3) {
    std::fprintf(stderr, "usage: plugin_host PLUGIN.so INPUT [LAMMPS arguments]\n");
    return 2;
  }
  std::vector<char *> args = {argv[0]};
  for (int i = 3; i < argc; i++) args.push_back(argv[i]);
  auto *lmp = new LAMMPS((int)args.size(), args.data(), MPI_COMM_WORLD);
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);

  // the host alone knows no PERIDEM style: whatever the input finds comes from the plugin
  if (lmp->atom->avec_map->count("peridem") || lmp->force->bond_map->count("peridem")) {
    std::fprintf(stderr, "PLUGIN-HOST-FAIL: PERIDEM styles present before loading\n");
    return 1;
  }
  void *dso = dlopen(argv[1], RTLD_NOW | RTLD_GLOBAL);
  if (!dso) {
    std::fprintf(stderr, "PLUGIN-HOST-FAIL: %s\n", dlerror());
    return 1;
  }
  void *init = dlsym(dso, "lammpsplugin_init");
  if (!init) {
    std::fprintf(stderr, "PLUGIN-HOST-FAIL: no lammpsplugin_init in %s\n", argv[1]);
    return 1;
  }
  (*(lammpsplugin_initfunc)(init))((void *)lmp, dso, (void *)&host_register);
  if (me == 0) {
    for (const auto &s : loaded) std::printf("plugin style: %s\n", s.c_str());
    std::printf("atom style peridem: %s\n",
                lmp->atom->avec_map->count("peridem") ? "registered" : "missing");
  }
  if (unknown_kind) {
    std::fprintf(stderr, "PLUGIN-HOST-FAIL: a style kind the loader does not know\n");
    return 1;
  }

  lmp->input->file(argv[2]);
  if (me == 0) std::printf("PLUGIN-HOST-OK %zu plugin styles\n", loaded.size());
  delete lmp;
  MPI_Finalize();
  return 0;
}
