# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# create_peridem_grains / cut_peridem_bonds

# examples: the same nodes, volumes, grain IDs and bonds on 1 and 2 ranks
peridem_add_example_test(grains_convex grains-convex in.grains_convex 1 2)
peridem_add_example_test(grains_concave grains-concave in.grains_concave 1 2)
peridem_add_example_test(grains_notched grains-notched in.grains_notched 1 2)
peridem_add_example_test(grains_3d grains-3d in.grains_3d 1 2)

# bad input: clear errors naming the command and the bad value
set(_g ${_in}/grains)
set(_ok "spacing 0.1 horizon 0.3 density 1 at 0 0 0")
peridem_add_error_test(grains_self_intersecting ${_g}/grain_box.in
  "create_peridem_grains: .*self_intersecting.poly.*self-intersecting"
  -var grain "file ${_g}/self_intersecting.poly ${_ok}")
peridem_add_error_test(grains_hole_outside ${_g}/grain_box.in
  "create_peridem_grains: .*hole.* is not strictly inside the outer ring"
  -var grain "file ${_g}/hole_outside.poly ${_ok}")
peridem_add_error_test(grains_spacing_too_large ${_g}/grain_box.in
  "create_peridem_grains: node spacing 1 is larger than the grain"
  -var grain "disk radius 0.3 spacing 1 horizon 3 density 1 at 0 0 0")
peridem_add_error_test(grains_horizon_below_spacing ${_g}/grain_box.in
  "create_peridem_grains: horizon 0.05 is smaller than the node spacing 0.1"
  -var grain "disk radius 1 spacing 0.1 horizon 0.05 density 1 at 0 0 0")
peridem_add_error_test(grains_unknown_shape ${_g}/grain_box.in
  "create_peridem_grains: unknown shape 'blob'"
  -var grain "blob radius 1 ${_ok}")
peridem_add_error_test(grains_missing_file ${_g}/grain_box.in
  "create_peridem_grains: cannot open polygon file 'no_such.poly'"
  -var grain "file no_such.poly ${_ok}")
peridem_add_error_test(grains_missing_mesh ${_g}/grain_box.in
  "create_peridem_grains: cannot open Gmsh file 'no_such.msh'"
  -var grain "gmsh no_such.msh horizon 0.3 density 1 at 0 0 0")
peridem_add_error_test(grains_overlap ${_g}/grain_box.in
  "create_peridem_grains: grain 1 at \\(1.5, 0, 0\\) overlaps existing atoms"
  -var before "create_peridem_grains 1 disk radius 1 ${_ok}"
  -var grain "disk radius 1 spacing 0.1 horizon 0.3 density 1 at 1.5 0 0 overlap 0.05")
peridem_add_error_test(grains_bonds_per_atom ${_g}/grain_box.in
  "create_peridem_grains: a grain node needs 14 bonds but atoms can hold 4; set extra/bond/per/atom"
  -var nbond 4 -var grain "disk radius 1 ${_ok}")
peridem_add_error_test(grains_unknown_keyword ${_g}/grain_box.in
  "create_peridem_grains: unknown keyword or shape parameter 'radius2'"
  -var grain "disk radius2 1 ${_ok}")
peridem_add_error_test(grains_negative_radius ${_g}/grain_box.in
  "create_peridem_grains: .*shape parameter radius must be positive, not -1"
  -var grain "disk radius -1 ${_ok}")
peridem_add_error_test(grains_no_density ${_g}/grain_box.in
  "create_peridem_grains: no density"
  -var grain "disk spacing 0.1 horizon 0.3 at 0 0 0")
peridem_add_error_test(grains_3d_shape_in_2d ${_g}/grain_box.in
  "create_peridem_grains: shape sphere needs a 3D box"
  -var grain "sphere radius 1 ${_ok}")
peridem_add_error_test(grains_outside_box ${_g}/grain_box.in
  "create_peridem_grains: .* grain nodes are outside the simulation box"
  -var before "change_box all boundary f f p"
  -var grain "disk radius 1 spacing 0.1 horizon 0.3 density 1 at 4.5 0 0")
peridem_add_error_test(cut_bonds_bad_segment ${_g}/grain_box.in
  "cut_peridem_bonds: segment 1 1 1 1 has zero length"
  -var before "create_peridem_grains 1 disk radius 1 ${_ok}"
  -var grain "disk radius 1 spacing 0.1 horizon 0.3 density 1 at 3 3 0"
  -var after "cut_peridem_bonds all segment 1 1 1 1")
# rotation axis: not zero, not with rotate random, about z only in 2d
peridem_add_error_test(grains_axis_zero ${_g}/grain_box.in
  "create_peridem_grains: rotation axis must not be zero"
  -var grain "disk radius 1 ${_ok} rotate 30 axis 0 0 0")
peridem_add_error_test(grains_axis_random ${_g}/grain_box.in
  "create_peridem_grains: axis applies to a fixed rotate angle, not to rotate random"
  -var grain "disk radius 1 ${_ok} rotate random 5 axis 0 0 1")
peridem_add_error_test(grains_axis_2d ${_g}/grain_box.in
  "create_peridem_grains: a 2d grain rotates about z only; axis 1 0 0 needs dimension 3"
  -var grain "disk radius 1 ${_ok} rotate 30 axis 1 0 0")

# perturbed_disk: each grain of one command its own outline (seed S + k; Bhattacharya & Lipton
# 2023, §7.2), or all the seed-S outline with outlines same; outlines on another shape is refused
foreach(_o each same)
  add_test(NAME grains_perturbed_outlines_${_o}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh $<TARGET_FILE:lmp_peridem>
            -in ${_g}/perturbed_outlines.in -log none -echo none -var outlines ${_o})
endforeach()
peridem_add_error_test(grains_outlines_not_perturbed ${_g}/grain_box.in
  "create_peridem_grains: outlines applies to perturbed_disk grains, not disk"
  -var grain "disk radius 1 ${_ok} outlines same")
# fit (enclosing | radius) sizes grains placed from a bed file; radius needs a radius parameter
peridem_add_error_test(grains_fit_without_bed ${_g}/grain_box.in
  "create_peridem_grains: fit applies to grains placed from a bed file \\(positions FILE with radii\\)"
  -var grain "disk radius 1 ${_ok} fit radius")
peridem_add_error_test(grains_fit_radius_square ${_g}/grain_box.in
  "create_peridem_grains: fit radius needs a built-in 2d shape with a radius parameter \\(disk, polygon, hexagon, plus, ring, perturbed_disk\\), not square"
  -var grain "square ${_ok} fit radius")

# nodes outline: 2d lattice grains only, with their exact clipped volumes; the smallest node
# distance in the summary (an aligned square keeps its spacing, a disk's outline nodes come closer)
peridem_add_error_test(grains_outline_gmsh ${_g}/grain_box.in
  "create_peridem_grains: nodes outline is for lattice grains; gmsh nodes are where the mesh puts them"
  -var grain "gmsh none.msh horizon 0.3 density 1 at 0 0 0 nodes outline")
peridem_add_error_test(grains_outline_volume_cell ${_g}/grain_box.in
  "create_peridem_grains: volume cell cannot be used with nodes outline"
  -var grain "disk radius 1 ${_ok} nodes outline volume cell")
peridem_add_error_test(grains_nodes_unknown ${_g}/grain_box.in
  "create_peridem_grains: nodes must be lattice or outline, not mesh"
  -var grain "disk radius 1 ${_ok} nodes mesh")
foreach(_case "square_lattice;square side 1.4;lattice;0.1" "square_outline;square side 1.4;outline;0.1"
              "disk_outline;disk radius 1;outline;0.080906131")
  list(GET _case 0 _name)
  list(GET _case 1 _shape)
  list(GET _case 2 _nodes)
  list(GET _case 3 _dist)
  add_test(NAME grains_nodes_report_${_name}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh
            --regex "smallest node distance in a grain: ${_dist} \\(nodes ${_nodes}\\)"
            $<TARGET_FILE:lmp_peridem> -in ${_g}/grain_box.in -log none -echo none
            -var grain "${_shape} ${_ok} nodes ${_nodes}")
endforeach()

