// The wear loop (docs/physics.md §6, docs/wear-loop.md): the worn depth h at the fixed lateral nodes of
// each wearing body's profile obeys an ODE in the revolutions N of the reference body (the first body
// that wears),
//   dh/dN = f(h):  worn profiles z + h -> normal problem -> tangential problem over the duty cycle
//                  -> dissipated energy per unit width E_l(y_j) per duty cycle -> the wear law's depth
//                  per strip -> mapped onto the profile's nodes and smoothed, conserving the volume
//                  -> times the duty cycles per revolution.
// One duty cycle is one revolution in steady running (E_l = P_l 2 pi R_ref / V), and the case's
// transient history otherwise (Satran; duty cycles per revolution 2 pi R_ref / q_cycle, q_cycle the
// distance it rolls). Its energy is spread evenly around each body's circumference: stop positions are
// assumed to vary, and wear at a fixed stop position (flat spots) is out of scope.
//
// The state vector is [h_body1 (its profile's nodes, if it wears) | h_body2 (likewise) | e | D], e the
// dissipated energy scaled to a depth, e = E kEnergyScale: integrated by the same Runge-Kutta weights
// as h, it makes "worn volume = k_E x dissipated energy" checkable to rounding at every step; D, with a
// wear.fatigue section only, the fatigue damage at the reference body's nodes (Miner's sum of Burstow's
// damage per pass, wear/fatigue.h, docs/fatigue.md), scaled to a depth as D x damage_scale_m.
// The rolling radius change of the worn body (Rx) is ignored: z is measured from the unworn radius.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/normal/profile.h"
#include "lib/tangential/satran.h"
#include "lib/normal/normal.h"
#include "lib/normal/semi_hertz.h"
#include "lib/tangential/tangential.h"
#include "lib/fidelity.h"
#include "lib/io/case.h"
#include "lib/io/case_run.h"
#include "lib/lubrication/regime.h"
#include "lib/model/contact_model.h"
#include "wear/dang_van_life.h"
#include "wear/fatigue.h"
#include "wear/integrator.h"
#include "wear/life.h"
#include "wear/profile_update.h"
#include "wear/wear_case.h"
#include "wear/wear_law.h"

namespace wear {

// everything an evaluation of f needs, built once from the case
struct WearModel {
  std::string name;
  contact::Profiles profiles;  // the unworn profiles
  double Rx1_m = 0, Rx2_m = 0;
  contact::ElasticPair materials;
  contact::GridSpec grid;
  contact::SemiHertzOptions normal_options;
  // solver.normal: semi-hertz, halfspace, or auto (Hertz while the curvature is constant and the profiles unworn)
  contact::NormalChoice normal_choice = contact::NormalChoice::Auto;
  double normal_load_N = 0;
  double mu = 0;
  contact::TangentialScheme scheme = contact::kDefaultTangentialScheme;
  // the exact theory's steady solves extrapolated over grids h and 2h (solver.grid_extrapolation)
  contact::SteadyModelOptions steady_options;
  // the duty cycle: steady running at speed and creepages, or the transient history
  double speed_m_per_s = 0;
  contact::Creepages creepages;
  std::optional<contact::TransientCase> transient;
  // wear
  std::optional<WearLaw> law1, law2;
  double reference_radius_m = 0;   // Rx of the first body that wears: life counted in its revolutions
  double energy_scale = 0;         // e = E energy_scale (m/J)
  double smoothing_wavelength_m = 0;
  // the smoothing filter's kernel on each wearing body's nodes (which never move): built once for the run
  SmoothingKernel smoothing1, smoothing2;
  WearLimits limits;
  int n1 = 0, n2 = 0;              // nodes of each body in the state (0: the body does not wear)
  // a load collective (wear/collective.h): each running condition's model and its share of the revolutions;
  // empty for the case's one running condition
  std::vector<WearModel> conditions;
  std::vector<double> weights;
  int collective_threads = 0;      // threads evaluating the conditions' rates; 0 = one per condition up to the cores
  // solver.fidelity (docs/fidelity.md): fast (the models above alone), corrected (their rate corrected by the
  // exact physics on a schedule, correction_tolerance) or exact (the models above are the exact physics)
  contact::Fidelity fidelity = contact::Fidelity::Fast;
  double correction_tolerance = 0.1;
  bool error_estimate = true;  // the fast fidelity's estimate at the end of the life (solver.error_estimate)
  // the exact physics on the same case (half-space normal, Kalker's exact theory, the case's grid): the
  // corrected fidelity's corrections and the fast fidelity's error estimate at the end of the life (a transient
  // duty cycle's: in steady rolling at its steady part); empty for the exact fidelity, mu = 0, a transient duty
  // cycle without a steady part, and a collective (its conditions have theirs)
  std::vector<WearModel> exact_physics;
  // a transient duty cycle's steady part (wear/wear_case.h), where the exact physics above runs in steady rolling;
  // empty for a steady duty cycle
  std::optional<SteadyPart> steady_part;
  // the fast models on the exact physics' grid when solver.correction_grid makes it another than the case's, and
  // at the steady part of a transient duty cycle:
  // a correction is the exact physics' rate over these, both on that grid (the fast models' own dependence on
  // the grid cancels in the ratio, the exact physics' does not: docs/fidelity.md), applied to the fast rate on
  // the case's grid; empty otherwise
  std::vector<WearModel> correction_fast;
  // and the exact physics on the case's grid, whose normal solve gives the limits near the end of the life
  // (FidelityCorrection::exact_limits): where the life ends is the edge of the case's grid, not the coarse one's
  std::vector<WearModel> limits_physics;
  // fatigue (wear.fatigue, docs/fatigue.md): the damage at each of the reference body's nD nodes, in the state as
  // D x damage_scale_m (the depth limit, or kDamageScale_m without one: the integrator's tolerances and a
  // fixed-depth step weigh damage 1 as they weigh that depth); nD = 0 without the section
  std::optional<FatigueSection> fatigue;
  int nD = 0;
  double damage_scale_m = 0;
  // the shakedown limit (wear.limits.shakedown): the reference body's shear yield stress k; 0 = not given
  double shear_yield_Pa = 0;
  // with the case's lubricant: (docs/lubrication-and-temperature.md §2, "In a life"): the film of the unworn contact
  // (the case's speed, load and profiles, the normal solver auto's patch), the regime law at its lambda; its mu is mu
  // above, and its wear factor multiplies the laws' depths per duty cycle. A collective's conditions each their own.
  std::optional<contact::ContactLubrication> lubrication;
  contact::RegimeFriction regime;
  double wear_factor = 1;
  // the flash temperature of a steady duty cycle (the case's thermal: section; lib/thermal), and the surfaces' speeds
  std::optional<contact::ThermalSection> thermal;
  double v1_m_per_s = 0, v2_m_per_s = 0;

  int state_size() const { return n1 + n2 + 1 + nD; }
  int energy_index() const { return n1 + n2; }
  int damage_index() const { return n1 + n2 + 1; }
};
// the depth damage 1 stands for in the state when the case has no depth limit
constexpr double kDamageScale_m = 1e-4;

// The memory a wear run needs, estimated before its model is built (bytes): what grows with the worn
// profiles' nodes. Per wearing body of n nodes, the smoothing kernel (wear/profile_update.h: 8 bytes per pair
// of nodes within wear.smoothing_wavelength_m, smoothing_kernel_entries, n^2 lc / width on uniform nodes)
// and kStateCopiesPerNode copies of the state and the worn profile; times the running conditions of a load
// collective (each has its own model). The grid's fields (solver.nx x ny) do not grow with the nodes and
// are not counted.
constexpr double kStateCopiesPerNode = 32;  // doubles per node: integrator stages, the cache's worn profiles, rows
double estimate_memory_bytes(const WearCase& c);

// estimate_memory_bytes against the case's solver.max_memory_bytes: contact::CaseError at the worn profile's
// line naming profiles.body<N>, wear.smoothing_wavelength_m and solver.max_memory_bytes when above it
void check_memory(const WearCase& c);

// throws contact::CaseError for what validate(WearCase) refuses, and check_memory's refusal
WearModel make_wear_model(const WearCase& c);

// the unworn state (zeros)
Eigen::VectorXd initial_state(const WearModel& m);

// the profiles worn by the state's depths
contact::Profiles worn_profiles(const WearModel& m, const Eigen::VectorXd& state);

// the normal problem on worn profiles, and what the tangential problem and the lifetime limits read from it,
// whichever solver ran
struct NormalState {
  contact::ContactPatch patch;  // the patch the duty cycle runs on
  contact::NormalSolverKind solver = contact::NormalSolverKind::SemiHertz;  // the solver that ran
  double grid_y0_m = 0;         // profiles' y of the patch grid's y = 0
  double contact_y_min_m = 0, contact_y_max_m = 0;  // lateral extent of the contact (profiles' y)
  double approach_m = 0;        // from the gap's minimum over the overlap
  bool reaches_edge = false;    // the contact reaches an end of the profiles' overlap
  double edge_margin_m = 0;  // lateral distance from the contact to the nearest end of the profiles' overlap
  // the edge limit's continuous function (< 0 inside, > 0 past the edge): edge_limit_value_m for Hertz and
  // semi-Hertz, contact::HalfspaceOnProfiles::edge_value_m for the half-space
  double edge_limit_m = 0;
  contact::SemiHertzResult profile_solve;  // Hertz's or the semi-Hertzian solve (empty for the half-space)
  contact::HalfspaceOnProfiles halfspace;  // the half-space's (its grids and pressures: the next solve's start)
};

// the contact's state after one evaluation
struct ContactReport {
  double a_m = 0, b_m = 0, p0_Pa = 0;
  double Fx_N = 0;        // steady: the creep force; transient: at the end of the duty cycle
  double power_W = 0;     // mean dissipated power over the duty cycle
  double edge_margin_m = 0;  // lateral, 0 once the contact reaches the edge
  double edge_limit_m = 0;   // edge_limit_value_m: < 0 inside, > 0 past the edge (the edge limit's function)
  contact::NormalSolverKind normal_solver = contact::NormalSolverKind::SemiHertz;  // Hertz, semi-Hertz or half-space
  // Johnson's shakedown margin (lib/subsurface/shakedown.h: limit / (p0/k) - 1, > 0 inside) from p0, |Fx|/Fz and
  // the reference body's k; NaN without k
  double shakedown_margin = std::numeric_limits<double>::quiet_NaN();
  double max_tgamma_N = 0;  // the largest strip T-gamma (wear/fatigue.h); 0 without wear.fatigue
  // with the case's thermal: section, the flash temperature's rise (Blok's partition, lib/thermal) and the scuffing
  // margin critical - (bulk + flash) (with both temperatures); NaN without
  double flash_rise_K = std::numeric_limits<double>::quiet_NaN();
  double scuffing_margin_K = std::numeric_limits<double>::quiet_NaN();
};

struct WearRate {
  Eigen::VectorXd dstate_dN;              // (state_size) per revolution of the reference body
  Eigen::ArrayXd strip_energy_J_per_m;    // (ny) per duty cycle
  double strip_y0_m = 0, strip_dy_m = 0;  // strip j covers [strip_y0 + j dy, strip_y0 + (j + 1) dy] (profiles' y)
  double cycles_per_revolution = 0;
  double energy_per_revolution_J = 0;
  ContactReport contact;
};

// The corrected fidelity's correction (docs/fidelity.md): the exact physics' and the fast models' rates on the
// worn state of the last correction. The corrected rate at a state h is, per worn node i (body1's, then body2's),
//   f_i(h) c_i + r_i,  c_i = (x_i + e) / (f0_i + e),  r_i = x_i - f0_i c_i,  clipped at 0,
// x the exact and f0 the fast rate at the correction (smoothed dh/dN; both on the exact physics' grid, so a
// coarser correction grid compares like with like: WearModel::correction_fast), f(h) the fast rate on the case's
// grid, e = kCorrectionFloor x the body's largest
// f0: a ratio where the fast model wears, an absolute difference held where it does not (no division by a
// rate near 0), and the exact rate itself at the correction's state. The energy's rate is the fast one scaled
// by the reference body's worn area rate, corrected over fast, so worn volume = k_E x energy still holds.
struct FidelityCorrection {
  bool valid = false;
  double N = 0;                          // revolutions where the exact physics was solved
  Eigen::VectorXd state;                 // the worn state it was solved on
  Eigen::VectorXd exact_rate, fast_rate;  // (n1 + n2) dh/dN per node there, exact and fast (the exact's grid)
  double exact_energy_J = 0, fast_energy_J = 0;  // per revolution there (fast: the case's grid, the schedule's)
  double approach_m = 0;                 // the exact physics' approach there (the schedule's depth scale)
  // the lifetime limits' functions, exact minus fast there, held and added to the fast ones until the next
  // correction: the life ends where the exact physics' edge and peak pressure say (as the exact life does)
  double edge_offset_m = 0, pressure_offset_Pa = 0;
  // near the end of the life (the exact edge value within kNearEdge approaches of 0, or the exact peak pressure
  // within kNearEdge x the tolerance of its limit) the limits are the exact physics' normal solve itself, from
  // this correction on: the two normal models define the edge differently, and their offset drifts
  bool exact_limits = false;
  long solves = 0;                       // exact-physics solves over the life (resumed runs included)
};
constexpr double kCorrectionFloor = 0.1;
constexpr double kNearEdge = 1.0;

// The fast models' error against the exact physics on one worn state (the last correction's, or the end of a
// fast life): total dissipated power relative error, fast / exact - 1, and the per-strip power's relative L1,
// both strips' energies mapped onto the reference body's nodes (conserving, unsmoothed), sum |fast - exact| /
// sum |exact| weighted by the nodes' widths. NaN where not estimated.
struct FidelityError {
  double N = std::numeric_limits<double>::quiet_NaN();
  double power_rel = std::numeric_limits<double>::quiet_NaN();
  double power_l1 = std::numeric_limits<double>::quiet_NaN();
  double exact_energy_J = std::numeric_limits<double>::quiet_NaN();  // the exact physics' per revolution there
};

// the last results, keyed by the worn profiles' hash (an unchanged profile is not solved again)
struct WearCache {
  bool reuse = true;  // false: every evaluation solves afresh (to show that reuse changes nothing)
  std::uint64_t normal_key = 0;
  bool normal_valid = false;
  NormalState normal;
  std::vector<std::pair<std::uint64_t, WearRate>> rates;  // the last few
  LifeCounters counters;  // only the solve and evaluation counts are kept here
  bool edge_reported = false;  // the contact at the edge of a life without the edge limit: warned once
  // the half-space (solver.normal halfspace): each solve starts from the last one's pressures (normal's
  // halfspace); false starts every solve cold (to show what the warm start saves and that it changes
  // nothing beyond the solver's tolerance). Its solves and iterations, coarse and fine, over the run:
  bool halfspace_warm_start = true;
  long halfspace_solves = 0, halfspace_iterations = 0;
  std::vector<WearCache> conditions;  // a load collective's: one per running condition (its solves added above)
  // the fidelity: the correction in force (corrected), the fast models' error estimate, and the exact
  // physics' own cache (one, its half-space solves started cold so that they depend on the state alone)
  FidelityCorrection correction;
  FidelityError error;
  std::vector<WearCache> exact_physics;
  std::vector<WearCache> correction_fast;  // WearModel::correction_fast's
  std::vector<WearCache> limits_physics;   // WearModel::limits_physics's (its half-space solves cold)
};

// Thrown by normal_state where the worn geometry ends the life: run_life ends it at its last accepted
// step, status failed, with the message (docs/stress-suite.md):
//   UnresolvedContact: a worn profile splits the contact into patches that no strip centre hits, even
//     with 8 times the case's strips (finding 7, "patches"): the strips cannot carry the load;
//   WornThrough: a body's worn profile is deeper than the body is wide (finding 13), which no profile
//     may be; wear.limits.max_depth_m ends a life before that.
struct LifeEndingGeometry : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct UnresolvedContact : LifeEndingGeometry {
  using LifeEndingGeometry::LifeEndingGeometry;
};
struct WornThrough : LifeEndingGeometry {
  using LifeEndingGeometry::LifeEndingGeometry;
};
//   NormalNotConverged: no approach carries the load on the worn geometry (semi_hertz.h's root find,
//     its remedy for lobes merging included, ended with status MaxIterations).
struct NormalNotConverged : LifeEndingGeometry {
  using LifeEndingGeometry::LifeEndingGeometry;
};

NormalState normal_state(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache);
// normal_state as the wear loop uses it: the normal solver's own warnings held back, and reported from
// its typed result instead (an unconverged approach at every solve; the contact at the edge once, as a
// warning only when wear.limits.edge is off: with it on, that is the life's end, which run_life reports)
NormalState solved_normal_state(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache);

// The edge limit as a signed, continuous function of the worn state (m of gap): the interpenetration
// eps delta that bounds the contact (docs/semi-hertz.md) minus the gap at the nearer end of the profiles'
// lateral overlap, both measured from the gap's minimum. Negative while the contact lies inside the
// overlap, 0 where its edge reaches an end, positive once it would extend past one (the solver then cuts
// it at the end: SemiHertzResult::reaches_edge). Unlike the lateral margin, it keeps changing past the
// edge, so a root finder sees a sign change and locates the limit.
double edge_limit_value_m(const contact::Profiles& worn, const contact::SemiHertzResult& normal);
// dh/dN at the state: the fast models' rate, corrected by cache.correction for the corrected fidelity
WearRate wear_rate(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache);

// The corrected fidelity's schedule, at an accepted step's end (and the life's start): solves the exact physics
// on the state and makes it the correction when there is none yet, when the worn depth has moved somewhere by
// more than correction_tolerance x the last correction's approach, or when the fast models' energy per
// revolution has moved by more than correction_tolerance (relative); returns whether it did. Also sets
// cache.error from that solve. False for the other fidelities.
bool update_correction(const WearModel& m, double N, const Eigen::VectorXd& state, WearCache& cache);
// whether the model has exact physics to estimate its error with (a collective: any condition has)
bool has_exact_physics(const WearModel& m);
// whether the corrected fidelity's correction is in force (a collective: every condition's)
bool correction_made(const WearModel& m, const WearCache& cache);
// the exact-physics solves counted in the cache (a collective: its conditions' added)
long exact_solves(const WearModel& m, const WearCache& cache);
// the exact physics' normal solve on the state, in cache.exact_physics (the corrected fidelity's limits near the end)
NormalState exact_normal_state(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache);
// The fast models' error against the exact physics on the state (one exact solve), as in FidelityError;
// NaN fields for a model without exact_physics
FidelityError fast_model_error(const WearModel& m, double N, const Eigen::VectorXd& state, WearCache& cache);

// what the state says: the largest depth over the wearing bodies, each body's worn volume
// (2 pi R_k x the profile's worn area), the dissipated energy, the largest fatigue damage (0 without
// wear.fatigue) and the reference body's y where it is (NaN where there is no damage)
double max_depth_m(const WearModel& m, const Eigen::VectorXd& state);
double max_damage(const WearModel& m, const Eigen::VectorXd& state);
double max_damage_y_m(const WearModel& m, const Eigen::VectorXd& state);
double worn_volume_m3(const WearModel& m, const Eigen::VectorXd& state, int body);  // body 1 or 2
double dissipated_energy_J(const WearModel& m, const Eigen::VectorXd& state);

// ---- the life ----
// The roller's life on the one life driver (wear/life.h): its rate wear_rate, its limits depth, peak pressure
// and edge; LifeStart, LifeCounters, LifeEnd and LifeFailure are the driver's.

struct LifeStep {
  long step = 0;              // accepted steps so far, over the whole life
  double N = 0;
  const Eigen::VectorXd* state = nullptr;
  StepInfo info;              // this step (its counters over the whole life)
  LifeCounters counters;      // the life's, up to this step's end (a checkpoint stores them)
  ContactReport contact;      // at the step's end
};

struct LifeHooks {
  std::function<bool(const LifeStep&)> on_step;  // after every accepted step; false stops the run
  std::function<void(double N, const Eigen::VectorXd& state)> on_snapshot;  // at each snapshot revolution
};

struct LifeResult : LifeOutcome {
  ContactReport contact;  // at the end
  // the fast models' error against the exact physics: at the last correction (corrected), on the final worn
  // state (fast), NaN for the exact fidelity and where there is no exact physics (docs/fidelity.md)
  FidelityError error;
  long exact_solves = 0;  // exact-physics solves over the life (corrections; the fast life's estimate)
  // Dang Van's index on the final worn contact, per body with bodies.bodyN.dang_van (wear/dang_van_life.h): set by
  // session::drive_wear_life when asked, empty otherwise
  std::vector<LifeDangVan> dang_van;
};

// integrates from start to the first lifetime limit (located by root finding) or the budget
// wear.revolutions, stepping through the snapshot revolutions
LifeResult run_life(const WearModel& m, const WearCase& c, const LifeStart& start, const LifeHooks& hooks,
                    WearCache& cache);

}  // namespace wear
