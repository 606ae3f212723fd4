// Satran: Kalker's simplified theory stepped in time (docs/physics.md §3-4; the paper is cited in
// docs/physics.md §7). With u = L tau on every strip,
//   du/dt - V du/dx = s - c,   c = L ( w_x/L1 - omega_z y/L3 ,  w_y/L2 + omega_z x/L3 ),
// w = (w_x, w_y) = V (xi, eta) the rigid slip velocity and omega_z = V phi the spin rate, and the
// Coulomb bound |tau| <= mu p. Built from w, c has no 0/0 at V = 0.
//
// Schemes (the state is the node tractions at the cell edges; the strip ends carry tau = 0 at the
// leading edge and the bound, 0 for a semi-elliptic pressure, at the trailing edge):
//   shift          steps of rolled distance dq = dx: material moves exactly one node, and the
//                  interval update is the steady solver's (lib/tangential/strip_march.h) applied to the previous
//                  step's upstream node. Its steady state is the steady solver's to rounding, and the
//                  discrete energy balance of §4 holds to rounding at every step. A step that rolls
//                  less than dx (rolling that stops before covering dx, the last step cut short to
//                  end the run, an inertia step bounded by dt_s) falls back to upwind at CFL = dq/dx
//                  < 1 (StepScheme::Upwind, counted); one that rolls nothing is exact (Standstill).
//   upwind         fixed dt, CFL = V dt/dx <= 1: tau* = tau_i + CFL (tau_{i+1} - tau_i) - c dt/L.
//   lax-friedrichs the paper's scheme: tau* = (tau_{i+1} + tau_{i-1})/2 + CFL (tau_{i+1} - tau_{i-1})/2 - c dt/L.
// The last two clip tau* to the bound node by node; the slip is (tau - tau*) L / dt. They smear at
// CFL < 1 and are kept for comparison.
//
// Energy over a step (per unit width, then summed over strips), E = (L dx/2) sum over interior nodes
// of |tau|^2:
//   dissipated = creep work - (E_end - E_start) - carried out at the trailing edge - transport loss,
// with E_start taken after two changes at the start of the step, both reported: nodes that left
// the contact (load decreased) release their energy, and a change of L (load, contact size or
// creepage ratio) rescales tau = u/L with u carried, where a smaller L lifts tau above mu p slipping
// back onto the bound; the energy that changes with both is reported as the flexibility term. For shift the balance is exact
// to rounding with no transport loss; upwind and Lax-Friedrichs lose energy in their transport
// (numerical diffusion), reported as its own term, not as dissipation by slip (which would wear).
#pragma once

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lib/elastic.h"
#include "lib/normal/hertz.h"
#include "lib/history.h"
#include "lib/tangential/strip_node.h"
#include "lib/tangential/tangential.h"

namespace contact {

enum class TransientScheme { Shift, Upwind, LaxFriedrichs };

std::string to_string(TransientScheme scheme);
// throws std::invalid_argument naming the valid schemes
TransientScheme parse_transient_scheme(const std::string& name);

// The scheme one step actually ran. A shift run's steps are Shift (dq = dx, exact), Standstill (no rolling,
// dq = 0: nothing is transported, exact too) or Upwind (0 < dq < dx: the fallback at CFL dq/dx < 1, which
// smears like the upwind scheme: where rolling never covers dx before the run ends, the inertia's steps
// bounded by dt_s, the last step cut short to end at t_end_s).
enum class StepScheme { Shift, Standstill, Upwind, LaxFriedrichs };
std::string to_string(StepScheme scheme);
// what satran_step runs for `scheme` with the rolled distance dq on cells of length dx
StepScheme step_scheme(TransientScheme scheme, double dq_m, double dx_m);

// rigid kinematics over one step
struct StepKinematics {
  double dt_s = 0;
  double dq_m = 0;      // rolled distance, integral of V dt
  double slip_x_m = 0;  // integral of w_x = v2 - v1 = V xi
  double slip_y_m = 0;  // integral of w_y = V eta
  double spin_rad = 0;  // integral of omega_z = V phi
};

// tractions at the nodes; lives across steps, owned by the caller
struct TransientState {
  int nx = 0, ny = 0;
  StripNodes nodes;  // (nx+1) x ny, one array per quantity: node i of strip j sits at x_edge(i), index i + j (nx+1)
  double L_m_per_Pa = 0;         // the flexibility the tractions refer to (u = L tau); 0 = not set yet
  double normal_load_N = 0;      // the contact's load at the last step (0 = none yet)
  // strips j and ny - 1 - j hold the same nodes, bit for bit: true at rest and after a step that
  // mirrored its strips (TransientSkips::mirrored); whoever writes the nodes otherwise clears it
  bool mirror_images = false;
  // every node's tau_y is 0: true at rest and after a step without lateral creepage or spin from such a
  // state (TransientSkips::lateral); whoever writes the nodes otherwise clears it
  bool lateral_free = false;
  // the strips from ny - ny/2 up are stale: they are the mirror images of the strips below them, which a run
  // (SatranWorkspace::defer_mirror) copies only when it reads them, not at every step; fill_mirrored_strips
  // copies them. false for every state a public function hands out.
  bool mirror_deferred = false;

  std::size_t index(int i, int j) const { return static_cast<std::size_t>(i) + static_cast<std::size_t>(j) * (nx + 1); }
  StripNode node(int i, int j) const { return nodes[index(i, j)]; }
  void set_node(int i, int j, const StripNode& n) { nodes.set(index(i, j), n); }
};

// the unloaded state (u = 0) on a grid
TransientState rest_state(const Grid& grid);
// copies the deferred mirror images into their strips (TransientState::mirror_deferred); nothing otherwise
void fill_mirrored_strips(TransientState& state);

struct StepResult {
  // exact shift steps: averages over the step (path integrals of the material crossing each
  // interval); upwind, lax-friedrichs and fallback steps: at the end of the step
  double Fx_N = 0, Fy_N = 0, Mz_N_m = 0;
  double stick_fraction = 0;
  Eigen::ArrayXd strip_energy_J_per_m;  // (ny) dissipated energy per unit width over the step

  // energy over the step (J)
  double dissipated_J = 0;
  double creep_work_J = 0;       // -integral(tau . c) dt: the energy the rigid slip puts in
  double elastic_change_J = 0;   // E_end - E_start (after the flexibility change)
  double trailing_J = 0;         // carried out at the trailing edge
  double released_J = 0;         // held by nodes that left the contact
  double flexibility_J = 0;      // change of E when tau is rescaled for a new L (u carried)
  double transport_J = 0;        // upwind, lax-friedrichs: energy lost by the transport's averaging
                                 // (numerical diffusion and outflow); 0 for exact shift steps
  double balance_residual_J = 0;  // dissipated - (creep - elastic change - trailing - transport)

  // fields on the grid (only when asked for): step means per cell
  Eigen::ArrayXXd tau_x_Pa, tau_y_Pa, slip_x_m_per_s, slip_y_m_per_s;
};

// What satran_step may leave out (each off only for its tests and benchmarks):
//   mirrored: without spin, on a mirror-symmetric patch (first_mirrored_strip) whose state holds mirror
//     images (TransientState::mirror_images), half the strips are stepped and the others take their
//     mirror images (the same to rounding);
//   lateral: without lateral creepage or spin, from a state without tau_y (TransientState::lateral_free),
//     the shift step's stick pass does not compute tau_y, which stays 0 (the same to the bit).
//   steady_strips: a strip whose last shift step left every node as it was (to the bit), stepped again with
//     the same rates, patch, flexibility and rolled distance (to the bit), is left as it is with the last
//     step's totals (the same to the bit); not where the fields are written.
struct TransientSkips {
  bool mirrored = true;
  bool lateral = true;
  bool steady_strips = true;
};

// One step on the contact `patch` with the flexibilities (L1, L2, L3, L) and friction of `problem`;
// the rigid kinematics `k` drive it (problem.creepages and speed are not used). For shift, k.dq_m is
// dx or less (less: an upwind step at CFL dq/dx). Throws std::invalid_argument for a CFL number
// above 1 or a state on another grid. `skips` leaves out work that cannot change the result beyond
// rounding (docs/accuracy-and-speed.md).
StepResult satran_step(const ContactPatch& patch, const TangentialProblem& problem, const StepKinematics& k,
                       TransientScheme scheme, TransientState& state, bool fields = false,
                       TransientSkips skips = {});

// What a run keeps from one step to the next, so that a step does not redo it (the numbers are the same to
// the bit): the shift step's scratch (rebuilt when the grid or the lateral rates change), the patch's mirror
// symmetry and which nodes lie outside its contact (asked again when patch_serial changes), the strips'
// totals. One per run, used by one caller at a time.
struct SatranWorkspace {
  SatranWorkspace();
  ~SatranWorkspace();
  SatranWorkspace(SatranWorkspace&&) noexcept;
  SatranWorkspace& operator=(SatranWorkspace&&) noexcept;

  // the caller's count of contact patches: bumped whenever the patch passed to satran_step is not the one of
  // the previous step (another object, or the same one changed). Steps on the same serial take its symmetry,
  // and that every node outside its contact holds no traction (true of every state from rest_state or from a
  // step on that patch), from the first step on it.
  unsigned long patch_serial = 0;
  // the threads the step may share its strips among (1: the calling thread alone); used where the grid has
  // at least kSatranParallelCells cells, where a second core pays for waking it
  int threads = 1;
  // mirrored strips left stale in the state until read (TransientState::mirror_deferred): the owner calls
  // fill_mirrored_strips before it hands the state out
  bool defer_mirror = false;

  struct Impl;
  std::unique_ptr<Impl> impl;
};

// a grid of fewer cells steps its strips on one thread (measured: docs/benchmarks.md)
constexpr int kSatranParallelCells = 160 * 160;

// The threads one run of Satran shares its strips among, for the runs started on the calling thread
// (run_transient with TransientSettings::threads = 0): by default every core. A program that runs
// one case per thread (a sweep) sets 1 on each of its threads, so that its cases do not compete for cores.
void set_satran_threads(int threads);
int satran_threads();

// satran_step with what the run keeps in `ws` (the numbers of the step above, to the bit)
StepResult satran_step(const ContactPatch& patch, const TangentialProblem& problem, const StepKinematics& k,
                       TransientScheme scheme, TransientState& state, bool fields, TransientSkips skips,
                       SatranWorkspace& ws);

// ---- runs over a time history ----

struct TransientInputs {
  History speed_m_per_s = constant_history(1.0);  // rolling speed V(t) >= 0
  History xi = constant_history(0.0);
  History eta = constant_history(0.0);
  History phi_per_m = constant_history(0.0);
  History normal_load_N = constant_history(0.0);
};

// The roller's speed at the end of an implicit inertia step: the root of the spin balance
// balance(omega_end) = J1 (omega_end - omega1) - (-R1 Fx - T_res) dt, monotone in omega_end, within omega1 +- span
// (span from the creep force's bound mu F), never below 0 (where the balance stays positive the roller stops at the
// bracket's low end). Shared by Satran's inertia step and the relaxed model's (lib/tangential/relaxed.h); `who` names
// the solver in the error thrown (std::runtime_error) when the root does not converge at time t_s.
double implicit_roller_speed_rad_per_s(const std::function<double(double)>& balance, double omega1_rad_per_s,
                                       double span_rad_per_s, double t_s, const char* who);

// The roller's inertia (beyond the paper): the path's surface speed V2(t) is prescribed; the roller
// (radius R1, polar moment J1, resisting torque T_res) spins up under the creep force,
//   J1 d omega1/dt = -R1 Fx - T_res,  w_x = V2 - omega1 R1,  V = (omega1 R1 + V2)/2 (docs/physics.md §5).
// omega1 is advanced implicitly with the tractions: the end-of-step balance is solved for omega1.
// Inertia runs use the shift scheme, with steps of at most dt_s (the coupling is stiff): where dt_s is
// shorter than dx/V a step falls back to upwind at CFL V dt/dx < 1 (counted in TransientResult::fallback_steps).
struct RollerInertia {
  double R1_m = 0;
  double J1_kg_m2 = 0;
  double T_res_N_m = 0;
  double omega1_0_rad_per_s = 0;
  History path_speed_m_per_s = constant_history(0.0);  // V2(t)
};

struct TransientSettings {
  TransientScheme scheme = TransientScheme::Shift;
  double t_end_s = 0;
  // upwind, lax-friedrichs: the step. shift: a step rolls one dx whatever dt_s is; dt_s (0 = no limit)
  // bounds only the steps that roll nothing (a standstill, exact) and the inertia's steps
  double dt_s = 0;
  bool substep = false;   // split a step that breaks CFL <= 1 instead of refusing it
  GridSpec grid;
  std::vector<double> snapshot_times_s;  // fields are recorded at the end of the step that reaches each
  // Skip steady running (shift, no inertia): once every input has been constant over a rolled
  // distance of 2 max a_j + 2 dx, the state is the steady one (to rounding), and the rest of the
  // constant stretch (whole steps, up to one step before the next change of an input, snapshot time
  // or t_end_s) is one record with the last step's strip powers times its duration, instead of a step
  // per dx rolled. The steps after it fall where they would without the skip.
  bool skip_steady = false;
  // the skips of satran_step: on by default, exact to rounding; off for their tests and benchmarks
  TransientSkips skips;
  // threads for the strips of a large grid (SatranWorkspace::threads): 0 = satran_threads() of the calling
  // thread; the results are the same to the bit for any count
  int threads = 0;
};

struct TransientCase {
  Bodies bodies;
  ElasticPair materials;
  double mu = 0;
  TransientInputs inputs;
  std::optional<RollerInertia> inertia;
  TransientSettings settings;
  // The contact on its own grid (e.g. semi-Hertzian on worn profiles, lib/normal/semi_hertz.h), used at
  // every step in place of Hertz's from the bodies; the load history must then be the constant
  // patch->normal_load_N (throws std::invalid_argument otherwise), settings.grid is not used.
  std::optional<ContactPatch> patch;
};

struct TransientRecord {  // one step
  int step = 0;
  double t_s = 0, q_m = 0;  // when the forces hold: mid-step for exact shift steps, else the step's end
  double dt_s = 0;
  double speed_m_per_s = 0, xi = 0, eta = 0, phi_per_m = 0, normal_load_N = 0;
  double omega1_rad_per_s = 0;  // at the end of the step (inertia runs; 0 otherwise)
  double Fx_N = 0, Fy_N = 0, Mz_N_m = 0;
  double power_W = 0;  // dissipated energy over the step / dt
  double stick_fraction = 0;
  double balance_residual_W = 0;
  double cfl = 0;
  StepScheme scheme = StepScheme::Shift;  // what the step ran
  bool skipped = false;  // steady running skipped (settings.skip_steady): dt_s spans the whole stretch
  // the last step, cut short to end at t_end_s (shift: an upwind step at CFL < 1): not the run's end values
  bool shortened = false;
};

struct Snapshot {
  double t_s = 0;  // end of the step
  Eigen::ArrayXXd pressure_Pa, tau_x_Pa, tau_y_Pa, slip_x_m_per_s, slip_y_m_per_s;
};

struct TransientResult {
  Grid grid;                             // covers the largest contact of the run
  Eigen::ArrayXd strip_energy_J_per_m;  // (ny) dissipated energy per unit width, whole run
  std::vector<Snapshot> snapshots;
  TransientState final_state;
  int steps = 0;
  double t_end_s = 0, q_end_m = 0;
  double dissipated_J = 0;
  // the run's end values: the last whole step's record (the last step's if no step is whole), since the
  // step cut short to end at t_end_s runs a less accurate scheme
  TransientRecord end;
  int fallback_steps = 0;  // shift runs: steps that ran upwind at CFL < 1 (StepScheme::Upwind)
};

// called after every step with the record and the strip powers P_l(y_j) of the step (W/m)
using StepObserver = std::function<void(const TransientRecord&, const Eigen::ArrayXd& strip_power_W_per_m)>;

// Gross sliding (docs/physics.md §4.5): the whole contact slides when the creep force is at its Coulomb
// bound, |(Fx, Fy)| = mu F. A run from rest builds its tractions up over the first steps (stick at the
// leading edge while the force is below the bound), so the first step with stick is not the end of gross
// sliding: it ends at the first step below the bound after a step at it. "At the bound" is within
// kGrossSlidingTolerance of mu F: while the whole contact slides the relaxed model's force is mu F to 1e-9,
// Satran's to 5e-4 (its grid's sum of p dA against F), and cases/roller-spinup.yaml leaves the bound by more
// than 1e-3 within two steps of the first stick.
constexpr double kGrossSlidingTolerance = 1e-3;
struct GrossSliding {
  int start_step = 0;  // the first step at the bound (0: none yet)
  double start_s = std::numeric_limits<double>::quiet_NaN();
  int end_step = 0;    // the first step below the bound after start_step (0: not ended)
  double end_s = std::numeric_limits<double>::quiet_NaN();  // its t_s
};
// feed every step's record in order (a shortened last step, cut to end at t_end_s, is not judged); mu: the
// case's coefficient of friction
void track_gross_sliding(const TransientRecord& r, double mu, GrossSliding& sliding);

// throws std::invalid_argument for bad settings (naming the largest allowed dt for a CFL breach)
// the inputs every transient run needs, whatever solver steps it: finite histories, speed and load >= 0,
// a load that is positive somewhere, t_end_s > 0, dt_s >= 0 (throws SettingError naming the key)
void check_transient_inputs(const TransientCase& c);

TransientResult run_transient(const TransientCase& c, const StepObserver& observe = {});

}  // namespace contact
