# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# LAMMPS-facing part of the build: the styles (libperidem.so), the lmp_peridem
# driver and the header checks against the matching LAMMPS source tree.

# Supported LAMMPS versions: 29 Sep 2021 (Debian bookworm's liblammps-dev, the default) and
# 4 Feb 2025 (built from source by scripts/build_lammps_2025.sh; LAMMPS_DIR points at it).
set(PERIDEM_LAMMPS_VERSIONS 20210929 20250204)
set(MPI_CXX_SKIP_MPICXX ON CACHE BOOL "Do not link the deprecated MPI C++ bindings")
find_package(MPI REQUIRED COMPONENTS C CXX)
find_package(LAMMPS CONFIG)
if(NOT LAMMPS_FOUND OR NOT LAMMPS_VERSION IN_LIST PERIDEM_LAMMPS_VERSIONS)
  message(FATAL_ERROR
    "PERIDEM needs LAMMPS 20210929 (Debian bookworm: liblammps-dev) or 20250204 "
    "(found: '${LAMMPS_VERSION}'). Run scripts/setup-debian.sh, or point LAMMPS_DIR at the "
    "LAMMPSConfig.cmake of a supported version (scripts/build_lammps_2025.sh builds 20250204).")
endif()

# The installed headers are incomplete (no fmt/, neigh_request.h, atom_vec.h, ...):
# take them from the matching LAMMPS source tree (Debian: apt-get source lammps).
file(GLOB _peridem_default_src LIST_DIRECTORIES true /opt/peridem/lammps-source/lammps-*/src)
list(SORT _peridem_default_src)
list(GET _peridem_default_src -1 _peridem_default_src_last)
set(PERIDEM_LAMMPS_SRC "${_peridem_default_src_last}" CACHE PATH
    "src/ directory of the LAMMPS source tree matching the installed LAMMPS")
foreach(_h fmt/format.h atom_vec.h neigh_request.h math_const.h version.h pointers.h)
  if(NOT EXISTS "${PERIDEM_LAMMPS_SRC}/${_h}")
    message(FATAL_ERROR
      "PERIDEM_LAMMPS_SRC='${PERIDEM_LAMMPS_SRC}' has no ${_h}. Set -DPERIDEM_LAMMPS_SRC=<lammps>/src "
      "to the source tree of LAMMPS ${LAMMPS_VERSION} (scripts/setup-debian.sh fetches 20210929).")
  endif()
endforeach()

# The source tree must be the same LAMMPS version as the library we link.
file(STRINGS "${PERIDEM_LAMMPS_SRC}/version.h" _peridem_version_line REGEX "define LAMMPS_VERSION")
string(REGEX REPLACE ".*\"([0-9]+) ([A-Za-z]+) ([0-9]+)\".*" "\\1;\\2;\\3" _peridem_dmy "${_peridem_version_line}")
list(GET _peridem_dmy 0 _d)
list(GET _peridem_dmy 1 _m)
list(GET _peridem_dmy 2 _y)
set(_months Jan Feb Mar Apr May Jun Jul Aug Sep Oct Nov Dec)
list(FIND _months "${_m}" _mi)
math(EXPR _mi "${_mi} + 1")
math(EXPR _src_version "${_y} * 10000 + ${_mi} * 100 + ${_d}")
if(NOT _src_version EQUAL LAMMPS_VERSION)
  message(FATAL_ERROR
    "LAMMPS headers in ${PERIDEM_LAMMPS_SRC} are version ${_src_version} but the installed "
    "LAMMPS library is ${LAMMPS_VERSION}: point PERIDEM_LAMMPS_SRC at the matching source tree.")
endif()
message(STATUS "PERIDEM: LAMMPS ${LAMMPS_VERSION}, headers from ${PERIDEM_LAMMPS_SRC}")

# Styles: every src/*.cpp that is not part of the LAMMPS-free core.
file(GLOB _peridem_all_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/*.cpp)
set(PERIDEM_STYLE_SOURCES)
foreach(_f ${_peridem_all_sources})
  get_filename_component(_n ${_f} NAME)
  if(NOT _n MATCHES "^peridem_")
    list(APPEND PERIDEM_STYLE_SOURCES ${_f})
  endif()
endforeach()

add_library(peridem SHARED ${PERIDEM_STYLE_SOURCES} ${PROJECT_SOURCE_DIR}/driver/post_create_hook.cpp
  ${PROJECT_SOURCE_DIR}/driver/register_driver.cpp ${PROJECT_SOURCE_DIR}/driver/register_peridem.cpp)
# bond_style peridem/opt (bond_peridem_opt.cpp): its chunked bond loop vectorises its square
# roots only without errno (they take sums of squares, never negative). No FMA contraction in
# any bond file: it is what keeps each fast force pass equal to its one-by-one pass, and
# peridem/opt equal to peridem, to the bit on targets with FMA (the AVX-512 copy of
# peridem/opt's loop, -march=native); bond_peridem_base.cpp holds the break path and the
# reference lengths every loop shares. The plain style's file gets no other flag: portable.
set_source_files_properties(${PROJECT_SOURCE_DIR}/src/bond_peridem_opt.cpp PROPERTIES
  COMPILE_OPTIONS "-fno-math-errno;-ftree-vectorize;-ffp-contract=off")
set_source_files_properties(${PROJECT_SOURCE_DIR}/src/bond_peridem.cpp
  ${PROJECT_SOURCE_DIR}/src/bond_peridem_base.cpp ${PROJECT_SOURCE_DIR}/src/bond_peridem_lps.cpp
  PROPERTIES COMPILE_OPTIONS "-ffp-contract=off")
target_include_directories(peridem PUBLIC ${PROJECT_SOURCE_DIR}/src ${PROJECT_SOURCE_DIR}/driver)
# after LAMMPS's own include directory, so installed headers win where both exist
target_include_directories(peridem SYSTEM AFTER PUBLIC ${PERIDEM_LAMMPS_SRC})
target_link_libraries(peridem PUBLIC LAMMPS::lammps MPI::MPI_CXX PRIVATE peridem_core ${CMAKE_DL_LIBS})
target_compile_options(peridem PRIVATE -Wall -Wextra -Wno-unused-parameter
  $<$<BOOL:${PERIDEM_WERROR}>:-Werror>)
set_target_properties(peridem PROPERTIES OUTPUT_NAME peridem)

add_executable(lmp_peridem ${PROJECT_SOURCE_DIR}/driver/lmp_peridem.cpp)
# libperidem must come before liblammps in the link order: it provides the
# LAMMPS::post_create hook that re-registers the styles after `clear`.
target_link_libraries(lmp_peridem PRIVATE peridem)
target_link_options(lmp_peridem PRIVATE -Wl,--no-as-needed)
set_target_properties(lmp_peridem PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR})

install(TARGETS peridem lmp_peridem)

# peridemplugin.so for LAMMPS builds with the PLUGIN package ("plugin load
# peridemplugin.so"); Debian's LAMMPS has none, see plugin/peridem_plugin.cpp
add_library(peridemplugin MODULE ${PROJECT_SOURCE_DIR}/plugin/peridem_plugin.cpp)
target_link_libraries(peridemplugin PRIVATE peridem)
target_compile_options(peridemplugin PRIVATE -Wall -Wextra -Wno-unused-parameter
  $<$<BOOL:${PERIDEM_WERROR}>:-Werror>)
# never unloaded: LAMMPS 2025 unloads plugins (plugin_clear) before it deletes the atom,
# force and modify styles they created, whose code would then be gone (a crash at exit)
target_link_options(peridemplugin PRIVATE -Wl,-z,nodelete)
set_target_properties(peridemplugin PROPERTIES PREFIX "" OUTPUT_NAME peridemplugin
  LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR})
install(TARGETS peridemplugin LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/lammps/plugins)
