// A case file (YAML) read into validated plain structs. One struct per section, YAML keys equal to
// the field names, defaults in-class. Every key the reader reads is marked; a key left over is an
// error, so a typo never becomes a silent default. Errors throw CaseError, whose message names the
// file, the line and column, and the key path:
//   cases/paper.yaml:12:5: friction.mu: must be in [0, 10], got -1
//
// Time histories. The load, the kinematics and the path speed of the roller's inertia are read as
// contact::History (lib/history.h), in one of three forms:
//   speed_m_per_s: 1.8                                   # a constant
//   speed_m_per_s: { ramp: [0, 0, 1.0e-4, 1.8] }         # [t0_s, v0, t1_s, v1]: linear, held outside
//   speed_m_per_s: { table: [[0, 0], [1.0e-4, 1.8]] }    # [t_s, value] rows: linear, held outside
// The steady 'contact' command takes constants only (validate_steady); the 'transient' command
// needs a transient: section and takes the histories as they are (transient_case_of):
//   transient: { scheme: shift, t_end_s: 4.0e-4, dt_s: 0, substep: false, snapshots_s: [1.0e-4] }
//   inertia:   { R1_m: 0.020, J1_kg_m2: 3.946e-5, T_res_N_m: 0, omega1_0_rad_per_s: 0,
//                path_speed_m_per_s: 1.0 }    # then kinematics.speed_m_per_s and xi follow from the spin
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/elastic.h"
#include "lib/grid.h"
#include "lib/normal/hertz.h"
#include "lib/normal/normal.h"
#include "lib/history.h"
#include "lib/errors.h"
#include "lib/fidelity.h"
#include "lib/lubrication/film.h"
#include "lib/lubrication/regime.h"
#include "lib/thermal/flash_temperature.h"
#include "lib/io/key_locations.h"
#include "lib/patch.h"
#include "lib/subsurface/dang_van.h"
#include "lib/normal/profile.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/tangential.h"

namespace contact {


struct BodySection {                  // bodies.body1 / bodies.body2
  double Rx_m = kFlat, Ry_m = kFlat;  // required (Ry_m: only without profiles:); .inf for flat, negative for concave
  double E_Pa = 0;                    // required
  double nu = 0;                      // required, [0, 0.5)
  // optional: the shear yield stress k for the fatigue indicators (lib/subsurface/shakedown.h), in
  // [kShearYieldMin_Pa, kShearYieldMax_Pa]; 0 (absent): none for this body
  double shear_yield_Pa = 0;
  // optional (dang_van: { a, b_Pa }): Dang Van's constants for the subsurface fatigue index over a rolling
  // pass (lib/subsurface/dang_van.h); absent: none for this body
  std::optional<DangVanConstants> dang_van = std::nullopt;
};
struct BodiesSection {
  BodySection body1;  // upper body (roller)
  BodySection body2;  // lower body (path)
};
struct LoadSection {
  History normal_load_N = constant_history(0.0);  // required: a constant > 0, or values >= 0, positive somewhere
};
struct KinematicsSection {  // histories; the steady command takes constants only
  History speed_m_per_s = constant_history(1.0);  // rolling speed V >= 0
  History xi = constant_history(0.0);             // longitudinal creepage, (v2 - v1)/V
  History eta = constant_history(0.0);            // lateral creepage
  History phi_per_m = constant_history(0.0);      // spin creepage
};
struct FrictionSection {
  double mu = 0;  // required, >= 0
};
// Lateral profiles of the bodies (lib/normal/profile.h), each one of
//   body1: { file: profiles/x.csv }                       # relative to the case file's directory, or absolute
//   body1: { crowned: { Ry_m: 0.5, width_m: 0.02 } }
//   body1: { flat: { width_m: 0.03 } }
//   body1: { arc: { R_m: -0.6, width_m: 0.02 } }
//   body1: { flat_worn_crown: { Ry_m: 0.5, width_m: 0.02, band_half_width_m: 0.0015 } }
// With profiles the bodies' Ry_m are not given (the profiles are the lateral geometry); Rx_m stay.
struct ProfilesSection {
  Profiles profiles;          // read or generated when the case is read
  bool heathcote_slip = true;  // the strips' creepage offset from the rolling radii across the profiles
};
// The choices are read once into their enums (named by their to_string/parse functions, which the messages
// and the reports share); the solvers take them from here (lib/model/contact_model.h, lib/normal/normal.h).
struct SolverSection {
  NormalChoice normal = NormalChoice::Auto;  // auto | hertz | semi-hertz | halfspace
  // relaxed (the default: lib/tangential/relaxed.h) | consistent | classic | exact
  TangentialScheme tangential = kDefaultTangentialScheme;
  int nx = 80, ny = 80;
  // a wear life's physics (lib/fidelity.h, docs/fidelity.md): fast (the models above), corrected (them,
  // corrected by the exact physics on a schedule) or exact (sets normal halfspace and tangential exact)
  Fidelity fidelity = Fidelity::Fast;
  // corrected: the exact physics is solved again once the worn depth has moved by more than this fraction of
  // the contact's approach at the last correction somewhere, or the fast model's power by more than it
  double correction_tolerance = 0.1;
  // the exact physics' grid (n x n) for the corrections and the error estimate; 0 = the case's nx x ny
  int correction_grid = 0;
  // the fast fidelity's error estimate at the end of a wear life: one exact-physics solve on the final worn state
  // (about 70 ms on the paper's roller at 80 x 80); false leaves it out (large sweeps)
  bool error_estimate = true;
  // Kalker's exact theory's steady solves extrapolated in the grid: each solved on the grid and on half its cells
  // each way and combined (lib/tangential/grid_extrapolation.h, docs/exact-theory.md §4); needs the exact theory
  // (tangential: exact, or the exact physics of a corrected fidelity), nx and ny even, steady running
  bool grid_extrapolation = false;
  // a run whose memory is estimated above this is refused before it starts, naming the keys that drive the
  // estimate (a wear run: wear/wear_loop.h estimate_memory_bytes); 2 GiB
  double max_memory_bytes = 2.0 * 1024 * 1024 * 1024;
};
struct TransientSection {  // the 'transient' command's run (lib/tangential/satran.h)
  TransientScheme scheme = TransientScheme::Shift;  // shift | upwind | lax-friedrichs
  double t_end_s = 0;               // required, > 0
  double dt_s = 0;                  // upwind, lax-friedrichs: the step; shift: the longest step (0 = no limit)
  bool substep = false;             // split a step that breaks CFL <= 1 instead of refusing it
  std::vector<double> snapshots_s;  // increasing, in [0, t_end_s]: fields at the end of the step reaching each
};
struct InertiaSection {  // the roller spins up under the creep force (lib/tangential/satran.h, RollerInertia)
  double R1_m = 0;                // required, > 0: the roller's rolling radius
  double J1_kg_m2 = 0;            // required, > 0: its polar moment of inertia
  double T_res_N_m = 0;           // resisting torque on the roller
  double omega1_0_rad_per_s = 0;  // spin at t = 0, >= 0
  History path_speed_m_per_s = constant_history(0.0);  // required: V2(t) >= 0, the path's surface speed
};
// An EHL lubricant between the bodies (lib/lubrication/, docs/lubrication-and-temperature.md); without
// this section the contact is dry. Keys:
//   lubricant:
//     viscosity_Pa_s: 0.01                  # eta0 at the bulk temperature, > 0
//     pressure_viscosity_1_per_Pa: 2.0e-8   # alpha, > 0
//     roughness_Rq_m: { body1: 0.1e-6, body2: 0.2e-6 }   # RMS roughness of each surface, >= 0
//     lambda_mixed: 1.0                     # optional: boundary below (default kLambdaMixed)
//     lambda_full_film: 3.0                 # optional: full film above (default kLambdaFullFilm)
//     friction: { boundary: 0.1, mixed: 0.06, full_film: 0.03 }       # required: mu per regime
//     wear_factor: { boundary: 1, mixed: 0.1, full_film: 0 }         # required: factor on K per regime
// The regime law (lib/lubrication/regime.h regime_friction) reads the boundary and full-film values and the
// thresholds; a life takes its mu and wear factor (wear/wear_loop.h, cam/cam_lubrication.h).
struct LubricantSection {
  Lubricant lubricant;
  double Rq1_m = 0, Rq2_m = 0;   // RMS roughness of body 1 and body 2
  RegimeThresholds thresholds;
  RegimeCoefficients by_regime;  // the user's: no default (they depend on the oil, additives, surfaces)
};
// The flash temperature (lib/thermal/flash_temperature.h) of the steady contact's frictional power:
//   thermal:
//     body1: { conductivity_W_per_m_K: 46, density_kg_per_m3: 7850, specific_heat_J_per_kg_K: 470 }
//     body2: { ... }                       # each required, > 0
//     bulk_temperature_C: 80               # optional; required with critical_temperature_C
//     critical_temperature_C: 300          # optional: Blok's scuffing criterion on bulk + flash
struct ThermalSection {
  ThermalBody body1, body2;
  std::optional<double> bulk_temperature_C;
  std::optional<double> critical_temperature_C;
};
struct OutputSection {
  std::string directory;  // default: out/<case name>, relative to the working directory
  bool fields = true;     // write the fields on the grid (fields.csv)
  bool subsurface = true;  // 'contact': the stresses below the surface (subsurface.csv, subsurface_section.csv)
  double max_bytes = 1024.0 * 1024 * 1024;  // 'transient' refuses a run estimated to write more (1 GiB)
};

class YamlMap;  // lib/io/yaml_reader.h
// the keys of a lubricant: and a thermal: section (above) from their mapping, with the same errors; a cam case's
// cam.lubricant and cam.thermal (cam/cam_case.h) are read by them too
void read_lubricant(YamlMap& m, LubricantSection& l);
void read_thermal(YamlMap& m, ThermalSection& t);

struct ContactCase {
  std::string path;  // the file it was read from
  std::string name;  // 'name:' or the file's stem
  BodiesSection bodies;
  std::optional<ProfilesSection> profiles;  // present when the file has a profiles: section
  LoadSection load;
  KinematicsSection kinematics;
  FrictionSection friction;
  SolverSection solver;
  std::optional<TransientSection> transient;  // present when the file has a transient: section
  std::optional<InertiaSection> inertia;      // present when the file has an inertia: section
  std::optional<LubricantSection> lubricant;  // present when the file has a lubricant: section (else dry)
  std::optional<ThermalSection> thermal;      // present when the file has a thermal: section
  OutputSection output;
  KeyLocations locations;  // where each value was read; empty for a case built in code
};

class YamlMap;  // lib/io/yaml_reader.h
// the sections a command reads beyond the contact's (e.g. wear/wear_case.h's wear:), from the same
// top-level mapping and with the same errors; a section nobody reads stays an error
using ExtraSections = std::function<void(YamlMap& top_level)>;

// reads and validates; throws CaseError (file, line, key) on any problem
ContactCase read_contact_case(const std::string& path, const ExtraSections& extra = {});
// the same from a document's text (the Python bindings' case given as a dict): `label` stands for the file
// in the messages and the default name (its stem), profile files are relative to base_dir
ContactCase read_contact_case_text(const std::string& text, const std::string& label,
                                   const std::filesystem::path& base_dir, const ExtraSections& extra = {});

// A running condition over a copy of a case (wear/collective.h): the sections load, kinematics, friction and
// transient of the mapping, each optional; a key given replaces the case's (a history as a whole, the
// transient section as a whole), the others stay. Checked as the case's own keys are.
void read_running_condition(YamlMap& m, ContactCase& c);

// "FILE:LINE:COL: " of the key if it was read from the file, else of its closest enclosing section
// that was, else "FILE: " (nothing for a case built in code): the prefix of a cross-key message
std::string where(const ContactCase& c, std::string key);
// the same place as data (the key itself, or its nearest enclosing key that was read; the file alone
// when none was), for a CaseError whose reader wants the file, line and key apart (the Python bindings)
InputLocation location_of(const ContactCase& c, std::string key);
// CaseError(where(c, key) + message) carrying location_of(c, key)
CaseError key_error(const ContactCase& c, const std::string& key, const std::string& message);
// true if the key was read from the file
bool given(const ContactCase& c, const std::string& key);

// cross-key checks of any case (read_contact_case runs them); throws CaseError naming every key involved
void validate(const ContactCase& c);
// what steady running needs besides: every history constant, no inertia; with thermal:, both surfaces moving
// (V > 0, |xi| < 2). Who runs it steadily: the 'contact' command (the refusal points to 'transient'), or a wear
// run's steady condition (it points to the condition's transient: section, its duty cycle)
enum class SteadyRunner { ContactCommand, WearRun };
void validate_steady(const ContactCase& c, SteadyRunner runner = SteadyRunner::ContactCommand);
// the commands that do not use the lubricant: and thermal: sections (transient) refuse them, naming the section,
// rather than ignoring them
void refuse_lubrication_and_thermal(const ContactCase& c, const std::string& command);
// what the 'transient' command needs besides: a transient: section
void validate_transient(const ContactCase& c);

// conversions to the solvers' inputs
Bodies bodies_of(const ContactCase& c);
ElasticPair materials_of(const ContactCase& c);
GridSpec grid_of(const ContactCase& c);
// profiles of constant curvature within this (relative) tolerance are treated by Hertz (lib/normal/normal.h)
constexpr double kCaseCurvatureRtol = kConstantCurvatureRtol;

// the normal problem of a case as solver.normal asks (lib/normal/normal.h chooses; this only builds the
// problem from the case); its profiles point into c, which must outlive it
NormalProblem normal_problem_of(const ContactCase& c);
// its solve (solve_normal_converged): throws CaseError for a case the solver named cannot treat,
// NormalSolveError (lib/normal/normal.h) for a solve that did not converge, at a body's edge too; a
// converged contact reaching a body's edge comes back with reaches_edge.
NormalSolution solve_normal_of(const ContactCase& c);

// the steady values: throw CaseError naming the key if its history is not a constant
double normal_load_of(const ContactCase& c);
double speed_of(const ContactCase& c);
Creepages creepages_of(const ContactCase& c);

// the transient run of the case: validate_transient, then bodies, materials, mu, histories,
// inertia and settings (solver.nx, ny as the grid; snapshots in the file's order)
TransientCase transient_case_of(const ContactCase& c);

// the grid run_transient puts the contact on: it covers the largest contact of the run
// (lib/tangential/satran_run.cpp); callers use it to label per-strip output while the run streams
Grid transient_grid(const TransientCase& t);

// What a transient run will write, estimated before it runs (an upper bound on the steps: one per dx
// rolled and one per dt_s, skips of steady stretches not counted; every number at full precision).
struct TransientOutputEstimate {
  double steps = 0;  // steps the run takes at most
  double bytes = 0;  // timeseries.csv, strip_power.csv, strip_energy.csv and the snapshots together
};
// bytes of one number at full precision with its separator: "-1.2345678901234567e-05," (lib/io/csv.h)
constexpr double kCsvBytesPerNumber = 24;
TransientOutputEstimate estimate_transient_output(const TransientCase& t, bool fields);
// The estimate against output.max_bytes, before the run: a CaseError at transient.t_end_s's line naming the keys
// that drive it (transient.t_end_s, transient.dt_s, solver.nx, solver.ny, output.max_bytes) unless force. The
// command line (which also checks the free disk: session/output_folder.h) and the Python bindings (whose
// arrays hold the same numbers as doubles, a third of the text's bytes) share it.
void check_transient_output(const ContactCase& c, const TransientCase& t, bool fields, bool force);

// run_transient's refusal of the settings (a SettingError: the setting's key as data) as a CaseError at
// the case's key and line: "FILE:LINE:COL: transient.dt_s: ... the largest allowed dt_s is ... s"
CaseError transient_error(const ContactCase& c, const SettingError& e);

}  // namespace contact
