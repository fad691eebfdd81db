/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM as a LAMMPS plugin (peridemplugin.so) for LAMMPS builds with the
   PLUGIN package: "plugin load peridemplugin.so". Debian's LAMMPS has no
   PLUGIN package; there use lmp_peridem, LD_PRELOAD or peridem_register
   (README). Tested by unittest/plugin/plugin_host.cpp, which loads it the
   way the PLUGIN package of LAMMPS 29Sep2021 does.

   The plugin loader of that LAMMPS version registers pair, bond, fix,
   compute and command styles; it has no atom styles ("not yet
   implemented"), so atom_style peridem is inserted into the LAMMPS instance
   directly: "plugin unload" cannot remove it, and "clear" unloads plugins
   in that version (load the plugin again after clear).
------------------------------------------------------------------------- */

#include "lammpsplugin.h"

#include "atom.h"
#include "lammps.h"
#include "version.h"

#include "register_driver.h"

using namespace LAMMPS_NS;

namespace {

// Passes each style of PERIDEM_NS::for_each_style to the plugin loader. The
// loader stores a creator as an untyped factory and casts it back to the
// typed creator of its style kind (Force::PairCreator, ...), so the typed
// creators travel through the casts unchanged.
class PluginRegistrar : public PERIDEM_NS::StyleSink {
 public:
  PluginRegistrar(LAMMPS *lmp, void *handle, lammpsplugin_regfunc reg)
      : lmp(lmp), handle(handle), reg(reg)
  {
  }
  // the loader of LAMMPS 29Sep2021 has no atom styles: insert it directly
  void atom(const char *name, PERIDEM_NS::AtomVecCreator c) override
  {
    (*lmp->atom->avec_map)[name] = c;
  }
  void bond(const char *name, PERIDEM_NS::BondCreator c) override
  {
    add("bond", name, (lammpsplugin_factory1 *)c, nullptr);
  }
  void pair(const char *name, PERIDEM_NS::PairCreator c) override
  {
    add("pair", name, (lammpsplugin_factory1 *)c, nullptr);
  }
  void fix(const char *name, PERIDEM_NS::FixCreator c) override
  {
    add("fix", name, nullptr, (lammpsplugin_factory2 *)c);
  }
  void compute(const char *name, PERIDEM_NS::ComputeCreator c) override
  {
    add("compute", name, nullptr, (lammpsplugin_factory2 *)c);
  }
  void command(const char *name, PERIDEM_NS::CommandCreator c) override
  {
    add("command", name, (lammpsplugin_factory1 *)c, nullptr);
  }

 private:
  void add(const char *style, const char *name, lammpsplugin_factory1 *v1,
           lammpsplugin_factory2 *v2)
  {
    lammpsplugin_t plugin;
    plugin.version = LAMMPS_VERSION;
    plugin.style = style;
    plugin.name = name;
    plugin.info = "PERIDEM: deformable, breakable grains (peridynamics + contact)";
    plugin.author = "the PERIDEM developers";
    if (v1)
      plugin.creator.v1 = v1;
    else
      plugin.creator.v2 = v2;
    plugin.handle = handle;
    (*reg)(&plugin, lmp);
  }
  LAMMPS *lmp;
  void *handle;
  lammpsplugin_regfunc reg;
};

} // namespace

extern "C" void lammpsplugin_init(void *lmp_ptr, void *handle, void *regfunc)
{
  auto *lmp = static_cast<LAMMPS *>(lmp_ptr);
  // refuses a LAMMPS of another version with a clear error, as peridem_register does
  PERIDEM_NS::check_lammps_version(lmp, LAMMPS_VERSION);
  PluginRegistrar registrar(lmp, handle, (lammpsplugin_regfunc)regfunc);
  PERIDEM_NS::for_each_style(registrar);
}
