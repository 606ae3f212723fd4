// The cam's life in cam revolutions (cam/cam_life.h).
#include "cam/cam_life.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "cam/revolution.h"
#include "cam/revolution_dissipation.h"
#include "cam/roller_motion.h"
#include "lib/io/enum_names.h"
#include "lib/numeric.h"
#include "wear/integrator.h"
#include "wear/profile_update.h"

namespace cam {

namespace {

constexpr contact::EnumTable<CamLifeEnd, 7> kCamLifeEndWords = {{{CamLifeEnd::NotRun, "not_run"},
                                                                 {CamLifeEnd::MaxDepth, "max_depth"},
                                                                 {CamLifeEnd::LiftLoss, "lift_loss"},
                                                                 {CamLifeEnd::Revolutions, "revolutions"},
                                                                 {CamLifeEnd::MaxSteps, "max_steps"},
                                                                 {CamLifeEnd::Failed, "failed"},
                                                                 {CamLifeEnd::Stopped, "stopped"}}};

constexpr int kLimits = 2;  // g_0 the depth limit, g_1 the lift-loss limit
constexpr CamLifeEnd kLimitEnds[kLimits] = {CamLifeEnd::MaxDepth, CamLifeEnd::LiftLoss};

// the state vector: [track map, arc-major columns as Eigen stores them | roller | e], e = E energy_scale
struct Layout {
  int n_cam = 0, n_roller = 0;
  int size() const { return n_cam + n_roller + 1; }
  int energy() const { return n_cam + n_roller; }
};

Layout layout(const CamWearGrid& g) { return {g.arc_cells * g.track_cells, g.roller_cells}; }

CamWearState state_of(const CamWearGrid& g, const Eigen::VectorXd& x) {
  CamWearState s;
  s.cam_depth_m = Eigen::Map<const Eigen::ArrayXXd>(x.data(), g.arc_cells, g.track_cells);
  s.roller_depth_m = x.segment(g.arc_cells * g.track_cells, g.roller_cells).array();
  return s;
}

double max_depth_of(const CamWearState& s) {
  return std::max(s.cam_depth_m.size() ? s.cam_depth_m.maxCoeff() : 0.0,
                  s.roller_depth_m.size() ? s.roller_depth_m.maxCoeff() : 0.0);
}

}  // namespace

std::string to_string(CamLifeEnd e) { return contact::enum_name(kCamLifeEndWords, e); }

std::vector<LiftLossSample> lift_loss_samples(const Revolution& r) {
  std::vector<LiftLossSample> out;
  out.reserve(r.rows.size());
  for (const RevolutionRow& row : r.rows) out.push_back({row.kin.theta_rad, row.contact_arc_m, row.kin.pressure_angle_rad});
  return out;
}

Eigen::ArrayXd lift_loss_m(const contact::Profiles& unworn, const CamWearGrid& g, const CamWearState& s,
                           const std::vector<LiftLossSample>& samples) {
  Eigen::ArrayXd loss(static_cast<Eigen::Index>(samples.size()));
  for (std::size_t k = 0; k < samples.size(); ++k)
    loss(static_cast<Eigen::Index>(k)) =
        normal_recession_m(unworn, g, s, samples[k].arc_m) / std::cos(samples[k].pressure_angle_rad);
  return loss;
}

LiftLoss max_lift_loss(const contact::Profiles& unworn, const CamWearGrid& g, const CamWearState& s,
                       const std::vector<LiftLossSample>& samples) {
  LiftLoss out;
  if (samples.empty()) return out;
  const Eigen::ArrayXd loss = lift_loss_m(unworn, g, s, samples);
  Eigen::Index k = 0;
  out.max_m = loss.maxCoeff(&k);
  out.at_theta_rad = samples[static_cast<std::size_t>(k)].theta_rad;
  return out;
}

LiftLossProbe::LiftLossProbe(const contact::Profiles& unworn, const CamWearGrid& g, std::vector<LiftLossSample> samples)
    : grid_(g), samples_(std::move(samples)) {
  check_grid(g);
  for (const LiftLossSample& x : samples_) {
    Weights w;
    cell_weights(x.arc_m, g.arc_cell_m(), g.arc_cells, true, w.c0, w.c1, w.w1);
    sample_arc_.push_back(w);
  }
  const contact::Profile& roller = unworn.body1;
  const contact::Profile& track = unworn.body2;
  const double lo = std::max(roller.y_m(0), track.y_m(0));
  const double hi = std::min(roller.y_m(roller.y_m.size() - 1), track.y_m(track.y_m.size() - 1));
  gap0_min_ = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < roller.y_m.size(); ++i) {
    const double y = roller.y_m(i);
    if (y < lo || y > hi) continue;
    gap0_.push_back(roller.z_m(i) + contact::profile_z(track, y));
    gap0_min_ = std::min(gap0_min_, gap0_.back());
    Weights r, t;
    cell_weights(y + 0.5 * g.roller_width_m, g.roller_cell_m(), g.roller_cells, false, r.c0, r.c1, r.w1);
    cell_weights(y + 0.5 * g.track_width_m, g.track_cell_m(), g.track_cells, false, t.c0, t.c1, t.w1);
    roller_lat_.push_back(r);
    track_lat_.push_back(t);
  }
  ROLLWEAR_ASSERT(!gap0_.empty(), "the roller's and the track's profiles do not overlap laterally");
}

LiftLoss LiftLossProbe::operator()(const CamWearState& s) const {
  LiftLoss out;
  if (samples_.empty()) return out;
  const std::size_t n = gap0_.size();
  // per node: the unworn gap plus the roller's depth; per arc cell used, its row at the nodes
  std::vector<double> base(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Weights& r = roller_lat_[i];
    base[i] = (1 - r.w1) * s.roller_depth_m(r.c0) + r.w1 * s.roller_depth_m(r.c1);
  }
  std::vector<std::vector<double>> rows(static_cast<std::size_t>(grid_.arc_cells));
  const auto row = [&](int c) -> const std::vector<double>& {
    std::vector<double>& v = rows[static_cast<std::size_t>(c)];
    if (v.empty()) {
      v.resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        const Weights& t = track_lat_[i];
        v[i] = (1 - t.w1) * s.cam_depth_m(c, t.c0) + t.w1 * s.cam_depth_m(c, t.c1);
      }
    }
    return v;
  };
  bool first = true;
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    const Weights& a = sample_arc_[k];
    const std::vector<double>& r0 = row(a.c0);
    const std::vector<double>& r1 = row(a.c1);
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) gap = std::min(gap, gap0_[i] + base[i] + ((1 - a.w1) * r0[i] + a.w1 * r1[i]));
    const double loss = (gap - gap0_min_) / std::cos(samples_[k].pressure_angle_rad);
    if (first || loss > out.max_m) {
      out.max_m = loss;
      out.at_theta_rad = samples_[k].theta_rad;
      first = false;
    }
  }
  return out;
}

CreepLawSettings worn_contact_settings(const contact::Profiles& unworn, const CamWearGrid& g, CreepLawSettings law,
                                       double max_strip_m) {
  const double lo = std::max(unworn.body1.y_m(0), unworn.body2.y_m(0));
  const double hi = std::min(unworn.body1.y_m(unworn.body1.y_m.size() - 1), unworn.body2.y_m(unworn.body2.y_m.size() - 1));
  law.fixed_grid_y_lo_m = lo;
  law.fixed_grid_y_hi_m = hi;
  const double cell = g.roller_cell_m();
  const int per_cell = max_strip_m > 0 ? std::max(1, static_cast<int>(std::ceil(cell / max_strip_m - 1e-9))) : 1;
  law.grid.ny = std::max(2, per_cell * static_cast<int>(std::lround((hi - lo) / cell)));
  law.worn = true;
  return law;
}

RevolutionDissipation worn_revolution_dissipation(const CamModel& m, const Revolution& r, const RollerMotion& motion,
                                                  const contact::Profiles& unworn, const CamWearGrid& g,
                                                  const CamWearState& s, const CreepLawSettings& law) {
  if (motion.angles.size() != r.rows.size())
    throw std::invalid_argument("worn_revolution_dissipation: the roller's motion does not match the revolution");
  const double duration = 2 * contact::kPi / m.angle_steps / m.omega_rad_per_s;
  // the strips no wider than the unworn revolution's narrowest contact's (2 b / ny)
  double b_min = std::numeric_limits<double>::infinity();
  for (const RevolutionRow& row : r.rows) b_min = std::min(b_min, row.contact.b_m);
  const CreepLawSettings fixed = worn_contact_settings(unworn, g, law, 2 * b_min / law.grid.ny);
  RevolutionDissipation out;
  out.reserve(r.rows.size());
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const RevolutionRow& row = r.rows[i];
    const contact::Profiles worn = worn_profiles_at(unworn, g, s, row.contact_arc_m);
    const AngleContact c = angle_contact(m.bodies, worn, m.geometry.roller_radius_m, row.kin, motion.angles[i].normal_N,
                                         m.mu, fixed);
    RollerAngle roller = motion.angles[i];
    const CreepageForForce xi = creepage_for_force(c, roller.tangential_N);
    if (xi.found) {
      roller.xi = xi.xi;
      roller.slip_speed_m_per_s = xi.xi * roller.speed_m_per_s;
    }
    out.push_back(angle_dissipation(c, row, roller, duration));
  }
  return out;
}

DissipationOf CamLifeSetup::producer() const {
  return [this](const CamWearState& s) {
    if ((s.cam_depth_m == 0).all() && (s.roller_depth_m == 0).all()) return unworn;
    return (*worn)(s);
  };
}

std::unique_ptr<CamLifeSetup> set_up_cam_life(const std::string& name, const CamModel& model, const CamWearSpec& spec,
                                              const RollerDynamicsSettings& dynamics) {
  auto setup = std::make_unique<CamLifeSetup>();
  CamLifeSetup& u = *setup;
  u.model = model;
  u.dynamics = dynamics;
  u.revolution = run_revolution(u.model);
  if (u.revolution.status == RevolutionStatus::Jump) return setup;
  u.motion = periodic_motion(u.model, u.revolution, u.dynamics);
  if (!u.motion.converged)
    throw std::runtime_error(fmt::format("the roller's motion is not periodic after {} revolutions (residual {:.3g} "
                                         "rad/s against {:.3g})",
                                         u.motion.revolutions, u.motion.periodicity_residual_rad_per_s,
                                         u.motion.tolerance_rad_per_s));
  u.unworn = revolution_dissipation(u.model, u.revolution, u.motion.motion, u.dynamics.law);
  u.unworn_profiles = roller_and_track_profiles(u.model.bodies);
  u.life = make_cam_life_model(name, spec, u.model.mu, u.unworn_profiles, u.model.geometry.roller_radius_m,
                               u.revolution.cam_circumference_m, u.unworn, lift_loss_samples(u.revolution));
  WornRevolutionOptions worn_options;
  worn_options.skip_stride = spec.skip_stride;
  worn_options.skip_power_rtol = spec.skip_power_rtol;
  u.worn = std::make_shared<WornRevolution>(u.model, u.revolution, u.motion.motion, u.unworn_profiles, u.life.grid,
                                            u.dynamics.law, worn_options);
  return setup;
}

double cam_worn_volume_m3(const CamWearGrid& g, const CamWearState& s) {
  return s.cam_depth_m.sum() * g.arc_cell_m() * g.track_cell_m();
}

double roller_worn_volume_m3(const CamWearGrid& g, const CamWearState& s) {
  return s.roller_depth_m.sum() * g.roller_cell_m() * 2 * contact::kPi * g.roller_radius_m;
}

CamLifeModel make_cam_life_model(const std::string& name, const CamWearSpec& spec, double mu,
                                 const contact::Profiles& unworn, double roller_radius_m, double circumference_m,
                                 const RevolutionDissipation& rev, std::vector<LiftLossSample> samples) {
  CamLifeModel m;
  m.name = name;
  m.grid.circumference_m = circumference_m;
  m.grid.arc_cells = spec.arc_cells;
  m.grid.track_width_m = unworn.body2.y_m(unworn.body2.y_m.size() - 1) - unworn.body2.y_m(0);
  m.grid.track_cells = spec.lateral_cells;
  m.grid.roller_radius_m = roller_radius_m;
  m.grid.roller_width_m = unworn.body1.y_m(unworn.body1.y_m.size() - 1) - unworn.body1.y_m(0);
  m.grid.roller_cells = spec.lateral_cells;
  m.grid.cell_theta_rad = cell_angles_rad(m.grid, rev);
  m.laws = spec.laws;
  m.laws.mu = mu;
  m.unworn = unworn;
  m.samples = std::move(samples);
  m.revolutions = spec.revolutions;
  m.max_depth_m = spec.max_depth_m;
  m.max_lift_loss_m = spec.max_lift_loss_m;
  m.stepping = spec.stepping;
  m.scheme = spec.scheme;
  m.smoothing_wavelength_m = spec.smoothing_wavelength_m;
  m.snapshots_revolutions = spec.snapshots_revolutions;
  return m;
}

CamLifeResult run_cam_life(const CamLifeModel& m, const DissipationOf& dissipation, const CamLifeHooks& hooks,
                           const CamLifeStart& start) {
  check_grid(m.grid);
  if (!(m.revolutions > 0)) throw std::invalid_argument("cam life: the budget of revolutions must be > 0");
  if (!m.laws.cam && !m.laws.roller) throw std::invalid_argument("cam life: nothing wears");
  const Layout lay = layout(m.grid);
  wear::IntegratorOptions options0 = wear::integrator_options(m.stepping);
  options0.scheme = m.scheme;

  CamLifeResult life;
  life.state = unworn_state(m.grid);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(lay.size());

  // the lateral filter's kernels on the cells' centres (which never move)
  const auto centres = [](double width_m, int n) {
    return Eigen::ArrayXd::LinSpaced(n, -0.5 * width_m + 0.5 * width_m / n, 0.5 * width_m - 0.5 * width_m / n);
  };
  const bool smooth = m.smoothing_wavelength_m > 0;
  const wear::SmoothingKernel track_kernel =
      smooth ? wear::smoothing_kernel(centres(m.grid.track_width_m, m.grid.track_cells), m.smoothing_wavelength_m)
             : wear::SmoothingKernel{};
  const wear::SmoothingKernel roller_kernel =
      smooth ? wear::smoothing_kernel(centres(m.grid.roller_width_m, m.grid.roller_cells), m.smoothing_wavelength_m)
             : wear::SmoothingKernel{};

  const LiftLossProbe lift_loss(m.unworn, m.grid, m.samples);

  // f(h): the wear per revolution on the worn geometry; the last one kept (an FSAL stage, the step
  // report and a limit's probe often ask at the same state)
  Eigen::VectorXd last_x;
  Eigen::VectorXd last_f;
  double energy_scale = 0;  // e = E energy_scale: on the depths' scale, so the error test weighs it alike
  const auto rate = [&](const Eigen::VectorXd& h) -> const Eigen::VectorXd& {
    if (last_x.size() == h.size() && last_x == h) return last_f;
    const CamWearState s = state_of(m.grid, h);
    CamWearRate r = wear_per_revolution(dissipation(s), m.grid, m.laws);
    ++life.revolutions_solved;
    if (smooth) {
      Eigen::ArrayXXd& h_cam = r.depth_per_revolution.cam_depth_m;
      for (int i = 0; i < h_cam.rows(); ++i)
        if ((h_cam.row(i) != 0).any()) h_cam.row(i) = wear::smooth_conserving(h_cam.row(i).transpose(), track_kernel).transpose();
      r.depth_per_revolution.roller_depth_m = wear::smooth_conserving(r.depth_per_revolution.roller_depth_m, roller_kernel);
    }
    if (energy_scale == 0) {
      const double depth_rate = std::max(max_depth_of(r.depth_per_revolution), 1e-300);
      energy_scale = r.energy_J > 0 ? depth_rate / r.energy_J : 1;
    }
    last_f.resize(lay.size());
    last_f.head(lay.n_cam) = Eigen::Map<const Eigen::VectorXd>(r.depth_per_revolution.cam_depth_m.data(), lay.n_cam);
    last_f.segment(lay.n_cam, lay.n_roller) = r.depth_per_revolution.roller_depth_m.matrix();
    last_f(lay.energy()) = r.energy_J * energy_scale;
    last_x = h;
    return last_f;
  };
  // the limits, g < 0 inside the life; -1 where a limit is off
  const auto limits = [&](const Eigen::VectorXd& h, Eigen::VectorXd& g) {
    g = Eigen::VectorXd::Constant(kLimits, -1.0);
    const CamWearState s = state_of(m.grid, h);
    if (m.max_depth_m > 0) g(0) = max_depth_of(s) - m.max_depth_m;
    if (m.max_lift_loss_m > 0) g(1) = lift_loss(s).max_m - m.max_lift_loss_m;
  };
  const auto finish = [&](CamLifeEnd end, std::string message) -> CamLifeResult& {
    const bool snapshot = end != CamLifeEnd::Stopped;
    life.ended_by = end;
    life.message = std::move(message);
    life.state = state_of(m.grid, x);
    life.max_depth_m = max_depth_of(life.state);
    life.lift_loss = lift_loss(life.state);
    life.energy_J = energy_scale > 0 ? x(lay.energy()) / energy_scale : 0;
    life.cam_volume_m3 = cam_worn_volume_m3(m.grid, life.state);
    life.roller_volume_m3 = roller_worn_volume_m3(m.grid, life.state);
    if (snapshot && hooks.on_snapshot) hooks.on_snapshot(life.N, life.state);
    return life;
  };

  const bool resumed = start.x.size() > 0;
  if (resumed) {
    if (start.x.size() != lay.size() || !(start.energy_scale > 0) || !(start.N >= 0) || !(start.N <= m.revolutions))
      throw std::invalid_argument(fmt::format("cam life: the start (state of {} values at N {:.10g}, energy scale "
                                              "{:.3g}) is not one of this model (state of {} values)",
                                              start.x.size(), start.N, start.energy_scale, lay.size()));
    x = start.x;
    life.N = start.N;
    energy_scale = start.energy_scale;
    life.steps = start.steps;
    life.rejected = start.rejected;
    // the integrator's first evaluation, at the start, is the last step's end's, counted already (as in the
    // wear loop's continuations, docs/wear-loop.md "Counters"); the producer is called there again
    life.rhs_evals = std::max(0L, start.rhs_evals - 1);
    life.revolutions_solved = start.revolutions_solved;
  } else {
    if (hooks.on_snapshot) hooks.on_snapshot(0, life.state);
    try {
      rate(x);  // the unworn revolution: fixes the energy's scale, and fails early on a bad producer
    } catch (const std::exception& e) {
      return finish(CamLifeEnd::Failed, fmt::format("the unworn revolution failed: {}", e.what()));
    }
  }

  std::vector<double> ends;  // the segments still ahead of the start
  for (double N : m.snapshots_revolutions)
    if (N > life.N && N < m.revolutions) ends.push_back(N);
  ends.push_back(m.revolutions);
  bool stopped = false;
  double next_step = resumed ? start.next_step : 0;

  const wear::Rhs f = [&](double, const Eigen::VectorXd& h, Eigen::VectorXd& dhdN) { dhdN = rate(h); };
  const wear::Roots roots = [&](double, const Eigen::VectorXd& h, Eigen::VectorXd& g) { limits(h, g); };
  for (const double N_end : ends) {
    if (N_end <= life.N) continue;  // a start at the budget's end (a checkpoint of its last step)
    wear::IntegratorOptions options = options0;
    if (next_step > 0 && options.method == wear::IntegratorOptions::Method::Adaptive) options.initial_step = next_step;
    next_step = 0;  // later segments start as the uninterrupted life's do: from ARKODE's estimate
    options.max_steps = m.stepping.max_steps - life.steps;
    if (options.max_steps <= 0) return finish(CamLifeEnd::MaxSteps, fmt::format("max_steps {} reached", m.stepping.max_steps));
    Eigen::VectorXd last_accepted = x;
    double last_N = life.N;
    const long steps_before = life.steps, rejected_before = life.rejected, rhs_evals_before = life.rhs_evals;
    const wear::OnStep on_step = [&](const wear::StepInfo& info, const Eigen::VectorXd& h) {
      last_accepted = h;
      last_N = info.N;
      if (hooks.on_step || hooks.stop_after) {
        const CamWearState s = state_of(m.grid, h);
        CamLifeStep step;
        step.step = steps_before + info.steps;
        step.N = info.N;
        step.state = &s;
        step.max_depth_m = max_depth_of(s);
        step.lift_loss = lift_loss(s);
        step.energy_J = h(lay.energy()) / energy_scale;
        step.resume.N = info.N;
        step.resume.x = h;
        step.resume.energy_scale = energy_scale;
        step.resume.next_step = info.next_step;
        step.resume.steps = step.step;
        step.resume.rejected = rejected_before + info.rejected;
        step.resume.rhs_evals = rhs_evals_before + info.rhs_evals;
        step.resume.revolutions_solved = life.revolutions_solved;
        if (hooks.on_step) hooks.on_step(step);
        if (hooks.stop_after && hooks.stop_after(step)) {
          stopped = true;
          return false;
        }
      }
      return true;
    };
    wear::IntegratorResult r;
    try {
      r = wear::integrate(f, roots, kLimits, life.N, x, N_end, options, on_step);
    } catch (const std::exception& e) {
      x = last_accepted;
      life.N = last_N;
      std::string why = e.what();
      try {
        std::rethrow_if_nested(e);
      } catch (const std::exception& inner) {
        why += std::string(": ") + inner.what();
      }
      return finish(CamLifeEnd::Failed, fmt::format("ended at N {:.10g}, the last accepted step: {}", life.N, why));
    }
    x = r.h_m;
    life.N = r.N;
    life.steps += r.steps;
    life.rejected += r.rejected;
    life.rhs_evals += r.rhs_evals;
    using Kind = wear::IntegratorStatus::Kind;
    switch (r.status.kind) {
      case Kind::ReachedEnd:
        if (N_end < m.revolutions && hooks.on_snapshot) hooks.on_snapshot(life.N, state_of(m.grid, x));
        continue;
      case Kind::RootFound: {
        const CamLifeEnd end = kLimitEnds[r.status.roots.front()];
        return finish(end, fmt::format("{} reached at N {:.10g}, in step {}", to_string(end), life.N, life.steps));
      }
      case Kind::MaxSteps: return finish(CamLifeEnd::MaxSteps, r.status.message);
      case Kind::Stopped:
        if (stopped)
          return finish(CamLifeEnd::Stopped, fmt::format("stopped after step {} at N {:.10g}", life.steps, life.N));
        return finish(CamLifeEnd::Failed, r.status.message);
      case Kind::Failed: return finish(CamLifeEnd::Failed, r.status.message);
    }
  }
  return finish(CamLifeEnd::Revolutions,
                fmt::format("the life budget revolutions = {:.10g} reached with no limit", m.revolutions));
}

}  // namespace cam
