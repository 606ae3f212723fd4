// The contact case file: one reader per section, the per-key ranges next to the keys, then the
// cross-key checks of validate(). The generic machinery (marking keys, locations) is yaml_reader.h.
#include "lib/case.h"

#include <filesystem>
#include <stdexcept>
#include <string>

#include <spdlog/spdlog.h>

#include "lib/yaml_reader.h"

namespace contact {
namespace {

// a radius of curvature: .inf for flat, negative for concave, never 0 (or NaN)
std::string radius(double v) {
  return v != 0 && !std::isnan(v) ? "" : "must be nonzero (.inf for flat, negative for concave)";
}

// a case name becomes a directory name (out/<name>)
std::string case_name(const std::string& v) {
  if (v.empty()) return "must not be empty";
  if (v.find_first_of("/\\") != std::string::npos || v == "." || v == "..")
    return "must be a plain name (it names the output directory out/<name>)";
  return {};
}

void read_body(YamlMap& m, BodySection& b) {
  m.required("Rx_m", b.Rx_m, radius);
  m.required("Ry_m", b.Ry_m, radius);
  m.required("E_Pa", b.E_Pa, positive_finite);
  m.required("nu", b.nu, in_half_open(0, 0.5));
}

void read_kinematics(YamlMap& m, KinematicsSection& k) {
  m.optional("speed_m_per_s", k.speed_m_per_s, nonnegative_finite);
  m.optional("xi", k.xi, finite);
  m.optional("eta", k.eta, finite);
  m.optional("phi_per_m", k.phi_per_m, finite);
}

void read_solver(YamlMap& m, SolverSection& s) {
  m.optional("tangential", s.tangential);
  try {
    parse_tangential_scheme(s.tangential);
  } catch (const std::invalid_argument& e) {
    m.fail("tangential", e.what());
  }
  m.optional("nx", s.nx, in_closed(1, 4096));
  m.optional("ny", s.ny, in_closed(1, 4096));
}

// "LOCATION: " of the first key that was read from a file, else "PATH: " (or nothing)
std::string where(const ContactCase& c, const std::string& key) {
  const auto it = c.locations.find(key);
  if (it != c.locations.end()) return it->second + ": ";
  return c.path.empty() ? std::string() : c.path + ": ";
}

// Hertz needs a positive relative curvature along each axis (hertz.h)
void check_curvature(const ContactCase& c, const char* axis, const char* symbol, double R1_m, double R2_m) {
  const double curvature_per_m = (1 / R1_m + 1 / R2_m) / 2;
  if (curvature_per_m > 0) return;
  const std::string key1 = std::string("bodies.body1.") + axis;
  const std::string key2 = std::string("bodies.body2.") + axis;
  const std::string what =
      curvature_per_m == 0
          ? fmt::format("no relative curvature ({} = 0 1/m): Hertz cannot treat a line contact", symbol)
          : fmt::format("conforming contact (relative curvature {} = {:.6g} 1/m <= 0): Hertz cannot treat it",
                        symbol, curvature_per_m);
  throw CaseError(where(c, key1) + key1 + ", " + key2 + ": " + what);
}

}  // namespace

ContactCase read_contact_case(const std::string& path) {
  ContactCase c;
  c.path = path;
  c.name = std::filesystem::path(path).stem().string();
  read_yaml_file(path, &c.locations, [&](YamlMap& m) {
    m.optional("name", c.name, case_name);
    m.section("bodies", [&](YamlMap& s) {
      s.section("body1", [&](YamlMap& b) { read_body(b, c.bodies.body1); });
      s.section("body2", [&](YamlMap& b) { read_body(b, c.bodies.body2); });
    });
    m.section("load", [&](YamlMap& s) { s.required("normal_load_N", c.load.normal_load_N, positive_finite); });
    m.optional_section("kinematics", [&](YamlMap& s) { read_kinematics(s, c.kinematics); });
    m.section("friction", [&](YamlMap& s) { s.required("mu", c.friction.mu, in_closed(0, 10)); });
    m.optional_section("solver", [&](YamlMap& s) { read_solver(s, c.solver); });
    m.optional_section("output", [&](YamlMap& s) {
      s.optional("directory", c.output.directory);
      s.optional("fields", c.output.fields);
    });
  });
  validate(c);
  spdlog::debug("case '{}' read from {}", c.name, path);
  return c;
}

void validate(const ContactCase& c) {
  // a point contact: both relative curvatures positive
  check_curvature(c, "Rx_m", "A", c.bodies.body1.Rx_m, c.bodies.body2.Rx_m);
  check_curvature(c, "Ry_m", "B", c.bodies.body1.Ry_m, c.bodies.body2.Ry_m);
}

Bodies bodies_of(const ContactCase& c) {
  Bodies b;
  b.body1 = {c.bodies.body1.Rx_m, c.bodies.body1.Ry_m};
  b.body2 = {c.bodies.body2.Rx_m, c.bodies.body2.Ry_m};
  return b;
}

ElasticPair materials_of(const ContactCase& c) {
  ElasticPair pair;
  pair.body1 = {c.bodies.body1.E_Pa, c.bodies.body1.nu};
  pair.body2 = {c.bodies.body2.E_Pa, c.bodies.body2.nu};
  return pair;
}

Creepages creepages_of(const ContactCase& c) {
  Creepages k;
  k.xi = c.kinematics.xi;
  k.eta = c.kinematics.eta;
  k.phi_per_m = c.kinematics.phi_per_m;
  return k;
}

GridSpec grid_of(const ContactCase& c) {
  GridSpec g;
  g.nx = c.solver.nx;
  g.ny = c.solver.ny;
  return g;
}

}  // namespace contact
