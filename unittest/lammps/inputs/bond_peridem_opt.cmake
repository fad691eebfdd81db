# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# bond_style peridem/opt, selected with -sf opt: the same thermo output as bond_style peridem,
# with zero tolerance, over fracture runs in which its vectorised loop breaks the bonds:
# examples/peri-impact (3d, the projectile breaks the cylinder's bonds, a stiffness per bond
# from volume_correction linear, 15 digits) and examples/notch-fracture reduced to 20 us (2d,
# the notched grain breaks into 3 fragments and 12 pieces of debris, 8 digits). Both fail when
# bond_peridem_opt.cpp is compiled with -ffp-contract=fast (GCC's default for C++) on a CPU with
# AVX-512 (tried:
# peri-impact's KinEng differs in the 14th digit at step 100, notch-fracture's PotEng at step
# 167). A few seconds of CPU.
set(_opt_compare "PERIDEM_THERMO_COMPARE_ARGS=--rtol 0 --atol 0")
add_test(NAME example.peri_impact_opt
  COMMAND ${PERIDEM_RUN}/run_variants.sh $<TARGET_FILE:lmp_peridem>
          ${PROJECT_SOURCE_DIR}/examples/peri-impact in.peri_impact
          ${CMAKE_CURRENT_BINARY_DIR}/examples/peri_impact_opt "" "1" "1 -sf opt")
add_test(NAME example.notch_fracture_opt
  COMMAND ${PERIDEM_RUN}/run_variants.sh $<TARGET_FILE:lmp_peridem>
          ${PROJECT_SOURCE_DIR}/examples/notch-fracture in.notch_fracture
          ${CMAKE_CURRENT_BINARY_DIR}/examples/notch_fracture_opt "-var time 2e-5" "1" "1 -sf opt")
set_tests_properties(example.peri_impact_opt example.notch_fracture_opt PROPERTIES TIMEOUT 300
  ENVIRONMENT "${_opt_compare}")

# -sf opt creates bond_style peridem/opt for bond_style peridem, and bond_style peridem/lps,
# which has no opt variant, for bond_style peridem/lps, without a word (LAMMPS's way with a
# suffix a style lacks); `info system` names the style created
foreach(_case "peridem|peridem/opt" "peridem/lps|peridem/lps")
  string(REPLACE "|" ";" _case "${_case}")
  list(GET _case 0 _bond)
  list(GET _case 1 _created)
  string(REPLACE "/" "_" _name "${_bond}")
  add_test(NAME bond_suffix_opt_${_name}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "^Bonds .* style = ${_created}$" --absent WARNING
            $<TARGET_FILE:lmp_peridem> -sf opt -in ${_in}/bond_suffix.in -log none -var inputs ${_in}
            -var bond ${_bond} -var potentials ${PROJECT_SOURCE_DIR}/potentials)
endforeach()
