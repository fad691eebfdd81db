/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// PERIDEM: material definitions and the *.peridem material file reader (no LAMMPS dependency).
// File format: doc/peridem_material_format.rst.  Physics references: see peridem_bond_law.h.
#ifndef PERIDEM_MATERIAL_H
#define PERIDEM_MATERIAL_H

#include "peridem_bond_law.h"

#include <string>
#include <vector>

namespace peridem {

// Isotropic (3D, material) elastic constants.  A constant that is not known is NaN: a material
// may be given by E alone or K alone, which is all bond-based peridynamics needs
// (Bhattacharya & Lipton 2023, Remark 1 fixes nu), but the state-based (LPS) model of Jha et al.
// 2021, eq. (7) needs K and G.
struct ElasticConstants {
  double E;              // Young's modulus
  double nu;             // Poisson ratio
  double K;              // bulk modulus K = E/(3(1-2nu))
  double G;              // shear modulus G = E/(2(1+nu))
  bool complete() const; // all four known
};

// Completes 3D isotropic constants from those given (pass NaN for "not given"):
//  - any two of E, nu, K, G determine all four (nu must lie in (-1, 1/2), moduli > 0);
//  - more than two: the first two in the order E, nu, K, G are used and the others must agree
//    to a relative 1e-6 (else ParameterError "inconsistent elastic constants");
//  - E alone or K alone: returned as is (others NaN);
//  - nothing, nu alone or G alone: ParameterError.
ElasticConstants complete_elastic_constants(double E, double nu, double K, double G);

// 2D (in-plane) moduli.  The 2D bulk modulus K2 relates the in-plane mean stress to the area
// change: (sigma_xx + sigma_yy)/2 = K2 (eps_xx + eps_yy); G is the ordinary shear modulus.
//   plane stress (thin sheet, sigma_zz = 0): K2 = E/(2(1-nu));  E = 4 K2 G/(K2+G), nu =
//   (K2-G)/(K2+G) plane strain (eps_zz = 0):  K2 = E/(2(1+nu)(1-2nu)) = lambda + G;
//                               nu = (K2-G)/(2 K2),   E = 2G(1+nu) = G(3 K2 - G)/K2
// 2D bond-based peridynamics (Bhattacharya & Lipton 2023, Table 1, nu = 1/3) is plane stress, the
// default.
enum class PlaneCondition { PlaneStress, PlaneStrain };
struct PlanarModuli {
  double K2;
  double G;
};
PlanarModuli planar_moduli(double E, double nu, PlaneCondition pc = PlaneCondition::PlaneStress);
struct YoungPoisson {
  double E;
  double nu;
};
YoungPoisson young_poisson_from_planar(double K2, double G,
                                       PlaneCondition pc = PlaneCondition::PlaneStress);

// One material (one atom type / grain type / bond type).
struct Material {
  std::string name;
  double density = 0.0;       // mass per volume (per area in 2D), in the file's units
  ElasticConstants elastic{}; // 3D isotropic constants, possibly partial (see above)
  double G_c = 0.0;           // critical energy release rate (fracture energy)
  double horizon = 0.0;       // 0 = not given in the file (must then come from elsewhere)
  Micromodulus micromodulus = Micromodulus::Constant; // w of Bhattacharya & Lipton 2023, eq. 3.2 /
                                                      // J of Jha et al. 2021, eq. 7
  std::string origin; // "file:line" where it was defined (for messages)
  // Contact settings (Kn, Rc, friction, damping of Jha et al. 2021, Sec. 2.2-2.3) are to be added
  // here.
};

// Bond-based constants for a material in the given dimension: 2D uses E (plane stress, Bhattacharya
// & Lipton 2023 Table 1) if known, else K; 3D uses K (isotropic-extension energy, [SA05]) if known,
// else E. horizon > 0 overrides the material's horizon; ParameterError if neither is set.
BondConstants material_bond_constants(const Material &m, int dimension, double horizon = 0.0);

// Unit styles accepted in the "units" line (LAMMPS unit style names).
bool is_known_unit_style(const std::string &units);

struct MaterialFile {
  std::string source; // file name (or the name given to parse_material_text)
  std::string units;  // LAMMPS unit style the numbers are in, e.g. "si"
  std::vector<Material> materials;
  // nullptr if absent.
  const Material *find(const std::string &name) const;
  // Throws ParameterError naming the file and listing the available materials.
  const Material &get(const std::string &name) const;
};

// Parse a *.peridem file.  All problems throw ParameterError with "file:line: message".
MaterialFile read_material_file(const std::string &path);
MaterialFile parse_material_text(const std::string &text, const std::string &source_name);

} // namespace peridem

#endif
