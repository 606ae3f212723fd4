// Satran's run driver (satran.h: run_transient): the time loop over a case's histories. Each step's
// contact on the run's grid (kept while its load is the same), the step's kinematics (prescribed, or the
// roller's spin found by its balance: inertia), the fixed step's substeps, the records and snapshots, the
// observer and the skip over steady running; every step is satran_step (satran_step.cpp).
#include "lib/tangential/satran.h"
#include "lib/tangential/satran_workspace.h"
#include "lib/errors.h"
#include "lib/numeric.h"

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace contact {

void check_transient_inputs(const TransientCase& c) {
  const TransientSettings& s = c.settings;
  check_history(c.inputs.speed_m_per_s, "speed_m_per_s");
  check_history(c.inputs.xi, "xi");
  check_history(c.inputs.eta, "eta");
  check_history(c.inputs.phi_per_m, "phi_per_m");
  check_history(c.inputs.normal_load_N, "normal_load_N");
  if (min_value(c.inputs.speed_m_per_s) < 0) throw SettingError("", "speed_m_per_s", "must be >= 0");
  if (min_value(c.inputs.normal_load_N) < 0) throw SettingError("", "normal_load_N", "must be >= 0");
  if (!(max_value(c.inputs.normal_load_N) > 0)) throw SettingError("", "normal_load_N", "never positive");
  if (!(s.t_end_s > 0) || !std::isfinite(s.t_end_s)) throw SettingError("", "t_end_s", "must be positive");
  if (!(s.dt_s >= 0) || !std::isfinite(s.dt_s)) throw SettingError("", "dt_s", "must be >= 0");
}

namespace {

void check_run(const TransientCase& c) {
  const TransientSettings& s = c.settings;
  check_transient_inputs(c);
  if (s.scheme != TransientScheme::Shift && !(s.dt_s > 0))
    throw SettingError("", "dt_s", "the " + to_string(s.scheme) + " scheme needs a time step");
  if (c.patch && !(is_constant(c.inputs.normal_load_N) && c.inputs.normal_load_N.value[0] == c.patch->normal_load_N))
    throw SettingError("", "normal_load_N", "a run on a given contact patch needs the constant load of the patch, " +
                                std::to_string(c.patch->normal_load_N) + " N");
  if (c.inertia) {
    const RollerInertia& in = *c.inertia;
    check_history(in.path_speed_m_per_s, "path_speed_m_per_s");
    if (!(in.R1_m > 0) || !(in.J1_kg_m2 > 0))
      throw SettingError("", "inertia", "R1_m and J1_kg_m2 must be positive");
    if (min_value(in.path_speed_m_per_s) < 0 || in.omega1_0_rad_per_s < 0)
      throw SettingError("", "inertia", "the path speed and the initial spin must be >= 0");
    if (!(s.dt_s > 0)) throw SettingError("", "dt_s", "an inertia run needs the longest step dt_s > 0");
    if (s.scheme != TransientScheme::Shift) throw SettingError("", "scheme", "an inertia run uses shift");
  }
}

// the contact at load F on the run's grid; no contact at F = 0
// No strip of the grid in contact; a and b (Kalker's a/b) from h
ContactPatch empty_patch(const Grid& grid, const HertzContact& h) {
  ContactPatch p;
  p.grid = grid;
  p.half_length_m = Eigen::ArrayXd::Zero(grid.ny);
  p.strip_peak_Pa = Eigen::ArrayXd::Zero(grid.ny);
  fill_strip_pressures(p);
  p.a_m = h.a_m;
  p.b_m = h.b_m;
  return p;
}

// The contact at load F on the run's grid: none at F = 0, and none either while the ellipse is so
// narrow that it misses every strip centre of the grid (a small load on the largest contact's grid:
// no strip can carry it, so it carries no traction)
ContactPatch contact_at(const TransientCase& c, const Grid& grid, double F) {
  if (c.patch) return *c.patch;  // check_run: F is its load
  if (!(F > 0)) return empty_patch(grid, solve_hertz(c.bodies, c.materials, 1.0));  // the shape at any load
  const HertzContact h = solve_hertz(c.bodies, c.materials, F);
  if (!(grid.y_m.abs() < h.b_m).any()) return empty_patch(grid, h);
  return hertz_patch(h, grid);
}

class PatchCache {
 public:
  PatchCache(const TransientCase& c, const Grid& g) : c_(c), g_(g) {}
  const ContactPatch& at(double F) {
    if (!valid_ || F != F_) {
      patch_ = contact_at(c_, g_, F);
      F_ = F;
      valid_ = true;
      ++serial_;
      if (F > 0 && !(patch_.half_length_m > 0).any() && !warned_) {
        spdlog::warn("satran: at {:.4g} N the contact (b = {:.4g} m) misses every strip centre of the run's grid "
                     "(dy = {:.4g} m, sized for the largest load): no traction while the load is that small",
                     F, patch_.b_m, g_.dy_m);
        warned_ = true;
      }
    }
    return patch_;
  }
  // counts the patches at() has built (SatranWorkspace::patch_serial)
  unsigned long serial() const { return serial_; }

 private:
  const TransientCase& c_;
  const Grid& g_;
  ContactPatch patch_;
  double F_ = 0;
  bool valid_ = false;
  bool warned_ = false;  // of a load too small for the grid, once per run
  unsigned long serial_ = 0;
};


// the CFL condition of the fixed-step schemes, checked before anything runs: the sub-steps per dt_s
int fixed_step_substeps(const TransientCase& c, double dx) {
  const TransientSettings& set = c.settings;
  if (set.scheme == TransientScheme::Shift || c.inertia) return 1;
  const double vmax = max_value(c.inputs.speed_m_per_s);
  const double cfl = vmax * set.dt_s / dx;
  if (!(cfl > 1 + 1e-12)) return 1;
  if (!set.substep)
    throw CflBreach("dt_s", std::to_string(set.dt_s) + " s breaks the CFL condition (V dt/dx = " +
                                std::to_string(cfl) + " > 1 at V = " + std::to_string(vmax) +
                                " m/s, dx = " + std::to_string(dx) + " m); the largest allowed dt is " +
                                std::to_string(dx / vmax) + " s (or set substep: true)",
                    set.dt_s, vmax, dx);
  return static_cast<int>(std::ceil(cfl - 1e-12));
}

// a step cut short to end the run: shorter than it would be, beyond rounding
bool cut_short(double dt_s, double natural_s) { return dt_s < natural_s * (1 - 1e-9); }

// One step of a run without inertia: its kinematics, and the inputs it runs on.
struct PrescribedStep {
  StepKinematics k;
  double V = 0, F = 0;
  Creepages cr;
  bool shortened = false;
};

// The step from t. Shift: one dx of rolling (dq = dx exactly, however short dt_s is). dt_s (0: no limit)
// bounds only the steps that cannot roll a whole dx: a standstill (no rolling over dt_s: an exact step
// that transports nothing), and the steps once the rolling stops for good less than dx further on (upwind
// at CFL dq/dx < 1, the fallback). The end of the run cuts the last step short. Upwind and
// lax-friedrichs: dt_s / substeps.
// The creepages and the speed are taken at mid-step (the rigid slip over the step), the load at the
// step's end, whose Coulomb bound the state at the step's end obeys (a falling load clips it in this step).
PrescribedStep prescribed_step(const TransientCase& c, double t, double dx, int substeps) {
  const TransientSettings& set = c.settings;
  const History& speed = c.inputs.speed_m_per_s;
  const double left = set.t_end_s - t;
  PrescribedStep s;
  StepKinematics& k = s.k;
  if (set.scheme == TransientScheme::Shift) {
    const double roll_s = time_to_accumulate(speed, t, dx) - t;  // +inf if the rolling never covers dx
    const bool standstill = set.dt_s > 0 && integral(speed, t, t + std::min(set.dt_s, left)) == 0;
    const double natural = standstill || (std::isinf(roll_s) && set.dt_s > 0) ? set.dt_s : roll_s;
    k.dt_s = std::min(natural, left);
    k.dq_m = k.dt_s == roll_s ? dx : std::min(dx, integral(speed, t, t + k.dt_s));
    s.shortened = cut_short(k.dt_s, natural);
  } else {
    const double natural = set.dt_s / substeps;
    k.dt_s = std::min(natural, left);
    k.dq_m = std::min(dx, integral(speed, t, t + k.dt_s));
    s.shortened = cut_short(k.dt_s, natural);
  }
  const double tm = t + k.dt_s / 2;
  s.V = value_at(speed, tm);
  s.F = value_at(c.inputs.normal_load_N, t + k.dt_s);
  s.cr = {value_at(c.inputs.xi, tm), value_at(c.inputs.eta, tm), value_at(c.inputs.phi_per_m, tm)};
  // rigid slip over the step: creepage x rolled distance
  k.slip_x_m = s.cr.xi * k.dq_m;
  k.slip_y_m = s.cr.eta * k.dq_m;
  k.spin_rad = s.cr.phi_per_m * k.dq_m;
  return s;
}

// One step of an inertia run: the roller's spin at the step's end, omega_end, balances the creep torque
// over the step (implicit in omega1): J1 (omega_end - omega1) = (-R1 Fx - T_res) dt, with V and the slip
// from the mean spin (omega1 + omega_end)/2.
struct InertiaStep {
  StepKinematics k;
  StepResult r;
  TransientState state;  // after the step
  double omega_end = 0, V = 0, F = 0;
  Creepages cr;
  bool shortened = false;
};

InertiaStep inertia_step(const TransientCase& c, PatchCache& patches, SatranWorkspace& ws,
                         const TransientState& state, double omega1, double t, double dx, bool fields) {
  const RollerInertia& in = *c.inertia;
  const TransientSettings& set = c.settings;
  const double longest = set.dt_s, left = set.t_end_s - t;
  const double V2_now = value_at(in.path_speed_m_per_s, t);
  const double V_now = (omega1 * in.R1_m + V2_now) / 2;
  const double dt_guess = std::min({V_now > 0 ? dx / V_now : longest, longest, left});
  const double V2 = value_at(in.path_speed_m_per_s, t + dt_guess / 2);
  InertiaStep s;
  s.F = value_at(c.inputs.normal_load_N, t + dt_guess / 2);
  const ContactPatch& patch = patches.at(s.F);
  // every trial below steps a copy of `state`: the workspace may take its nodes outside the contact as clear
  // only if `state` itself was stepped on this patch
  const bool state_on_patch = workspace_stepped_on(ws, patches.serial());
  ws.patch_serial = patches.serial();
  // the step from the mean spin; returns the residual of the spin balance
  auto evaluate = [&](double omega_end, InertiaStep& out) {
    const double omega_mid = (omega1 + omega_end) / 2;
    const double Vm = std::max(0.0, (omega_mid * in.R1_m + V2) / 2);
    StepKinematics& kk = out.k;
    const double natural = std::min(Vm > 0 ? dx / Vm : longest, longest);
    kk.dt_s = std::min(natural, left);
    kk.dq_m = std::min(dx, Vm * kk.dt_s);
    kk.slip_x_m = (V2 - omega_mid * in.R1_m) * kk.dt_s;
    kk.slip_y_m = kk.spin_rad = 0;
    out.shortened = cut_short(kk.dt_s, natural);
    // creepage ratio for the mean flexibility: only xi here
    const Creepages ratio{1.0, 0.0, 0.0};
    const TangentialProblem pb = make_tangential_problem(patch, c.materials, ratio, c.mu, Vm);
    out.state = state;
    if (!state_on_patch) workspace_forget_patch(ws);
    out.r = satran_step(patch, pb, kk, TransientScheme::Shift, out.state, fields, set.skips, ws);
    return in.J1_kg_m2 * (omega_end - omega1) - (-in.R1_m * out.r.Fx_N - in.T_res_N_m) * kk.dt_s;
  };
  // the bracket: the creep force is bounded by mu F
  const double span = (c.mu * s.F * in.R1_m + std::abs(in.T_res_N_m)) * longest / in.J1_kg_m2 * 1.01 + 1e-12;
  const double omega_end = implicit_roller_speed_rad_per_s([&](double w) { return evaluate(w, s); }, omega1, span, t,
                                                          "satran");
  evaluate(omega_end, s);
  s.omega_end = omega_end;
  s.V = s.k.dt_s > 0 ? s.k.dq_m / s.k.dt_s : 0;
  s.cr.xi = s.V > 0 ? s.k.slip_x_m / s.k.dq_m : 0;
  return s;
}

// A step's record: the forces of an exact shift step are averages over it (held at mid-step), those of an
// explicit step end values
TransientRecord record_of(const TransientCase& c, int step, double t, double q, double dx, const StepKinematics& k,
                          const StepResult& r, double V, double F, const Creepages& cr, double omega1) {
  const StepScheme ran = step_scheme(c.inertia ? TransientScheme::Shift : c.settings.scheme, k.dq_m, dx);
  const bool averages = ran == StepScheme::Shift;
  TransientRecord rec;
  rec.step = step;
  rec.t_s = t + (averages ? k.dt_s / 2 : k.dt_s);
  rec.q_m = q + (averages ? k.dq_m / 2 : k.dq_m);
  rec.dt_s = k.dt_s;
  rec.speed_m_per_s = V;
  rec.xi = cr.xi;
  rec.eta = cr.eta;
  rec.phi_per_m = cr.phi_per_m;
  rec.normal_load_N = F;
  rec.omega1_rad_per_s = omega1;
  rec.Fx_N = r.Fx_N;
  rec.Fy_N = r.Fy_N;
  rec.Mz_N_m = r.Mz_N_m;
  rec.power_W = k.dt_s > 0 ? r.dissipated_J / k.dt_s : 0;
  rec.stick_fraction = r.stick_fraction;
  rec.balance_residual_W = k.dt_s > 0 ? r.balance_residual_J / k.dt_s : 0;
  rec.cfl = k.dq_m / dx;
  rec.scheme = ran;
  return rec;
}

// The run between steps: where it stands, and what it has gathered.
struct RunState {
  double t = 0, q = 0;
  int step = 0;
  double omega1 = 0;
  TransientState tractions;
  std::vector<double> snaps;  // the snapshot times, sorted
  size_t next_snap = 0;
  bool has_whole_step = false;  // res.end holds a whole step's record
  Eigen::ArrayXd strip_power;   // the observer's strip powers of the step
};

// the fields only on a step that reaches the next snapshot time
bool reaches_snapshot(const RunState& run, double dt) {
  return run.next_snap < run.snaps.size() && run.snaps[run.next_snap] <= (run.t + dt) * (1 + 1e-12);
}

// a step taken: the clock advances, the energies add up, the observer sees it, the snapshots it reaches
// are kept, and the run's end values follow the last whole step
void record_step(RunState& run, TransientResult& res, const TransientRecord& rec, const StepKinematics& k,
                 StepResult& r, const ContactPatch& patch, const StepObserver& observe) {
  run.t += k.dt_s;
  run.q += k.dq_m;
  res.strip_energy_J_per_m += r.strip_energy_J_per_m;
  res.dissipated_J += r.dissipated_J;
  if (!rec.shortened || !run.has_whole_step) {
    res.end = rec;
    run.has_whole_step = !rec.shortened;
  }
  if (observe) {
    if (k.dt_s > 0) {
      run.strip_power = r.strip_energy_J_per_m / k.dt_s;  // no allocation after the first step
    } else {
      run.strip_power.setZero(res.grid.ny);
    }
    observe(rec, run.strip_power);
  }
  while (run.next_snap < run.snaps.size() && run.snaps[run.next_snap] <= run.t * (1 + 1e-12)) {
    Snapshot s;
    s.t_s = run.t;
    s.pressure_Pa = patch.pressure_Pa;
    s.tau_x_Pa = r.tau_x_Pa;
    s.tau_y_Pa = r.tau_y_Pa;
    s.slip_x_m_per_s = r.slip_x_m_per_s;
    s.slip_y_m_per_s = r.slip_y_m_per_s;
    res.snapshots.push_back(std::move(s));
    ++run.next_snap;
  }
  SPDLOG_TRACE("satran step {}: t {:.6e} s, Fx {:.6e} N, P {:.6e} W", run.step, run.t, r.Fx_N, rec.power_W);
}

// Steady running (shift, no inertia, after a whole step): once every input has been constant since the
// state was last disturbed, long enough for the material now in contact to have entered under the
// constant inputs, the rest of the constant stretch (whole steps, up to one step before the next change,
// snapshot time or t_end_s) is one record with the last step's strip energies times its step count.
void skip_steady_running(const TransientCase& c, RunState& run, TransientResult& res, const TransientRecord& rec,
                         const StepKinematics& k, const StepResult& r, const ContactPatch& patch,
                         const StepObserver& observe) {
  const double dx = res.grid.dx_m;
  const History* inputs[] = {&c.inputs.speed_m_per_s, &c.inputs.xi, &c.inputs.eta, &c.inputs.phi_per_m,
                             &c.inputs.normal_load_N};
  double since = 0, until = c.settings.t_end_s;
  for (const History* h : inputs) {  // constant on [since, until], the last step [t - dt, t] included
    since = std::max(since, constant_since(*h, run.t));
    until = std::min(until, constant_until(*h, run.t));
  }
  if (run.next_snap < run.snaps.size()) until = std::min(until, run.snaps[run.next_snap]);
  const double settle_m = 2 * patch.half_length_m.maxCoeff() + 2 * dx;
  // a whole number of steps, so that the steps after the stretch fall where they would without the skip
  const double whole_steps = std::floor((until - run.t) / k.dt_s) - 1;
  if (!(whole_steps >= 2 && integral(c.inputs.speed_m_per_s, since, run.t - k.dt_s) >= settle_m)) return;
  const double span = whole_steps * k.dt_s;
  TransientRecord skip = rec;
  skip.step = ++run.step;
  skip.t_s = run.t + span / 2;
  skip.q_m = run.q + rec.speed_m_per_s * span / 2;
  skip.dt_s = span;
  skip.cfl = rec.speed_m_per_s * span / dx;
  skip.skipped = true;
  run.t += span;
  run.q += whole_steps * k.dq_m;
  res.strip_energy_J_per_m += whole_steps * r.strip_energy_J_per_m;
  res.dissipated_J += whole_steps * r.dissipated_J;
  res.end = skip;
  if (observe) observe(skip, Eigen::ArrayXd(r.strip_energy_J_per_m / k.dt_s));
  SPDLOG_TRACE("satran: steady running skipped from t {:.6e} s to {:.6e} s", run.t - span, run.t);
}

// the grid covers the largest contact of the run
Grid run_grid(const TransientCase& c) {
  if (c.patch) return c.patch->grid;
  const HertzContact largest = solve_hertz(c.bodies, c.materials, max_value(c.inputs.normal_load_N));
  return make_grid(largest.a_m, largest.b_m, c.settings.grid);
}

}  // namespace

TransientResult run_transient(const TransientCase& c, const StepObserver& observe) {
  check_run(c);
  const TransientSettings& set = c.settings;
  TransientResult res;
  res.grid = run_grid(c);
  const Grid& g = res.grid;
  const double dx = g.dx_m;
  res.strip_energy_J_per_m = Eigen::ArrayXd::Zero(g.ny);
  PatchCache patches(c, g);
  const int substeps = fixed_step_substeps(c, dx);
  const bool shift_run = set.scheme == TransientScheme::Shift || c.inertia;

  SatranWorkspace ws;
  ws.threads = set.threads > 0 ? set.threads : satran_threads();
  ws.defer_mirror = true;  // the mirror images are filled before the state is handed out
  // the step's problem (Kalker's coefficients: elliptic integrals) kept while its patch and inputs are the same
  // to the bit
  struct ProblemCache {
    bool valid = false;
    unsigned long serial = 0;
    TangentialProblem pb;
    bool holds(unsigned long s, const Creepages& cr, double V) const {
      return valid && serial == s && std::memcmp(&pb.creepages, &cr, sizeof cr) == 0 &&
             std::memcmp(&pb.speed_m_per_s, &V, sizeof V) == 0;
    }
  } problems;
  RunState run;
  run.tractions = rest_state(g);
  run.snaps = set.snapshot_times_s;
  std::sort(run.snaps.begin(), run.snaps.end());
  run.omega1 = c.inertia ? c.inertia->omega1_0_rad_per_s : 0.0;
  while (run.t < set.t_end_s * (1 - 1e-12)) {
    StepKinematics k;
    StepResult r;
    TransientRecord rec;
    double F = 0;
    if (!c.inertia) {
      const PrescribedStep s = prescribed_step(c, run.t, dx, substeps);
      const ContactPatch& patch = patches.at(s.F);
      ws.patch_serial = patches.serial();
      if (!problems.holds(patches.serial(), s.cr, s.V)) {
        problems.pb = make_tangential_problem(patch, c.materials, s.cr, c.mu, s.V);
        problems.serial = patches.serial();
        problems.valid = true;
      }
      const TangentialProblem& pb = problems.pb;
      r = satran_step(patch, pb, s.k, set.scheme, run.tractions, reaches_snapshot(run, s.k.dt_s), set.skips, ws);
      k = s.k;
      F = s.F;
      rec = record_of(c, ++run.step, run.t, run.q, dx, k, r, s.V, s.F, s.cr, run.omega1);
      rec.shortened = s.shortened;
    } else {
      InertiaStep s = inertia_step(c, patches, ws, run.tractions, run.omega1, run.t, dx,
                                   reaches_snapshot(run, set.dt_s));
      run.tractions = std::move(s.state);
      run.omega1 = s.omega_end;
      k = s.k;
      r = std::move(s.r);
      F = s.F;
      rec = record_of(c, ++run.step, run.t, run.q, dx, k, r, s.V, s.F, s.cr, run.omega1);
      rec.shortened = s.shortened;
    }
    if (shift_run && rec.scheme == StepScheme::Upwind) ++res.fallback_steps;
    record_step(run, res, rec, k, r, patches.at(F), observe);
    if (!(k.dt_s > 0)) break;  // nothing left to advance
    if (set.skip_steady && set.scheme == TransientScheme::Shift && !c.inertia && rec.scheme == StepScheme::Shift)
      skip_steady_running(c, run, res, rec, k, r, patches.at(F), observe);
  }
  res.steps = run.step;
  res.t_end_s = run.t;
  res.q_end_m = run.q;
  fill_mirrored_strips(run.tractions);
  res.final_state = std::move(run.tractions);
  spdlog::debug("satran ({}): {} steps to t {:.6e} s, q {:.6e} m, dissipated {:.6e} J, {} upwind fallback steps",
                to_string(set.scheme), run.step, run.t, run.q, res.dissipated_J, res.fallback_steps);
  return res;
}

double implicit_roller_speed_rad_per_s(const std::function<double(double)>& balance, double omega1_rad_per_s,
                                       double span_rad_per_s, double t_s, const char* who) {
  const double lo = std::max(0.0, omega1_rad_per_s - span_rad_per_s), hi = omega1_rad_per_s + span_rad_per_s;
  const double f_lo = balance(lo), f_hi = balance(hi);
  // f_lo > 0: it cannot spin down below 0 within the bracket, it stops; otherwise the balance is monotone in omega_end
  if (!(f_lo <= 0 && f_hi >= 0)) return f_lo > 0 ? lo : hi;
  const RootResult root = find_root_bracketed(balance, lo, hi, f_lo, f_hi, 1e-13 * std::max(1.0, hi));
  if (!root.converged)
    throw std::runtime_error(fmt::format("{}: the roller's spin balance at t = {:.6g} s did not converge "
                                         "(residual {:.3g} after {} iterations)",
                                         who, t_s, root.f, root.iterations));
  return root.x;
}

void track_gross_sliding(const TransientRecord& r, double mu, GrossSliding& sliding) {
  if (r.shortened || sliding.end_step > 0) return;
  const double bound_N = mu * r.normal_load_N;
  const bool at_bound = bound_N > 0 && std::hypot(r.Fx_N, r.Fy_N) >= (1 - kGrossSlidingTolerance) * bound_N;
  if (sliding.start_step == 0) {
    if (at_bound) {
      sliding.start_step = r.step;
      sliding.start_s = r.t_s;
    }
  } else if (!at_bound) {
    sliding.end_step = r.step;
    sliding.end_s = r.t_s;
  }
}

}  // namespace contact
