/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

#include "lammps_fixture.h"

#include "input.h"
#include "lammps.h"
#include "register_driver.h"

#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <fstream>
#include <mpi.h>
#include <sstream>

using namespace LAMMPS_NS;

LAMMPS *make_lammps(const std::vector<std::string> &extra_args, bool screen)
{
  std::vector<std::string> args = {"lammps_test", "-log", "none", "-echo", "none"};
  if (!screen && !std::getenv("PERIDEM_TEST_VERBOSE")) {
    args.emplace_back("-screen");
    args.emplace_back("none");
  }
  args.insert(args.end(), extra_args.begin(), extra_args.end());
  std::vector<char *> argv;
  for (auto &a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  auto *lmp = new LAMMPS(static_cast<int>(args.size()), argv.data(), MPI_COMM_WORLD);
  peridem_register(lmp);
  return lmp;
}

void write_text_file(const std::string &path, const std::string &text)
{
  std::ofstream out(path);
  out << text;
}

void LammpsTest::SetUp()
{
  const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
  // rank 0's process ID in the name: ctest -j runs the same test program on 2, 3 and 4 ranks
  // at once (mpiN.*), and one run's TearDown removed the folder another was reading from
  // (mpi4.compute_peridem_fragments failed that way, 1 run in 10, session 6)
  long pid = static_cast<long>(getpid());
  MPI_Bcast(&pid, 1, MPI_LONG, 0, MPI_COMM_WORLD);
  scratch_dir =
      (std::filesystem::temp_directory_path() / (std::string("peridem_") + info->test_suite_name() +
                                                 "_" + info->name() + "_" + std::to_string(pid)))
          .string() +
      "/";
  // one rank makes the directory: on several ranks remove_all races
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (me == 0) {
    std::filesystem::remove_all(scratch_dir);
    std::filesystem::create_directories(scratch_dir);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  lmp = make_lammps();
}

void LammpsTest::TearDown()
{
  delete lmp;
  lmp = nullptr;
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Barrier(MPI_COMM_WORLD);
  std::error_code ec;
  if (me == 0) std::filesystem::remove_all(scratch_dir, ec);
}

void LammpsTest::command(const std::string &line)
{
  size_t start = 0;
  while (start <= line.size()) {
    size_t end = line.find('\n', start);
    if (end == std::string::npos) end = line.size();
    const std::string one = line.substr(start, end - start);
    if (one.find_first_not_of(" \t") != std::string::npos) lmp->input->one(one);
    start = end + 1;
  }
}

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  // death tests re-run the test binary, which then has its own MPI_Init
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const int rc = RUN_ALL_TESTS();
  MPI_Finalize();
  return rc;
}

std::map<long, std::array<double, 2>> read_dump_pairs(const std::string &path, long step)
{
  std::map<long, std::array<double, 2>> out;
  std::ifstream in(path);
  std::string line;
  long now = -1;
  bool atoms = false;
  while (std::getline(in, line)) {
    if (line.rfind("ITEM:", 0) == 0) {
      atoms = line.rfind("ITEM: ATOMS", 0) == 0;
      if (line.rfind("ITEM: TIMESTEP", 0) == 0 && std::getline(in, line)) now = std::stol(line);
    } else if (atoms && now == step) {
      std::istringstream ss(line);
      long id;
      double a, b;
      if (ss >> id >> a >> b) out[id] = {a, b};
    }
  }
  return out;
}
