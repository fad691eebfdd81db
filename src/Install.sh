# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# The PERIDEM package in LAMMPS's traditional make build, run by src/Makefile in
# src/PERIDEM with one argument: 1 install (make yes-peridem), 0 uninstall (make no-peridem),
# 2 update (make package-update). Copies the package's sources into src/, and makes
# Makefile.package.settings include PERIDEM/Makefile.lammps (Eigen's folder, the per-file
# flags) and Makefile.package add its include folder to PKG_SYSINC.

mode=$1
LC_ALL=C
export LC_ALL

# the sources: into src/ when they differ from the copy there (so that make recompiles only
# what changed), out of it on uninstall
for f in *.cpp *.h; do
  test -f "$f" || continue
  if test "$mode" = 0; then
    rm -f "../$f"
  elif ! cmp -s "$f" "../$f"; then
    cp "$f" ..
    if test "$mode" = 2; then echo "  updating src/$f"; fi
  fi
done

# the Makefile settings: taken out on uninstall and before they are put in on install, so
# that installing twice puts them in once; an update leaves them
if test "$mode" = 0 || test "$mode" = 1; then
  if test -e ../Makefile.package; then
    sed -i -e 's/$(peridem_SYSINC) //g' ../Makefile.package
  fi
  if test -e ../Makefile.package.settings; then
    sed -i -e '/^include \.\.\/PERIDEM\/Makefile\.lammps$/d' ../Makefile.package.settings
  fi
fi
if test "$mode" = 1; then
  if test -e ../Makefile.package; then
    sed -i -e 's/^PKG_SYSINC =[ \t]*/&$(peridem_SYSINC) /' ../Makefile.package
  fi
  if test -e ../Makefile.package.settings; then
    echo "include ../PERIDEM/Makefile.lammps" >>../Makefile.package.settings
  fi
fi
