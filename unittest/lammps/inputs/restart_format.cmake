# restart files of an older PERIDEM format are refused with a clear message
# (restart_format/make_old.in wrote them with the build of commit 970bea6)
peridem_add_error_test(restart_old_bond ${_in}/restart_format/read_old.in
  "bond_style peridem: the restart file was written by an older PERIDEM"
  -var file ${_in}/restart_format/old_bond.restart)
peridem_add_error_test(restart_old_pair ${_in}/restart_format/read_old.in
  "pair_style peridem/contact: the restart file was written by an older PERIDEM"
  -var file ${_in}/restart_format/old_pair.restart)
