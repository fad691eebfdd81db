# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Bad-input catalogue (doc/errors.md): one bad command on a valid two-grain system
# (catalogue/base.in reads unittest/force-styles/tests/data.peridem); each test checks
# the exit code and the stable part of the message (command, keyword, value).
function(peridem_catalogue_error name regex)
  peridem_add_error_test(catalogue_${name} ${_in}/catalogue/base.in "${regex}"
    -var input_dir ${PROJECT_SOURCE_DIR}/unittest/force-styles/tests ${ARGN})
endfunction()
peridem_catalogue_error(nan_bond_E "bond_coeff: E \\(Young's modulus\\) must be a finite number, not nan"
  -var bad "bond_coeff 1 E nan Gc 1000 horizon 2e-3")
peridem_catalogue_error(inf_bond_Gc "bond_coeff: Gc \\(fracture energy\\) must be a finite number, not inf"
  -var bad "bond_coeff 1 E 1e9 Gc inf horizon 2e-3")
peridem_catalogue_error(word_bond_horizon "bond_coeff: horizon must be a number, not 'two'"
  -var bad "bond_coeff 1 E 1e9 Gc 1000 horizon two")
# numbers are what LAMMPS's utils::is_double accepts: strtod's hexadecimal floats are refused
peridem_catalogue_error(two_points_bond_E "bond_coeff: E \\(Young's modulus\\) must be a number, not '1.2.3'"
  -var bad "bond_coeff 1 E 1.2.3 Gc 1000 horizon 2e-3")
peridem_catalogue_error(point_wall_pos "fix peridem/wall: wall xlo must be a number, not '.'"
  -var bad "fix w all peridem/wall xlo . Kn 1e23 Rc 0.9e-3")
peridem_catalogue_error(hex_bond_E "bond_coeff: E \\(Young's modulus\\) must be a number, not '0x1p30'"
  -var bad "bond_coeff 1 E 0x1p30 Gc 1000 horizon 2e-3")
peridem_catalogue_error(nan_pair_Kn "pair_coeff: Kn must be a finite number, not nan"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff * * Kn nan Rc 1e-3")
peridem_catalogue_error(inf_pair_Rc "pair_coeff: Rc \\(contact radius\\) must be a finite number, not -inf"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff * * Kn 1e23 Rc -inf")
peridem_catalogue_error(nan_wall_pos "fix peridem/wall: wall xlo must be a finite number, not nan"
  -var bad "fix w all peridem/wall xlo nan Kn 1e23 Rc 0.9e-3")
peridem_catalogue_error(inf_wall_velocity "fix peridem/wall: velocity must be a finite number, not inf"
  -var bad "fix w all peridem/wall xlo 0 velocity xlo inf Kn 1e23 Rc 0.9e-3")
peridem_catalogue_error(nan_wall_servo "fix peridem/wall: servo pressure must be a finite number, not nan"
  -var bad "fix w all peridem/wall xlo 0 servo xlo nan 1 1 Kn 1e23 Rc 0.9e-3")
peridem_catalogue_error(nan_wall_shear "fix peridem/wall: shear must be a finite number, not nan"
  -var bad "fix w all peridem/wall ylo 0 shear ylo nan 0 0 Kn 1e23 Rc 0.9e-3")
peridem_catalogue_error(bond_style_value_missing "bond_style peridem: keyword break needs a value"
  -var bad "bond_style peridem break")
peridem_catalogue_error(bond_style_unknown "bond_style peridem: unknown keyword stiff"
  -var bad "bond_style peridem stiff yes")
peridem_catalogue_error(bond_coeff_no_params "bond_coeff: bond_style peridem needs a bond type and its parameters"
  -var bad "bond_coeff 1")
peridem_catalogue_error(bond_coeff_value_missing "bond_coeff: keyword E needs a value"
  -var bad "bond_coeff 1 E")
peridem_catalogue_error(bond_coeff_material_args "bond_coeff: material needs a file name and a material name"
  -var bad "bond_coeff 1 material")
peridem_catalogue_error(bond_coeff_E_and_K "bond_coeff: give E or K, not both"
  -var bad "bond_coeff 1 E 1e9 K 1e9 Gc 1 horizon 2e-3")
peridem_catalogue_error(bond_coeff_Gc_and_s0 "bond_coeff: give Gc or s0, not both"
  -var bad "bond_coeff 1 material ${PROJECT_SOURCE_DIR}/potentials/peridem_M1.peridem M1 horizon 2e-3 Gc 1 s0 0.01")
peridem_catalogue_error(bond_coeff_c_without_s0 "bond_coeff: give both c and s0"
  -var bad "bond_coeff 1 c 1e20 horizon 2e-3")
peridem_catalogue_error(bond_coeff_Gc_with_s0 "bond_coeff: Gc does not go with c and s0 \\(s0 is given\\)"
  -var bad "bond_coeff 1 c 1e20 s0 0.01 Gc 1 horizon 2e-3")
peridem_catalogue_error(bond_vc_needs_spacing "bond_style peridem: volume_correction linear needs the node spacing of bond type 1: add spacing to its bond_coeff \\(or define a lattice\\)"
  -var pre "bond_style peridem volume_correction linear" -var bad "bond_coeff * E 1e9 Gc 1000 horizon 2.0001e-3")
peridem_catalogue_error(bond_fix_not_bonds "bond_style peridem: fix PERIDEM_BONDS is not a fix peridem/bonds"
  -var pre "fix PERIDEM_BONDS all nve")
peridem_catalogue_error(bond_fix_not_escapes "bond_style peridem: fix PERIDEM_ESCAPES is not a fix peridem/escapes"
  -var pre "fix PERIDEM_ESCAPES all nve")
peridem_catalogue_error(bond_fix_not_order "bond_style peridem: fix PERIDEM_ORDER is not a fix peridem/order"
  -var pre "fix PERIDEM_ORDER all nve")
peridem_catalogue_error(fix_escapes_args "Illegal fix peridem/escapes command: it takes no arguments"
  -var bad "fix e all peridem/escapes extra")
peridem_catalogue_error(fix_escapes_user "fix peridem/escapes is created by bond_style peridem \\(as fix PERIDEM_ESCAPES\\); do not define it yourself \\(fix mine\\)"
  -var bad "fix mine all peridem/escapes")
peridem_catalogue_error(fix_order_args "Illegal fix peridem/order command: it takes no arguments"
  -var bad "fix o all peridem/order extra")
peridem_catalogue_error(fix_order_user "fix peridem/order is created by bond_style peridem \\(as fix PERIDEM_ORDER\\); do not define it yourself \\(fix mine\\)"
  -var bad "fix mine all peridem/order")
peridem_catalogue_error(bond_micromodulus_unknown "bond_coeff: unknown micromodulus 'round' \\(use constant or conic\\)"
  -var bad "bond_coeff 1 E 1e9 Gc 1 horizon 2e-3 micromodulus round")
peridem_catalogue_error(lps_plane_value "bond_style peridem/lps: keyword plane needs a value"
  -var pre "bond_style peridem/lps plane")
peridem_catalogue_error(compute_bed_no_region "Illegal compute peridem/bed command: expected a region ID"
  -var bad "compute b all peridem/bed")
peridem_catalogue_error(compute_bed_unknown_keyword "Illegal compute peridem/bed command: unknown keyword colour"
  -var pre "region r2 block 0 1 0 1 0 1" -var bad "compute b all peridem/bed r2 colour red")
peridem_catalogue_error(compute_damage_args "Illegal compute peridem/damage command: unknown keyword extra"
  -var bad "compute d all peridem/damage extra")
peridem_catalogue_error(compute_damage_z_value "Illegal compute peridem/damage command: keyword z needs a value"
  -var bad "compute d all peridem/damage z")
peridem_catalogue_error(compute_damage_z_choice "compute peridem/damage: z must be stretch or displacement, not strain"
  -var bad "compute d all peridem/damage z strain")
peridem_catalogue_error(compute_dilation_args "Illegal compute peridem/dilation command: it takes no arguments"
  -var bad "compute d all peridem/dilation extra")
peridem_catalogue_error(compute_fragments_min "Illegal compute peridem/fragments command: min needs nodes N or volume V"
  -var bad "compute f all peridem/fragments min")
peridem_catalogue_error(compute_grain_unknown "Illegal compute peridem/grain command: colour needs a compute ID"
  -var bad "compute g all peridem/grain colour")
peridem_catalogue_error(cut_no_group "Illegal cut_peridem_bonds command: expected a group ID"
  -var bad "cut_peridem_bonds")
peridem_catalogue_error(cut_unknown_group "cut_peridem_bonds: cannot find group nogroup"
  -var bad "cut_peridem_bonds nogroup segment 0 0 1 1")
peridem_catalogue_error(cut_unknown_keyword "cut_peridem_bonds: unknown keyword 'line' \\(expected segment x1 y1 x2 y2\\)"
  -var bad "cut_peridem_bonds all line 0 0 1 1")
peridem_catalogue_error(cut_segment_values "cut_peridem_bonds: segment needs 4 values: x1 y1 x2 y2"
  -var bad "cut_peridem_bonds all segment 0 0 1")
peridem_catalogue_error(cut_no_segment "cut_peridem_bonds: no segment given"
  -var bad "cut_peridem_bonds all")
peridem_catalogue_error(fix_bonds_args "Illegal fix peridem/bonds command: it takes no arguments"
  -var bad "fix b all peridem/bonds extra")
peridem_catalogue_error(wall_twice "fix peridem/wall: wall xlo is given twice"
  -var bad "fix w all peridem/wall xlo 0 xlo 1e-4 Kn 1e23 Rc 0.9e-3")
peridem_catalogue_error(wall_velocity_and_servo "fix peridem/wall: wall xlo has a variable position or a velocity and a servo"
  -var bad "fix w all peridem/wall xlo 0 velocity xlo 1 servo xlo 1 1 1 Kn 1e23 Rc 0.9e-3")
peridem_catalogue_error(wall_servo_and_velocity "fix peridem/wall: wall xlo has a variable position or a servo and a velocity"
  -var bad "fix w all peridem/wall xlo 0 servo xlo 1 1 1 velocity xlo 1 Kn 1e23 Rc 0.9e-3")
peridem_catalogue_error(wall_servo_pressure "fix peridem/wall: servo pressure must be >= 0, not -1"
  -var bad "fix w all peridem/wall xlo 0 servo xlo -1 1 1 Kn 1e23 Rc 0.9e-3")
peridem_catalogue_error(wall_servo_vmax "fix peridem/wall: servo vmax must be > 0, not 0"
  -var bad "fix w all peridem/wall xlo 0 servo xlo 1 1 0 Kn 1e23 Rc 0.9e-3")
peridem_catalogue_error(wall_contact_word "fix peridem/wall: contact must be followed by pair, not wall"
  -var bad "fix w all peridem/wall xlo 0 contact wall")
peridem_catalogue_error(wall_none "fix peridem/wall: no wall given \\(xlo xhi ylo yhi zlo zhi\\)"
  -var bad "fix w all peridem/wall Kn 1e23 Rc 0.9e-3")
peridem_catalogue_error(wall_values_missing "fix peridem/wall: velocity needs 2 value\\(s\\)"
  -var bad "fix w all peridem/wall xlo 0 velocity xlo")
peridem_catalogue_error(contact_value_missing "pair_coeff: keyword Kn needs a value"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff * * Kn")
peridem_catalogue_error(contact_material_args "pair_coeff: material needs a file name and a material name"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff * * material")
peridem_catalogue_error(contact_damping_args "pair_coeff: damping needs none, nodal r_d, restitution eps_n C or centroid eps_n C"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff * * Kn 1e23 Rc 1e-3 damping")
peridem_catalogue_error(contact_damping_unknown "pair_coeff: damping must be none, nodal, restitution or centroid, not viscous"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff * * Kn 1e23 Rc 1e-3 damping viscous 1")
peridem_catalogue_error(contact_friction_args "pair_coeff: friction needs none, regularized mu or coulomb mu"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff * * Kn 1e23 Rc 1e-3 friction")
peridem_catalogue_error(contact_friction_unknown "pair_coeff: friction must be none, regularized or coulomb, not sticky"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff * * Kn 1e23 Rc 1e-3 friction sticky 1")
peridem_catalogue_error(contact_Rc_twice "pair_coeff: give exactly one of 'Rc value' and 'Rc_factor f' \\(with spacing h\\)"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff * * Kn 1e23 Rc 1e-3 Rc_factor 0.9 spacing 1e-3")
peridem_catalogue_error(pair_style_value_missing "pair_style peridem/contact: keyword self needs a value"
  -var bad "pair_style peridem/contact self")
peridem_catalogue_error(pair_style_unknown "pair_style peridem/contact: unknown keyword colour"
  -var bad "pair_style peridem/contact colour red")
peridem_catalogue_error(pair_coeff_not_mixed "pair_style peridem/contact: types 1 and 2 use different damping or friction laws: give pair_coeff 1 2 explicitly"
  -var pre "pair_style peridem/contact" -var pre2 "pair_coeff 1 1 Kn 1e23 Rc 1e-3 Kn_form eps5" -var bad "pair_coeff 2 2 Kn 1e23 Rc 1e-3 damping nodal 0.5")
peridem_catalogue_error(grains_no_args "Illegal create_peridem_grains command: expected atom type and shape"
  -var bad "create_peridem_grains")
peridem_catalogue_error(grains_bad_type "create_peridem_grains: atom type must be an integer from 1 to 2, not 7"
  -var bad "create_peridem_grains 7 sphere radius 1e-3 at 5e-3 5e-3 5e-3 spacing 5e-4 horizon 1e-3")
peridem_catalogue_error(grains_no_at "create_peridem_grains: no grain position given \\(use at x y z\\)"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 spacing 5e-4 horizon 1e-3")
peridem_catalogue_error(grains_no_spacing "create_peridem_grains: no node spacing given \\(use spacing h\\)"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 at 5e-3 5e-3 5e-3 horizon 1e-3 density 1000")
peridem_catalogue_error(grains_no_horizon "create_peridem_grains: no horizon: give horizon, or a material whose file sets it"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 at 5e-3 5e-3 5e-3 spacing 5e-4 density 1000")
peridem_catalogue_error(grains_negative_spacing "create_peridem_grains: spacing must be > 0, got -5e-4"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 at 5e-3 5e-3 5e-3 spacing -5e-4 horizon 1e-3")
peridem_catalogue_error(grains_volume_mode "create_peridem_grains: unknown volume mode 'approx' \\(use cell or exact\\)"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 at 5e-3 5e-3 5e-3 spacing 5e-4 horizon 1e-3 volume approx")
peridem_catalogue_error(grains_positions_missing "create_peridem_grains: cannot open positions file .?/nonexistent/positions\\.txt"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 positions /nonexistent/positions.txt spacing 5e-4 horizon 1e-3")
peridem_catalogue_error(grains_2d_shape_3d "create_peridem_grains: 2D shape disk in a 3D box needs extrude HEIGHT"
  -var bad "create_peridem_grains 1 disk at 5e-3 5e-3 5e-3 spacing 5e-4 horizon 1e-3 density 1000")
peridem_catalogue_error(grains_volume_exact_3d "create_peridem_grains: volume exact is 2D only \\(3D nodes have volume h\\^3\\)"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 at 5e-3 5e-3 5e-3 spacing 5e-4 horizon 1e-3 volume exact density 1000")
peridem_catalogue_error(grains_outline_3d "create_peridem_grains: nodes outline is 2d only, not sphere"
  -var bad "create_peridem_grains 1 sphere radius 1e-3 at 5e-3 5e-3 5e-3 spacing 5e-4 horizon 1e-3 density 1000 nodes outline")
peridem_catalogue_error(grains_outline_extrude "create_peridem_grains: nodes outline is 2d only, not extrude"
  -var bad "create_peridem_grains 1 disk radius 1e-3 extrude 1e-3 at 5e-3 5e-3 5e-3 spacing 5e-4 horizon 1e-3 density 1000 nodes outline")
peridem_catalogue_error(bed_no_output "Illegal create_peridem_bed command: expected an output file"
  -var bad "create_peridem_bed")
peridem_catalogue_error(bed_unknown_keyword "create_peridem_bed: unknown keyword 'colour'"
  -var bad "create_peridem_bed /tmp/bed.txt colour red")

# warnings: the run goes on (exit 0), prints the warning and no ERROR
function(peridem_catalogue_warning name regex)
  add_test(NAME warning.catalogue_${name}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "WARNING: ${regex}"
            $<TARGET_FILE:lmp_peridem> -in ${_in}/catalogue/base.in -log none -echo screen
            -var input_dir ${PROJECT_SOURCE_DIR}/unittest/force-styles/tests ${ARGN})
endfunction()
peridem_catalogue_warning(contact_Rc_above_horizon
  "pair_coeff: contact radius Rc = 0.003 is larger than the horizon 0.002"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff * * Kn 1e23 Rc 3e-3 horizon 2e-3")

# doc/errors.md lists every error call of src/ with its tests (which must exist)
find_program(PERIDEM_CATALOGUE_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH)
add_test(NAME error_catalogue
  COMMAND ${PERIDEM_CATALOGUE_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/check_error_catalogue.py
          --build ${CMAKE_BINARY_DIR})
peridem_catalogue_error(vhistory_not_vhistory "pair_style peridem/contact: fix PERIDEM_VHISTORY is not a fix peridem/vhistory"
  -var pre "comm_modify vel yes" -var pre2 "pair_style peridem/contact"
  -var pre3 "pair_coeff * * Kn 1e23 Rc 0.9e-3 damping nodal 0.5" -var bad "fix PERIDEM_VHISTORY all nve")
peridem_catalogue_error(vhistory_args "Illegal fix peridem/vhistory command: it takes no arguments"
  -var bad "fix h all peridem/vhistory extra")
peridem_catalogue_error(vhistory_user "fix peridem/vhistory is created by pair_style peridem/contact and fix peridem/wall \\(as fix PERIDEM_VHISTORY\\); do not define it yourself \\(fix mine\\)"
  -var bad "fix mine all peridem/vhistory")
