#include "wear/wear_case.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

#include <spdlog/fmt/fmt.h>

#include "lib/enum_names.h"
#include "lib/number.h"
#include "lib/io/yaml_reader.h"
#include "lib/normal/profile.h"
#include "wear/collective.h"

namespace wear {

using contact::CaseError;
using contact::YamlMap;
using contact::YamlValue;

namespace {

using contact::round_trip;
const auto number = [](double v) { return round_trip(v); };

void read_kth(YamlMap& m, KthWearMap& k) {
  m.optional("pressure_ratio", k.pressure_ratio);
  m.optional("slip_speed_low_m_per_s", k.slip_speed_low_m_per_s);
  m.optional("slip_speed_high_m_per_s", k.slip_speed_high_m_per_s);
  m.optional("K_mild_slow", k.K_mild_slow);
  m.optional("K_severe", k.K_severe);
  m.optional("K_mild_fast", k.K_mild_fast);
  m.optional("K_catastrophic", k.K_catastrophic);
}

void read_usfd(YamlMap& m, UsfdWearFunction& u) {
  m.optional("mild_slope", u.mild_slope);
  m.optional("severe_ug_per_m_mm2", u.severe_ug_per_m_mm2);
  m.optional("catastrophic_slope", u.catastrophic_slope);
  m.optional("catastrophic_offset_ug_per_m_mm2", u.catastrophic_offset_ug_per_m_mm2);
}

// one body's law; validate()'s message "wear.KEY: ..." is moved to this body's key and line
void read_law(YamlMap& m, WearLaw& law) {
  std::string name = to_string(law.law);
  m.optional("law", name);
  try {
    law.law = parse_wear_law(name);  // once, as it is read
  } catch (const contact::SettingError& e) {
    m.fail("law", e.problem);
  }
  m.optional("k_E_m3_per_J", law.k_E_m3_per_J);
  m.optional("archard_k", law.archard_k);
  m.optional("hardness_Pa", law.hardness_Pa);
  m.optional("density_kg_per_m3", law.density_kg_per_m3);
  m.optional_section("kth", [&](YamlMap& s) { read_kth(s, law.kth); });
  m.optional_section("usfd", [&](YamlMap& s) { read_usfd(s, law.usfd); });
  try {
    validate(law);
  } catch (const contact::SettingError& e) {  // the key within the law ("kth.pressure_ratio") as data
    const std::size_t dot = e.key.find('.');
    if (dot == std::string::npos) m.fail(e.key, e.problem);
    m.fail(e.key.substr(0, dot), e.key.substr(dot + 1) + ": " + e.problem);
  }
}

// wear.fatigue: the law and its values; validate()'s message is moved to the key and its line
void read_fatigue(YamlMap& m, FatigueSection& f) {
  std::string name = to_string(f.law);
  m.required("law", name);
  try {
    f.law = parse_fatigue_law(name);
  } catch (const contact::SettingError& e) {
    m.fail("law", e.problem);
  }
  m.optional("threshold_N", f.burstow.threshold_N);
  m.optional("peak_at_N", f.burstow.peak_at_N);
  m.optional("zero_at_N", f.burstow.zero_at_N);
  m.optional("peak_damage", f.burstow.peak_damage);
  try {
    validate(f.burstow);
  } catch (const contact::SettingError& e) {
    m.fail(e.key, e.problem);
  }
}

// wear.stepping.method's names (lib/enum_names.h)
using Method = IntegratorOptions::Method;
constexpr contact::EnumTable<Method, 3> kSteppingMethods = {
    {{Method::Adaptive, "adaptive"}, {Method::FixedDepth, "fixed-depth"}, {Method::FixedStep, "fixed-revolutions"}}};

void read_stepping(YamlMap& m, WearStepping& s) {
  std::string method = to_string(s.method);
  m.optional("method", method, [&s](const std::string& v) -> std::string {  // parsed once, as it is read
    const std::optional<Method> parsed = contact::enum_from_name(kSteppingMethods, v);
    if (!parsed) return "must be " + contact::enum_names_list(kSteppingMethods);
    s.method = *parsed;
    return "";
  });
  m.optional("rtol", s.rtol, [](double v) -> std::string {
    return v >= 1e-10 && v <= 0.1 ? "" : "must be in [1e-10, 0.1]";
  });
  m.optional("atol_m", s.atol_m, contact::positive_finite);
  m.optional("max_depth_step_m", s.max_depth_step_m, contact::positive_finite);
  m.optional("step_revolutions", s.step_revolutions, contact::nonnegative_finite);
  double max_steps = static_cast<double>(s.max_steps);
  m.optional("max_steps", max_steps, [](double v) -> std::string {  // 1e6 reads as well as 1000000; 1.5 does not
    return v >= 1 && v <= 1e9 && v == std::floor(v) ? "" : "must be a whole number in [1, 1e9]";
  });
  s.max_steps = static_cast<long>(max_steps);
}

void read_wear(YamlMap& m, WearSection& w, std::optional<YamlValue>& collective) {
  m.optional_section("body1", [&](YamlMap& s) { read_law(s, w.body1.emplace()); });
  m.optional_section("body2", [&](YamlMap& s) { read_law(s, w.body2.emplace()); });
  if (!w.body1 && !w.body2)
    m.fail_here("no body wears: give body1: and/or body2: with a law, e.g. body1: { law: energy, k_E_m3_per_J: 1.0e-13 }");
  m.required("revolutions", w.revolutions, [](double v) -> std::string {
    return v > 0 && v <= 1e15 ? "" : "must be in (0, 1e15]";
  });
  m.optional_section("limits", [&](YamlMap& s) {
    s.optional("max_depth_m", w.limits.max_depth_m, contact::nonnegative_finite);
    s.optional("max_pressure_Pa", w.limits.max_pressure_Pa, contact::nonnegative_finite);
    s.optional("edge", w.limits.edge);
    s.optional("shakedown", w.limits.shakedown);
    s.optional("scuffing", w.limits.scuffing);
  });
  m.optional_section("fatigue", [&](YamlMap& s) { read_fatigue(s, w.fatigue.emplace()); });
  m.optional_section("stepping", [&](YamlMap& s) { read_stepping(s, w.stepping); });
  m.optional("smoothing_wavelength_m", w.smoothing_wavelength_m, contact::in_closed(0, 0.1));
  m.optional_value("snapshots_revolutions", [&](const YamlValue& v) {
    const std::vector<YamlValue> e = v.elements("a list of revolutions, e.g. [1.0e7, 2.0e7]");
    for (std::size_t k = 0; k < e.size(); ++k) {
      const std::string element = "element " + std::to_string(k + 1);
      const double N = e[k].as<double>(contact::positive_finite, element);
      if (k > 0 && !(N > w.snapshots_revolutions.back()))
        e[k].fail(element + " must be after element " + std::to_string(k) + "'s " +
                  number(w.snapshots_revolutions.back()) + " (revolutions strictly increasing), got " +
                  contact::clipped(e[k].node().Scalar()));
      w.snapshots_revolutions.push_back(N);
    }
  });
  m.optional("checkpoint_interval_s", w.checkpoint_interval_s, contact::nonnegative_finite);
  // read once the case's own sections are (each condition starts from them): read_wear_case
  m.optional_value("collective", [&](const YamlValue& v) { collective.emplace(v); });
}

}  // namespace

namespace {

// the wear case of a reader of the contact case (a file's or a text's), `path` naming it
template <class ReadContact>
WearCase read_wear_case_with(const std::string& path, ReadContact read_contact) {
  WearCase c;
  bool has_wear = false;
  std::optional<YamlValue> collective;
  c.contact = read_contact([&](YamlMap& m) {
    m.optional_section("wear", [&](YamlMap& s) {
      has_wear = true;
      read_wear(s, c.wear, collective);
    });
  });
  if (collective) c.wear.collective = read_collective(*collective, c.contact);
  if (!has_wear)
    throw CaseError(path + ": wear: the run command needs a wear: section (the bodies that wear, their law "
                    "and the revolutions), e.g. cases/paper-wear.yaml",
                    contact::InputLocation{path, 0, 0, "wear"});
  validate(c);
  return c;
}

}  // namespace

WearCase read_wear_case(const std::string& path) {
  return read_wear_case_with(path, [&](const contact::ExtraSections& extra) { return contact::read_contact_case(path, extra); });
}

WearCase read_wear_case_text(const std::string& text, const std::string& label, const std::filesystem::path& base_dir) {
  return read_wear_case_with(label, [&](const contact::ExtraSections& extra) {
    return contact::read_contact_case_text(text, label, base_dir, extra);
  });
}

void validate(const WearCase& c) {
  using contact::where;
  const contact::ContactCase& k = c.contact;
  const WearSection& w = c.wear;
  // the lubricant's regime law sets the life's mu and wear factor from the film of the steady unworn contact
  // (docs/lubrication-and-temperature.md §2); the flash temperature (thermal:) it computes per evaluation of a steady
  // duty cycle (the scuffing margin, docs/fatigue.md)
  if (k.lubricant && k.transient)
    throw key_error(k, "lubricant", "lubricant, transient: a wear run takes the film of a steady duty cycle (one "
                    "entrainment speed); remove the lubricant: section or the transient: one");
  if (k.lubricant)
    for (const auto& [key, law] : {std::pair{"wear.body1.law", &w.body1}, std::pair{"wear.body2.law", &w.body2}})
      if (*law && ((*law)->law == WearLawKind::Kth || (*law)->law == WearLawKind::Usfd))
        throw key_error(k, key, std::string(key) + ", lubricant: the " + to_string((*law)->law) + " law's map is "
                        "measured on dry contacts; with a lubricant use energy or archard (their coefficient is "
                        "scaled by the regime's wear factor)");
  if (k.lubricant && !(contact::speed_of(k) > 0))
    throw key_error(k, "kinematics.speed_m_per_s", "kinematics.speed_m_per_s, lubricant: the film needs an "
                    "entrainment speed V > 0");
  if (k.thermal && k.transient)
    throw key_error(k, "thermal", "thermal, transient: a wear run computes the flash temperature of a steady duty "
                    "cycle; remove the thermal: section or the transient: one");
  // Dang Van's index on the final worn contact is of a steady rolling pass (wear/dang_van_life.h)
  for (const auto& [key, body] : {std::pair{"bodies.body1.dang_van", &k.bodies.body1}, std::pair{"bodies.body2.dang_van", &k.bodies.body2}})
    if (body->dang_van && k.transient)
      throw key_error(k, key, std::string(key) + ", transient: a wear run evaluates Dang Van's index on its final worn "
                      "contact in steady rolling; remove the dang_van key or the transient: section");
  if (w.limits.scuffing && !(k.thermal && k.thermal->critical_temperature_C && k.thermal->bulk_temperature_C))
    throw key_error(k, "wear.limits.scuffing", "wear.limits.scuffing, thermal: the scuffing limit needs the flash "
                    "temperature's thermal: section with bulk_temperature_C and critical_temperature_C (Blok's criterion)");
  if (!k.profiles)
    throw key_error(k, "wear", "wear, profiles: the worn body needs a lateral profile; give a profiles: "
                    "section (e.g. body1: { crowned: { Ry_m: 0.5, width_m: 0.02 } })");
  if (k.solver.normal == contact::NormalChoice::Hertz)
    throw key_error(k, "solver.normal", "solver.normal: a wear run solves the worn profiles with auto "
                    "(Hertz while the curvature is constant, then semi-Hertz), semi-hertz or halfspace, not " +
                    std::string(to_string(k.solver.normal)));
  if (k.inertia) throw key_error(k, "inertia", "inertia: not supported in a wear run");
  for (const auto& [key, law, R] : {std::tuple<const char*, const std::optional<WearLaw>*, double>{
                                        "wear.body1", &w.body1, k.bodies.body1.Rx_m},
                                    {"wear.body2", &w.body2, k.bodies.body2.Rx_m}}) {
    if (!law->has_value()) continue;
    if (!(R > 0) || !std::isfinite(R))
      throw key_error(k, key, std::string(key) + ": the body wears but its rolling radius Rx_m = " + number(R) +
                      " gives no revolutions (a flat or concave body cannot be the worn body)");
    const WearLawKind kind = (*law)->law;
    // Archard's law is the energy law with k_E = K/(H mu) (wear_law.h): mu = 0 has no energy equivalent
    if (kind == WearLawKind::Archard && !(k.friction.mu > 0))
      throw key_error(k, "friction.mu", std::string("friction.mu, ") + key + ".law: the archard law needs friction (it is "
                      "the energy law with k_E = K/(H mu)), got mu = " + number(k.friction.mu) + "; give mu > 0");
    if (k.transient && kind != WearLawKind::Energy && kind != WearLawKind::Archard)
      throw key_error(k, std::string(key) + ".law", std::string(key) + ".law, transient: the " + to_string(kind) +
                      " law reads steady per-cell fields; a transient duty cycle takes energy or archard");
  }
  if (k.transient) {
    if (!contact::is_constant(k.load.normal_load_N))
      throw key_error(k, "load.normal_load_N", "load.normal_load_N: a wear run's duty cycle needs a constant "
                      "load (the worn contact is solved once per evaluation)");
    if (k.transient->scheme != contact::TransientScheme::Shift)
      throw key_error(k, "transient.scheme", "transient.scheme: a wear run's duty cycle uses shift");
  } else {
    contact::validate_steady(k, contact::SteadyRunner::WearRun);
    if (!(contact::speed_of(k) > 0))
      throw key_error(k, "kinematics.speed_m_per_s", "kinematics.speed_m_per_s: steady running needs a "
                      "rolling speed > 0 (revolutions)");
  }
  if (!w.snapshots_revolutions.empty() && w.snapshots_revolutions.back() > w.revolutions)
    throw key_error(k, "wear.snapshots_revolutions", "wear.snapshots_revolutions, wear.revolutions: snapshot at " +
                    number(w.snapshots_revolutions.back()) + " is after the end of the life budget, " +
                    number(w.revolutions));
  if (w.stepping.method == Method::FixedStep &&
      !(w.stepping.step_revolutions > 0))
    throw key_error(k, "wear.stepping", "wear.stepping.step_revolutions: fixed-revolutions needs a step > 0");
  if (!w.collective.empty()) validate_collective(c);
  // the shakedown limit reads the reference body's shear yield stress k
  if (w.limits.shakedown) {
    const int reference = w.body1 ? 1 : 2;
    const double k_Pa = reference == 1 ? k.bodies.body1.shear_yield_Pa : k.bodies.body2.shear_yield_Pa;
    if (!(k_Pa > 0))
      throw key_error(k, "wear.limits.shakedown", fmt::format("wear.limits.shakedown, bodies.body{0}.shear_yield_Pa: the "
                      "shakedown limit needs the shear yield stress k of body{0}, the reference body (the first that "
                      "wears); give bodies.body{0}.shear_yield_Pa", reference));
  }
  // the corrected fidelity (docs/fidelity.md): the exact theory needs friction; a transient duty cycle is corrected
  // at its steady part, which it must have (a collective's conditions are checked each by validate_collective)
  if (k.solver.fidelity == contact::Fidelity::Corrected && w.collective.empty()) {
    if (!(k.friction.mu > 0))
      throw key_error(k, "friction.mu", "friction.mu, solver.fidelity: the corrected fidelity solves Kalker's exact "
                      "theory, which needs friction; got mu = " + number(k.friction.mu));
    if (k.transient) {
      const contact::TransientCase t = contact::transient_case_of(k);
      if (!steady_part(t.inputs, t.settings.t_end_s))
        throw key_error(k, "solver.fidelity", "solver.fidelity, kinematics, transient.t_end_s: the corrected fidelity "
                        "corrects a transient duty cycle by the exact physics in steady rolling at the cycle's steady "
                        "part (a stretch of constant speed > 0, creepages and load, docs/fidelity.md); this duty cycle "
                        "has none before t_end_s = " + number(t.settings.t_end_s) + "; use fast or exact");
    }
  }
}

std::optional<SteadyPart> steady_part(const contact::TransientInputs& in, double t_end_s) {
  const contact::History* histories[] = {&in.speed_m_per_s, &in.xi, &in.eta, &in.phi_per_m, &in.normal_load_N};
  std::vector<double> t = {0.0, t_end_s};
  for (const contact::History* h : histories)
    for (const double ti : h->t_s)
      if (ti > 0 && ti < t_end_s) t.push_back(ti);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  std::optional<SteadyPart> best;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double t0 = t[i], t1 = t[i + 1];
    bool constant = true;
    for (const contact::History* h : histories) constant = constant && contact::constant_until(*h, t0) >= t1;
    if (!constant) continue;
    SteadyPart part;
    part.t0_s = t0;
    part.t1_s = t1;
    part.speed_m_per_s = contact::value_at(in.speed_m_per_s, t0);
    part.creepages = {contact::value_at(in.xi, t0), contact::value_at(in.eta, t0), contact::value_at(in.phi_per_m, t0)};
    if (part.speed_m_per_s > 0 && (!best || part.rolled_m() > best->rolled_m())) best = part;
  }
  return best;
}

void check_profile_resolves_contact(const WearCase& c, int body, double node_spacing_m, double contact_width_m,
                                    int min_nodes) {
  if (!(contact_width_m < min_nodes * node_spacing_m)) return;
  const std::string key = "profiles.body" + std::to_string(body);
  const double needed_m = contact_width_m / min_nodes;
  const std::string what = fmt::format(
      "{}: its nodes ({:.3g} m apart at most) are too coarse for the contact, {:.3g} m wide: the wear needs at least "
      "{} nodes across it, {:.3g} m apart or closer; ",
      key, node_spacing_m, contact_width_m, min_nodes, needed_m);
  if (contact::given(c.contact, key + ".file"))
    throw contact::key_error(c.contact, key + ".file", what + "give a profile file with nodes that close");
  throw contact::key_error(c.contact, key, what + "a generated profile spaces its nodes by its width_m (at "
                  "most width_m/" + number(1 / contact::kProfileMaxSpacingFraction) + "), so give " + key +
                  " as { file: PATH } (y_m,z_m) with nodes that close");
}

IntegratorOptions integrator_options(const WearStepping& s) {
  IntegratorOptions o;
  o.method = s.method;
  o.rtol = s.rtol;
  o.atol = s.atol_m;
  o.max_depth_step = s.max_depth_step_m;
  o.fixed_step = s.step_revolutions;
  o.max_steps = s.max_steps;
  return o;
}

std::string to_string(IntegratorOptions::Method method) { return contact::enum_name(kSteppingMethods, method); }

IntegratorOptions::Method parse_stepping_method(const std::string& name) {
  if (const std::optional<Method> method = contact::enum_from_name(kSteppingMethods, name)) return *method;
  throw contact::SettingError("wear.stepping", "method", "must be " + contact::enum_names_list(kSteppingMethods) +
                                                             ", got '" + contact::clipped(name) + "'");
}

void read_wear_law(YamlMap& m, WearLaw& law) { read_law(m, law); }
void read_wear_stepping(YamlMap& m, WearStepping& s) { read_stepping(m, s); }
void read_wear_fatigue(YamlMap& m, FatigueSection& f) { read_fatigue(m, f); }

}  // namespace wear
