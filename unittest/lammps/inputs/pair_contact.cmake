# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# pair_style peridem/contact

# head-on collision without damping or friction: energy conserved to 1e-5,
# and the same thermo output on 1 and 2 ranks
peridem_add_example_test(contact_collision contact-collision in.collision 1 2)
add_test(NAME contact_collision_energy
  COMMAND ${PERIDEM_RUN}/expect_pass.sh $<TARGET_FILE:lmp_peridem> -in ${_in}/contact_energy_check.in -log none -echo none
          -var example in.collision -var limit 1e-5 -var potentials ${PROJECT_SOURCE_DIR}/potentials
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}/examples/contact-collision)

# the quick-start job, shortened to 18000 steps (the grains land from step
# ~15000): the same thermo output on 1 and 2 ranks (it ran on one
# rank only and could fail only by crashing)
peridem_add_example_test(pile pile in.pile 1 2)
set_tests_properties(example.pile PROPERTIES ENVIRONMENT "PERIDEM_EXAMPLE_ARGS=-var steps 18000")

# pair_style peridem/contact forces on 2 ranks equal those of 1 rank after
# run 0, with newton_pair on and off
add_test(NAME PairContact.ranks_match_one_rank_np2
  COMMAND ${PERIDEM_RUN}/mpirun.sh 2 $<TARGET_FILE:test_pair_peridem_contact>
          --gtest_filter=*RanksMatchOneRank*)
