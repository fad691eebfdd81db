/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// PERIDEM: material definitions and *.peridem reader (format: doc/peridem_material_format.rst).
#include "peridem_material.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace peridem {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool known(double v)
{
  return !std::isnan(v);
}

bool close(double a, double b)
{
  return std::fabs(a - b) <= 1e-6 * std::max(std::fabs(a), std::fabs(b));
}

std::string fmt(double v)
{
  std::ostringstream os;
  os.precision(8);
  os << v;
  return os.str();
}

// E and nu from two given constants (index order E=0, nu=1, K=2, G=3).
YoungPoisson young_poisson_from_pair(int a, int b, const double v[4])
{
  const double E = v[0], nu = v[1], K = v[2], G = v[3];
  if (a == 0 && b == 1) return {E, nu};
  if (a == 0 && b == 2) return {E, (3.0 * K - E) / (6.0 * K)};
  if (a == 0 && b == 3) return {E, E / (2.0 * G) - 1.0};
  if (a == 1 && b == 2) return {3.0 * K * (1.0 - 2.0 * nu), nu};
  if (a == 1 && b == 3) return {2.0 * G * (1.0 + nu), nu};
  return {9.0 * K * G / (3.0 * K + G), (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G))};
}

} // namespace

bool ElasticConstants::complete() const
{
  return known(E) && known(nu) && known(K) && known(G);
}

ElasticConstants complete_elastic_constants(double E, double nu, double K, double G)
{
  const char *names[4] = {"E", "nu", "K", "G"};
  const double v[4] = {E, nu, K, G};
  int given[4], n = 0;
  for (int i = 0; i < 4; ++i) {
    if (!known(v[i])) continue;
    if (!std::isfinite(v[i]))
      throw ParameterError(std::string(names[i]) + " must be finite (got " + fmt(v[i]) + ")");
    if (i != 1 && !(v[i] > 0.0))
      throw ParameterError(std::string(names[i]) + " must be positive (got " + fmt(v[i]) + ")");
    given[n++] = i;
  }
  if (known(nu) && !(nu > -1.0 && nu < 0.5))
    throw ParameterError("Poisson ratio nu must lie in (-1, 0.5) (got " + fmt(nu) + ")");
  if (n == 0)
    throw ParameterError(
        "no elastic constant given: need E or K (bond-based) or any two of E, nu, K, G");
  if (n == 1) {
    if (given[0] == 1 || given[0] == 3)
      throw ParameterError(std::string("elastic constant ") + names[given[0]] +
                           " alone is not enough: give E or K, or any two of E, nu, K, G");
    return {E, nu, K, G};
  }
  const YoungPoisson yp = young_poisson_from_pair(given[0], given[1], v);
  if (!(yp.nu > -1.0 && yp.nu < 0.5) || !(yp.E > 0.0))
    throw ParameterError(std::string("inconsistent elastic constants: ") + names[given[0]] +
                         " and " + names[given[1]] + " imply nu = " + fmt(yp.nu) +
                         ", outside (-1, 0.5)");
  const ElasticConstants out{yp.E, yp.nu, yp.E / (3.0 * (1.0 - 2.0 * yp.nu)),
                             yp.E / (2.0 * (1.0 + yp.nu))};
  const double full[4] = {out.E, out.nu, out.K, out.G};
  for (int k = 2; k < n; ++k) {
    const int i = given[k];
    if (!close(v[i], full[i]))
      throw ParameterError(std::string("inconsistent elastic constants: ") + names[i] + " = " +
                           fmt(v[i]) + " but " + names[given[0]] + " and " + names[given[1]] +
                           " imply " + names[i] + " = " + fmt(full[i]));
  }
  return out;
}

PlanarModuli planar_moduli(double E, double nu, PlaneCondition pc)
{
  const double G = E / (2.0 * (1.0 + nu));
  if (pc == PlaneCondition::PlaneStress) return {E / (2.0 * (1.0 - nu)), G};
  return {E / (2.0 * (1.0 + nu) * (1.0 - 2.0 * nu)), G};
}

YoungPoisson young_poisson_from_planar(double K2, double G, PlaneCondition pc)
{
  if (pc == PlaneCondition::PlaneStress) return {4.0 * K2 * G / (K2 + G), (K2 - G) / (K2 + G)};
  const double nu = (K2 - G) / (2.0 * K2);
  return {2.0 * G * (1.0 + nu), nu};
}

BondConstants material_bond_constants(const Material &m, int dimension, double horizon)
{
  const double eps = horizon > 0.0 ? horizon : m.horizon;
  if (!(eps > 0.0))
    throw ParameterError("material '" + m.name + "' has no horizon; give one explicitly");
  const bool has_e = known(m.elastic.E), has_k = known(m.elastic.K);
  if (!has_e && !has_k) throw ParameterError("material '" + m.name + "' has neither E nor K");
  const bool use_e = dimension == 2 ? has_e : !has_k;
  return derive_bond_constants(dimension, m.micromodulus,
                               use_e ? ElasticInput::YoungsModulus : ElasticInput::BulkModulus,
                               use_e ? m.elastic.E : m.elastic.K, m.G_c, eps);
}

bool is_known_unit_style(const std::string &u)
{
  static const char *styles[] = {"lj", "real", "metal", "si", "cgs", "electron", "micro", "nano"};
  for (const char *s : styles)
    if (u == s) return true;
  return false;
}

const Material *MaterialFile::find(const std::string &name) const
{
  for (const auto &m : materials)
    if (m.name == name) return &m;
  return nullptr;
}

const Material &MaterialFile::get(const std::string &name) const
{
  if (const Material *m = find(name)) return *m;
  std::string list;
  for (const auto &m : materials) list += (list.empty() ? "" : ", ") + m.name;
  throw ParameterError(source + ": no material '" + name + "' (available: " + list + ")");
}

// ------------------------------------------------------------------------------------------
// Reader
// ------------------------------------------------------------------------------------------
namespace {

struct Token {
  std::string text;
  int line;
};

[[noreturn]] void fail(const std::string &source, int line, const std::string &msg)
{
  throw ParameterError(source + ":" + std::to_string(line) + ": " + msg);
}

// Split into logical lines: '#' starts a comment, a trailing '&' continues the line.
std::vector<std::vector<Token>> logical_lines(const std::string &text, const std::string &source)
{
  std::vector<std::vector<Token>> out;
  std::vector<Token> cur;
  bool continued = false;
  int lineno = 0;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    ++lineno;
    // a NUL byte would cut every later message short (C strings): name it
    for (size_t c = 0; c < line.size(); ++c) {
      const auto ch = static_cast<unsigned char>(line[c]);
      if (ch < 0x20 && ch != '\t' && ch != '\r') {
        char code[8];
        std::snprintf(code, sizeof(code), "0x%02x", ch);
        fail(source, lineno,
             "control character " + std::string(code) + (ch == 0 ? " (NUL)" : "") + " at column " +
                 std::to_string(c + 1) + ": not a text file?");
      }
    }
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string w;
    std::vector<Token> toks;
    while (words >> w) toks.push_back({w, lineno});
    continued = !toks.empty() && toks.back().text == "&";
    if (continued) toks.pop_back();
    cur.insert(cur.end(), toks.begin(), toks.end());
    if (!continued && !cur.empty()) {
      out.push_back(cur);
      cur.clear();
    }
  }
  if (continued) fail(source, lineno, "file ends after a continuation '&'");
  if (!cur.empty()) out.push_back(cur);
  return out;
}

double parse_number(const std::string &source, const Token &t, const std::string &key,
                    const std::string &value)
{
  const char *begin = value.c_str();
  char *end = nullptr;
  const double v = std::strtod(begin, &end);
  if (end == begin || *end != '\0' || !std::isfinite(v))
    fail(source, t.line, "value of '" + key + "' is not a finite number: '" + value + "'");
  return v;
}

Micromodulus parse_micromodulus(const std::string &source, const Token &t, const std::string &value)
{
  if (value == "constant") return Micromodulus::Constant;
  if (value == "conic") return Micromodulus::Conic;
  fail(source, t.line, "micromodulus must be 'constant' or 'conic', got '" + value + "'");
}

Material parse_material(const std::vector<Token> &toks, const std::string &source)
{
  static const std::vector<std::string> keys = {"density", "E",  "nu",      "K",
                                                "G",       "Gc", "horizon", "micromodulus"};
  const int line = toks[0].line;
  if (toks.size() < 2 || toks[1].text.find('=') != std::string::npos)
    fail(source, line, "'material' must be followed by a name");
  Material m;
  m.name = toks[1].text;
  m.origin = source + ":" + std::to_string(line);
  std::map<std::string, double> num;
  bool seen_mm = false;
  for (size_t i = 2; i < toks.size(); ++i) {
    const Token &t = toks[i];
    const auto eq = t.text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == t.text.size())
      fail(source, t.line, "expected key=value (no spaces around '='), got '" + t.text + "'");
    const std::string key = t.text.substr(0, eq), value = t.text.substr(eq + 1);
    bool valid = false;
    for (const auto &k : keys) valid = valid || k == key;
    if (!valid) {
      std::string list;
      for (const auto &k : keys) list += " " + k;
      fail(source, t.line,
           "unknown key '" + key + "' in material '" + m.name + "' (valid:" + list + ")");
    }
    if (num.count(key) || (key == "micromodulus" && seen_mm))
      fail(source, t.line, "key '" + key + "' given twice in material '" + m.name + "'");
    if (key == "micromodulus") {
      m.micromodulus = parse_micromodulus(source, t, value);
      seen_mm = true;
      continue;
    }
    const double v = parse_number(source, t, key, value);
    if (key != "nu" && !(v > 0.0))
      fail(source, t.line,
           "'" + key + "' must be positive in material '" + m.name + "' (got " + value + ")");
    num[key] = v;
  }
  for (const char *req : {"density", "Gc"})
    if (!num.count(req))
      fail(source, line,
           std::string("material '") + m.name + "' is missing required key '" + req + "'");
  auto get = [&](const char *k) { return num.count(k) ? num[k] : kNaN; };
  try {
    m.elastic = complete_elastic_constants(get("E"), get("nu"), get("K"), get("G"));
  } catch (const ParameterError &e) {
    fail(source, line, "material '" + m.name + "': " + e.what());
  }
  m.density = num["density"];
  m.G_c = num["Gc"];
  m.horizon = num.count("horizon") ? num["horizon"] : 0.0;
  return m;
}

} // namespace

MaterialFile parse_material_text(const std::string &text, const std::string &source)
{
  MaterialFile mf;
  mf.source = source;
  int units_line = 0;
  for (const auto &toks : logical_lines(text, source)) {
    const std::string &kw = toks[0].text;
    const int line = toks[0].line;
    if (kw == "units") {
      if (units_line)
        fail(source, line,
             "'units' given twice (first at line " + std::to_string(units_line) + ")");
      if (toks.size() != 2) fail(source, line, "'units' takes exactly one unit style");
      if (!is_known_unit_style(toks[1].text))
        fail(source, line,
             "unknown unit style '" + toks[1].text +
                 "' (LAMMPS styles: lj real metal si cgs electron micro nano)");
      mf.units = toks[1].text;
      units_line = line;
    } else if (kw == "material") {
      if (!units_line) fail(source, line, "'units' must be stated before the first material");
      Material m = parse_material(toks, source);
      if (const Material *prev = mf.find(m.name))
        fail(source, line,
             "material '" + m.name + "' defined twice (first at " + prev->origin + ")");
      mf.materials.push_back(m);
    } else {
      fail(source, line, "unknown keyword '" + kw + "' (expected 'units' or 'material')");
    }
  }
  if (mf.materials.empty()) throw ParameterError(source + ": no material defined");
  return mf;
}

MaterialFile read_material_file(const std::string &path)
{
  std::ifstream in(path);
  if (!in) throw ParameterError("cannot open material file '" + path + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_material_text(ss.str(), path);
}

} // namespace peridem
