// The cam's life in cam revolutions (cam/cam_life.h).
#include "cam/cam_life.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "cam/cam_error.h"
#include "cam/revolution.h"
#include "cam/revolution_dissipation.h"
#include "cam/roller_motion.h"
#include "lib/numeric.h"
#include "wear/integrator.h"
#include "wear/life.h"
#include "wear/wear_output.h"
#include "wear/profile_update.h"

namespace cam {

namespace {

// the state vector: [track map, arc-major columns as Eigen stores them | roller | e | with fatigue: the track's
// damage, as the map | the roller's], e = E energy_scale, the damage D damage_scale_m
struct Layout {
  int n_cam = 0, n_roller = 0;
  bool damage = false;
  int size() const { return (n_cam + n_roller) * (damage ? 2 : 1) + 1; }
  int energy() const { return n_cam + n_roller; }
  int damage_start() const { return n_cam + n_roller + 1; }
};

Layout layout(const CamWearGrid& g, bool damage = false) {
  return {g.arc_cells * g.track_cells, g.roller_cells, damage};
}
Layout layout(const CamLifeModel& m) { return layout(m.grid, m.fatigue.has_value()); }

// the damage held in x (with the model's fatigue)
CamDamage damage_of(const CamLifeModel& m, const Eigen::VectorXd& x) {
  const Layout lay = layout(m);
  CamDamage d;
  d.cam = Eigen::Map<const Eigen::ArrayXXd>(x.data() + lay.damage_start(), m.grid.arc_cells, m.grid.track_cells) /
          m.damage_scale_m;
  d.roller = x.segment(lay.damage_start() + lay.n_cam, lay.n_roller).array() / m.damage_scale_m;
  return d;
}

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
                                         mu_at(m, i), fixed);
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

ProducerMemory CamLifeSetup::memory() const {
  ProducerMemory m;
  m.save = [w = worn] { return w->memory(); };
  m.restore = [w = worn](const std::vector<double>& v) { w->restore(v); };
  return m;
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
  // on the half-space the unworn revolution is the worn one's at no wear (its fixed lattice, cam/halfspace_contact.h),
  // so the rate is continuous at the start of the life
  if (u.dynamics.law.normal == contact::NormalChoice::Halfspace) u.unworn = (*u.worn)(unworn_state(u.life.grid));
  return setup;
}

std::string cam_life_report_text(const std::string& case_name, double omega_rad_per_s, const CamLifeResult& life,
                                 const WornRevolutionStats& worn, bool resumed, double cpu_s) {
  wear::LifeReport r;
  r.case_name = case_name;
  r.ended_by = life.ended_by;
  r.failure = life.failure;
  r.message = life.message;
  r.revolutions = life.N;
  r.hours = life.N * 2 * contact::kPi / omega_rad_per_s / 3600;
  r.max_depth_m = life.max_depth_m;
  r.dissipated_J = life.energy_J;
  r.counters.steps = life.steps;
  r.counters.rejected = life.rejected;
  r.counters.rhs_evals = life.rhs_evals;
  r.resumed = resumed;
  r.digits = 6;
  const auto g6 = [](double v) { return fmt::format("{:.6g}", v); };
  r.own = {{"speed_rad_per_s", g6(omega_rad_per_s)},
           {"lift_loss_m", g6(life.lift_loss.max_m)},
           {"lift_loss_at_deg", fmt::format("{:.4g}", life.lift_loss.at_theta_rad * kDegPerRad)},
           {"worn_volume_track_m3", g6(life.cam_volume_m3)},
           {"worn_volume_roller_m3", g6(life.roller_volume_m3)},
           {"revolutions_solved", std::to_string(life.revolutions_solved)},
           {"worn_angle_steps", std::to_string(worn.angles)},
           {"interpolated_angle_steps", std::to_string(worn.interpolated_angles)},
           {"normal_solves", std::to_string(worn.contacts_solved)},
           {"approach_evaluations", std::to_string(worn.approach_evaluations)},
           {"creep_evaluations", std::to_string(worn.creep_evaluations)},
           {"cold_retries", std::to_string(worn.cold_retries)},
           {"cpu_s", fmt::format("{:.3g}", cpu_s)}};
  return wear::life_report_text(r);
}

std::string cam_damage_report_text(const CamLifeModel& m, const CamLifeResult& life) {
  if (!m.fatigue) return "";
  const auto g6 = [](double v) { return fmt::format("{:.6g}", v); };
  const CamDamageMax& d = life.max_damage;
  std::string out;
  out += "fatigue_law: " + wear::to_string(m.fatigue->law) + "\n";
  out += "max_damage: " + g6(d.value) + "\n";
  out += "max_damage_body: " + (d.body.empty() ? std::string("none") : d.body) + "\n";
  out += "max_damage_at_deg: " + fmt::format("{:.4g}", d.theta_rad * kDegPerRad) + "\n";
  out += "max_damage_arc_m: " + g6(d.arc_m) + "\n";
  out += "max_damage_y_m: " + g6(d.y_m) + "\n";
  out += "max_tgamma_N: " + g6(life.max_tgamma_N) + "\n";
  out += "max_tgamma_at_deg: " + fmt::format("{:.4g}", life.max_tgamma_at_rad * kDegPerRad) + "\n";
  return out;
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
  m.fatigue = spec.fatigue;
  if (spec.max_depth_m > 0) m.damage_scale_m = spec.max_depth_m;
  return m;
}

namespace {

void check_life_model(const CamLifeModel& m) {
  check_grid(m.grid);
  if (!(m.revolutions > 0)) throw std::invalid_argument("cam life: the budget of revolutions must be > 0");
  if (!m.laws.cam && !m.laws.roller) throw std::invalid_argument("cam life: nothing wears");
  if (m.fatigue && !(m.damage_scale_m > 0 && std::isfinite(m.damage_scale_m)))
    throw std::invalid_argument("cam life: the damage's scale must be > 0 and finite");
}

// f(x): the wear per revolution on the worn geometry, smoothed across the width, with the dissipated energy
// on the depths' scale (e = E energy_scale, fixed by the first evaluation, so that the error test weighs it
// alike); the last one kept (an FSAL stage, the step report and a limit's probe often ask at the same state)
class CamRate {
 public:
  CamRate(const CamLifeModel& m, const DissipationOf& dissipation)
      : m_(m), dissipation_(dissipation), layout_(layout(m)), smooth_(m.smoothing_wavelength_m > 0) {
    // the lateral filter's kernels on the cells' centres (which never move)
    const auto centres = [](double width_m, int n) {
      return Eigen::ArrayXd::LinSpaced(n, -0.5 * width_m + 0.5 * width_m / n, 0.5 * width_m - 0.5 * width_m / n);
    };
    if (smooth_) {
      track_kernel_ = wear::smoothing_kernel(centres(m.grid.track_width_m, m.grid.track_cells), m.smoothing_wavelength_m);
      roller_kernel_ =
          wear::smoothing_kernel(centres(m.grid.roller_width_m, m.grid.roller_cells), m.smoothing_wavelength_m);
    }
  }

  const Eigen::VectorXd& operator()(const Eigen::VectorXd& h) {
    if (last_x_.size() == h.size() && last_x_ == h) return last_f_;
    const CamWearState s = state_of(m_.grid, h);
    const RevolutionDissipation rev = dissipation_(s);
    CamWearRate r = wear_per_revolution(rev, m_.grid, m_.laws);
    ++solved;
    if (smooth_) {
      Eigen::ArrayXXd& h_cam = r.depth_per_revolution.cam_depth_m;
      for (int i = 0; i < h_cam.rows(); ++i)
        if ((h_cam.row(i) != 0).any()) h_cam.row(i) = wear::smooth_conserving(h_cam.row(i).transpose(), track_kernel_).transpose();
      r.depth_per_revolution.roller_depth_m = wear::smooth_conserving(r.depth_per_revolution.roller_depth_m, roller_kernel_);
    }
    if (energy_scale == 0) {
      const double depth_rate = std::max(max_depth_of(r.depth_per_revolution), 1e-300);
      energy_scale = r.energy_J > 0 ? depth_rate / r.energy_J : 1;
    }
    const Layout& lay = layout_;
    last_f_.resize(lay.size());
    last_f_.head(lay.n_cam) = Eigen::Map<const Eigen::VectorXd>(r.depth_per_revolution.cam_depth_m.data(), lay.n_cam);
    last_f_.segment(lay.n_cam, lay.n_roller) = r.depth_per_revolution.roller_depth_m.matrix();
    last_f_(lay.energy()) = r.energy_J * energy_scale;
    if (lay.damage) damage_rate(rev);
    last_x_ = h;
    return last_f_;
  }

  // the rate at h when it is the last one evaluated (a step's end: its slope), else nullptr
  const Eigen::VectorXd* last_at(const Eigen::VectorXd& h) const {
    return last_x_.size() == h.size() && last_x_ == h ? &last_f_ : nullptr;
  }
  // the rate at h as an earlier evaluation made it (a checkpoint's), asked for again without the producer
  void remember(const Eigen::VectorXd& h, const Eigen::VectorXd& f) {
    last_x_ = h;
    last_f_ = f;
  }

  double energy_scale = 0;  // e = E energy_scale
  long solved = 0;          // calls of the producer
  double max_tgamma_N = 0, max_tgamma_at_rad = 0;  // the last evaluation's (with fatigue)

 private:
  const CamLifeModel& m_;
  const DissipationOf& dissipation_;
  Layout layout_;
  bool smooth_;
  wear::SmoothingKernel track_kernel_, roller_kernel_;
  Eigen::VectorXd last_x_, last_f_;

  // with fatigue: the damage per revolution of the same dissipation into the rate's damage segment
  void damage_rate(const RevolutionDissipation& rev) {
    const CamDamageRate d = damage_per_revolution(rev, m_.grid, *m_.fatigue);
    const Layout& lay = layout_;
    last_f_.segment(lay.damage_start(), lay.n_cam) =
        Eigen::Map<const Eigen::VectorXd>(d.per_revolution.cam.data(), lay.n_cam) * m_.damage_scale_m;
    last_f_.segment(lay.damage_start() + lay.n_cam, lay.n_roller) = d.per_revolution.roller.matrix() * m_.damage_scale_m;
    max_tgamma_N = d.max_tgamma_N;
    max_tgamma_at_rad = d.max_tgamma_at_rad;
  }
};

// the largest damage held in x, and where (with the model's fatigue; value 0 without)
CamDamageMax max_damage_in(const CamLifeModel& m, const Eigen::VectorXd& x) {
  if (!m.fatigue) return {};
  return max_damage(m.grid, damage_of(m, x));
}

// the cam's life as the driver's problem: its rate, its limits (the depth and the lift loss, g < 0 inside
// the life, -1 where a limit is off); any failure of the producer ends the life at its last accepted step
wear::LifeProblem cam_life_problem(const CamLifeModel& m, CamRate& rate, const LiftLossProbe& lift_loss) {
  wear::LifeProblem p;
  p.rate = [&rate](double, const Eigen::VectorXd& h, Eigen::VectorXd& dhdN) { dhdN = rate(h); };
  p.limits = {wear::LifeEnd::MaxDepth, wear::LifeEnd::LiftLoss};
  if (m.fatigue) p.limits.push_back(wear::LifeEnd::Fatigue);  // g = max D - 1
  p.limit_values = [&m, &lift_loss](double, const Eigen::VectorXd& h, Eigen::VectorXd& g) {
    g = Eigen::VectorXd::Constant(m.fatigue ? 3 : 2, -1.0);
    const CamWearState s = state_of(m.grid, h);
    if (m.max_depth_m > 0) g(0) = max_depth_of(s) - m.max_depth_m;
    if (m.max_lift_loss_m > 0) g(1) = lift_loss(s).max_m - m.max_lift_loss_m;
    if (m.fatigue) {
      const Layout lay = layout(m);
      g(2) = h.segment(lay.damage_start(), lay.n_cam + lay.n_roller).maxCoeff() / m.damage_scale_m - 1;
    }
  };
  p.options = wear::integrator_options(m.stepping);
  p.options.scheme = m.scheme;
  p.revolutions = m.revolutions;
  p.budget_key = "revolutions";
  for (const double N : m.snapshots_revolutions)  // the budget's end has the life's end snapshot
    if (N < m.revolutions) p.snapshots_revolutions.push_back(N);
  p.solves = [&rate] {
    wear::LifeCounters c;
    c.tangential_solves = rate.solved;
    return c;
  };
  p.failure_of = [](const std::exception&, double) { return wear::LifeFailure::Rate; };
  return p;
}

// the driver's start from the caller's (a checkpoint's content, checked against the model), the producer's
// revolutions solved counted as the life's tangential solves
// (its rate at the state remembered, so that the first step does not evaluate it again, and the producer's
// memory restored: the uninterrupted life's next evaluation starts from the same)
wear::LifeStart driver_start(const CamLifeModel& m, const CamLifeStart& start, CamRate& rate,
                             const ProducerMemory& memory) {
  const Layout lay = layout(m);
  if (start.x.size() != lay.size() || !(start.energy_scale > 0) || !(start.N >= 0) || !(start.N <= m.revolutions) ||
      (start.rate.size() != 0 && start.rate.size() != lay.size()))
    throw std::invalid_argument(fmt::format("cam life: the start (state of {} values at N {:.10g}, energy scale "
                                            "{:.3g}, rate of {} values) is not one of this model (state of {} values)",
                                            start.x.size(), start.N, start.energy_scale, start.rate.size(),
                                            lay.size()));
  if (!start.producer_memory.empty() && memory.restore) memory.restore(start.producer_memory);
  if (start.rate.size() != 0) rate.remember(start.x, start.rate);
  rate.energy_scale = start.energy_scale;
  wear::LifeStart s;
  s.N = start.N;
  s.state = start.x;
  s.next_step = start.next_step;
  s.counters.steps = start.steps;
  s.counters.rejected = start.rejected;
  s.counters.rhs_evals = start.rhs_evals;
  s.counters.tangential_solves = start.revolutions_solved;
  return s;
}

// the step as the cam's hooks see it: the worn state, its depth, lift loss and energy, and the start that
// continues the life from there
CamLifeStep cam_life_step(const CamLifeModel& m, const wear::LifeStepEnd& e, const CamWearState& s,
                          const LiftLossProbe& lift_loss, const CamRate& rate, const ProducerMemory& memory) {
  const double energy_scale = rate.energy_scale;
  const wear::LifeCounters counters = e.counters();
  CamLifeStep step;
  step.step = counters.steps;
  step.N = e.N;
  step.state = &s;
  step.max_depth_m = max_depth_of(s);
  step.lift_loss = lift_loss(s);
  step.energy_J = (*e.state)(layout(m.grid).energy()) / energy_scale;
  step.damage = max_damage_in(m, *e.state);
  step.resume.N = e.N;
  step.resume.x = *e.state;
  step.resume.energy_scale = energy_scale;
  step.resume.next_step = e.next_step;
  step.resume.steps = counters.steps;
  step.resume.rejected = counters.rejected;
  step.resume.rhs_evals = counters.rhs_evals;
  step.resume.revolutions_solved = counters.tangential_solves;
  if (const Eigen::VectorXd* f = rate.last_at(*e.state)) step.resume.rate = *f;
  if (memory.save) step.resume.producer_memory = memory.save();
  return step;
}

// the life's end: the worn state and what it says, and its snapshot (none for a stopped life: a kill's state)
CamLifeResult finish_cam_life(const CamLifeModel& m, const wear::LifeOutcome& out, const LiftLossProbe& lift_loss,
                              const CamRate& rate, const CamLifeHooks& hooks) {
  const double energy_scale = rate.energy_scale;
  CamLifeResult life;
  life.ended_by = out.ended_by;
  life.failure = out.failure;
  life.message = out.message;
  life.N = out.N;
  life.state = state_of(m.grid, out.state);
  life.max_depth_m = max_depth_of(life.state);
  life.lift_loss = lift_loss(life.state);
  life.energy_J = energy_scale > 0 ? out.state(layout(m.grid).energy()) / energy_scale : 0;
  life.cam_volume_m3 = cam_worn_volume_m3(m.grid, life.state);
  life.roller_volume_m3 = roller_worn_volume_m3(m.grid, life.state);
  life.steps = out.counters.steps;
  life.rejected = out.counters.rejected;
  life.rhs_evals = out.counters.rhs_evals;
  life.revolutions_solved = out.counters.tangential_solves;
  if (m.fatigue) {
    life.damage = damage_of(m, out.state);
    life.max_damage = max_damage(m.grid, life.damage);
    life.max_tgamma_N = rate.max_tgamma_N;
    life.max_tgamma_at_rad = rate.max_tgamma_at_rad;
  }
  if (out.ended_by != wear::LifeEnd::Stopped && m.fatigue && hooks.on_damage_snapshot)
    hooks.on_damage_snapshot(life.N, life.damage);
  if (out.ended_by != wear::LifeEnd::Stopped && hooks.on_snapshot) hooks.on_snapshot(life.N, life.state);
  return life;
}

}  // namespace

CamLifeResult run_cam_life(const CamLifeModel& m, const DissipationOf& dissipation, const CamLifeHooks& hooks,
                           const CamLifeStart& start, const ProducerMemory& memory) {
  check_life_model(m);
  CamRate rate(m, dissipation);
  const LiftLossProbe lift_loss(m.unworn, m.grid, m.samples);
  const wear::LifeProblem problem = cam_life_problem(m, rate, lift_loss);
  const Layout lay = layout(m);

  // where the life starts: a checkpoint's step end, or the unworn state, whose revolution fixes the energy's
  // scale (and fails early on a bad producer)
  wear::LifeStart from;
  if (start.x.size() > 0) {
    from = driver_start(m, start, rate, memory);
  } else {
    from.state = Eigen::VectorXd::Zero(lay.size());
    if (m.fatigue && hooks.on_damage_snapshot) hooks.on_damage_snapshot(0, damage_of(m, from.state));
    if (hooks.on_snapshot) hooks.on_snapshot(0, unworn_state(m.grid));
    try {
      rate(from.state);
    } catch (const std::exception& e) {
      wear::LifeOutcome failed;
      failed.ended_by = wear::LifeEnd::Failed;
      failed.failure = wear::LifeFailure::Rate;
      failed.message = fmt::format("the unworn revolution failed: {}", e.what());
      failed.state = from.state;
      failed.counters.tangential_solves = rate.solved;
      return finish_cam_life(m, failed, lift_loss, rate, hooks);
    }
    from.counters.tangential_solves = rate.solved;
  }

  // each accepted step to the caller's hooks; stop_after ends the life there
  wear::LifeDriverHooks driver;
  if (hooks.on_step || hooks.stop_after)
    driver.on_step = [&](const wear::LifeStepEnd& e) {
      const CamWearState s = state_of(m.grid, *e.state);
      const CamLifeStep step = cam_life_step(m, e, s, lift_loss, rate, memory);
      if (hooks.on_step) hooks.on_step(step);
      return !(hooks.stop_after && hooks.stop_after(step));
    };
  driver.on_snapshot = [&](double N, const Eigen::VectorXd& x) {
    if (m.fatigue && hooks.on_damage_snapshot) hooks.on_damage_snapshot(N, damage_of(m, x));
    if (hooks.on_snapshot) hooks.on_snapshot(N, state_of(m.grid, x));
  };
  const wear::LifeOutcome out = wear::integrate_life(problem, from, driver);
  return finish_cam_life(m, out, lift_loss, rate, hooks);
}

}  // namespace cam
