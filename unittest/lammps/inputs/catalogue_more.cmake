# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Bad-input catalogue (doc/errors.md), continued: the calls catalogue.cmake left
# untested and the numbers of create_peridem_grains, create_peridem_bed,
# cut_peridem_bonds and the computes (nan, inf, words). Each test checks the exit
# code and the stable part of the message (command, keyword, value).
set(_cat ${_in}/catalogue)
set(_fs ${PROJECT_SOURCE_DIR}/unittest/force-styles/tests)
# peridem_catalogue_error (catalogue.cmake, read first: file(GLOB) sorts) runs one
# command on the two-grain system of catalogue/base.in (3D, 2 atom and 2 bond types)
# on the empty 2D box of catalogue/base2d.in
function(peridem_catalogue2d name regex)
  peridem_add_error_test(catalogue_${name} ${_cat}/base2d.in "${regex}" ${ARGN})
endfunction()
# a list of commands (catalogue/commands.in: -var c1 ... -var c9)
function(peridem_catalogue_commands name regex)
  peridem_add_error_test(catalogue_${name} ${_cat}/commands.in "${regex}" ${ARGN})
endfunction()
set(_atomic -var c1 "atom_style atomic" -var c2 "region box block 0 1e-3 0 1e-3 0 1e-3"
  -var c3 "create_box 1 box")
set(_sphere "create_peridem_grains 1 sphere radius 1e-3 at 5e-3 5e-3 5e-3 spacing 5e-4 horizon 1e-3 density 1000")
set(_disk "create_peridem_grains 1 disk radius 1e-3 at 0 0 0 spacing 2.5e-4 horizon 7.5e-4 density 1000")
set(_bed "create_peridem_bed catalogue_bed.txt")

# ---- numbers: nan, inf and words name the command, the keyword and the value
peridem_catalogue_error(grains_nan_spacing "create_peridem_grains: spacing must be a finite number, not nan"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 at 5e-3 5e-3 5e-3 spacing nan horizon 1e-3 density 1000")
peridem_catalogue_error(grains_inf_at "create_peridem_grains: at must be a finite number, not inf"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 at inf 5e-3 5e-3 spacing 5e-4 horizon 1e-3 density 1000")
peridem_catalogue_error(grains_word_radius "create_peridem_grains: radius must be a number, not 'big'"
  -var bad "create_peridem_grains 1 sphere radius big at 5e-3 5e-3 5e-3 spacing 5e-4 horizon 1e-3 density 1000")
peridem_catalogue_error(grains_word_type "create_peridem_grains: atom type must be an integer, not 'one'"
  -var bad "create_peridem_grains one sphere radius 1e-3 at 5e-3 5e-3 5e-3 spacing 5e-4 horizon 1e-3 density 1000")
peridem_catalogue_error(grains_nan_rotate "create_peridem_grains: rotate must be a finite number, not nan"
  -var bad "${_sphere} rotate nan")
peridem_catalogue_error(grains_word_rotate_seed "create_peridem_grains: rotate random must be an integer, not 'x'"
  -var bad "${_sphere} rotate random x")
peridem_catalogue_error(grains_fraction_bond_type "create_peridem_grains: bond/type must be an integer, not '1.5'"
  -var bad "${_sphere} bond/type 1.5")
peridem_catalogue_error(grains_inf_axis "create_peridem_grains: axis must be a finite number, not -inf"
  -var bad "${_sphere} rotate 30 axis 0 0 -inf")
peridem_catalogue_error(grains_nan_notch "create_peridem_grains: notch must be a finite number, not nan"
  -var bad "${_sphere} notch 0 0 nan 1")
peridem_catalogue_error(grains_nan_density "create_peridem_grains: density must be a finite number, not nan"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 at 5e-3 5e-3 5e-3 spacing 5e-4 horizon 1e-3 density nan")
peridem_catalogue_error(bed_nan_radius "create_peridem_bed: radius must be a finite number, not nan"
  -var bad "${_bed} count 10 radius uniform nan 2e-4 seed 1")
peridem_catalogue_error(bed_word_count "create_peridem_bed: count must be an integer, not 'ten'"
  -var bad "${_bed} count ten radius uniform 1e-4 2e-4 seed 1")
peridem_catalogue_error(bed_fraction_seed "create_peridem_bed: seed must be an integer, not '1.5'"
  -var bad "${_bed} count 10 radius uniform 1e-4 2e-4 seed 1.5")
peridem_catalogue_error(bed_inf_box "create_peridem_bed: box must be a finite number, not inf"
  -var bad "${_bed} count 10 radius uniform 1e-4 2e-4 seed 1 box 0 inf 0 1e-3 0 1e-3")
peridem_catalogue_error(bed_nan_contact_radius "create_peridem_bed: contact_radius must be a finite number, not nan"
  -var bad "${_bed} count 10 radius uniform 1e-4 2e-4 seed 1 contact_radius nan")
peridem_catalogue_error(cut_nan_segment "cut_peridem_bonds: segment must be a finite number, not nan"
  -var bad "cut_peridem_bonds all segment 0 0 nan 1e-3")
peridem_catalogue_error(cut_word_segment "cut_peridem_bonds: segment must be a number, not 'left'"
  -var bad "cut_peridem_bonds all segment left 0 1e-3 1e-3")
peridem_catalogue_error(compute_bed_nan_bin "compute peridem/bed: bin must be a finite number, not nan"
  -var pre "region r2 block 0 1 0 1 0 1" -var bad "compute b all peridem/bed r2 bin nan")
peridem_catalogue_error(compute_fragments_inf_min "compute peridem/fragments: min must be a finite number, not inf"
  -var bad "compute f all peridem/fragments min volume inf")
# a node count is a whole number (issue 27: 2.5 was accepted)
peridem_catalogue_error(compute_fragments_fraction_min_nodes "compute peridem/fragments: min nodes must be an integer, not '2.5'"
  -var bad "compute f all peridem/fragments min nodes 2.5")
peridem_catalogue_error(compute_fragments_word_min_nodes "compute peridem/fragments: min nodes must be an integer, not 'inf'"
  -var bad "compute f all peridem/fragments min nodes inf")

# ---- bond styles
peridem_add_error_test(bond_same_reference_position ${_in}/bond_error.in
  "bond_style peridem: atoms [12] and [12] are bonded but have the same reference position"
  -var inputs ${_in} -var data catalogue/bond_same_x0.data -var case bond_ok.lmp)
peridem_catalogue_error(bond_material_no_horizon "bond_coeff: material NOHORIZON of .*no_horizon.peridem has no horizon: add horizon to the file or the command"
  -var bad "bond_coeff 1 material ${_cat}/no_horizon.peridem NOHORIZON")
peridem_catalogue_error(bond_c_s0_no_horizon "bond_coeff: bond_style peridem needs a horizon"
  -var bad "bond_coeff 1 c 1e20 s0 0.01")
peridem_catalogue_error(bond_constants_overflow "bond_coeff: spring constant c must be a positive finite number \\(got inf\\)"
  -var bad "bond_coeff 1 E 1e300 Gc 1 horizon 2.0001e-3")
peridem_catalogue_error(lps_material_no_horizon "bond_coeff: material NOHORIZON of .*no_horizon.peridem has no horizon: add horizon to the file or the command"
  -var pre "bond_style peridem/lps" -var bad "bond_coeff * material ${_cat}/no_horizon.peridem NOHORIZON")

# ---- computes
peridem_catalogue_error(compute_bed_value_missing "Illegal compute peridem/bed command: top needs a value"
  -var pre "region r2 block 0 1 0 1 0 1" -var bad "compute b all peridem/bed r2 top")
peridem_catalogue_error(compute_bed_no_variable "compute peridem/bed: variable nope does not exist"
  -var pre "region r2 block 0 1 0 1 0 1" -var bad "compute b all peridem/bed r2 top v_nope")
peridem_catalogue_error(compute_bed_atom_variable "compute peridem/bed: variable a is not equal-style"
  -var pre "region r2 block 0 1 0 1 0 1" -var pre2 "variable a atom x" -var bad "compute b all peridem/bed r2 top v_a")
peridem_catalogue_commands(compute_damage_atomic "compute peridem/damage requires atom style peridem"
  ${_atomic} -var c4 "compute d all peridem/damage")
peridem_catalogue_commands(compute_damage_no_peridem_bonds "compute peridem/damage needs bond_style peridem"
  -var c1 "atom_style peridem" -var c2 "region box block 0 1e-3 0 1e-3 0 1e-3"
  -var c3 "create_box 1 box bond/types 1 extra/bond/per/atom 4"
  -var c4 "bond_style zero" -var c5 "bond_coeff *" -var c6 "compute d all peridem/damage" -var c7 "run 0 post no")
peridem_catalogue_error(compute_fragments_new_grains "compute peridem/fragments f: grain IDs beyond 2 were added after the compute was defined"
  -var pre "compute f all peridem/fragments" -var bad "create_peridem_grains 1 sphere radius 1e-3 at 7e-3 5e-3 5e-3 spacing 5e-4 horizon 5.5e-4 density 1000")
peridem_catalogue_error(compute_grain_new_grains "compute peridem/grain g: grain IDs beyond 2 were added after the compute was defined"
  -var pre "compute g all peridem/grain" -var bad "create_peridem_grains 1 sphere radius 1e-3 at 7e-3 5e-3 5e-3 spacing 5e-4 horizon 5.5e-4 density 1000")
peridem_catalogue_error(compute_grain_unknown_keyword "Illegal compute peridem/grain command: unknown keyword colour"
  -var bad "compute g all peridem/grain colour red")

# ---- create_peridem_bed
peridem_catalogue_commands(bed_no_box "create_peridem_bed command before simulation box is defined"
  -var c1 "${_bed} count 10")
peridem_catalogue_error(bed_count_value "Illegal create_peridem_bed command: count needs 1 value"
  -var bad "${_bed} count")
peridem_catalogue_error(bed_count_zero "create_peridem_bed: count must be an integer from 1 to 2147483647, not 0"
  -var bad "${_bed} count 0")
peridem_catalogue_error(bed_seed_zero "create_peridem_bed: seed must be > 0, got 0"
  -var bad "${_bed} count 10 seed 0")
peridem_catalogue_error(bed_box_inverted "create_peridem_bed: box 1e-3 0 is empty or inverted"
  -var bad "${_bed} count 10 box 1e-3 0 0 1e-3 0 1e-3")
peridem_catalogue_error(bed_contact_radius_negative "create_peridem_bed: contact_radius must be >= 0, got -1"
  -var bad "${_bed} count 10 contact_radius -1")
peridem_catalogue_error(bed_perturb_negative "create_peridem_bed: perturb must be >= 0, got -0.5"
  -var bad "${_bed} count 10 perturb -0.5")
peridem_catalogue_error(bed_label_proportion "create_peridem_bed: proportion of label disk must be > 0, got 0"
  -var bad "${_bed} count 10 labels disk 0")
peridem_catalogue_error(bed_labels_empty "Illegal create_peridem_bed command: labels needs NAME PROPORTION pairs"
  -var bad "${_bed} count 10 labels")
peridem_catalogue_error(bed_no_count "create_peridem_bed: no number of disks given \\(use count N\\)"
  -var bad "${_bed} radius uniform 1e-4 2e-4 seed 1")
peridem_catalogue_error(bed_no_radius "create_peridem_bed: no radius distribution given \\(use radius ...\\)"
  -var bad "${_bed} count 10 seed 1")

# ---- create_peridem_grains
peridem_catalogue_commands(grains_no_box "create_peridem_grains command before simulation box is defined"
  -var c1 "create_peridem_grains 1 sphere")
peridem_catalogue_commands(grains_atomic "create_peridem_grains requires atom style peridem"
  ${_atomic} -var c4 "create_peridem_grains 1 sphere")
peridem_catalogue_commands(grains_triclinic "create_peridem_grains does not support triclinic boxes"
  -var c1 "atom_style peridem" -var c2 "region box prism 0 1 0 1 0 1 0.1 0 0" -var c3 "create_box 1 box"
  -var c4 "create_peridem_grains 1 sphere")
peridem_catalogue_error(grains_value_missing "Illegal create_peridem_grains command: spacing needs 1 value"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 spacing")
peridem_catalogue_error(grains_rotate_seed_zero "create_peridem_grains: rotate random seed must be > 0"
  -var bad "${_sphere} rotate random 0")
peridem_catalogue_error(grains_pruning_unknown "create_peridem_grains: unknown pruning 'maybe' \\(use extended, exact or off\\)"
  -var bad "${_sphere} pruning maybe")
peridem_catalogue_error(grains_radii_and_at "create_peridem_grains: a positions file with radii cannot be mixed with at or other positions"
  -var bad "${_sphere} positions ${_cat}/pos_radii.txt")
peridem_catalogue_error(grains_label_without_column "create_peridem_grains: label disk needs a positions file with a label column"
  -var bad "${_sphere} label disk")
peridem_catalogue_error(grains_scale_with_radii "create_peridem_grains: scale cannot be used with a positions file that gives radii"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 positions ${_cat}/pos_radii.txt scale 2 spacing 5e-4 horizon 1e-3 density 1000")
peridem_catalogue_error(grains_rotate_with_angles "create_peridem_grains: rotate cannot be used with a positions file that gives angles"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 positions ${_cat}/pos_angles.txt rotate 30 spacing 5e-4 horizon 1e-3 density 1000")
peridem_catalogue2d(grains_no_bond_types "create_peridem_grains: the box has no bond types; set bond/types in create_box"
  -var box_cmd "create_box 2 box" -var bad "${_disk}")
peridem_catalogue_error(grains_bond_type_range "create_peridem_grains: bond/type must be an integer from 1 to 2, not 3"
  -var bad "${_sphere} bond/type 3")
# types are ints: 2^32 + 1 and 2^32 + 2 would wrap to the valid types 1 and 2
peridem_catalogue_error(grains_wrap_type "create_peridem_grains: atom type must be an integer from 1 to 2, not 4294967297"
  -var bad "create_peridem_grains 4294967297 sphere radius 1e-3 at 5e-3 5e-3 5e-3 spacing 5e-4 horizon 1e-3 density 1000")
peridem_catalogue_error(grains_wrap_bond_type "create_peridem_grains: bond/type must be an integer from 1 to 2, not 4294967298"
  -var bad "${_sphere} bond/type 4294967298")
peridem_catalogue_error(grains_zero_type "create_peridem_grains: atom type must be an integer from 1 to 2, not 0"
  -var bad "create_peridem_grains 0 sphere radius 1e-3 at 5e-3 5e-3 5e-3 spacing 5e-4 horizon 1e-3 density 1000")
peridem_catalogue_error(grains_negative_bond_type "create_peridem_grains: bond/type must be an integer from 1 to 2, not -4294967295"
  -var bad "${_sphere} bond/type -4294967295")
peridem_catalogue_error(grains_gmsh_spacing "create_peridem_grains: gmsh grains take the spacing from the mesh"
  -var bad "create_peridem_grains 1 gmsh none.msh spacing 1e-4 at 5e-3 5e-3 5e-3 horizon 1e-3 density 1000")
peridem_catalogue_error(grains_boundary_not_gmsh "create_peridem_grains: boundary is only used with gmsh meshes"
  -var bad "${_sphere} boundary outer")
peridem_catalogue2d(grains_2d_z "create_peridem_grains: a 2D grain needs z = 0 in at, got 0.0001"
  -var bad "create_peridem_grains 1 disk radius 1e-3 at 0 0 1e-4 spacing 2.5e-4 horizon 7.5e-4 density 1000")
peridem_catalogue_error(grains_gmsh_3d "create_peridem_grains: gmsh meshes are 2D only"
  -var bad "create_peridem_grains 1 gmsh none.msh extrude 1e-3 at 5e-3 5e-3 5e-3 horizon 1e-3 density 1000")
peridem_catalogue_error(grains_positions_ragged "create_peridem_grains: positions file .*pos_ragged.txt:3: expected 'x y z \\[radius \\[angle \\[label\\]\\]\\]' with the same columns on every line"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 positions ${_cat}/pos_ragged.txt spacing 5e-4 horizon 1e-3 density 1000")
peridem_catalogue_error(grains_positions_word "create_peridem_grains: positions file .*pos_word.txt:2: 'five' is not a number"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 positions ${_cat}/pos_word.txt spacing 5e-4 horizon 1e-3 density 1000")
peridem_catalogue_error(grains_positions_radius_zero "create_peridem_grains: positions file .*pos_radius0.txt:2: radius 0 must be > 0"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 positions ${_cat}/pos_radius0.txt spacing 5e-4 horizon 1e-3 density 1000")

# ---- cut_peridem_bonds
peridem_catalogue_commands(cut_no_box "cut_peridem_bonds command before simulation box is defined"
  -var c1 "cut_peridem_bonds all segment 0 0 1 1")
peridem_catalogue_commands(cut_atomic "cut_peridem_bonds requires atom style peridem"
  ${_atomic} -var c4 "cut_peridem_bonds all segment 0 0 1 1")

# ---- fix peridem/bonds: damage carried by a data file (per-atom properties)
peridem_catalogue_error(fix_bonds_nbroken_alone "fix PERIDEM_BONDS: per-atom property peridem_nbroken needs peridem_zbroken"
  -var pre "fix p all property/atom d_peridem_nbroken")
peridem_catalogue_error(fix_bonds_negative_count "fix PERIDEM_BONDS: invalid damage of atom 1 in the data file: broken count -1 and Z 0"
  -var pre "fix p all property/atom d_peridem_nbroken d_peridem_zbroken" -var pre2 "set atom 1 d_peridem_nbroken -1")

# ---- fix peridem/lps: the weighted volume m of bond_style peridem/lps
set(_lps_pre -var pre2 "bond_style peridem/lps" -var pre3 "bond_coeff * K 1e9 G 0.5e9 Gc 1000 horizon 2.0001e-3")
peridem_catalogue_error(fix_lps_wvolume_int "fix PERIDEM_LPS: per-atom property peridem_wvolume must be a d_ vector"
  -var pre "fix p all property/atom d_peridem_nbroken d_peridem_zbroken i_peridem_wvolume" ${_lps_pre})
peridem_catalogue_error(fix_lps_not_lps "bond_style peridem/lps: fix PERIDEM_LPS is not a fix peridem/lps"
  -var pre "fix PERIDEM_LPS all nve" ${_lps_pre})
peridem_catalogue_error(fix_lps_args "Illegal fix peridem/lps command: it takes no arguments"
  -var bad "fix l all peridem/lps extra")
peridem_catalogue_error(fix_lps_user "fix peridem/lps is created by bond_style peridem/lps \\(as fix PERIDEM_LPS\\); do not define it yourself \\(fix mine\\)"
  -var bad "fix mine all peridem/lps")

# ---- fix peridem/wall
peridem_catalogue_commands(wall_atomic "fix peridem/wall needs per-atom volumes and masses \\(atom_style peridem\\)"
  ${_atomic} -var c4 "fix w all peridem/wall xlo 0 Kn 1e23 Rc 1e-4")
peridem_catalogue2d(wall_shear_z_2d "fix peridem/wall: shear velocity of wall ylo has a z component in 2D"
  -var bad "fix w all peridem/wall ylo -4e-3 shear ylo 1 0 1 Kn 1e23 Rc 1e-4")
# grain 1 at 1e5 m/s crosses the wall at x = 0.85 mm in one step of 10 ns
peridem_catalogue_error(wall_node_beyond "fix peridem/wall: atom [0-9]+ is .* beyond wall xlo \\(more than Rc = 0.0001\\): it crossed the wall"
  -var pre "velocity all set -1e5 0 0" -var pre2 "fix n all nve"
  -var pre3 "fix w all peridem/wall xlo 0.85e-3 Kn 1e23 Rc 1e-4" -var bad "run 1")
# a wall through a grain names each grain / wall pair once (issue 27: "grain 1 / wall xlo" x 5)
peridem_catalogue_error(wall_through_grain_named_once "fix peridem/wall w: 18 nodes lie more than Rc = 0.0001 beyond a wall at the first step \\(e.g. grain 1 / wall xlo\\): a wall placed through a grain"
  -var bad "fix w all peridem/wall xlo 2.5e-3 Kn 1e23 Rc 1e-4")
peridem_catalogue_warning(wall_lost_warn "fix peridem/wall w: [0-9]+ node-steps with a node completely beyond a wall in the last run"
  -var bad "fix w all peridem/wall xlo 2.5e-3 Kn 1e23 Rc 1e-4 lost warn")

# ---- contact (pair_style peridem/contact and its parser)
peridem_catalogue_error(contact_material_no_horizon "pair_coeff: material NOHORIZON of .*no_horizon.peridem has no horizon: add horizon to the file or the command"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff * * material ${_cat}/no_horizon.peridem NOHORIZON Rc 1e-3")
peridem_catalogue_error(pair_coeff_too_few "pair_coeff: pair_style peridem/contact needs two atom types and contact keywords"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff 1 1")
peridem_catalogue_error(pair_coeff_no_pairs "pair_coeff: no type pairs in 2\\*2 1\\*1"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff 2*2 1*1 Kn 1e23 Rc 1e-3")
peridem_catalogue2d(pair_mix_kn_form "pair_style peridem/contact: types 1 and 2 use different Kn_form"
  -var pre "pair_style peridem/contact" -var pre2 "pair_coeff 1 1 Kn 1e23 Rc 1e-3 Kn_form eps5"
  -var bad "pair_coeff 2 2 Kn 1e23 Rc 1e-3 Kn_form eps4")

# ---- two ranks: a bond partner beyond the ghost cutoff (bond_style zero sets no
# communication cutoff; the box is cut at x = 1.5 mm, through grain 1's bonds)
set(_np2 -var c1 "units si" -var c2 "atom_style peridem"
  -var c3 "processors 2 1 1" -var c4 "neighbor 1e-5 bin" -var c5 "bond_style zero"
  -var c6 "read_data ${_fs}/data.peridem" -var c7 "bond_coeff *" -var c8 "balance 0.9 x 0.318")
function(peridem_catalogue_np2 name regex)
  add_test(NAME error.catalogue_${name}_np2
    COMMAND ${PERIDEM_RUN}/expect_error.sh "${regex}" ${PERIDEM_RUN}/mpirun.sh 2
            $<TARGET_FILE:lmp_peridem> -in ${_cat}/commands.in -log none -echo screen ${ARGN}
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endfunction()
peridem_catalogue_np2(cut_partner_beyond_ghosts "cut_peridem_bonds: bond partner [0-9]+ of atom [0-9]+ is beyond the ghost cutoff of proc [01]"
  ${_np2} -var c9 "cut_peridem_bonds all segment 0 0 1 1")
peridem_catalogue_np2(fragments_partner_missing "compute peridem/fragments: atom [0-9]+ bonded to atom [0-9]+ is missing on proc [01]"
  ${_np2} -var c9 "include ${_cat}/fragments_np2.in")

# ---- issue 27, item 8: bond_style peridem/lps plane strain|stress is a 2d model (it was
# silently ignored in 3d); the bond_coeff log line names the plane mode
peridem_catalogue_error(lps_plane_stress_3d "bond_style peridem/lps: plane stress is a 2d model; a 3d simulation always uses the 3d constants"
  -var pre "bond_style peridem/lps plane stress" -var pre2 "bond_coeff * K 1e9 G 0.5e9 Gc 1000 horizon 2.0001e-3")
add_test(NAME lps.log_names_plane_2d
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "bond_style peridem/lps type \\*: .*influence conic, plane stress$"
          $<TARGET_FILE:lmp_peridem> -in ${_cat}/base2d.in -log none -echo screen
          -var pre "bond_style peridem/lps plane stress" -var bad "bond_coeff * K 1e9 G 0.5e9 Gc 1000 horizon 6e-4")
add_test(NAME lps.log_names_plane_3d
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "bond_style peridem/lps type \\*: .*influence conic, 3d$"
          $<TARGET_FILE:lmp_peridem> -in ${_cat}/base.in -log none -echo screen
          -var input_dir ${_fs} -var pre "bond_style peridem/lps" -var pre2 "bond_coeff * K 1e9 G 0.5e9 Gc 1000 horizon 2.0001e-3")

# compute peridem/stress and compute peridem/contacts
peridem_catalogue_commands(compute_stress_atomic "compute peridem/stress requires per-atom masses"
  ${_atomic} -var c4 "compute s all peridem/stress volume 1")
peridem_catalogue_error(compute_stress_no_volume "Illegal compute peridem/stress command: expected volume V, v_name or box"
  -var bad "compute s all peridem/stress")
peridem_catalogue_error(compute_stress_value_missing "Illegal compute peridem/stress command: volume needs a value"
  -var bad "compute s all peridem/stress volume")
peridem_catalogue_error(compute_stress_unknown_keyword "Illegal compute peridem/stress command: unknown keyword colour"
  -var bad "compute s all peridem/stress colour 1")
peridem_catalogue_error(compute_stress_negative_volume "Illegal compute peridem/stress command: volume -1 must be positive"
  -var bad "compute s all peridem/stress volume -1")
peridem_catalogue_error(compute_stress_nan_volume "compute peridem/stress: volume must be a finite number, not nan"
  -var bad "compute s all peridem/stress volume nan")
peridem_catalogue_error(compute_stress_no_variable "compute peridem/stress: variable nope does not exist"
  -var bad "compute s all peridem/stress volume v_nope")
peridem_catalogue_error(compute_stress_atom_variable "compute peridem/stress: variable a is not equal-style"
  -var pre "variable a atom x" -var bad "compute s all peridem/stress volume v_a")
peridem_catalogue_error(compute_stress_variable_volume_zero "compute peridem/stress: the volume \\(0\\) must be positive"
  -var pre "variable V equal 0" -var pre2 "compute s all peridem/stress volume v_V"
  -var bad "thermo_style custom step c_s[2]")
peridem_catalogue_error(compute_stress_wall_without_virial "compute peridem/stress: fix w \\(peridem/wall\\) tallies no virial: add 'fix_modify w virial yes'"
  -var pre "fix w all peridem/wall xlo -5e-3 Kn 1e23 Rc 0.9e-3" -var bad "compute s all peridem/stress volume 1")
peridem_catalogue_error(compute_contacts_arguments "Illegal compute peridem/contacts command: it takes no arguments after the style"
  -var bad "compute c all peridem/contacts 1")
peridem_catalogue_commands(compute_contacts_atomic "compute peridem/contacts requires atom style peridem"
  ${_atomic} -var c4 "compute c all peridem/contacts")
peridem_catalogue_error(compute_contacts_no_pair "compute peridem/contacts needs pair_style peridem/contact"
  -var bad "compute c all peridem/contacts")
