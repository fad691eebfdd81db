/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: keep the styles registered across the `clear` command.

   `clear` deletes and re-creates Atom, Force and Modify, and with them the
   style maps into which PERIDEM inserted its styles; afterwards it calls
   LAMMPS::post_create(), as the LAMMPS constructor does. liblammps calls
   post_create() through its PLT, so a definition that comes earlier in the
   symbol lookup order (this library, linked before liblammps into
   lmp_peridem, or loaded with LD_PRELOAD) replaces it. The replacement calls
   liblammps's own post_create() and then registers the PERIDEM styles, so
   they exist after construction and after every `clear`.

   This file is not part of src/: in a LAMMPS source tree the styles are
   registered by LAMMPS itself through the style headers.
------------------------------------------------------------------------- */

#include "lammps.h"
#include "library.h"
#include "register_driver.h"

#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>

using namespace LAMMPS_NS;

namespace {

using PostCreate = void (*)(LAMMPS *);

// The definition inside liblammps, found through the library that holds a
// LAMMPS C-API function (robust whatever the load order of this library).
PostCreate lammps_post_create()
{
  static PostCreate original = nullptr;
  if (original) return original;
  Dl_info info;
  if (dladdr(reinterpret_cast<void *>(&lammps_version), &info) && info.dli_fname) {
    void *handle = dlopen(info.dli_fname, RTLD_LAZY | RTLD_NOLOAD);
    if (handle) {
      original = reinterpret_cast<PostCreate>(dlsym(handle, "_ZN9LAMMPS_NS6LAMMPS11post_createEv"));
      dlclose(handle);
    }
  }
  if (!original) {
    fprintf(stderr, "PERIDEM: cannot find LAMMPS::post_create in liblammps\n");
    abort();
  }
  return original;
}

} // namespace

void LAMMPS::post_create()
{
  lammps_post_create()(this);
  peridem_register(this);
}
