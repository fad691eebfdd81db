# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# PERIDEM as a package of a LAMMPS source tree (PKG_PERIDEM=ON): LAMMPS's CMake compiles
# src/PERIDEM/*.cpp into liblammps itself; this module adds what those files need.
# scripts/build_lammps_2025.sh copies it to <lammps>/cmake/Modules/Packages/ and lists
# PERIDEM among the packages of <lammps>/cmake/CMakeLists.txt (STANDARD_PACKAGES and the
# PKG_WITH_INCL loop), as LAMMPS's "Adding a package" instructions describe.

# The package is C++17 (LAMMPS itself requires C++17 since 2023; older trees build as C++11).
if(CMAKE_CXX_STANDARD LESS 17)
  message(FATAL_ERROR "The PERIDEM package needs C++17: configure LAMMPS with -D CMAKE_CXX_STANDARD=17")
endif()

# Eigen 3 (header only): the principal axes of a grain (a symmetric 3x3 eigenproblem,
# src/PERIDEM/peridem_grain_shape.cpp). Debian: libeigen3-dev.
find_package(Eigen3 3.3 NO_MODULE)
if(NOT TARGET Eigen3::Eigen)
  message(FATAL_ERROR "The PERIDEM package needs Eigen 3 (Debian: libeigen3-dev); set Eigen3_DIR "
                      "to the folder of its Eigen3Config.cmake")
endif()
# Eigen's include folder and the warnings of the stand-alone build for the package's own files
# only: flags on the whole lammps target would recompile all of LAMMPS when the package is added.
get_target_property(PERIDEM_EIGEN_INCLUDE Eigen3::Eigen INTERFACE_INCLUDE_DIRECTORIES)
file(GLOB PERIDEM_SOURCES ${LAMMPS_SOURCE_DIR}/PERIDEM/*.cpp)
set_property(SOURCE ${PERIDEM_SOURCES} APPEND PROPERTY INCLUDE_DIRECTORIES ${PERIDEM_EIGEN_INCLUDE})
set_property(SOURCE ${PERIDEM_SOURCES} APPEND PROPERTY COMPILE_OPTIONS -Wall -Wextra -Wno-unused-parameter)
# bond_style peridem/opt's chunked force loop (bond_peridem_opt.cpp): GCC vectorises its square
# roots and divisions (sqrtpd, divpd) only without errno (the roots take sums of squares, never
# negative) and, below -O3 (LAMMPS's default build type RelWithDebInfo is -O2), only with
# -ftree-vectorize (GCC 12: no sqrtpd at -O1/-O2/-O3 without -fno-math-errno, nor at -O2
# without -ftree-vectorize). No FMA contraction in any bond file: it keeps each fast force pass
# equal to its one-by-one pass, and peridem/opt equal to peridem, to the bit on targets with
# FMA (peridem/opt's AVX-512 copy; tested: ChunkedLoopEqualsOneByOne, OptEqualsPlain);
# bond_peridem_base.cpp holds the break path and the reference lengths every loop shares. The
# plain style's file gets no other flag: portable. The stand-alone build
# (cmake/PeridemLAMMPS.cmake, -O3) and the traditional make build (src/Makefile.lammps) set the
# same flags. These files only, so that LAMMPS's own files keep LAMMPS's flags.
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  set_property(SOURCE ${LAMMPS_SOURCE_DIR}/PERIDEM/bond_peridem_opt.cpp APPEND PROPERTY
    COMPILE_OPTIONS -fno-math-errno -ftree-vectorize -ffp-contract=off)
  set_property(SOURCE ${LAMMPS_SOURCE_DIR}/PERIDEM/bond_peridem.cpp
    ${LAMMPS_SOURCE_DIR}/PERIDEM/bond_peridem_base.cpp
    ${LAMMPS_SOURCE_DIR}/PERIDEM/bond_peridem_lps.cpp APPEND PROPERTY
    COMPILE_OPTIONS -ffp-contract=off)
endif()
