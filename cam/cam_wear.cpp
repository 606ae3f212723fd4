// The wear map of the cam track and the roller's wear over one revolution (cam/cam_wear.h).
#include "cam/cam_wear.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>

#include "cam/cam_error.h"
#include "lib/enum_names.h"
#include "lib/number.h"
#include "lib/io/yaml_reader.h"
#include "lib/numeric.h"

namespace cam {

namespace {

bool positive_finite(double v) { return std::isfinite(v) && v > 0; }

}  // namespace

double deposit(double lo, double hi, double amount, double dx, int n, bool periodic, double* out) {
  const double length = n * dx;
  const double density = amount / (hi - lo);
  double deposited = 0;
  if (periodic) {
    const double shift = std::floor(lo / length) * length;
    lo -= shift;
    hi -= shift;  // lo in [0, length), hi < lo + length <= 2 length
  } else {
    lo = std::max(lo, 0.0);
    hi = std::min(hi, length);
    if (!(hi > lo)) return 0;
  }
  const int first = static_cast<int>(std::floor(lo / dx));
  const int last = static_cast<int>(std::ceil(hi / dx));  // one past
  for (int c = first; c < last; ++c) {
    const double overlap = std::min(hi, (c + 1) * dx) - std::max(lo, c * dx);
    if (!(overlap > 0)) continue;
    const int cell = periodic ? ((c % n) + n) % n : std::min(std::max(c, 0), n - 1);
    out[cell] += density * overlap;
    deposited += density * overlap;
  }
  return deposited;
}

Eigen::ArrayXd strip_edges(const Eigen::ArrayXd& y) {
  const Eigen::Index n = y.size();
  Eigen::ArrayXd e(n + 1);
  for (Eigen::Index j = 1; j < n; ++j) e(j) = 0.5 * (y(j - 1) + y(j));
  e(0) = y(0) - 0.5 * (y(1) - y(0));
  e(n) = y(n - 1) + 0.5 * (y(n - 1) - y(n - 2));
  return e;
}

namespace {

// the depth for energy per unit width E spread over a length (the circumference a worn surface's point
// goes round once): the wear law's depth per duty cycle with 2 pi R_w = length
Eigen::ArrayXd law_depth(const wear::WearLaw& law, double mu, const Eigen::ArrayXd& energy_J_per_m, double length_m) {
  if (law.law == wear::WearLawKind::Kth || law.law == wear::WearLawKind::Usfd)
    throw std::invalid_argument("cam wear: the law '" + wear::to_string(law.law) +
                                "' needs per-cell slip fields that the revolution's record does not carry: use "
                                "energy or archard");
  wear::DutyCycle duty;
  duty.worn_radius_m = length_m / (2 * contact::kPi);
  duty.mu = mu;
  duty.strip_energy_J_per_m = energy_J_per_m;
  return wear::depth_per_duty_cycle(law, duty);
}

}  // namespace

void cell_weights(double x, double dx, int n, bool periodic, int& c0, int& c1, double& w1) {
  double u = x / dx - 0.5;
  if (n == 1) {
    c0 = c1 = 0;
    w1 = 0;
    return;
  }
  if (periodic) {
    u -= std::floor(u / n) * n;  // [0, n)
    c0 = std::min(static_cast<int>(std::floor(u)), n - 1);
    c1 = (c0 + 1) % n;
    w1 = u - c0;
    return;
  }
  if (u <= 0) {
    c0 = c1 = 0;
    w1 = 0;
    return;
  }
  if (u >= n - 1) {
    c0 = c1 = n - 1;
    w1 = 0;
    return;
  }
  c0 = static_cast<int>(std::floor(u));
  c1 = c0 + 1;
  w1 = u - c0;
}

void check_grid(const CamWearGrid& g) {
  if (!positive_finite(g.circumference_m) || !positive_finite(g.track_width_m) || !positive_finite(g.roller_width_m) ||
      !positive_finite(g.roller_radius_m))
    throw std::invalid_argument(fmt::format("cam wear grid: circumference {} m, track width {} m, roller width {} m "
                                            "and radius {} m must all be > 0 and finite",
                                            g.circumference_m, g.track_width_m, g.roller_width_m, g.roller_radius_m));
  if (g.arc_cells < 1 || g.track_cells < 1 || g.roller_cells < 1)
    throw std::invalid_argument(fmt::format("cam wear grid: cells {} x {} (track), {} (roller) must be >= 1",
                                            g.arc_cells, g.track_cells, g.roller_cells));
  if (g.cell_theta_rad.size() != 0 && g.cell_theta_rad.size() != g.arc_cells)
    throw std::invalid_argument("cam wear grid: cell_theta_rad must be empty or have arc_cells entries");
}

CamWearState unworn_state(const CamWearGrid& g) {
  check_grid(g);
  return {Eigen::ArrayXXd::Zero(g.arc_cells, g.track_cells), Eigen::ArrayXd::Zero(g.roller_cells)};
}

void check_dissipation(const RevolutionDissipation& rev, const CamWearGrid& g) {
  check_grid(g);
  if (rev.empty()) throw std::invalid_argument("cam wear: the revolution's dissipation has no angle step");
  const std::size_t n = rev.size();
  const double theta0 = rev.front().theta_rad, arc0 = rev.front().cam_arc_m;
  for (std::size_t k = 0; k < n; ++k) {
    const AngleDissipation& a = rev[k];
    const auto fail = [&](const std::string& what) {
      throw std::invalid_argument(fmt::format("cam wear: angle step {} (cam angle {:.6g} deg): {}", k,
                                              a.theta_rad * kDegPerRad, what));
    };
    if (!std::isfinite(a.theta_rad) || !std::isfinite(a.cam_arc_m) || !positive_finite(a.duration_s) ||
        !std::isfinite(a.rolling_speed_m_per_s) || !std::isfinite(a.roller_surface_speed_m_per_s))
      fail("theta, arc and speeds must be finite and the duration > 0");
    if (k > 0 && !(a.theta_rad > rev[k - 1].theta_rad)) fail("cam angles must increase step by step");
    if (!(a.theta_rad < theta0 + 2 * contact::kPi)) fail("the steps must lie within one revolution");
    if (k > 0 && !(a.cam_arc_m > rev[k - 1].cam_arc_m)) fail("the contact's arc must increase step by step");
    if (!(a.cam_arc_m < arc0 + g.circumference_m)) fail("the contact's arc must stay within one circumference");
    const Eigen::Index ny = a.y_m.size();
    if (ny < 2) fail("at least two strips are needed (a strip's width is the spacing of their centres)");
    if (a.power_W_per_m.size() != ny) fail("power_W_per_m must have one entry per strip");
    if (a.mean_pressure_Pa.size() != 0 && a.mean_pressure_Pa.size() != ny)
      fail("mean_pressure_Pa must be empty or have one entry per strip");
    for (Eigen::Index j = 0; j < ny; ++j) {
      if (!std::isfinite(a.y_m(j)) || (j > 0 && !(a.y_m(j) > a.y_m(j - 1))))
        fail("strip centres must be finite and strictly increasing");
      if (!std::isfinite(a.power_W_per_m(j)) || a.power_W_per_m(j) < 0)
        fail(fmt::format("strip {}: the dissipated power must be finite and >= 0, got {}", j, a.power_W_per_m(j)));
    }
  }
}

Eigen::ArrayXd cell_angles_rad(const CamWearGrid& g, const RevolutionDissipation& rev) {
  check_dissipation(rev, g);
  const std::size_t n = rev.size();
  const double L = g.circumference_m;
  Eigen::ArrayXd theta(g.arc_cells);
  for (int i = 0; i < g.arc_cells; ++i) {
    // the arc relative to step 0's, in [0, L); the step whose swept arc holds it, and the fraction swept
    double s = g.arc_m(i) - rev.front().cam_arc_m;
    s -= std::floor(s / L) * L;
    std::size_t k = 0;
    while (k + 1 < n && rev[k + 1].cam_arc_m - rev.front().cam_arc_m <= s) ++k;
    const double s0 = rev[k].cam_arc_m - rev.front().cam_arc_m;
    const double s1 = k + 1 < n ? rev[k + 1].cam_arc_m - rev.front().cam_arc_m : L;
    const double t0 = rev[k].theta_rad;
    const double t1 = k + 1 < n ? rev[k + 1].theta_rad : rev.front().theta_rad + 2 * contact::kPi;
    double t = t0 + (t1 - t0) * (s - s0) / (s1 - s0);
    t -= std::floor(t / (2 * contact::kPi)) * 2 * contact::kPi;
    theta(i) = t;
  }
  return theta;
}

CamWearRate wear_per_revolution(const RevolutionDissipation& rev, const CamWearGrid& g, const CamWearLaws& laws) {
  check_dissipation(rev, g);
  const std::size_t n = rev.size();
  const double L = g.circumference_m;
  // the energy per unit width each track cell and each roller cell receives over the revolution (J/m)
  Eigen::ArrayXXd track_energy = Eigen::ArrayXXd::Zero(g.arc_cells, g.track_cells);
  Eigen::ArrayXd roller_energy = Eigen::ArrayXd::Zero(g.roller_cells);
  CamWearRate r;
  Eigen::ArrayXd lateral(g.track_cells);
  // the regime law's weights per step (CamWearLaws): none, or f_k (energy) and f_k mu / mu_k (archard) per body
  const bool weighted = !laws.mu_by_step.empty() || !laws.wear_factor_by_step.empty();
  if (weighted && (laws.mu_by_step.size() != n || laws.wear_factor_by_step.size() != n))
    throw std::invalid_argument(fmt::format("cam wear: the friction and wear factor per angle step have {} and {} "
                                            "values for {} steps", laws.mu_by_step.size(),
                                            laws.wear_factor_by_step.size(), n));
  const auto weight = [&](const std::optional<wear::WearLaw>& law, std::size_t k) {
    if (!law) return 0.0;
    const double f = laws.wear_factor_by_step[k], mu_k = laws.mu_by_step[k];
    if (!(f >= 0) || !std::isfinite(f) || !(mu_k > 0) || !std::isfinite(mu_k))
      throw std::invalid_argument(fmt::format("cam wear: step {}: the wear factor must be >= 0 and the friction > 0, "
                                              "got {} and {}", k, f, mu_k));
    return law->law == wear::WearLawKind::Archard ? f * laws.mu / mu_k : f;
  };
  Eigen::ArrayXd roller_step = Eigen::ArrayXd::Zero(weighted ? g.roller_cells : 0);
  for (std::size_t k = 0; k < n; ++k) {
    const AngleDissipation& a = rev[k];
    const double w_cam = weighted ? weight(laws.cam, k) : 1.0, w_roller = weighted ? weight(laws.roller, k) : 1.0;
    // a weight of exactly 1 deposits the step's energy as the unweighted record does (the same sums, to the bit)
    const bool roller_weighted = weighted && w_roller != 1.0;
    if (roller_weighted) roller_step.setZero();
    const double arc_lo = a.cam_arc_m, arc_hi = k + 1 < n ? rev[k + 1].cam_arc_m : rev.front().cam_arc_m + L;
    const Eigen::ArrayXd edges = strip_edges(a.y_m);
    // the step's energy per strip (J), deposited laterally onto the track's and the roller's cells
    lateral.setZero();
    for (Eigen::Index j = 0; j < a.y_m.size(); ++j) {
      const double width = edges(j + 1) - edges(j);
      const double energy = a.power_W_per_m(j) * width * a.duration_s;
      r.energy_J += energy;
      const double y0 = edges(j) + 0.5 * g.track_width_m, y1 = edges(j + 1) + 0.5 * g.track_width_m;
      r.track_energy_J += deposit(y0, y1, energy, g.track_cell_m(), g.track_cells, false, lateral.data());
      const double r0 = edges(j) + 0.5 * g.roller_width_m, r1 = edges(j + 1) + 0.5 * g.roller_width_m;
      r.roller_energy_J += deposit(r0, r1, energy, g.roller_cell_m(), g.roller_cells, false,
                                   roller_weighted ? roller_step.data() : roller_energy.data());
    }
    if (roller_weighted) roller_energy += w_roller * roller_step;
    // then along the arc the step's contact swept, per lateral cell
    for (int j = 0; j < g.track_cells; ++j)
      if (lateral(j) > 0)
        deposit(arc_lo, arc_hi, w_cam * lateral(j), g.arc_cell_m(), g.arc_cells, true, &track_energy(0, j));
  }
  // energies (J per cell) -> per unit width of the cell, then the wear law
  track_energy /= g.track_cell_m();
  roller_energy /= g.roller_cell_m();
  r.depth_per_revolution = unworn_state(g);
  if (laws.cam)
    for (int i = 0; i < g.arc_cells; ++i)
      r.depth_per_revolution.cam_depth_m.row(i) =
          law_depth(*laws.cam, laws.mu, track_energy.row(i).transpose(), g.arc_cell_m()).transpose();
  if (laws.roller)
    r.depth_per_revolution.roller_depth_m = law_depth(*laws.roller, laws.mu, roller_energy, 2 * contact::kPi * g.roller_radius_m);
  return r;
}

double cam_depth_at(const CamWearGrid& g, const CamWearState& s, double arc_m, double y_m) {
  int a0, a1, l0, l1;
  double wa, wl;
  cell_weights(arc_m, g.arc_cell_m(), g.arc_cells, true, a0, a1, wa);
  cell_weights(y_m + 0.5 * g.track_width_m, g.track_cell_m(), g.track_cells, false, l0, l1, wl);
  const Eigen::ArrayXXd& h = s.cam_depth_m;
  return (1 - wa) * ((1 - wl) * h(a0, l0) + wl * h(a0, l1)) + wa * ((1 - wl) * h(a1, l0) + wl * h(a1, l1));
}

double roller_depth_at(const CamWearGrid& g, const CamWearState& s, double y_m) {
  int l0, l1;
  double wl;
  cell_weights(y_m + 0.5 * g.roller_width_m, g.roller_cell_m(), g.roller_cells, false, l0, l1, wl);
  return (1 - wl) * s.roller_depth_m(l0) + wl * s.roller_depth_m(l1);
}

contact::Profiles worn_profiles_at(const contact::Profiles& unworn, const CamWearGrid& g, const CamWearState& s,
                                   double arc_m) {
  contact::Profiles p = unworn;
  for (Eigen::Index i = 0; i < p.body1.y_m.size(); ++i) p.body1.z_m(i) += roller_depth_at(g, s, p.body1.y_m(i));
  for (Eigen::Index i = 0; i < p.body2.y_m.size(); ++i) p.body2.z_m(i) += cam_depth_at(g, s, arc_m, p.body2.y_m(i));
  return p;
}

double normal_recession_m(const contact::Profiles& unworn, const CamWearGrid& g, const CamWearState& s,
                          double arc_m) {
  const contact::Profile& roller = unworn.body1;
  const contact::Profile& track = unworn.body2;
  const double lo = std::max(roller.y_m(0), track.y_m(0));
  const double hi = std::min(roller.y_m(roller.y_m.size() - 1), track.y_m(track.y_m.size() - 1));
  double gap0 = std::numeric_limits<double>::infinity(), gap = gap0;
  for (Eigen::Index i = 0; i < roller.y_m.size(); ++i) {
    const double y = roller.y_m(i);
    if (y < lo || y > hi) continue;
    const double g0 = roller.z_m(i) + contact::profile_z(track, y);
    gap0 = std::min(gap0, g0);
    gap = std::min(gap, g0 + roller_depth_at(g, s, y) + cam_depth_at(g, s, arc_m, y));
  }
  ROLLWEAR_ASSERT(std::isfinite(gap0), "the roller's and the track's profiles do not overlap laterally");
  return gap - gap0;
}

std::string grid_csv_header(const CamWearGrid& g, double revolutions, const std::string& name, const std::string& what) {
  return fmt::format("# case: {}\n# {}\n# revolutions: {}\n# grid: {} arc cells over {} m, {} track cells over {} m, "
                     "{} roller cells over {} m\n",
                     name, what, contact::round_trip(revolutions), g.arc_cells, contact::round_trip(g.circumference_m),
                     g.track_cells, contact::round_trip(g.track_width_m), g.roller_cells,
                     contact::round_trip(g.roller_width_m));
}

std::string wear_map_csv(const CamWearGrid& g, const CamWearState& s, double revolutions, const std::string& name) {
  std::string out = grid_csv_header(g, revolutions, name,
                           "the cam track's worn depth; cam_angle_deg: the cam angle at which the contact passes");
  out += "cam_angle_deg,cam_arc_m,y_m,depth_m\n";
  const bool angles = g.cell_theta_rad.size() == g.arc_cells;
  for (int i = 0; i < g.arc_cells; ++i) {
    const std::string angle = angles ? fmt::format("{:.8g}", g.cell_theta_rad(i) * kDegPerRad) : "nan";
    for (int j = 0; j < g.track_cells; ++j)
      fmt::format_to(std::back_inserter(out), "{},{:.10g},{:.10g},{:.10g}\n", angle, g.arc_m(i), g.track_y_m(j),
                     s.cam_depth_m(i, j));
  }
  return out;
}

std::string roller_wear_csv(const CamWearGrid& g, const CamWearState& s, double revolutions, const std::string& name) {
  std::string out = grid_csv_header(g, revolutions, name, "the roller's worn depth, even around its circumference");
  out += "y_m,depth_m\n";
  for (int j = 0; j < g.roller_cells; ++j)
    fmt::format_to(std::back_inserter(out), "{:.10g},{:.10g}\n", g.roller_y_m(j), s.roller_depth_m(j));
  return out;
}

namespace {
// cam.wear.stepping.scheme's names
using Scheme = wear::IntegratorOptions::Scheme;
constexpr contact::EnumTable<Scheme, 2> kSchemes = {{{Scheme::Euler, "euler"}, {Scheme::Heun, "heun"}}};
}  // namespace

void read_cam_wear(contact::YamlMap& m, CamWearSpec& spec) {
  m.optional_section("cam", [&](contact::YamlMap& s) { wear::read_wear_law(s, spec.laws.cam.emplace()); });
  m.optional_section("roller", [&](contact::YamlMap& s) { wear::read_wear_law(s, spec.laws.roller.emplace()); });
  if (!spec.laws.cam && !spec.laws.roller)
    m.fail_here("nothing wears: give cam: and/or roller: with a law, e.g. cam: { law: energy, k_E_m3_per_J: 1.0e-14 }");
  for (const std::optional<wear::WearLaw>* law : {&spec.laws.cam, &spec.laws.roller})
    if (*law && ((*law)->law == wear::WearLawKind::Kth || (*law)->law == wear::WearLawKind::Usfd))
      m.fail(law == &spec.laws.cam ? "cam" : "roller",
             "law: '" + wear::to_string((*law)->law) +
                 "' needs per-cell slip fields the cam's revolution does not carry: use energy or archard");
  m.required("revolutions", spec.revolutions, [](double v) -> std::string {
    return v > 0 && v <= 1e15 ? "" : "must be in (0, 1e15]";
  });
  m.optional_section("limits", [&](contact::YamlMap& s) {
    s.optional("max_depth_m", spec.max_depth_m, contact::nonnegative_finite);
    s.optional("max_lift_loss_m", spec.max_lift_loss_m, contact::nonnegative_finite);
    if (!(spec.max_depth_m > 0) && !(spec.max_lift_loss_m > 0))
      s.fail_here("no limit: give max_depth_m and/or max_lift_loss_m > 0");
  });
  if (!(spec.max_depth_m > 0) && !(spec.max_lift_loss_m > 0))
    m.fail_here("give limits: { max_depth_m: ..., max_lift_loss_m: ... } (one at least > 0): they end the life");
  m.optional_section("stepping", [&](contact::YamlMap& s) {
    wear::read_wear_stepping(s, spec.stepping);
    std::string scheme;
    s.optional("scheme", scheme, [](const std::string& v) -> std::string {
      return contact::enum_from_name(kSchemes, v) ? "" : "must be " + contact::enum_names_list(kSchemes);
    });
    if (!scheme.empty()) {
      if (spec.stepping.method == wear::IntegratorOptions::Method::Adaptive)
        s.fail("scheme", "the fixed steps' update: give it with method: fixed-depth or fixed-revolutions");
      spec.scheme = *contact::enum_from_name(kSchemes, scheme);
    }
  });
  m.optional_section("skip", [&](contact::YamlMap& s) {
    s.optional("stride", spec.skip_stride, [](int v) { return v >= 1 && v <= 64 ? "" : "must be in [1, 64]"; });
    s.optional("power_rtol", spec.skip_power_rtol, contact::in_closed(0, 1));
  });
  m.optional("arc_cells", spec.arc_cells, [](int v) { return v >= 8 && v <= 100000 ? "" : "must be in [8, 100000]"; });
  m.optional("lateral_cells", spec.lateral_cells,
             [](int v) { return v >= 2 && v <= 10000 ? "" : "must be in [2, 10000]"; });
  m.optional("smoothing_wavelength_m", spec.smoothing_wavelength_m, contact::in_closed(0, 0.1));
  m.optional("checkpoint_interval_s", spec.checkpoint_interval_s, contact::nonnegative_finite);
  m.optional_section("fatigue", [&](contact::YamlMap& s) { wear::read_wear_fatigue(s, spec.fatigue.emplace()); });
  m.optional_value("snapshots_revolutions", [&](const contact::YamlValue& v) {
    const std::vector<contact::YamlValue> e = v.elements("a list of revolutions, e.g. [1.0e7, 2.0e7]");
    for (std::size_t k = 0; k < e.size(); ++k) {
      const std::string element = "element " + std::to_string(k + 1);
      const double N = e[k].as<double>(contact::positive_finite, element);
      if (k > 0 && !(N > spec.snapshots_revolutions.back())) e[k].fail(element + " must be after the one before it");
      if (N > spec.revolutions) e[k].fail(element + " must be <= revolutions");
      spec.snapshots_revolutions.push_back(N);
    }
  });
}

}  // namespace cam
