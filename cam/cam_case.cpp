// Reading a cam case (cam/cam_case.h).
#include "cam/cam_case.h"

#include <cmath>
#include <filesystem>
#include <limits>

#include "lib/io/yaml_reader.h"
#include "lib/model/contact_model.h"
#include "lib/numeric.h"

namespace cam {

using contact::CaseError;
using contact::YamlMap;
using contact::YamlValue;

namespace {

std::string positive_or_inf(double v) { return v > 0 ? "" : "must be > 0 (.inf for flat)"; }

// Plausibility bounds (lib/io/yaml_reader.h, listed in docs/cam-follower.md "The case keys"): far wider than
// any disc cam's, to refuse a unit slip at its key before it reaches the solvers (a 40 m base circle stalled the
// roller; a 2 pm wide roller gave p0 = 3.5e17 Pa)
using contact::Quantity;
const auto kRadius = contact::plausible(Quantity::Length, 1e-4, 10);       // base circle, roller: 0.1 mm .. 10 m
const auto kWidth = contact::plausible(Quantity::Length, 1e-5, 10);        // roller, track: 10 um .. 10 m
const auto kLift = contact::plausible(Quantity::Length, 1e-6, 10);         // 1 um .. 10 m
const auto kMinRadius = contact::plausible(Quantity::Length, 0, 10);       // 0 .. 10 m
const auto kModulus = contact::plausible(Quantity::Modulus, 1e6, 1e13);    // rubber .. beyond diamond
const auto kPreload = contact::plausible(Quantity::Force, 1e-3, 1e7);      // 1 mN .. 10 MN
const auto kSpringRate = contact::plausible(Quantity::Stiffness, 0, 1e10);
const auto kMass = contact::plausible(Quantity::Mass, 1e-6, 1e4);          // 1 mg .. 10 t
// a body's shear yield stress k, as bodies.bodyN.shear_yield_Pa of a contact case (lib/subsurface/shakedown.h)
const auto kShearYield = contact::in_closed(contact::kShearYieldMin_Pa, contact::kShearYieldMax_Pa);
std::string crown_radius(double v) {  // a crown of 0.1 mm .. 10 km, or .inf (flat)
  if (std::isinf(v) && v > 0) return "";
  const std::string sign = positive_or_inf(v);
  return sign.empty() ? contact::plausible(Quantity::Length, 1e-4, 1e4)(v) : sign;
}

// The keys are SI (docs/cam-follower.md §6): a key of the former spelling (speed_rpm, *_deg) is refused
// with its SI key and the value converted, so that an old case is mended by copying one line.
void refuse_old_key(YamlMap& s, const std::string& old_key, const std::string& si_key, double factor) {
  double v = 0;
  bool present = false;
  s.optional_value(old_key, [&](const YamlValue& y) {
    v = y.as<double>(contact::finite);
    present = true;
  });
  if (present)
    s.fail(old_key, fmt::format("the cam's keys are in SI units: write {}: {:.17g}", si_key, v * factor));
}

constexpr double kRadPerDeg = 1 / kDegPerRad;
constexpr double kRadPerSPerRpm = 2 * contact::kPi / 60;
// a table row's angle is only checked (the nodes are 2 pi i/n): to 1e-6 rad, a value written to 7 digits
constexpr double kTableAngleTol = 1e-6;
std::string poisson(double v) { return v >= 0 && v < 0.5 ? "" : "must be in [0, 0.5)"; }

void read_lift(YamlMap& s, CamCase& c, double table_tolerance) {
  if (s.optional_value("table", [&](const YamlValue& v) {
        std::vector<double> lift;
        std::vector<double> angle;
        int row = 0;
        for (const YamlValue& r : v.elements("a list of [angle_rad, lift_m] rows")) {
          ++row;
          const std::vector<YamlValue> pair = r.elements("a row [angle_rad, lift_m]");
          if (pair.size() != 2) r.fail(fmt::format("row {}: expected [angle_rad, lift_m]", row));
          angle.push_back(pair[0].as<double>(contact::finite, fmt::format("row {}: angle_rad", row)));
          lift.push_back(pair[1].as<double>(contact::finite, fmt::format("row {}: lift_m", row)));
        }
        const std::size_t n = lift.size();
        if (n < 8) v.fail(fmt::format("a lift table needs at least 8 rows, got {}", n));
        for (std::size_t i = 0; i < n; ++i) {
          const double want = 2 * contact::kPi * static_cast<double>(i) / static_cast<double>(n);
          if (std::abs(angle[i] - want) > kTableAngleTol)
            v.fail(fmt::format("row {}: angle_rad must be {:.10g} (equal steps of 2 pi/{} from 0, 2 pi excluded; "
                               "to {:g} rad), got {:.10g}", i + 1, want, n, kTableAngleTol, angle[i]));
        }
        try {
          c.model.law = make_table_law(lift, table_tolerance);
        } catch (const CamError& e) {
          throw case_error_of(c, e);
        }
      }))
    return;
  DwellRiseDwellReturn d;
  std::string rise_law, return_law;
  // a segment's law, parsed once as it is read into `law`; a rise or a return is no dwell (the reader adds
  // what it got)
  const auto law_name = [](SegmentLaw& law) {
    return [&law](const std::string& v) -> std::string {
      try {
        law = parse_segment_law(v);
      } catch (const std::invalid_argument&) {
        law = SegmentLaw::Dwell;
      }
      return law == SegmentLaw::Dwell ? "must be cycloidal, polynomial-345 or harmonic" : "";
    };
  };
  s.required("rise_law", rise_law, law_name(d.rise_law));
  s.required("return_law", return_law, law_name(d.return_law));
  s.required("lift_m", d.lift_m, kLift);
  for (const char* k : {"rise", "dwell_high", "return"})
    refuse_old_key(s, std::string(k) + "_deg", std::string(k) + "_rad", kRadPerDeg);
  s.required("rise_rad", d.rise_rad, contact::positive_finite);
  s.optional("dwell_high_rad", d.dwell_high_rad, contact::nonnegative_finite);
  s.required("return_rad", d.return_rad, contact::positive_finite);
  // 2 pi within rounding: angles written to 17 digits may sum a few ulps above it
  if (d.rise_rad + d.dwell_high_rad + d.return_rad > 2 * contact::kPi * (1 + 1e-12))
    s.fail("return_rad", fmt::format("rise_rad + dwell_high_rad + return_rad = {:.10g} must be <= 2 pi",
                                     d.rise_rad + d.dwell_high_rad + d.return_rad));
  try {
    c.model.law = make_dwell_rise_dwell_return(d);
  } catch (const CamError& e) {
    throw case_error_of(c, e);
  }
}

}  // namespace

contact::CaseError case_error_of(const CamCase& c, const CamError& e) {
  const std::string key = "cam." + e.key;
  std::string where;
  for (std::string k = key;;) {  // the key's place, else its closest enclosing section's
    const auto it = c.locations.find(k);
    if (it != c.locations.end()) {
      where = it->second;
      break;
    }
    const std::size_t dot = k.rfind('.');
    if (dot == std::string::npos) break;
    k = k.substr(0, dot);
  }
  if (where.empty()) where = c.path;
  return CaseError(where + ": " + key + ": " + e.what());
}

CamCase read_cam_case(const std::string& path) {
  CamCase c;
  c.path = path;
  c.name = std::filesystem::path(path).stem().string();
  CamModel& m = c.model;
  contact::read_yaml_file(path, &c.locations, [&](YamlMap& top) {
    top.optional("name", c.name, [](const std::string& v) { return v.empty() ? "must not be empty" : ""; });
    top.optional_section("output", [&](YamlMap& s) { s.optional("directory", c.output_directory); });
    top.section("cam", [&](YamlMap& s) {
      double table_tolerance = 0.02;
      refuse_old_key(s, "speed_rpm", "speed_rad_per_s", kRadPerSPerRpm);
      refuse_old_key(s, "max_pressure_angle_deg", "max_pressure_angle_rad", kRadPerDeg);
      s.required("speed_rad_per_s", m.omega_rad_per_s, contact::positive_finite);
      s.required("base_radius_m", m.geometry.base_radius_m, kRadius);
      s.optional("offset_m", m.geometry.offset_m, contact::finite);
      s.required("mu", m.mu, contact::in_closed(0, 2));
      s.required("min_radius_m", m.min_radius_m, kMinRadius);
      m.max_pressure_angle_rad = 30 * kRadPerDeg;
      s.optional("max_pressure_angle_rad", m.max_pressure_angle_rad, [](double v) {
        return v > 0 && v < contact::kPi / 2 ? "" : "must be in (0, pi/2)";
      });
      s.optional("table_tolerance", table_tolerance, contact::positive_finite);
      s.optional("angle_steps", m.angle_steps, [](int v) { return v >= 8 && v <= 1000000 ? "" : "must be in [8, 1000000]"; });
      s.section("roller", [&](YamlMap& r) {
        r.required("radius_m", m.geometry.roller_radius_m, kRadius);
        r.required("width_m", m.bodies.roller_width_m, kWidth);
        m.bodies.roller_crown_radius_m = std::numeric_limits<double>::infinity();
        r.optional("crown_radius_m", m.bodies.roller_crown_radius_m, crown_radius);
        r.required("E_Pa", m.bodies.pair.body1.E_Pa, kModulus);
        r.required("nu", m.bodies.pair.body1.nu, poisson);
        r.optional("inertia_kg_m2", m.train.roller_inertia_kg_m2, contact::nonnegative_finite);
        r.optional("bearing_torque_N_m", m.train.bearing_torque_N_m, contact::nonnegative_finite);
        r.optional("bearing_drag_N_m_s", m.train.bearing_drag_N_m_s, contact::nonnegative_finite);
        // the roller's shear yield stress k: its fatigue indicators per angle (cam/cam_lubrication.h)
        r.optional("shear_yield_Pa", c.lubrication.fatigue.roller_shear_yield_Pa, kShearYield);
        if (!std::isinf(m.bodies.roller_crown_radius_m) && m.bodies.roller_width_m >= 2 * m.bodies.roller_crown_radius_m)
          r.fail("crown_radius_m", "must exceed half the roller's width_m");
      });
      s.section("track", [&](YamlMap& t) {
        t.required("width_m", m.bodies.track_width_m, kWidth);
        m.bodies.track_crown_radius_m = std::numeric_limits<double>::infinity();
        t.optional("crown_radius_m", m.bodies.track_crown_radius_m, crown_radius);
        t.required("E_Pa", m.bodies.pair.body2.E_Pa, kModulus);
        t.required("nu", m.bodies.pair.body2.nu, poisson);
        t.optional("shear_yield_Pa", c.lubrication.fatigue.cam_shear_yield_Pa, kShearYield);  // the cam's k
        if (!std::isinf(m.bodies.track_crown_radius_m) && m.bodies.track_width_m >= 2 * m.bodies.track_crown_radius_m)
          t.fail("crown_radius_m", "must exceed half the track's width_m");
      });
      if (std::isinf(m.bodies.roller_crown_radius_m) && std::isinf(m.bodies.track_crown_radius_m))
        s.fail("roller", "a cylindrical roller on a flat track is a line contact: give roller.crown_radius_m or "
                         "track.crown_radius_m");
      s.section("follower", [&](YamlMap& f) {
        f.required("spring_rate_N_per_m", m.train.spring_rate_N_per_m, kSpringRate);
        f.required("preload_N", m.train.preload_N, kPreload);
        f.required("moving_mass_kg", m.train.moving_mass_kg, kMass);
        f.optional("guide_mu", m.train.guide_mu, contact::in_closed(0, 2));
      });
      if (!(std::abs(m.geometry.offset_m) < m.geometry.base_radius_m + m.geometry.roller_radius_m))
        s.fail("offset_m", "|offset_m| must be < base_radius_m + roller.radius_m");
      s.section("lift", [&](YamlMap& l) { read_lift(l, c, table_tolerance); });
      s.optional_section("tangential", [&](YamlMap& t) {
        const auto cells = [](int v) { return v >= 4 && v <= 400 ? "" : "must be in [4, 400]"; };
        t.optional("nx", c.solver.nx, cells);
        t.optional("ny", c.solver.ny, cells);
        t.optional("quasi_steady_tolerance", c.solver.quasi_steady_tolerance, contact::nonnegative_finite);
        t.optional("periodic_rtol", c.solver.periodic_rtol, contact::positive_finite);
        t.optional("max_revolutions", c.solver.max_revolutions,
                   [](int v) { return v >= 2 && v <= 1000 ? "" : "must be in [2, 1000]"; });
        t.optional("compare_full_transient", c.solver.compare_full_transient);
        // the tangential model, as a wear case's solver.tangential: one the cam takes (lib/model/contact_model.h),
        // relaxed (the default) or consistent; parsed once, as it is read
        std::string scheme = contact::to_string(c.solver.scheme);
        t.optional("scheme", scheme, [&c](const std::string& v) -> std::string {
          try {
            const contact::TangentialScheme k = contact::parse_tangential_scheme(v);
            if (contact::tangential_traits(k).cam) {
              c.solver.scheme = k;
              return "";
            }
          } catch (const std::invalid_argument&) {
          }
          return "must be relaxed (the default: the model matched to the exact theory), consistent (the simplified "
                 "theory) or exact (Kalker's exact theory); a cam does not take classic";
        });
      });
      // the normal solver of every angle's contact: auto (Hertz's closed form on the unworn profiles, semi-Hertz on
      // worn ones), semi-hertz, or halfspace (the exact normal problem on the angle's fixed lattice,
      // cam/halfspace_contact.h); parsed once, as it is read
      s.optional_section("normal", [&](YamlMap& nm) {
        std::string solver = contact::to_string(c.solver.normal);
        nm.optional("solver", solver, [&c](const std::string& v) -> std::string {
          try {
            const contact::NormalChoice k = contact::parse_normal_choice(v);
            if (k != contact::NormalChoice::Hertz) {
              c.solver.normal = k;
              return "";
            }
          } catch (const std::invalid_argument&) {
          }
          return "must be auto (the default: Hertz's closed form on the unworn profiles, semi-Hertz on worn ones), "
                 "semi-hertz or halfspace (the exact normal problem); hertz is what auto takes where it holds";
        });
      });
      s.optional_section("wear", [&](YamlMap& w) { read_cam_wear(w, c.wear.emplace()); });
      // the film and the flash temperature per angle (cam/cam_lubrication.h): a contact case's lubricant: and
      // thermal: keys (lib/io/case.h), body1 the roller, body2 the cam, with the same checks at their lines
      s.optional_section("lubricant", [&](YamlMap& l) {
        contact::LubricantSection& lub = c.lubrication.lubricant.emplace();
        // the regime law's mu and wear factor fed back to the solves and the wear (else reported only)
        l.optional("friction_by_regime", c.lubrication.friction_by_regime);
        contact::read_lubricant(l, lub);
        if (c.lubrication.friction_by_regime)  // the solves' mu (cam.mu's range) and archard's K/(H mu) need mu > 0
          for (const auto& [key, regime] : {std::pair{"boundary", contact::LubricationRegime::Boundary},
                                            std::pair{"full_film", contact::LubricationRegime::FullFilm}}) {
            const double mu = lub.by_regime.mu[static_cast<int>(regime)];
            if (!(mu > 0 && mu <= 2))
              l.fail("friction", fmt::format("{}: with friction_by_regime the solves use it as cam.mu: must be in "
                                             "(0, 2], got {}", key, mu));
          }
        if (!(lub.thresholds.lambda_full_film > lub.thresholds.lambda_mixed))
          l.fail("lambda_full_film", fmt::format("need lambda_mixed < lambda_full_film, got {} and {}",
                                                 lub.thresholds.lambda_mixed, lub.thresholds.lambda_full_film));
      });
      s.optional_section("thermal", [&](YamlMap& t) {
        contact::ThermalSection& th = c.lubrication.thermal.emplace();
        contact::read_thermal(t, th);
        if (th.critical_temperature_C && !th.bulk_temperature_C)
          t.fail("critical_temperature_C", "Blok's criterion is on bulk + flash: give bulk_temperature_C too");
      });
    });
  });
  return c;
}

}  // namespace cam
