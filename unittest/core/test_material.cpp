/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Tests of material definitions and the *.peridem reader (src/peridem_material.h).
#include "peridem_material.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>
#include <fstream>
#include <string>

using namespace peridem;

namespace {

constexpr double kPi = 3.14159265358979323846;
const double kNone = std::nan("");

std::string potential(const std::string &file)
{
  return std::string(PERIDEM_SOURCE_DIR) + "/potentials/" + file;
}

// Writes `text` to a fresh file in a temporary directory and returns its path.
std::string write_fixture(const std::string &name, const std::string &text)
{
  // one folder per process: two test runs at once (two checkouts) must not share it;
  // removed when the program ends
  struct Folder {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("peridem_test_material_" + std::to_string(static_cast<long>(getpid())));
    ~Folder()
    {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Folder folder;
  const auto &dir = folder.path;
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

// Error message of reading a fixture ("" if it parsed).
std::string read_error(const std::string &name, const std::string &text)
{
  const std::string path = write_fixture(name, text);
  try {
    read_material_file(path);
  } catch (const ParameterError &e) {
    return e.what();
  }
  return "";
}

std::string elastic_error(double E, double nu, double K, double G)
{
  try {
    complete_elastic_constants(E, nu, K, G);
  } catch (const ParameterError &e) {
    return e.what();
  }
  return "";
}

#define EXPECT_CONTAINS(haystack, needle)                                                          \
  EXPECT_NE(std::string(haystack).find(needle), std::string::npos)                                 \
      << "message: '" << (haystack) << "' lacks '" << (needle) << "'"

} // namespace

// Shipped material M1 of Jha et al. 2021, Sec. 4.1 Table 1.
TEST(Material, ReadsShippedM1)
{
  const auto mf = read_material_file(potential("peridem_M1.peridem"));
  EXPECT_EQ(mf.units, "si");
  ASSERT_EQ(mf.materials.size(), 1u);
  const Material &m = mf.get("M1");
  EXPECT_DOUBLE_EQ(m.density, 1200.0);
  EXPECT_DOUBLE_EQ(m.elastic.K, 0.0216e9);
  EXPECT_NEAR(m.elastic.G / 0.01296e9, 1.0, 1e-12);
  EXPECT_NEAR(m.elastic.E / 0.0324e9, 1.0, 1e-12); // 9KG/(3K+G)
  EXPECT_NEAR(m.elastic.nu, 0.25, 1e-12);
  EXPECT_DOUBLE_EQ(m.G_c, 50.0);
  EXPECT_DOUBLE_EQ(m.horizon, 0.6e-3);
  EXPECT_EQ(m.micromodulus, Micromodulus::Conic);
  EXPECT_CONTAINS(m.origin, "peridem_M1.peridem:14");
  // Bond constants: 2D from E (plane stress, Bhattacharya & Lipton 2023, Table 1 conic), 3D from K
  // (90K/(pi eps^4)).
  const double eps = 0.6e-3;
  const auto b2 = material_bond_constants(m, 2);
  EXPECT_NEAR(b2.c / (36 * 0.0324e9 / (kPi * std::pow(eps, 3))), 1.0, 1e-12);
  EXPECT_NEAR(b2.s0 / std::sqrt(5 * kPi * 50 / (9 * 0.0324e9 * eps)), 1.0, 1e-12);
  const auto b3 = material_bond_constants(m, 3);
  EXPECT_NEAR(b3.c / (90 * 0.0216e9 / (kPi * std::pow(eps, 4))), 1.0, 1e-12);
  EXPECT_NEAR(b3.s0 / std::sqrt(2 * 50 / (3 * 0.0216e9 * eps)), 1.0, 1e-12);
  // Horizon override.
  const auto b3h = material_bond_constants(m, 3, 2 * eps);
  EXPECT_NEAR(b3h.c / b3.c, 1.0 / 16.0, 1e-12);
}

TEST(Material, ReadsShippedM2)
{
  const auto mf = read_material_file(potential("pmma_M2.peridem"));
  const Material &m = mf.get("M2");
  EXPECT_NEAR(m.elastic.E / 3e9, 1.0, 1e-12);
  EXPECT_NEAR(m.elastic.nu, 0.25, 1e-12);
  EXPECT_DOUBLE_EQ(m.G_c, 500.0);
  EXPECT_EQ(mf.find("M1"), nullptr);
  try {
    mf.get("M1");
    FAIL() << "no exception";
  } catch (const ParameterError &e) {
    EXPECT_CONTAINS(e.what(), "no material 'M1' (available: M2)");
  }
}

// Any two of E, nu, K, G give all four (3D isotropic), for all six pairs.
TEST(Material, ElasticConstantsFromAnyPair)
{
  const double E = 200e9, nu = 0.3, K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  const double v[4] = {E, nu, K, G};
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) {
      double in[4] = {kNone, kNone, kNone, kNone};
      in[a] = v[a];
      in[b] = v[b];
      const auto c = complete_elastic_constants(in[0], in[1], in[2], in[3]);
      EXPECT_TRUE(c.complete());
      EXPECT_NEAR(c.E / E, 1.0, 1e-12) << a << b;
      EXPECT_NEAR(c.nu / nu, 1.0, 1e-12) << a << b;
      EXPECT_NEAR(c.K / K, 1.0, 1e-12) << a << b;
      EXPECT_NEAR(c.G / G, 1.0, 1e-12) << a << b;
    }
  // All four consistent: accepted.
  EXPECT_NO_THROW(complete_elastic_constants(E, nu, K, G));
  // A single E or K (bond-based) stays partial.
  const auto onlyK = complete_elastic_constants(kNone, kNone, 5e9, kNone);
  EXPECT_FALSE(onlyK.complete());
  EXPECT_DOUBLE_EQ(onlyK.K, 5e9);
  EXPECT_TRUE(std::isnan(onlyK.E));
}

TEST(Material, ElasticConstantsRejected)
{
  EXPECT_CONTAINS(elastic_error(1e9, 0.5, kNone, kNone), "nu must lie in (-1, 0.5)");
  EXPECT_CONTAINS(elastic_error(1e9, -1.0, kNone, kNone), "nu must lie in (-1, 0.5)");
  EXPECT_CONTAINS(elastic_error(1e9, 0.25, 5e9, kNone), "inconsistent elastic constants: K");
  EXPECT_CONTAINS(elastic_error(4e9, kNone, kNone, 1e9), "imply nu = 1");   // E > 3G
  EXPECT_CONTAINS(elastic_error(10e9, kNone, 1e9, kNone), "imply nu = -1"); // E > 9K
  EXPECT_CONTAINS(elastic_error(-1e9, 0.2, kNone, kNone), "E must be positive");
  EXPECT_CONTAINS(elastic_error(kNone, 0.2, kNone, kNone), "nu alone is not enough");
  EXPECT_CONTAINS(elastic_error(kNone, kNone, kNone, 1e9), "G alone is not enough");
  EXPECT_CONTAINS(elastic_error(kNone, kNone, kNone, kNone), "no elastic constant given");
}

// 2D moduli: known identities and round trips, plane stress and plane strain.
TEST(Material, PlanarConversions)
{
  const double E = 3e9;
  // Bond-based 2D (nu = 1/3, plane stress): K2 = E/(2(1-nu)) = 3E/4, G = 3E/8.
  const auto ps = planar_moduli(E, 1.0 / 3.0);
  EXPECT_NEAR(ps.K2 / (0.75 * E), 1.0, 1e-14);
  EXPECT_NEAR(ps.G / (0.375 * E), 1.0, 1e-14);
  // Plane strain: K2 = lambda + mu.
  const double nu = 0.25, lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const auto pe = planar_moduli(E, nu, PlaneCondition::PlaneStrain);
  EXPECT_NEAR(pe.K2 / (lambda + mu), 1.0, 1e-14);
  for (PlaneCondition pc : {PlaneCondition::PlaneStress, PlaneCondition::PlaneStrain})
    for (double n : {-0.5, 0.0, 0.25, 1.0 / 3.0, 0.45}) {
      const auto pm = planar_moduli(E, n, pc);
      const auto yp = young_poisson_from_planar(pm.K2, pm.G, pc);
      EXPECT_NEAR(yp.E / E, 1.0, 1e-13);
      EXPECT_NEAR(yp.nu, n, 1e-13);
    }
}

TEST(Material, MaterialBondConstantsChoices)
{
  Material m;
  m.name = "onlyK";
  m.elastic = complete_elastic_constants(kNone, kNone, 2e9, kNone);
  m.G_c = 10.0;
  // No horizon anywhere.
  try {
    material_bond_constants(m, 3);
    FAIL() << "no exception";
  } catch (const ParameterError &e) {
    EXPECT_CONTAINS(e.what(), "material 'onlyK' has no horizon");
  }
  // 2D with K only: E = K (nu = 1/3).
  const auto b2 = material_bond_constants(m, 2, 1e-3);
  const auto ref = derive_bond_constants(2, Micromodulus::Constant, ElasticInput::YoungsModulus,
                                         2e9, 10.0, 1e-3);
  EXPECT_NEAR(b2.c / ref.c, 1.0, 1e-14);
  // Material with E and nu != 1/4: 3D uses K.
  Material s;
  s.name = "steel";
  s.elastic = complete_elastic_constants(191e9, 0.3, kNone, kNone);
  s.G_c = 135;
  s.horizon = 1e-3;
  const auto b3 = material_bond_constants(s, 3);
  EXPECT_NEAR(b3.c / (18 * s.elastic.K / (kPi * 1e-12)), 1.0, 1e-12);
  EXPECT_THROW(material_bond_constants(s, 4), ParameterError);
}

TEST(Material, ParsesFormatFeatures)
{
  const std::string text = "# header comment\n"
                           "units metal   # trailing comment\n"
                           "\n"
                           "material A density=2.5 E=1e3 Gc=0.5   # one line\n"
                           "material B density=1 K=3 &\n"
                           "    G=2 Gc=1 horizon=0.25 micromodulus=constant\n"
                           "material C density=1 E=2 nu=-0.2 Gc=1\n";
  const auto mf = parse_material_text(text, "inline");
  EXPECT_EQ(mf.units, "metal");
  ASSERT_EQ(mf.materials.size(), 3u);
  EXPECT_DOUBLE_EQ(mf.get("A").density, 2.5);
  EXPECT_DOUBLE_EQ(mf.get("A").horizon, 0.0);
  EXPECT_DOUBLE_EQ(mf.get("A").elastic.E, 1e3);
  EXPECT_TRUE(std::isnan(mf.get("A").elastic.K));
  EXPECT_NEAR(mf.get("B").elastic.E, 9 * 3 * 2 / 11.0, 1e-13);
  EXPECT_DOUBLE_EQ(mf.get("B").horizon, 0.25);
  EXPECT_EQ(mf.get("B").origin, "inline:5");
  EXPECT_NEAR(mf.get("C").elastic.nu, -0.2, 1e-15);
  EXPECT_TRUE(is_known_unit_style("si"));
  EXPECT_FALSE(is_known_unit_style("SI"));
}

// Bad files: clear messages with file name and line number.
TEST(Material, BadFilesGiveClearErrors)
{
  const std::string u = "units si\n";
  struct Case {
    const char *file, *text, *expect;
  };
  const std::string ok = "material X density=1 E=1e9 Gc=1";
  const Case cases[] = {
      {"unknown_key.peridem", "units si\n# c\nmaterial X density=1 E=1 Gc=1 foo=2\n",
       "unknown_key.peridem:3: unknown key 'foo' in material 'X' (valid: density E nu K G Gc"},
      {"missing_gc.peridem", "units si\nmaterial X density=1 E=1\n",
       "missing_gc.peridem:2: material 'X' is missing required key 'Gc'"},
      {"missing_density.peridem", "units si\nmaterial X E=1 Gc=1\n",
       "missing required key 'density'"},
      {"missing_elastic.peridem", "units si\nmaterial X density=1 Gc=1\n",
       "missing_elastic.peridem:2: material 'X': no elastic constant given"},
      {"negative.peridem", "units si\nmaterial X density=-1 E=1 Gc=1\n",
       "negative.peridem:2: 'density' must be positive in material 'X' (got -1)"},
      {"zero_horizon.peridem", "units si\nmaterial X density=1 E=1 Gc=1 horizon=0\n",
       "'horizon' must be positive"},
      {"zero_gc.peridem", "units si\nmaterial X density=1 E=1 Gc=0\n", "'Gc' must be positive"},
      {"nu_range.peridem", "units si\nmaterial X density=1 E=1 nu=0.6 Gc=1\n",
       "nu_range.peridem:2: material 'X': Poisson ratio nu must lie in (-1, 0.5)"},
      {"inconsistent.peridem", "units si\nmaterial X density=1 E=1 nu=0.25 K=5 Gc=1\n",
       "inconsistent elastic constants: K = 5 but E and nu imply K = 0.66666667"},
      {"no_units.peridem", "material X density=1 E=1 Gc=1\n",
       "no_units.peridem:1: 'units' must be stated before the first material"},
      {"bad_units.peridem", "units imperial\nmaterial X density=1 E=1 Gc=1\n",
       "bad_units.peridem:1: unknown unit style 'imperial'"},
      {"two_units.peridem", "units si\nunits si\n", "'units' given twice (first at line 1)"},
      {"dup_material.peridem",
       "units si\nmaterial X density=1 E=1 Gc=1\n\nmaterial X "
       "density=2 E=1 Gc=1\n",
       "dup_material.peridem:4: material 'X' defined twice (first at "},
      {"dup_key.peridem", "units si\nmaterial X density=1 E=1 E=2 Gc=1\n", "key 'E' given twice"},
      {"bad_number.peridem", "units si\nmaterial X density=1 E=abc Gc=1\n",
       "bad_number.peridem:2: value of 'E' is not a finite number: 'abc'"},
      {"trailing_junk.peridem", "units si\nmaterial X density=1kg E=1 Gc=1\n",
       "value of 'density' is not a finite number: '1kg'"},
      {"spaces.peridem", "units si\nmaterial X density = 1 E=1 Gc=1\n",
       "expected key=value (no spaces around '='), got 'density'"},
      {"keyword.peridem", "units si\nmaterials X density=1 E=1 Gc=1\n",
       "keyword.peridem:2: unknown keyword 'materials' (expected 'units' or 'material')"},
      {"no_name.peridem", "units si\nmaterial density=1 E=1 Gc=1\n",
       "'material' must be followed by a name"},
      {"empty.peridem", "# nothing\nunits si\n", "empty.peridem: no material defined"},
      {"micro.peridem", "units si\nmaterial X density=1 E=1 Gc=1 micromodulus=quadratic\n",
       "micromodulus must be 'constant' or 'conic', got 'quadratic'"},
      {"continued.peridem", "units si\nmaterial X density=1 E=1 &\n  Gc=1 bogus=3\n",
       "continued.peridem:3: unknown key 'bogus'"},
      {"dangling.peridem", "units si\nmaterial X density=1 E=1 Gc=1 &\n",
       "dangling.peridem:2: file ends after a continuation '&'"},
      {"only_nu.peridem", "units si\nmaterial X density=1 nu=0.3 Gc=1\n", "nu alone is not enough"},
  };
  for (const Case &c : cases) EXPECT_CONTAINS(read_error(c.file, c.text), c.expect) << c.file;
  EXPECT_EQ(read_error("fine.peridem", u + ok + "\n"), "");
  EXPECT_CONTAINS(read_error("zero_bytes.peridem", ""), "zero_bytes.peridem: no material defined");
  // a NUL byte is named, and the message goes on after it
  const std::string nul = u + "material X density=1" + std::string(1, '\0') + " E=1 Gc=1\n";
  const std::string msg = read_error("nul.peridem", nul);
  EXPECT_CONTAINS(msg,
                  "nul.peridem:2: control character 0x00 (NUL) at column 21: not a text file?");
  EXPECT_EQ(msg.find('\0'), std::string::npos);
  try {
    read_material_file("/nonexistent/dir/none.peridem");
    FAIL() << "no exception";
  } catch (const ParameterError &e) {
    EXPECT_CONTAINS(e.what(), "cannot open material file '/nonexistent/dir/none.peridem'");
  }
}

// Files named after their paper and table: Bhattacharya & Lipton's (2023) Table 2 and the
// Table 1 of Jha et al. (2021), each with its M1 and M2; the old one-material files agree.
TEST(Material, ReadsPaperTableFiles)
{
  const auto gs = read_material_file(potential("grain_shape_2023_table2.peridem"));
  ASSERT_EQ(gs.materials.size(), 2u);
  const Material &m1 = gs.get("M1"), &m2 = gs.get("M2");
  // Bhattacharya & Lipton 2023, Table 2: M1 E 191 GPa, k 159.2 GPa, rho 8000; M2 E 1.23 GPa, k 2
  // GPa, rho 1200
  EXPECT_DOUBLE_EQ(m1.elastic.E, 191e9);
  EXPECT_DOUBLE_EQ(m1.elastic.K, 159.2e9);
  EXPECT_DOUBLE_EQ(m1.density, 8000.0);
  EXPECT_NEAR(m1.elastic.nu, (3 * 159.2 - 191) / (6 * 159.2), 1e-12); // implied, 0.300
  EXPECT_DOUBLE_EQ(m2.elastic.E, 1.23e9);
  EXPECT_DOUBLE_EQ(m2.elastic.K, 2e9);
  EXPECT_DOUBLE_EQ(m2.density, 1200.0);
  EXPECT_NEAR(m2.elastic.nu, (6.0 - 1.23) / 12.0, 1e-12); // implied, 0.3975
  EXPECT_DOUBLE_EQ(m2.horizon, 0.5e-3);                   // Bhattacharya & Lipton 2023, Sec. 7.3
  const auto pd = read_material_file(potential("peridem_2021_table1.peridem"));
  const auto old1 = read_material_file(potential("peridem_M1.peridem"));
  const auto old2 = read_material_file(potential("pmma_M2.peridem"));
  for (const auto &[name, old] : {std::make_pair("M1", &old1), std::make_pair("M2", &old2)}) {
    const Material &a = pd.get(name), &b = old->get(name);
    EXPECT_DOUBLE_EQ(a.density, b.density);
    EXPECT_DOUBLE_EQ(a.elastic.K, b.elastic.K);
    EXPECT_DOUBLE_EQ(a.elastic.G, b.elastic.G);
    EXPECT_DOUBLE_EQ(a.G_c, b.G_c);
    EXPECT_DOUBLE_EQ(a.horizon, b.horizon);
    EXPECT_EQ(a.micromodulus, b.micromodulus);
  }
}
