// The contact case file: one reader per section, the per-key ranges next to the keys, then the
// cross-key checks of validate(). The generic machinery (marking keys, locations) is yaml_reader.h.
#include "lib/io/case.h"
#include "lib/io/case_node.h"
#include "lib/subsurface/dang_van.h"
#include "lib/subsurface/shakedown.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "lib/normal/semi_hertz.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/tangential.h"
#include "lib/number.h"
#include "lib/io/yaml_reader.h"
#include "lib/model/contact_model.h"

namespace contact {
namespace {

// a radius of curvature: .inf for flat, negative for concave, never 0 (or NaN); its size plausible (0.1 mm to
// 10 km either way: lib/io/yaml_reader.h, README "The case file")
std::string radius(double v) {
  if (v == 0 || std::isnan(v)) return "must be nonzero (.inf for flat, negative for concave)";
  return std::isinf(v) ? "" : plausible(Quantity::Length, 1e-4, 1e4)(std::fabs(v));
}
// plausibility bounds (README "The case file"): a unit slip refused at its key, naming the slip
const auto kModulus = plausible(Quantity::Modulus, 1e6, 1e13);   // rubber .. beyond diamond
const auto kWidth = plausible(Quantity::Length, 1e-5, 10);       // a generated profile: 10 um .. 10 m
std::string profile_radius(double v) {                           // a generated profile's crown, arc: 0.1 mm .. 10 km
  return v == 0 || !std::isfinite(v) ? "must be nonzero and finite" : plausible(Quantity::Length, 1e-4, 1e4)(std::fabs(v));
}

// a case name becomes a directory name (out/<name>)
std::string case_name(const std::string& v) {
  if (v.empty()) return "must not be empty";
  if (v.find_first_of("/\\") != std::string::npos || v == "." || v == "..")
    return "must be a plain name (it names the output directory out/<name>)";
  return {};
}

// with profiles, Ry_m is read (to be refused by validate, naming both keys) but not required
void read_body(YamlMap& m, BodySection& b, bool with_profiles) {
  m.required("Rx_m", b.Rx_m, radius);
  if (with_profiles) m.optional("Ry_m", b.Ry_m, radius);
  else m.required("Ry_m", b.Ry_m, radius);
  m.required("E_Pa", b.E_Pa, kModulus);
  m.required("nu", b.nu, in_half_open(0, 0.5));
  m.optional("shear_yield_Pa", b.shear_yield_Pa, in_closed(kShearYieldMin_Pa, kShearYieldMax_Pa));
  m.optional_value("dang_van", [&](const YamlValue& v) {
    DangVanConstants k;
    v.mapping([&](YamlMap& d) {
      d.required("a", k.a, in_closed(kDangVanAMin, kDangVanAMax));
      d.required("b_Pa", k.b_Pa, in_closed(kDangVanBMin_Pa, kDangVanBMax_Pa));
    });
    b.dang_van = k;
  });
}

// ---- lateral profiles ----

constexpr const char* kProfileForms =
    "{ file: PATH }, { crowned: { Ry_m, width_m } }, { flat: { width_m } }, { arc: { R_m, width_m } } or "
    "{ flat_worn_crown: { Ry_m, width_m, band_half_width_m } }";

// a profile in any of its forms; a CSV path is relative to the case file's directory
Profile read_profile(const YamlValue& v, const std::filesystem::path& case_dir) {
  if (!v.node().IsMap()) v.fail(std::string("expected ") + kProfileForms + ", got " + yaml_describe(v.node()));
  Profile p;
  int forms = 0;
  // a generator's refusal (std::invalid_argument) at the form's node
  const auto generated = [&](const YamlValue& g, const auto& generate) {
    try {
      p = generate();
    } catch (const std::invalid_argument& e) {
      g.fail(e.what());
    }
  };
  v.mapping([&](YamlMap& m) {
    forms += m.optional_value("file", [&](const YamlValue& f) {
      const std::filesystem::path file = f.as<std::string>();
      const std::filesystem::path resolved = file.is_absolute() ? file : case_dir / file;
      try {
        p = read_profile_csv(resolved.string());
      } catch (const std::invalid_argument& e) {  // names the CSV's file:line
        f.fail(e.what());
      }
    });
    forms += m.optional_value("crowned", [&](const YamlValue& g) {
      double Ry_m = 0, width_m = 0;
      g.mapping([&](YamlMap& s) {
        s.required("Ry_m", Ry_m, [](double v) { return v > 0 ? profile_radius(v) : "must be > 0 and finite"; });
        s.required("width_m", width_m, kWidth);
      });
      generated(g, [&] { return crowned_profile(Ry_m, width_m); });
    });
    forms += m.optional_value("flat", [&](const YamlValue& g) {
      double width_m = 0;
      g.mapping([&](YamlMap& s) { s.required("width_m", width_m, kWidth); });
      generated(g, [&] { return flat_profile(width_m); });
    });
    forms += m.optional_value("arc", [&](const YamlValue& g) {
      double R_m = 0, width_m = 0;
      g.mapping([&](YamlMap& s) {
        s.required("R_m", R_m, profile_radius);
        s.required("width_m", width_m, kWidth);
      });
      generated(g, [&] { return arc_profile(R_m, width_m); });
    });
    forms += m.optional_value("flat_worn_crown", [&](const YamlValue& g) {
      double Ry_m = 0, width_m = 0, band_m = 0;
      g.mapping([&](YamlMap& s) {
        s.required("Ry_m", Ry_m, [](double v) { return v > 0 ? profile_radius(v) : "must be > 0 and finite"; });
        s.required("width_m", width_m, kWidth);
        s.required("band_half_width_m", band_m, nonnegative_finite);
      });
      generated(g, [&] { return flat_worn_crown_profile(Ry_m, width_m, band_m); });
    });
  });
  if (forms != 1)
    v.fail(forms == 0 ? std::string("expected one of ") + kProfileForms + ", got an empty mapping"
                      : "give one of file, crowned, flat, arc and flat_worn_crown, not several");
  return p;
}

void read_profiles(YamlMap& m, ProfilesSection& s, const std::filesystem::path& case_dir) {
  m.required_value("body1", [&](const YamlValue& v) { s.profiles.body1 = read_profile(v, case_dir); });
  m.required_value("body2", [&](const YamlValue& v) { s.profiles.body2 = read_profile(v, case_dir); });
  m.optional("heathcote_slip", s.heathcote_slip);
}

// ---- time histories ----

constexpr const char* kHistoryForms = "a number, { ramp: [t0_s, v0, t1_s, v1] } or { table: [[t_s, value], ...] }";

// the shortest spelling that reads back the same double, for messages
std::string number(double v) { return round_trip(v); }

// "1 element", "3 elements"
std::string count_of_elements(std::size_t n) { return std::to_string(n) + (n == 1 ? " element" : " elements"); }

// { ramp: [t0_s, v0, t1_s, v1] }: linear from (t0, v0) to (t1, v1), held outside
template <class Check>
History read_ramp(const YamlValue& r, const Check& check_value) {
  const std::vector<YamlValue> e = r.elements("[t0_s, v0, t1_s, v1]");
  if (e.size() != 4) r.fail("expected [t0_s, v0, t1_s, v1], got " + count_of_elements(e.size()));
  const double t0 = e[0].as<double>(finite, "t0_s");
  const double v0 = e[1].as<double>(check_value, "v0");
  const double t1 = e[2].as<double>(finite, "t1_s");
  const double v1 = e[3].as<double>(check_value, "v1");
  if (!(t1 > t0)) e[2].fail("t1_s must be after t0_s = " + number(t0) + ", got " + clipped(e[2].node().Scalar()));
  return ramp_history(t0, v0, t1, v1);
}

// { table: [[t_s, value], ...] }: linear between rows, held outside; times strictly increasing
template <class Check>
History read_table(const YamlValue& tv, const Check& check_value) {
  const std::vector<YamlValue> rows = tv.elements("a list of [t_s, value] rows");
  if (rows.empty()) tv.fail("expected at least one [t_s, value] row, got none");
  History h;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::string row = "row " + std::to_string(k + 1);
    if (!rows[k].node().IsSequence() || rows[k].node().size() != 2)
      rows[k].fail(row + ": expected [t_s, value], got " +
                   (rows[k].node().IsSequence() ? count_of_elements(rows[k].node().size())
                                                : yaml_describe(rows[k].node())));
    const std::vector<YamlValue> cells = rows[k].elements();
    const double t = cells[0].as<double>(finite, row + ": t_s");
    const double v = cells[1].as<double>(check_value, row + ": value");
    if (k > 0 && !(t > h.t_s.back()))
      cells[0].fail(row + ": t_s must be after row " + std::to_string(k) + "'s " + number(h.t_s.back()) +
                    " (times strictly increasing), got " + clipped(cells[0].node().Scalar()));
    h.t_s.push_back(t);
    h.value.push_back(v);
  }
  return h;
}

// a history in any of its forms; check_value applies to every value
template <class Check>
History read_history(const YamlValue& v, const Check& check_value) {
  if (v.node().IsScalar()) return constant_history(v.as<double>(check_value));
  if (!v.node().IsMap()) v.fail(std::string("expected ") + kHistoryForms + ", got " + yaml_describe(v.node()));
  History h;
  int forms = 0;
  v.mapping([&](YamlMap& m) {
    forms += m.optional_value("ramp", [&](const YamlValue& r) { h = read_ramp(r, check_value); });
    forms += m.optional_value("table", [&](const YamlValue& t) { h = read_table(t, check_value); });
  });
  if (forms != 1) v.fail(forms == 0 ? std::string("expected ") + kHistoryForms + ", got an empty mapping"
                                    : "give one of 'ramp' and 'table', not both");
  try {
    check_history(h, v.path().c_str());
  } catch (const std::invalid_argument& e) {
    throw CaseError(v.location() + ": " + e.what());
  }
  return h;
}

// the normal load: a constant > 0, or a history >= 0 that is positive at some time
History read_load(const YamlValue& v) {
  if (v.node().IsScalar()) return constant_history(v.as<double>(positive_finite));
  const History h = read_history(v, nonnegative_finite);
  if (!(max_value(h) > 0)) v.fail("must be positive at some time, got 0 throughout");
  return h;
}

void read_kinematics(YamlMap& m, KinematicsSection& k) {
  m.optional_value("speed_m_per_s", [&](const YamlValue& v) { k.speed_m_per_s = read_history(v, nonnegative_finite); });
  m.optional_value("xi", [&](const YamlValue& v) { k.xi = read_history(v, finite); });
  m.optional_value("eta", [&](const YamlValue& v) { k.eta = read_history(v, finite); });
  m.optional_value("phi_per_m", [&](const YamlValue& v) { k.phi_per_m = read_history(v, finite); });
}

// A choice: its name read and parsed once into the enum, the default being the value's own (a name outside the
// parse's table: its message at the key, clipped to clip_chars when given)
template <class E, class Parse>
void read_choice(YamlMap& m, const char* key, E& value, Parse parse, std::size_t clip_chars = 0) {
  std::string name = to_string(value);
  m.optional(key, name);
  try {
    value = parse(name);
  } catch (const std::invalid_argument& e) {
    m.fail(key, clip_chars > 0 ? clipped(e.what(), clip_chars) : std::string(e.what()));
  }
}

void read_transient(YamlMap& m, TransientSection& t) {
  read_choice(m, "scheme", t.scheme, parse_transient_scheme, 200);
  m.required("t_end_s", t.t_end_s, positive_finite);
  m.optional("dt_s", t.dt_s, nonnegative_finite);
  m.optional("substep", t.substep);
  m.optional_value("snapshots_s", [&](const YamlValue& v) {
    const std::vector<YamlValue> e = v.elements("a list of times, e.g. [1.0e-4, 2.0e-4]");
    for (std::size_t k = 0; k < e.size(); ++k) {
      const std::string element = "element " + std::to_string(k + 1);
      const double t_s = e[k].as<double>(nonnegative_finite, element);
      if (k > 0 && !(t_s > t.snapshots_s.back()))
        e[k].fail(element + " must be after element " + std::to_string(k) + "'s " + number(t.snapshots_s.back()) +
                  " (times strictly increasing), got " + clipped(e[k].node().Scalar()));
      t.snapshots_s.push_back(t_s);
    }
  });
}

void read_inertia(YamlMap& m, InertiaSection& in) {
  m.required("R1_m", in.R1_m, positive_finite);
  m.required("J1_kg_m2", in.J1_kg_m2, positive_finite);
  m.optional("T_res_N_m", in.T_res_N_m, finite);
  m.optional("omega1_0_rad_per_s", in.omega1_0_rad_per_s, nonnegative_finite);
  m.required_value("path_speed_m_per_s",
                   [&](const YamlValue& v) { in.path_speed_m_per_s = read_history(v, nonnegative_finite); });
}

// { boundary: x, mixed: x, full_film: x } into an array indexed by LubricationRegime
template <class Check>
void read_by_regime(YamlMap& m, std::array<double, 3>& v, Check check) {
  m.required("boundary", v[static_cast<int>(LubricationRegime::Boundary)], check);
  m.required("mixed", v[static_cast<int>(LubricationRegime::Mixed)], check);
  m.required("full_film", v[static_cast<int>(LubricationRegime::FullFilm)], check);
}

}  // namespace

void read_lubricant(YamlMap& m, LubricantSection& l) {
  m.required("viscosity_Pa_s", l.lubricant.viscosity_Pa_s, positive_finite);
  m.required("pressure_viscosity_1_per_Pa", l.lubricant.pressure_viscosity_1_per_Pa, positive_finite);
  m.section("roughness_Rq_m", [&](YamlMap& r) {
    r.required("body1", l.Rq1_m, nonnegative_finite);
    r.required("body2", l.Rq2_m, nonnegative_finite);
  });
  m.optional("lambda_mixed", l.thresholds.lambda_mixed, positive_finite);
  m.optional("lambda_full_film", l.thresholds.lambda_full_film, positive_finite);
  m.section("friction", [&](YamlMap& f) { read_by_regime(f, l.by_regime.mu, in_closed(0, 10)); });
  m.section("wear_factor", [&](YamlMap& f) { read_by_regime(f, l.by_regime.wear_factor, nonnegative_finite); });
}

static void read_thermal_body(YamlMap& m, ThermalBody& b) {
  m.required("conductivity_W_per_m_K", b.conductivity_W_per_m_K, positive_finite);
  m.required("density_kg_per_m3", b.density_kg_per_m3, positive_finite);
  m.required("specific_heat_J_per_kg_K", b.specific_heat_J_per_kg_K, positive_finite);
}

void read_thermal(YamlMap& m, ThermalSection& t) {
  m.section("body1", [&](YamlMap& b) { read_thermal_body(b, t.body1); });
  m.section("body2", [&](YamlMap& b) { read_thermal_body(b, t.body2); });
  const auto above_absolute_zero = [](double v) {
    return std::isfinite(v) && v > -273.15 ? "" : "must be finite and above -273.15";
  };
  double bulk = 0, critical = 0;
  if (m.optional_value("bulk_temperature_C", [&](const YamlValue& v) { bulk = v.as<double>(above_absolute_zero); }))
    t.bulk_temperature_C = bulk;
  if (m.optional_value("critical_temperature_C",
                       [&](const YamlValue& v) { critical = v.as<double>(above_absolute_zero); }))
    t.critical_temperature_C = critical;
}

namespace {

void read_solver(YamlMap& m, SolverSection& s) {
  read_choice(m, "normal", s.normal, parse_normal_choice);
  read_choice(m, "tangential", s.tangential, parse_tangential_scheme, 200);
  m.optional("nx", s.nx, in_closed(1, 4096));
  m.optional("ny", s.ny, in_closed(1, 4096));
  read_choice(m, "fidelity", s.fidelity, parse_fidelity);
  m.optional("correction_tolerance", s.correction_tolerance, in_closed(1e-6, 10));
  m.optional("error_estimate", s.error_estimate);
  m.optional("grid_extrapolation", s.grid_extrapolation);
  m.optional("correction_grid", s.correction_grid, in_closed(0, 4096));
  // the exact fidelity is the exact physics: the half-space normal problem and Kalker's exact theory
  if (s.fidelity == Fidelity::Exact) {
    if (s.normal != NormalChoice::Auto && s.normal != NormalChoice::Halfspace)
      m.fail("normal", "solver.normal, solver.fidelity: the exact fidelity solves the half-space, not " +
                           std::string(to_string(s.normal)) + " (leave solver.normal out)");
    if (s.tangential != kDefaultTangentialScheme && s.tangential != TangentialScheme::Exact)
      m.fail("tangential", "solver.tangential, solver.fidelity: the exact fidelity solves Kalker's exact theory, not " +
                               to_string(s.tangential) + " (leave solver.tangential out)");
    s.normal = NormalChoice::Halfspace;
    s.tangential = TangentialScheme::Exact;
  }
  m.optional("max_memory_bytes", s.max_memory_bytes, positive_finite);
}

}  // namespace

std::string where(const ContactCase& c, std::string key) {
  for (;;) {
    const auto it = c.locations.find(key);
    if (it != c.locations.end()) return it->second + ": ";
    const std::size_t dot = key.rfind('.');
    if (dot == std::string::npos) break;
    key.erase(dot);
  }
  return c.path.empty() ? std::string() : c.path + ": ";
}

InputLocation location_of(const ContactCase& c, std::string key) {
  const std::string asked = key;
  for (;;) {
    const auto it = c.locations.find(key);
    if (it != c.locations.end()) {  // "FILE:LINE:COL"
      const std::string& place = it->second;
      const std::size_t col_at = place.rfind(':');
      const std::size_t line_at = col_at == std::string::npos || col_at == 0 ? std::string::npos
                                                                             : place.rfind(':', col_at - 1);
      InputLocation l{place, 0, 0, asked};
      const auto number = [&](std::size_t from, std::size_t to, int& v) {
        const auto [end, ec] = std::from_chars(place.data() + from, place.data() + to, v);
        return ec == std::errc() && end == place.data() + to && to > from;
      };
      if (line_at != std::string::npos && number(line_at + 1, col_at, l.line) &&
          number(col_at + 1, place.size(), l.column))
        l.file = place.substr(0, line_at);
      else
        l.line = l.column = 0;
      return l;
    }
    const std::size_t dot = key.rfind('.');
    if (dot == std::string::npos) break;
    key.erase(dot);
  }
  return {c.path, 0, 0, asked};
}

CaseError key_error(const ContactCase& c, const std::string& key, const std::string& message) {
  return CaseError(where(c, key) + message, location_of(c, key));
}

bool given(const ContactCase& c, const std::string& key) { return c.locations.count(key) > 0; }

namespace {

// the constant of a history the steady command needs
double steady_value(const ContactCase& c, const History& h, const std::string& key) {
  if (h.value.empty() || !is_constant(h))
    throw key_error(c, key, std::string(key) + ": the steady 'contact' command needs a constant; histories are for "
                    "'transient'");
  return h.value.front();
}

// with inertia, the roller's spin sets the rolling speed and the longitudinal creepage
void check_inertia_kinematics(const ContactCase& c) {
  std::vector<std::string> keys;
  for (const char* k : {"kinematics.speed_m_per_s", "kinematics.xi"})
    if (given(c, k)) keys.push_back(k);
  if (!keys.empty()) {
    std::string names;
    for (const std::string& k : keys) names += (names.empty() ? "" : ", ") + k;
    throw key_error(c, keys.front(), names + ", inertia: with inertia the rolling speed and xi follow "
                    "from the roller's spin (V = (omega1 R1 + V2)/2, xi = (V2 - omega1 R1)/V); remove " +
                    (keys.size() > 1 ? "them" : "it") + " and give inertia.path_speed_m_per_s");
  }
  // the inertia run carries longitudinal creep only (lib/tangential/satran.h)
  for (const auto& [key, h] : {std::pair<const char*, const History*>{"kinematics.eta", &c.kinematics.eta},
                               {"kinematics.phi_per_m", &c.kinematics.phi_per_m}})
    if (!h->value.empty() && (min_value(*h) != 0 || max_value(*h) != 0))
      throw key_error(c, key, std::string(key) + ", inertia: an inertia run models longitudinal creep only; " +
                      "lateral and spin creepage must be 0");
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
  throw key_error(c, key1, key1 + ", " + key2 + ": " + what);
}

}  // namespace

namespace {

// the case of a parsed document named `path`; profile files relative to base_dir
ContactCase read_contact_document(const YAML::Node& doc, const std::string& path, const std::filesystem::path& base_dir,
                                  const ExtraSections& extra) {
  ContactCase c;
  c.path = path;
  c.name = std::filesystem::path(path).stem().string();
  read_yaml_document(doc, path, &c.locations, [&](YamlMap& m) {
    m.optional("name", c.name, case_name);
    // the profiles first: with them the bodies take no Ry_m
    m.optional_section("profiles", [&](YamlMap& s) { read_profiles(s, c.profiles.emplace(), base_dir); });
    m.section("bodies", [&](YamlMap& s) {
      s.section("body1", [&](YamlMap& b) { read_body(b, c.bodies.body1, c.profiles.has_value()); });
      s.section("body2", [&](YamlMap& b) { read_body(b, c.bodies.body2, c.profiles.has_value()); });
    });
    m.section("load", [&](YamlMap& s) {
      s.required_value("normal_load_N", [&](const YamlValue& v) { c.load.normal_load_N = read_load(v); });
    });
    m.optional_section("kinematics", [&](YamlMap& s) { read_kinematics(s, c.kinematics); });
    m.section("friction", [&](YamlMap& s) { s.required("mu", c.friction.mu, in_closed(0, 10)); });
    m.optional_section("solver", [&](YamlMap& s) { read_solver(s, c.solver); });
    m.optional_section("transient", [&](YamlMap& s) { read_transient(s, c.transient.emplace()); });
    m.optional_section("inertia", [&](YamlMap& s) { read_inertia(s, c.inertia.emplace()); });
    m.optional_section("lubricant", [&](YamlMap& s) { read_lubricant(s, c.lubricant.emplace()); });
    m.optional_section("thermal", [&](YamlMap& s) { read_thermal(s, c.thermal.emplace()); });
    m.optional_section("output", [&](YamlMap& s) {
      s.optional("directory", c.output.directory);
      s.optional("fields", c.output.fields);
      s.optional("subsurface", c.output.subsurface);
      s.optional("max_bytes", c.output.max_bytes, positive_finite);
    });
    if (extra) extra(m);
  });
  validate(c);
  spdlog::debug("case '{}' read from {}", c.name, path);
  return c;
}

}  // namespace

ContactCase read_contact_case(const std::string& path, const ExtraSections& extra) {
  return read_contact_document(load_yaml_file(path), path, std::filesystem::path(path).parent_path(), extra);
}

ContactCase read_contact_case_text(const std::string& text, const std::string& label,
                                   const std::filesystem::path& base_dir, const ExtraSections& extra) {
  return read_contact_document(parse_yaml_text(text, label), label, base_dir, extra);
}

ContactCase read_contact_case_node(const YAML::Node& doc, const std::string& label, const std::filesystem::path& base_dir,
                                   const ExtraSections& extra) {
  return read_contact_document(doc, label, base_dir, extra);
}

void validate(const ContactCase& c) {
  // a point contact: both relative curvatures positive (laterally: from the profiles when given)
  check_curvature(c, "Rx_m", "A", c.bodies.body1.Rx_m, c.bodies.body2.Rx_m);
  if (!c.profiles) {
    check_curvature(c, "Ry_m", "B", c.bodies.body1.Ry_m, c.bodies.body2.Ry_m);
    if (c.solver.normal == NormalChoice::SemiHertz || c.solver.normal == NormalChoice::Halfspace)
      throw key_error(c, "solver.normal", "solver.normal, profiles: the " + std::string(to_string(c.solver.normal)) +
                      " solver works on lateral profiles; give a profiles: section (or normal: auto)");
  } else {
    // the profiles are the lateral geometry: no Ry_m besides
    for (const char* key : {"bodies.body1.Ry_m", "bodies.body2.Ry_m"})
      if (given(c, key))
        throw key_error(c, key, std::string(key) + ", profiles: the lateral geometry comes from the profiles; "
                        "remove Ry_m (Rx_m stays: the rolling radius)");
    // Hertz needs constant curvature
    if (c.solver.normal == NormalChoice::Hertz)
      for (const auto& [key, p] : {std::pair<const char*, const Profile*>{"profiles.body1", &c.profiles->profiles.body1},
                                   {"profiles.body2", &c.profiles->profiles.body2}})
        if (!has_constant_curvature(*p, kCaseCurvatureRtol))
          throw key_error(c, "solver.normal", std::string("solver.normal, ") + key + ": Hertz needs profiles of " +
                          "constant curvature (within " + number(kCaseCurvatureRtol) + "), " + key +
                          " is not; use normal: auto, semi-hertz or halfspace");
  }

  // a model that solves with friction only (Kalker's exact theory, lib/tangential/exact.h)
  if (const TangentialModelTraits& model = tangential_traits(c.solver.tangential);
      model.needs_friction && !(c.friction.mu > 0))
    throw key_error(c, "friction.mu", std::string("friction.mu, solver.tangential: the ") + model.needs_friction_as +
                    " needs mu > 0");

  // the grid extrapolation of the exact theory's steady solves (lib/tangential/grid_extrapolation.h)
  if (c.solver.grid_extrapolation) {
    const bool exact = c.solver.tangential == TangentialScheme::Exact;
    if (!exact && c.solver.fidelity != Fidelity::Corrected)
      throw key_error(c, "solver.grid_extrapolation", "solver.grid_extrapolation, solver.tangential: the grid "
                      "extrapolation is of Kalker's exact theory's solves; give tangential: exact (or fidelity: exact "
                      "or corrected), not " + to_string(c.solver.tangential));
    if (c.transient)
      throw key_error(c, "solver.grid_extrapolation", "solver.grid_extrapolation, transient: the grid extrapolation "
                      "is of steady solves; a transient run steps its grid by one cell (leave it out)");
    // on half the cells each way: even counts, at least 2 coarse cells
    const auto even = [](int n) { return n >= 4 && n % 2 == 0; };
    for (const auto& [key, n] : {std::pair{"nx", c.solver.nx}, std::pair{"ny", c.solver.ny}})
      if (exact && !even(n))
        throw key_error(c, std::string("solver.") + key, std::string("solver.") + key + ", solver.grid_extrapolation: "
                        "the extrapolation solves on half the cells each way: give an even number of cells, at least 4, "
                        "not " + std::to_string(n));
    if (c.solver.fidelity == Fidelity::Corrected && c.solver.correction_grid > 0 && !even(c.solver.correction_grid))
      throw key_error(c, "solver.correction_grid", "solver.correction_grid, solver.grid_extrapolation: the "
                      "extrapolation solves on half the cells each way: give an even number of cells, at least 4, not " +
                      std::to_string(c.solver.correction_grid));
    if (c.solver.fidelity == Fidelity::Corrected && c.solver.correction_grid == 0 && !(even(c.solver.nx) && even(c.solver.ny)))
      throw key_error(c, "solver.nx", "solver.nx, solver.ny, solver.grid_extrapolation: the corrected fidelity's exact "
                      "physics solves on the case's grid, and the extrapolation on half its cells each way: give even "
                      "numbers of cells, at least 4 (or an even solver.correction_grid)");
  }

  // the run: snapshots within it, a time step for the fixed-step schemes
  if (c.transient) {
    const TransientSection& t = *c.transient;
    if (!t.snapshots_s.empty() && t.snapshots_s.back() > t.t_end_s)
      throw key_error(c, "transient.snapshots_s", "transient.snapshots_s, transient.t_end_s: snapshot at " +
                      number(t.snapshots_s.back()) + " s is after the end of the run, t_end_s = " +
                      number(t.t_end_s) + " s");
    if (t.scheme != TransientScheme::Shift && !(t.dt_s > 0))
      throw key_error(c, "transient.dt_s", "transient.dt_s, transient.scheme: the " + to_string(t.scheme) +
                      " scheme needs a time step dt_s > 0");
  }

  // the lubricant's regime thresholds in order; Blok's criterion needs the bulk temperature
  if (c.lubricant && !(c.lubricant->thresholds.lambda_full_film > c.lubricant->thresholds.lambda_mixed))
    throw key_error(c, "lubricant.lambda_full_film", "lubricant.lambda_full_film, lubricant.lambda_mixed: need "
                    "lambda_mixed < lambda_full_film, got " + number(c.lubricant->thresholds.lambda_mixed) + " and " +
                    number(c.lubricant->thresholds.lambda_full_film));
  if (c.thermal && c.thermal->critical_temperature_C && !c.thermal->bulk_temperature_C)
    throw key_error(c, "thermal.critical_temperature_C", "thermal.critical_temperature_C, thermal.bulk_temperature_C: "
                    "Blok's criterion compares bulk + flash temperature with the critical one; give "
                    "bulk_temperature_C too");

  // the roller's inertia: its spin sets V and xi; the run is a shift run with a longest step
  if (c.inertia) {
    check_inertia_kinematics(c);
    if (c.transient && c.transient->scheme != TransientScheme::Shift)
      throw key_error(c, "transient.scheme", "transient.scheme, inertia: an inertia run uses the shift "
                      "scheme, got '" + to_string(c.transient->scheme) + "'");
    if (c.transient && !(c.transient->dt_s > 0))
      throw key_error(c, "transient.dt_s", "transient.dt_s, inertia: an inertia run needs the longest "
                      "step dt_s > 0 (the spin-up is stiff; e.g. 2.0e-6 s)");
  }
}

void validate_steady(const ContactCase& c, SteadyRunner runner) {
  if (runner == SteadyRunner::WearRun) {
    for (const auto& [h, key] : {std::pair<const History*, const char*>{&c.load.normal_load_N, "load.normal_load_N"},
                                 {&c.kinematics.speed_m_per_s, "kinematics.speed_m_per_s"},
                                 {&c.kinematics.xi, "kinematics.xi"},
                                 {&c.kinematics.eta, "kinematics.eta"},
                                 {&c.kinematics.phi_per_m, "kinematics.phi_per_m"}})
      if (h->value.empty() || !is_constant(*h))
        throw key_error(c, key, std::string(key) + ": a history runs as a duty cycle, which needs a transient: "
                        "section (e.g. transient: { scheme: shift, t_end_s: 0.5 }); steady running needs a constant");
    if (c.inertia)
      throw key_error(c, "inertia", "inertia: a wear run has no roller inertia");
    return;
  }
  steady_value(c, c.load.normal_load_N, "load.normal_load_N");
  steady_value(c, c.kinematics.speed_m_per_s, "kinematics.speed_m_per_s");
  steady_value(c, c.kinematics.xi, "kinematics.xi");
  steady_value(c, c.kinematics.eta, "kinematics.eta");
  steady_value(c, c.kinematics.phi_per_m, "kinematics.phi_per_m");
  if (c.inertia)
    throw key_error(c, "inertia", "inertia: the steady 'contact' command has no roller inertia; "
                    "inertia is for 'transient'");
  // the flash temperature: each surface passes through the contact (a surface at rest has no steady one)
  if (c.thermal) {
    const double V = speed_of(c), xi = c.kinematics.xi.value.front();
    if (!(V > 0) || !(std::abs(xi) < 2))
      throw key_error(c, given(c, "kinematics.xi") ? "kinematics.xi" : "kinematics.speed_m_per_s",
                      "kinematics.speed_m_per_s, kinematics.xi, thermal: the flash temperature needs both surfaces "
                      "moving, v1 = V (1 - xi/2) > 0 and v2 = V (1 + xi/2) > 0; got V = " + number(V) +
                      " m/s, xi = " + number(xi));
  }
  if (c.lubricant && !(speed_of(c) > 0))
    throw key_error(c, "kinematics.speed_m_per_s", "kinematics.speed_m_per_s, lubricant: the film needs an "
                    "entrainment speed V > 0");
}

void refuse_lubrication_and_thermal(const ContactCase& c, const std::string& command) {
  for (const auto& [section, present] : {std::pair<const char*, bool>{"lubricant", c.lubricant.has_value()},
                                         {"thermal", c.thermal.has_value()}})
    if (present)
      throw key_error(c, section, std::string(section) + ": the '" + command + "' command does not use this "
                      "section yet (the film, the regime and the flash temperature are reported by 'contact'); "
                      "remove it");
}

void validate_transient(const ContactCase& c) {
  if (!c.transient)
    throw CaseError((c.path.empty() ? std::string() : c.path + ": ") +
                    "transient: the 'transient' command needs a transient: section, e.g. "
                    "transient: { scheme: shift, t_end_s: 4.0e-4 }");
  refuse_lubrication_and_thermal(c, "transient");
}

Bodies bodies_of(const ContactCase& c) {
  Bodies b;
  b.body1 = {c.bodies.body1.Rx_m, c.bodies.body1.Ry_m};
  b.body2 = {c.bodies.body2.Rx_m, c.bodies.body2.Ry_m};
  if (c.profiles) {  // Ry from the profiles, which must then have constant curvature
    const auto lateral_radius = [&](const Profile& p, const char* key) {
      if (!has_constant_curvature(p, kCaseCurvatureRtol))
        throw key_error(c, key, std::string(key) + ": the radii of this command need profiles of constant curvature "
                        "(within " + number(kCaseCurvatureRtol) + ")");
      const double curvature_per_m = fit_parabola(p).curvature_per_m;
      return curvature_per_m == 0 ? kFlat : 1 / curvature_per_m;
    };
    b.body1.Ry_m = lateral_radius(c.profiles->profiles.body1, "profiles.body1");
    b.body2.Ry_m = lateral_radius(c.profiles->profiles.body2, "profiles.body2");
  }
  return b;
}

ElasticPair materials_of(const ContactCase& c) {
  ElasticPair pair;
  pair.body1 = {c.bodies.body1.E_Pa, c.bodies.body1.nu};
  pair.body2 = {c.bodies.body2.E_Pa, c.bodies.body2.nu};
  return pair;
}

GridSpec grid_of(const ContactCase& c) {
  GridSpec g;
  g.nx = c.solver.nx;
  g.ny = c.solver.ny;
  return g;
}

NormalProblem normal_problem_of(const ContactCase& c) {
  NormalProblem problem;
  problem.choice = c.solver.normal;
  problem.bodies = {{c.bodies.body1.Rx_m, c.bodies.body1.Ry_m}, {c.bodies.body2.Rx_m, c.bodies.body2.Ry_m}};
  if (c.profiles) {
    problem.profiles = &c.profiles->profiles;
    problem.semi_hertz.heathcote_slip = c.profiles->heathcote_slip;
  }
  problem.pair = materials_of(c);
  problem.normal_load_N = normal_load_of(c);
  problem.grid = grid_of(c);
  problem.curvature_rtol = kCaseCurvatureRtol;
  return problem;
}

NormalSolution solve_normal_of(const ContactCase& c) {
  try {
    return solve_normal_converged(normal_problem_of(c));
  } catch (const NormalChoiceError& e) {
    throw key_error(c, "solver.normal", std::string("solver.normal, profiles: ") + e.what());
  }
}

double normal_load_of(const ContactCase& c) { return steady_value(c, c.load.normal_load_N, "load.normal_load_N"); }

double speed_of(const ContactCase& c) {
  return steady_value(c, c.kinematics.speed_m_per_s, "kinematics.speed_m_per_s");
}

Creepages creepages_of(const ContactCase& c) {
  Creepages k;
  k.xi = steady_value(c, c.kinematics.xi, "kinematics.xi");
  k.eta = steady_value(c, c.kinematics.eta, "kinematics.eta");
  k.phi_per_m = steady_value(c, c.kinematics.phi_per_m, "kinematics.phi_per_m");
  return k;
}

TransientCase transient_case_of(const ContactCase& c) {
  validate_transient(c);
  TransientCase t;
  t.bodies = bodies_of(c);
  t.materials = materials_of(c);
  t.mu = c.friction.mu;
  t.inputs.normal_load_N = c.load.normal_load_N;
  t.inputs.speed_m_per_s = c.kinematics.speed_m_per_s;
  t.inputs.xi = c.kinematics.xi;
  t.inputs.eta = c.kinematics.eta;
  t.inputs.phi_per_m = c.kinematics.phi_per_m;
  if (c.inertia) {
    RollerInertia in;
    in.R1_m = c.inertia->R1_m;
    in.J1_kg_m2 = c.inertia->J1_kg_m2;
    in.T_res_N_m = c.inertia->T_res_N_m;
    in.omega1_0_rad_per_s = c.inertia->omega1_0_rad_per_s;
    in.path_speed_m_per_s = c.inertia->path_speed_m_per_s;
    t.inertia = in;
  }
  const TransientSection& s = *c.transient;
  t.settings.scheme = s.scheme;
  t.settings.t_end_s = s.t_end_s;
  t.settings.dt_s = s.dt_s;
  t.settings.substep = s.substep;
  t.settings.grid = grid_of(c);
  t.settings.snapshot_times_s = s.snapshots_s;
  return t;
}

Grid transient_grid(const TransientCase& t) {
  if (t.patch) return t.patch->grid;
  const HertzContact largest = solve_hertz(t.bodies, t.materials, max_value(t.inputs.normal_load_N));
  return make_grid(largest.a_m, largest.b_m, t.settings.grid);
}

TransientOutputEstimate estimate_transient_output(const TransientCase& t, bool fields) {
  const Grid grid = transient_grid(t);
  const TransientSettings& s = t.settings;
  // the rolled distance: the path's speed bounds the rolling speed of an inertia run from above
  const History& speed = t.inertia ? t.inertia->path_speed_m_per_s : t.inputs.speed_m_per_s;
  const double rolled_m = integral(speed, 0, s.t_end_s);
  const double per_dt = s.dt_s > 0 ? s.t_end_s / s.dt_s : 0;
  TransientOutputEstimate e;
  // shift: a step per dx rolled, shortened to dt_s; the fixed-step schemes: a step per dt_s, split by substep
  e.steps = 1 + per_dt + (s.scheme == TransientScheme::Shift || t.inertia || s.substep ? rolled_m / grid.dx_m : 0);
  constexpr double kTimeseriesColumns = 17, kStripPowerColumns = 4, kSnapshotColumns = 8, kStripEnergyColumns = 2;
  const double cells = static_cast<double>(grid.nx) * grid.ny;
  const double numbers = e.steps * (kTimeseriesColumns + (fields ? kStripPowerColumns * grid.ny : 0)) +
                         kStripEnergyColumns * grid.ny +
                         (fields ? static_cast<double>(s.snapshot_times_s.size()) * kSnapshotColumns * cells : 0);
  e.bytes = numbers * kCsvBytesPerNumber;
  return e;
}

void check_transient_output(const ContactCase& c, const TransientCase& t, bool fields, bool force) {
  const TransientOutputEstimate estimate = estimate_transient_output(t, fields);
  if (force || !(estimate.bytes > c.output.max_bytes)) return;
  throw key_error(
      c, "transient.t_end_s",
      fmt::format("transient.t_end_s, transient.dt_s, solver.nx, solver.ny, output.max_bytes: the run would write "
                  "about {:.3g} bytes ({:.3g} GB: about {:.3g} steps of {} strips), more than output.max_bytes = {:.0f}; "
                  "shorten t_end_s, coarsen the grid, raise output.max_bytes, or run with --force (Python: force=True)",
                  estimate.bytes, estimate.bytes / 1e9, estimate.steps, transient_grid(t).y_m.size(),
                  c.output.max_bytes));
}

CaseError transient_error(const ContactCase& c, const SettingError& e) {
  // run_transient's setting (the key, as data) -> the case file's key it was read from
  static const std::pair<const char*, const char*> kKeys[] = {
      {"dt_s", "transient.dt_s"},
      {"t_end_s", "transient.t_end_s"},
      {"scheme", "transient.scheme"},
      {"speed_m_per_s", "kinematics.speed_m_per_s"},
      {"xi", "kinematics.xi"},
      {"eta", "kinematics.eta"},
      {"phi_per_m", "kinematics.phi_per_m"},
      {"normal_load_N", "load.normal_load_N"},
      {"path_speed_m_per_s", "inertia.path_speed_m_per_s"},
      {"inertia", "inertia"},
  };
  for (const auto& [name, key] : kKeys) {
    if (e.key != name) continue;
    std::string what = e.problem;
    // a CFL breach of a fixed-step scheme: the numbers at full precision, the largest allowed step
    if (const auto* cfl = dynamic_cast<const CflBreach*>(&e); cfl && c.transient) {
      const double dx = cfl->dx_m, vmax = cfl->v_max_m_per_s;
      // dx / V rounded down to the six digits shown, so that the step named runs
      const double scale = std::pow(10.0, std::floor(std::log10(dx / vmax)) - 5);
      const double dt_max = std::floor(dx / vmax / scale) * scale;
      what = fmt::format("{} s breaks the CFL condition of the {} scheme (V dt/dx = {:.9g} > 1 at the largest "
                         "speed V = {} m/s, dx = {:.6g} m); the largest allowed dt_s is {:.6g} s (or set "
                         "substep: true)",
                         number(cfl->dt_s), to_string(c.transient->scheme), vmax * cfl->dt_s / dx, number(vmax), dx,
                         dt_max);
    }
    return key_error(c, key, std::string(key) + ": " + what);
  }
  return CaseError((c.path.empty() ? std::string() : c.path + ": ") + "transient: " + e.what());
}

void read_running_condition(YamlMap& m, ContactCase& c) {
  m.optional_section("load", [&](YamlMap& s) {
    s.optional_value("normal_load_N", [&](const YamlValue& v) { c.load.normal_load_N = read_load(v); });
  });
  m.optional_section("kinematics", [&](YamlMap& s) { read_kinematics(s, c.kinematics); });
  m.optional_section("friction", [&](YamlMap& s) { s.optional("mu", c.friction.mu, in_closed(0, 10)); });
  m.optional_section("transient", [&](YamlMap& s) { read_transient(s, c.transient.emplace()); });
}

}  // namespace contact
