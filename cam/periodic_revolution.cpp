// One periodic cam revolution, all of it (cam/periodic_revolution.h).
#include "cam/periodic_revolution.h"

#include <ctime>
#include <limits>

#include <spdlog/fmt/fmt.h>

#include "cam/cam_error.h"
#include "cam/revolution_dissipation.h"
#include "lib/number.h"
#include "lib/model/contact_model.h"

namespace cam {

namespace {

double cpu_s() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

RollerDynamicsSettings roller_dynamics_of(const CamSolverSettings& s) {
  RollerDynamicsSettings ds;
  ds.law.grid = {s.nx, s.ny};
  ds.law.scheme = s.scheme;
  ds.law.normal = s.normal;
  ds.periodicity_rtol = s.periodic_rtol;
  ds.max_revolutions = s.max_revolutions;
  return ds;
}

namespace {
// the film and the flash temperature per angle on the periodic motion, when the case asks for them
void lubricate(CamRun& run, const CamModel& m, const CamSolverSettings& s) {
  if (!run.lubrication_spec.any()) return;
  const double t0 = cpu_s();
  run.lubrication = revolution_lubrication(run.lubrication_spec, m, run.revolution, run.motion.motion,
                                           roller_dynamics_of(s).law);
  run.cpu_lubrication_s = cpu_s() - t0;
}
}  // namespace

CamRun run_cam(const CamModel& dry, const CamSolverSettings& s, const CamLubricationSpec& lubrication) {
  // with cam.lubricant.friction_by_regime, the regime law's friction per angle step (cam/cam_lubrication.h)
  const CamModel m = with_regime_friction(lubrication, dry, roller_dynamics_of(s));
  CamRun run;
  run.lubrication_spec = lubrication;
  run.revolution = run_revolution(m);
  if (run.revolution.status != RevolutionStatus::Complete) return run;
  double t0 = cpu_s();
  run.motion = periodic_motion(m, run.revolution, roller_dynamics_of(s));
  if (!run.motion.converged)
    throw PeriodicityError(fmt::format("the roller's spin is not periodic after {} revolutions: |omega_r(2 pi) - "
                                       "omega_r(0)| = {:.3g} rad/s > {:.3g} rad/s (cam.tangential.periodic_rtol)",
                                       run.motion.revolutions, run.motion.periodicity_residual_rad_per_s,
                                       run.motion.tolerance_rad_per_s));
  double t1 = cpu_s();
  run.mu = m.mu;
  run.mu_by_step = m.mu_by_step;
  for (std::size_t i = 0; i < run.revolution.rows.size(); ++i) {
    const RollerAngle& a = run.motion.motion.angles[i];
    run.loads.push_back(cam_loads_with_tangential(m.train, m.geometry, run.revolution.rows[i].kin, m.omega_rad_per_s,
                                                  a.tangential_N));
    run.loads.back().regime = a.regime;
    run.loads.back().shaft_torque_N_m = shaft_torque_N_m(run.loads.back(), run.revolution.rows[i].kin,
                                                         a.track_depth_moment_N_m);
  }
  const CreepLawSettings law = roller_dynamics_of(s).law;
  if (!is_motion_law(law)) {  // the half-space or the exact theory: the rows quasi-steady, each on its own contact
    run.transient = quasi_steady_revolution(m, run.revolution, run.motion.motion, law);
    run.cpu_dynamics_s = t1 - t0;
    run.cpu_transient_s = cpu_s() - t1;
    run.energy = revolution_energy(m, run.revolution, run.motion, &run.transient);
    lubricate(run, m, s);
    return run;
  }
  TransientRevolutionSettings ts;
  ts.grid = {s.nx, s.ny};
  ts.scheme = s.scheme;
  ts.quasi_steady_tolerance = s.quasi_steady_tolerance;
  ts.skip = s.quasi_steady_tolerance > 0;
  run.transient = transient_revolution(m, run.revolution, run.motion.motion, ts);
  double t2 = cpu_s();
  run.cpu_dynamics_s = t1 - t0;
  run.cpu_transient_s = t2 - t1;
  if (s.compare_full_transient) {
    ts.skip = false;
    run.full = transient_revolution(m, run.revolution, run.motion.motion, ts);
    run.cpu_full_s = cpu_s() - t2;
    run.skip = compare_skip(run.transient, run.full);
  }
  run.energy = revolution_energy(m, run.revolution, run.motion, &run.transient);
  lubricate(run, m, s);
  return run;
}

std::string cam_summary(const CamRun& run) {
  const PeriodicMotion& p = run.motion;
  const TransientRevolution& t = run.transient;
  const RevolutionEnergy& e = run.energy;
  std::string out;
  out += fmt::format("roller dynamics: periodic after {} revolutions (|omega_r(2 pi) - omega_r(0)| = {:.3g} rad/s, "
                     "tolerance {:.3g}); sliding at {} of {} angle steps; {} steady solves, {:.3g} s CPU\n",
                     p.revolutions, p.periodicity_residual_rad_per_s, p.tolerance_rad_per_s, p.sliding_steps,
                     p.motion.angles.size(), p.motion.creep_law_evaluations, run.cpu_dynamics_s);
  const contact::TangentialModelTraits& model = contact::tangential_traits(t.scheme);
  if (t.quasi_steady_only)
    out += fmt::format("quasi-steady: every angle step the steady {} on its own {} contact (no transient along the "
                       "revolution on these), {} steady solves ({} for the creepages carrying the motion's F_t), "
                       "{:.3g} s CPU\n",
                       model.theory, contact::to_string(t.normal_solver), t.steady_solves + t.creep_evaluations,
                       t.creep_evaluations, run.cpu_transient_s);
  else
    out += fmt::format("transient: grid {} x {}, {}, {} {} steps + {} warm-up, {} of {} angle steps quasi-steady "
                       "(skipped), {:.3g} s CPU\n",
                       t.grid.nx, t.grid.ny, model.theory, t.transient_steps, model.steps_name, t.warmup_steps,
                       t.skipped_rows, t.dissipation.size(), run.cpu_transient_s);
  if (!run.full.dissipation.empty())
    out += fmt::format("quasi-steady skip against the full transient ({} steps, {:.3g} s CPU): {:.1f} % of the steps "
                       "saved; power error {:.3g} of the peak, energy error {:.3g}\n",
                       run.full.transient_steps + run.full.warmup_steps, run.cpu_full_s, 100 * run.skip.step_saving,
                       run.skip.max_power_error, run.skip.energy_error);
  out += fmt::format("energy per revolution: shaft {:.6g} J = guide {:.6g} + bearing {:.6g} + creep (rigid slip) "
                     "{:.6g} + Heathcote (roller's radii) {:.6g} + Heathcote (track's) {:.3g} + spring and mass {:.3g} + "
                     "roller spin {:.3g} + rounding {:.3g}\n",
                     e.shaft_J, e.guide_J, e.bearing_J, e.creep_rigid_J, e.heathcote_roller_J, e.heathcote_track_J,
                     e.train_J, e.roller_J, e.residual_J);
  out += fmt::format("contact: dissipated {:.6g} J = creep work {:.6g} J - {} {:.3g} J + {:.3g}; creep work = "
                     "steady law's {:.6g} (= rigid + Heathcote + contact frame's rotation {:.3g}) + "
                     "transient's {:.3g}\n",
                     e.dissipated_J, e.creep_work_J, model.stored_energy, e.elastic_J,
                     e.tangential_residual_J, e.creep_steady_J, e.frame_J, e.transient_J);
  out += lubrication_summary(run.lubrication_spec, run.lubrication);
  return out;
}

std::string revolution_csv(const CamRun& run) {
  const Revolution& r = run.revolution;
  const std::size_t n = r.rows.size();
  const bool dynamic = run.motion.motion.angles.size() == n && run.transient.dissipation.size() == n &&
                       run.loads.size() == n;
  if (!dynamic) return revolution_csv(r);
  Revolution copy = r;  // the revolution's columns with the motion's loads, contact and spin
  for (std::size_t i = 0; i < n; ++i) {
    RevolutionRow& w = copy.rows[i];
    const RollerAngle& a = run.motion.motion.angles[i];
    w.loads = run.loads[i];
    w.contact.a_m = run.transient.a_m[i];
    w.contact.b_m = run.transient.b_m[i];
    w.contact.p0_Pa = run.transient.p0_Pa[i];
    w.contact.xi = a.xi;
    w.contact.linear_range = std::abs(a.tangential_N) <= kLinearRangeFraction * (run.mu_by_step.empty() ? run.mu : run.mu_by_step[i]) * a.normal_N;
    w.kin.roller_omega_rad_per_s = a.omega_r_rad_per_s;
  }
  const std::string base = revolution_csv(copy);
  // the added columns
  std::string out;
  std::size_t line = 0, pos = 0;
  const auto num = [&out](double v, bool last = false) {
    contact::append_round_trip(out, v);
    if (!last) out += ',';
  };
  while (pos < base.size()) {
    const std::size_t end = base.find('\n', pos);
    out.append(base, pos, end - pos);
    if (line == 0) {
      out += ",required_tangential_load_N,roller_omega_kinematic_rad_per_s,slip_speed_m_per_s,stick_fraction,"
             "dissipated_power_W,quasi_steady,unsteadiness";
      out += lubrication_csv_header(run.lubrication_spec);
    } else {
      const std::size_t i = line - 1;
      const RollerAngle& a = run.motion.motion.angles[i];
      out += ',';
      num(r.rows[i].loads.required_tangential_N);
      num(r.rows[i].kin.roller_omega_rad_per_s);
      num(a.slip_speed_m_per_s);
      num(a.stick_fraction);
      num(total_power_W(run.transient.dissipation[i]));
      out += run.transient.skipped[i] ? "1," : "0,";
      num(run.transient.unsteadiness[i], true);
      if (run.lubrication.angles.size() == n) out += lubrication_csv_cells(run.lubrication_spec, run.lubrication.angles[i]);
    }
    out += '\n';
    pos = end + 1;
    ++line;
  }
  return out;
}

}  // namespace cam
