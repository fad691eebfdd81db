/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// A LAMMPS instance with the PERIDEM styles for GoogleTest, driven through
// the input interface; screen and log output off unless PERIDEM_TEST_VERBOSE.
#ifndef PERIDEM_TEST_LAMMPS_FIXTURE_H
#define PERIDEM_TEST_LAMMPS_FIXTURE_H

#include "gtest/gtest.h"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

class LammpsTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  // run one input line (or several, separated by newlines)
  void command(const std::string &line);
  // a fresh scratch directory for this test, with a trailing '/'
  std::string scratch() const { return scratch_dir; }

  LAMMPS_NS::LAMMPS *lmp = nullptr;

 private:
  std::string scratch_dir;
};

// Create a LAMMPS instance with the PERIDEM styles and the given extra
// command-line arguments; screen output goes to stdout only if `screen`.
LAMMPS_NS::LAMMPS *make_lammps(const std::vector<std::string> &extra_args = {},
                               bool screen = false);

// Write text to a file (test fixtures).
void write_text_file(const std::string &path, const std::string &text);

// The per-atom lines "id a b" of the snapshot at `step` of a LAMMPS text dump (dump custom
// ... id a b, e.g. id fx fy), by atom ID.
std::map<long, std::array<double, 2>> read_dump_pairs(const std::string &path, long step);

#endif
