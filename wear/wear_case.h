// A wear case: a contact case (lib/io/case.h) with a wear: section, read in one pass with the same
// errors (file, line, column, key path). The duty cycle is the case's kinematic history:
//   no transient: section  steady running, every history a constant; one duty cycle = one
//                          revolution of the reference body (the first body that wears);
//   transient: section     the histories over [0, transient.t_end_s], run by Satran (shift) with
//                          its steady stretches skipped (lib/tangential/satran.h, skip_steady), repeated over
//                          the life. The load must be constant (the worn profiles' contact is solved
//                          once per evaluation), and the law energy or archard (the per-cell laws
//                          read steady fields).
//
//   wear:
//     body1: { law: energy, k_E_m3_per_J: 1.0e-13 }   # the body that wears, with its law (and/or body2)
//     revolutions: 1.0e9            # the life budget, revolutions of the reference body (required)
//     limits: { max_depth_m: 1.0e-4, max_pressure_Pa: 0, edge: true, shakedown: false, scuffing: false }
//     stepping: { method: adaptive, rtol: 1.0e-3, atol_m: 1.0e-9,
//                 max_depth_step_m: 1.0e-5, step_revolutions: 0, max_steps: 100000 }
//     smoothing_wavelength_m: 5.0e-4    # cut-off of the volume-conserving Gaussian filter; 0 = none
//     snapshots_revolutions: [1.0e7, 3.0e7]   # worn profiles written there (and at the start and end)
//     checkpoint_interval_s: 10      # wall time between checkpoints (the last step is always saved)
//     fatigue: { law: burstow, threshold_N: 20, peak_at_N: 65, zero_at_N: 175, peak_damage: 1.0e-5 }
//                                    # optional: fatigue damage per strip, Miner (wear/fatigue.h, docs/fatigue.md)
//     collective:                    # optional: running conditions and their shares (wear/collective.h)
//       - { weight: 0.7 }                                            # the case's own condition
//       - { weight: 0.3, load: { normal_load_N: 2500 }, kinematics: { xi: 2.0e-3 } }
//
// Each body's law takes the keys of wear::WearLaw (wear_law.h): law, k_E_m3_per_J, archard_k,
// hardness_Pa, density_kg_per_m3, kth: {...}, usfd: {...}.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lib/io/case.h"
#include "wear/fatigue.h"
#include "wear/integrator.h"
#include "wear/wear_law.h"

namespace contact {
class YamlMap;
}

namespace wear {

struct WearLimits {
  double max_depth_m = 0;      // the life ends when the maximum worn depth reaches it; 0 = none
  double max_pressure_Pa = 0;  // ... when the peak contact pressure exceeds it; 0 = none
  bool edge = true;            // ... when the contact reaches a body's edge
  // ... when the load leaves Johnson's shakedown map (lib/subsurface/shakedown.h: the margin limit / (p0/k) - 1
  // crosses 0), k the reference body's bodies.bodyN.shear_yield_Pa; off unless asked (docs/fatigue.md)
  bool shakedown = false;
  // ... when the flash temperature reaches Blok's critical one (lib/thermal, docs/fatigue.md: the scuffing margin
  // thermal.critical_temperature_C - (bulk + flash) crosses 0); needs the thermal: section with both temperatures
  bool scuffing = false;
};

struct WearStepping {
  IntegratorOptions::Method method = IntegratorOptions::Method::Adaptive;  // adaptive | fixed-depth | fixed-revolutions
  double rtol = 1e-3;               // adaptive: relative tolerance on the worn depth
  double atol_m = 1e-9;             // adaptive: absolute tolerance, m
  double max_depth_step_m = 1e-5;   // fixed-depth: the largest depth worn in one update, m
  double step_revolutions = 0;      // fixed-revolutions: revolutions per update
  long max_steps = 100000;          // accepted steps in the whole run
};

// One running condition of a load collective (wear/collective.h): the case with the condition's load,
// kinematics, friction and transient keys in place of the case's, and its share of the revolutions.
struct WearCondition {
  double weight = 0;             // > 0; the weights of a collective sum to 1
  contact::ContactCase contact;  // the case as this condition runs it
  std::string location;          // FILE:LINE:COL of the condition's entry
};

struct WearSection {
  std::optional<WearLaw> body1, body2;  // the bodies that wear; at least one
  double revolutions = 0;               // required: the life budget
  WearLimits limits;
  WearStepping stepping;
  double smoothing_wavelength_m = 5e-4;
  std::vector<double> snapshots_revolutions;  // increasing, in (0, revolutions]
  double checkpoint_interval_s = 10;
  std::vector<WearCondition> collective;  // empty: the case's own running condition alone
  // rolling-contact fatigue damage accumulated over the life (wear/fatigue.h, docs/fatigue.md): damage 1 on the
  // reference body ends the life (LifeEnd::Fatigue); without the section there is none
  std::optional<FatigueSection> fatigue;
};

struct WearCase {
  contact::ContactCase contact;
  WearSection wear;
};

// reads and validates; throws contact::CaseError (file, line, key) on any problem, among them a case
// without profiles: (the worn body needs a lateral profile), a law the duty cycle cannot feed, or a
// worn body with a flat rolling radius (no revolutions)
WearCase read_wear_case(const std::string& path);
// the same from a document's text (lib/io/case.h read_contact_case_text: label, profiles relative to base_dir)
WearCase read_wear_case_text(const std::string& text, const std::string& label, const std::filesystem::path& base_dir);

// cross-key checks (read_wear_case runs them)
void validate(const WearCase& c);

// The steady part of a transient duty cycle (docs/fidelity.md, "Transient duty cycles"): the longest stretch, by
// distance rolled, between the breakpoints of the speed, creepage and load histories over [0, t_end_s] on which
// all of them are constant and the speed is > 0. The corrected fidelity corrects the cycle by the exact physics
// in steady rolling at its speed and creepages. Empty when the cycle has no such stretch.
struct SteadyPart {
  double t0_s = 0, t1_s = 0;
  double speed_m_per_s = 0;
  contact::Creepages creepages;
  double rolled_m() const { return speed_m_per_s * (t1_s - t0_s); }
};
std::optional<SteadyPart> steady_part(const contact::TransientInputs& inputs, double t_end_s);

// The worn body's profile must resolve the contact, its nodes carrying the wear: at least min_nodes
// across the contact's width. Throws contact::CaseError at profiles.body<N> (file, line) with what the
// user can set: a generated profile's nodes are width_m * kProfileMaxSpacingFraction apart, so the
// advice is a { file: PATH } profile with nodes close enough.
void check_profile_resolves_contact(const WearCase& c, int body, double node_spacing_m, double contact_width_m,
                                    int min_nodes);

// the integrator's settings of the case
IntegratorOptions integrator_options(const WearStepping& s);

// wear.stepping.method's names (one table, wear_case.cpp): "adaptive", "fixed-depth", "fixed-revolutions";
// the parse throws contact::SettingError (wear.stepping, method) naming them for anything else
std::string to_string(IntegratorOptions::Method method);
IntegratorOptions::Method parse_stepping_method(const std::string& name);

// one body's wear law and the stepping, read from their sections with a wear case's keys and errors (for
// the cases that carry a wear section of their own: the cam's, cam/cam_wear.h)
void read_wear_law(contact::YamlMap& m, WearLaw& law);
void read_wear_stepping(contact::YamlMap& m, WearStepping& s);

}  // namespace wear
