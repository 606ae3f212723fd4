// The shift scheme's time stepping shared by the exact theory's and the relaxed model's runs (shift_run.h).
#include "lib/tangential/shift_run.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "lib/history.h"
#include "lib/errors.h"
#include "lib/normal/hertz.h"

namespace contact {

TangentialSolution no_contact_solution(const Grid& g) {
  TangentialSolution s;
  s.tau_x_Pa = s.tau_y_Pa = s.slip_x_m_per_s = s.slip_y_m_per_s = s.power_W_per_m2 = Eigen::ArrayXXd::Zero(g.nx, g.ny);
  s.state = Eigen::ArrayXXi::Zero(g.nx, g.ny);
  s.strip_power_W_per_m = s.strip_creep_power_W_per_m = s.strip_trailing_W_per_m = s.strip_force_x_N_per_m =
      s.strip_force_y_N_per_m = Eigen::ArrayXd::Zero(g.ny);
  return s;
}

namespace {

// the contact at load F on the run's grid (as Satran's run puts it: a given patch, or Hertz's ellipse on
// the grid of the largest load; a patch without pressure when none, at F = 0)
ContactPatch contact_at(const TransientCase& c, const Grid& grid, double F) {
  if (c.patch) return *c.patch;
  if (F > 0) {
    const HertzContact h = solve_hertz(c.bodies, c.materials, F);
    if ((grid.y_m.abs() < h.b_m).any()) return hertz_patch(h, grid);
  }
  ContactPatch p;
  p.grid = grid;
  p.half_length_m = Eigen::ArrayXd::Zero(grid.ny);
  p.strip_peak_Pa = Eigen::ArrayXd::Zero(grid.ny);
  fill_strip_pressures(p);
  return p;
}

}  // namespace

ContactPatch shift_run_contact(const TransientCase& c, const Grid& grid, double F) { return contact_at(c, grid, F); }

Grid shift_run_grid(const TransientCase& c) {
  if (c.patch) return c.patch->grid;
  const HertzContact largest = solve_hertz(c.bodies, c.materials, max_value(c.inputs.normal_load_N));
  return make_grid(largest.a_m, largest.b_m, c.settings.grid);
}

void add_shift_step(TransientResult& res, const TransientRecord& rec, const TangentialSolution& f,
                    const ContactPatch& patch, double dt_s, double t_s, const std::vector<double>& snapshots_s,
                    std::size_t& next_snap, const StepObserver& observe) {
  res.strip_energy_J_per_m += f.strip_power_W_per_m * dt_s;
  res.dissipated_J += f.power_W * dt_s;
  if (observe) observe(rec, f.strip_power_W_per_m);
  while (next_snap < snapshots_s.size() && snapshots_s[next_snap] <= t_s * (1 + 1e-12)) {
    Snapshot sn;
    sn.t_s = t_s;
    sn.pressure_Pa = patch.pressure_Pa;
    sn.tau_x_Pa = f.tau_x_Pa;
    sn.tau_y_Pa = f.tau_y_Pa;
    sn.slip_x_m_per_s = f.slip_x_m_per_s;
    sn.slip_y_m_per_s = f.slip_y_m_per_s;
    res.snapshots.push_back(std::move(sn));
    ++next_snap;
  }
}

TransientResult run_shift_steps(const TransientCase& c, const StepObserver& observe, const ShiftStepSolve& solve,
                                const std::function<void(const Grid&)>& no_contact, const ShiftSkip& skip) {
  const TransientSettings& set = c.settings;
  if (c.patch && !(is_constant(c.inputs.normal_load_N) && c.inputs.normal_load_N.value[0] == c.patch->normal_load_N))
    throw SettingError("", "normal_load_N", "a run on a given contact patch needs the constant load of the patch, " +
                                                std::to_string(c.patch->normal_load_N) + " N");
  TransientResult res;
  res.grid = shift_run_grid(c);
  const Grid& g = res.grid;
  const double dx = g.dx_m;
  res.strip_energy_J_per_m = Eigen::ArrayXd::Zero(g.ny);
  res.final_state = rest_state(g);  // Satran's node state: not these solvers' (left at rest)

  std::vector<double> snaps = set.snapshot_times_s;
  std::sort(snaps.begin(), snaps.end());
  std::size_t next_snap = 0;
  double t = 0, q = 0, F_patch = std::numeric_limits<double>::quiet_NaN();
  ContactPatch patch;
  bool in_contact = false;
  const double longest = set.dt_s > 0 ? set.dt_s : std::numeric_limits<double>::infinity();
  int step = 0;
  bool has_whole_step = false;  // res.end holds a whole step's record
  while (t < set.t_end_s * (1 - 1e-12)) {
    const double left = set.t_end_s - t;
    // a step rolls dx, or less when the longest step or the end comes first (at V = 0: no rolling)
    const double t_roll = time_to_accumulate(c.inputs.speed_m_per_s, t, dx);
    const double dt = std::min({t_roll - t, longest, left});
    const double dq = dt == t_roll - t ? dx : std::min(dx, integral(c.inputs.speed_m_per_s, t, t + dt));
    if (!(dt > 0)) break;
    // the last step, cut short by t_end_s rather than by the longest step or by rolling: flagged, and not
    // the run's end values (as in Satran's runs)
    const bool shortened = dt == left && dt < std::min(t_roll - t, longest) * (1 - 1e-9);
    const double tm = t + dt / 2;
    ShiftStep s;
    s.step = step + 1;
    s.t_s = t;
    s.dt_s = dt;
    s.dq_m = dq;
    s.speed_m_per_s = value_at(c.inputs.speed_m_per_s, tm);
    s.creepages = {value_at(c.inputs.xi, tm), value_at(c.inputs.eta, tm), value_at(c.inputs.phi_per_m, tm)};
    s.normal_load_N = value_at(c.inputs.normal_load_N, t + dt);  // the contact at the step's end
    s.fields = next_snap < snaps.size();
    if (!(s.normal_load_N == F_patch)) {
      patch = contact_at(c, g, s.normal_load_N);
      F_patch = s.normal_load_N;
      in_contact = (patch.pressure_Pa > 0).any();
    }
    TangentialSolution f;
    if (in_contact) {
      f = solve(patch, s);
    } else {
      f = no_contact_solution(g);
      if (no_contact) no_contact(g);
    }
    TransientRecord rec;
    rec.step = ++step;
    rec.t_s = t + dt;  // the tractions of the step's end (backward Euler in time)
    rec.q_m = q + dq;
    rec.dt_s = dt;
    rec.speed_m_per_s = s.speed_m_per_s;
    rec.xi = s.creepages.xi;
    rec.eta = s.creepages.eta;
    rec.phi_per_m = s.creepages.phi_per_m;
    rec.normal_load_N = s.normal_load_N;
    rec.Fx_N = f.Fx_N;
    rec.Fy_N = f.Fy_N;
    rec.Mz_N_m = f.Mz_N_m;
    rec.power_W = f.power_W;
    rec.stick_fraction = f.stick_fraction;
    // the half-space stores elastic energy outside the contact too, and a model has no discrete balance
    rec.balance_residual_W = std::numeric_limits<double>::quiet_NaN();
    rec.cfl = dq / dx;
    rec.scheme = dq == 0 ? StepScheme::Standstill : StepScheme::Shift;  // interpolated in the step if dq < dx
    rec.shortened = shortened;
    if (!shortened || !has_whole_step) {
      res.end = rec;
      has_whole_step = !shortened;
    }
    t += dt;
    q += dq;
    add_shift_step(res, rec, f, patch, dt, t, snaps, next_snap, observe);
    if (set.skip_steady && skip.settled && in_contact && dq == dx && !shortened && skip.settled()) {
      // the inputs constant over the step just taken and the stretch ahead
      const History* inputs[] = {&c.inputs.speed_m_per_s, &c.inputs.xi, &c.inputs.eta, &c.inputs.phi_per_m,
                                 &c.inputs.normal_load_N};
      double since = 0, until = set.t_end_s;
      for (const History* h : inputs) {
        since = std::max(since, constant_since(*h, t));
        until = std::min(until, constant_until(*h, t));
      }
      if (next_snap < snaps.size()) until = std::min(until, snaps[next_snap]);
      // a whole number of steps, so that the steps after the stretch fall where they would without the skip
      const double whole_steps = std::floor((until - t) / dt) - 1;
      if (whole_steps >= 2 && since <= t - dt) {
        const double span = whole_steps * dt;
        TransientRecord sk = rec;
        sk.step = ++step;
        sk.t_s = t + span / 2;
        sk.q_m = q + whole_steps * dq / 2;
        sk.dt_s = span;
        sk.cfl = whole_steps;
        sk.skipped = true;
        sk.shortened = false;
        Eigen::ArrayXd strip_J = f.strip_power_W_per_m * span;
        double J = f.power_W * span;
        if (skip.energy) skip.energy(span, whole_steps * dq, f, strip_J, J);
        sk.power_W = J / span;
        t += span;
        q += whole_steps * dq;
        res.strip_energy_J_per_m += strip_J;
        res.dissipated_J += J;
        res.end = sk;
        has_whole_step = true;
        if (skip.skipped) skip.skipped(whole_steps * dq);
        if (observe) observe(sk, Eigen::ArrayXd(strip_J / span));
      }
    }
  }
  res.steps = step;
  res.t_end_s = t;
  res.q_end_m = q;
  return res;
}

}  // namespace contact
