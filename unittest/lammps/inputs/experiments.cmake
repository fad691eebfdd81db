# The grain-shape paper's fracture experiments as examples (issue 14):
# examples/notch-fracture (§6.4), examples/kalthoff-winkler (§6.2),
# examples/plus-collision (§6.3).

# a notch or cut along a node row separates the grain (it cut nothing while
# nodes on the line counted on neither side); 1 and 2 ranks
foreach(_np 1 2)
  add_test(NAME notch_node_row_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh ${PERIDEM_RUN}/mpirun.sh ${_np} $<TARGET_FILE:lmp_peridem>
            -in ${_in}/notch_node_row.in -log none -echo none
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endforeach()
