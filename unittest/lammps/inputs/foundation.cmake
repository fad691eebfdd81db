# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Examples run at 1 and 2 MPI ranks with identical thermo output.
peridem_add_example_test(grain_block grain-block in.grain_block 1 2)

# atom_style peridem: bad Atoms lines in data files
peridem_add_error_test(atom_zero_volume ${_in}/read_data.in "Invalid volume 0 for atom 2"
  -var inputs ${_in} -var data bad_volume.data)
peridem_add_error_test(atom_negative_density ${_in}/read_data.in "Invalid density -1 for atom 2"
  -var inputs ${_in} -var data bad_density.data)
peridem_add_error_test(atom_zero_grain ${_in}/read_data.in "Invalid grain ID 0 for atom 2"
  -var inputs ${_in} -var data bad_grain.data)
# reference positions: far outside a periodic box (hung in LAMMPS's minimum image when the
# bond style measured the bond) and not finite
peridem_add_error_test(atom_x0_far_periodic ${_in}/bond_error.in
  "Reference position 1e\\+30 0 0 of atom 2 in Atoms section of data file lies more than one box length outside the periodic box along x"
  -var inputs ${_in} -var data bond_x0_far.data -var case bond_ok.lmp)
# (LAMMPS 4Feb2025 refuses 1e999 itself while reading the data file, before atom style peridem
# sees it: either message, with a non-zero exit)
peridem_add_error_test(atom_x0_not_finite ${_in}/bond_error.in
  "(Invalid reference position 0.1 inf 0 of atom 2 in Atoms section of data file|Floating point number 1e999 in input script or data file is out of range)"
  -var inputs ${_in} -var data bond_x0_inf.data -var case bond_ok.lmp)
set_tests_properties(error.atom_x0_far_periodic error.atom_x0_not_finite PROPERTIES TIMEOUT 60)
# (LAMMPS's own message: 29 Sep 2021 and 4 Feb 2025 word it differently)
peridem_add_error_test(atom_missing_x0 ${_in}/read_data.in
  "Incorrect (atom format in|format in Atoms section of) data file"
  -var inputs ${_in} -var data missing_x0.data)

# `clear` keeps the styles: in lmp_peridem, and in the stock lmp with
# libperidem.so preloaded (the same post_create hook).
add_test(NAME driver.clear_keeps_styles
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "PERIDEM-ROUTE-OK after clear" $<TARGET_FILE:lmp_peridem>
          -in ${_in}/clear_keeps_styles.in -log none -var inputs ${_in})
# The routes through Debian's stock lmp and python3-lammps: only against that LAMMPS
# (29 Sep 2021); they load this build's libperidem into Debian's liblammps.
if(LAMMPS_VERSION EQUAL 20210929)
# Loading PERIDEM into the stock LAMMPS: the python command of `lmp`, and
# the lammps Python module.
add_test(NAME python.lmp_command_route
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "PERIDEM-ROUTE-OK" lmp
          -in ${_in}/python_command_route.in -log none -var inputs ${_in}
          -var pydir ${PROJECT_SOURCE_DIR}/python)
# Debian's python3-lammps belongs to Debian's python3, not to one earlier on PATH
find_program(PERIDEM_DEBIAN_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH)
add_test(NAME python.module_route
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "PERIDEM-ROUTE-OK" ${PERIDEM_DEBIAN_PYTHON} ${_in}/../python_module_route.py
          ${PROJECT_SOURCE_DIR}/python ${_in})
set_tests_properties(python.lmp_command_route python.module_route PROPERTIES
  ENVIRONMENT "PERIDEM_LIBRARY=$<TARGET_FILE:peridem>")

add_test(NAME preload.clear_keeps_styles
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "PERIDEM-ROUTE-OK after clear"
          ${PERIDEM_RUN}/preload.sh $<TARGET_FILE:peridem> lmp
          -in ${_in}/clear_keeps_styles.in -log none -var inputs ${_in})
endif()

# configuration stops (non-zero exit, CMake Error) with a clear message when the LAMMPS
# headers are missing or belong to another LAMMPS version. CMake wraps the message at
# word boundaries wherever the (machine-dependent) path length puts them: expect_error.sh
# --cmake reads a line break as a space.
add_test(NAME configure.missing_lammps_headers
  COMMAND ${PERIDEM_RUN}/expect_error.sh --cmake "no_such_dir' has no fmt/format.h"
          ${CMAKE_COMMAND} -S ${PROJECT_SOURCE_DIR} -B ${CMAKE_CURRENT_BINARY_DIR}/configure_missing
          -DPERIDEM_BUILD_TESTS=OFF -DPERIDEM_LAMMPS_SRC=${CMAKE_CURRENT_BINARY_DIR}/no_such_dir)
set(_fake ${CMAKE_CURRENT_BINARY_DIR}/fake_lammps_src)
foreach(_h fmt/format.h atom_vec.h neigh_request.h math_const.h pointers.h)
  file(WRITE ${_fake}/${_h} "")
endforeach()
file(WRITE ${_fake}/version.h "#define LAMMPS_VERSION \"1 Jan 2000\"\n")
add_test(NAME configure.other_lammps_version
  COMMAND ${PERIDEM_RUN}/expect_error.sh --cmake
          "version 20000101 but the installed LAMMPS library is 20210929"
          ${CMAKE_COMMAND} -S ${PROJECT_SOURCE_DIR} -B ${CMAKE_CURRENT_BINARY_DIR}/configure_other
          -DPERIDEM_BUILD_TESTS=OFF -DPERIDEM_LAMMPS_SRC=${_fake})
