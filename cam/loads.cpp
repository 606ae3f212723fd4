// Loads of the follower train (docs/cam-follower.md §3).
#include "cam/loads.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "lib/numeric.h"

namespace cam {

const char* to_string(RollerRegime r) { return r == RollerRegime::Rolling ? "rolling" : "sliding"; }

void check_train(const FollowerTrain& t) {
  const auto nonneg = [](double v) { return v >= 0 && std::isfinite(v); };
  if (!nonneg(t.spring_rate_N_per_m) || !nonneg(t.guide_mu) || !nonneg(t.roller_inertia_kg_m2) ||
      !nonneg(t.bearing_torque_N_m) || !nonneg(t.bearing_drag_N_m_s))
    throw std::invalid_argument("the follower train's values must be >= 0 and finite");
  if (!(t.preload_N > 0) || !std::isfinite(t.preload_N)) throw std::invalid_argument("preload must be > 0");
  if (!(t.moving_mass_kg > 0) || !std::isfinite(t.moving_mass_kg)) throw std::invalid_argument("mass must be > 0");
}

namespace {

double sign(double v) { return v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0; }

// F_n from the axial balance with F_t = a0 + a1 F_n; the guide's branch whose Q sign is consistent
double solve_normal_load(double W, double phi, double s1, double mu_g, double a0, double a1) {
  const double c = std::cos(phi), s = std::sin(phi), v = sign(s1);
  if (mu_g == 0 || v == 0) return (W - a0 * s) / (c + a1 * s);
  for (double sq : {1.0, -1.0}) {
    const double coef = c + a1 * s - mu_g * sq * v * (s - a1 * c);
    const double Fn = (W - a0 * s - mu_g * sq * v * a0 * c) / coef;
    const double Q = Fn * s - (a0 + a1 * Fn) * c;
    if (sign(Q) == sq || Q == 0) return Fn;
  }
  return (W - a0 * s) / (c + a1 * s);  // no consistent branch: Q ~ 0, no guide friction
}

}  // namespace

double bearing_torque_N_m(const FollowerTrain& t, double wr) {
  return t.bearing_torque_N_m * sign(wr) + t.bearing_drag_N_m_s * wr;
}

namespace {

CamLoads axial_and_required(const FollowerTrain& t, const CamGeometry& g, const CamKinematics& k, double omega) {
  CamLoads L;
  L.axial_N = t.preload_N + t.spring_rate_N_per_m * k.lift.s_m + t.moving_mass_kg * omega * omega * k.lift.d2s_m_per_rad2;
  // the roller's need: R_r F_t = J alpha + T_b(omega_r)
  L.required_tangential_N =
      (t.roller_inertia_kg_m2 * k.roller_alpha_rad_per_s2 + bearing_torque_N_m(t, k.roller_omega_rad_per_s)) /
      g.roller_radius_m;
  return L;
}

void guide_and_torque(const CamKinematics& k, CamLoads& L) {
  const double phi = k.pressure_angle_rad;
  L.contact_lost = !(L.normal_N > 0);
  L.guide_reaction_N = L.normal_N * std::sin(phi) - L.tangential_N * std::cos(phi);
  // torque: C x (F_n n + F_t t)
  const double fx = L.normal_N * k.normal_x + L.tangential_N * k.tangent_x;
  const double fy = L.normal_N * k.normal_y + L.tangential_N * k.tangent_y;
  L.shaft_torque_N_m = k.contact_x_m * fy - k.contact_y_m * fx;
}

}  // namespace

CamLoads cam_loads(const FollowerTrain& t, const CamGeometry& g, const CamKinematics& k, double omega, double mu) {
  CamLoads L = axial_and_required(t, g, k, omega);
  const double phi = k.pressure_angle_rad, s1 = k.lift.ds_m_per_rad;
  // rolling first; sliding if the friction cannot supply it
  L.tangential_N = L.required_tangential_N;
  L.normal_N = solve_normal_load(L.axial_N, phi, s1, t.guide_mu, L.required_tangential_N, 0);
  if (!(std::abs(L.required_tangential_N) < mu * L.normal_N)) {
    const double a1 = mu * sign(L.required_tangential_N);
    L.regime = RollerRegime::Sliding;
    L.normal_N = solve_normal_load(L.axial_N, phi, s1, t.guide_mu, 0, a1);
    L.tangential_N = a1 * L.normal_N;
  }
  guide_and_torque(k, L);
  return L;
}

CamLoads cam_loads_with_tangential(const FollowerTrain& t, const CamGeometry& g, const CamKinematics& k, double omega,
                                   double tangential_N) {
  CamLoads L = axial_and_required(t, g, k, omega);
  L.tangential_N = tangential_N;
  L.normal_N = solve_normal_load(L.axial_N, k.pressure_angle_rad, k.lift.ds_m_per_rad, t.guide_mu, tangential_N, 0);
  guide_and_torque(k, L);
  return L;
}

JumpSpeed jump_speed(const FollowerTrain& t, const LiftLaw& law, int n_samples) {
  JumpSpeed j{std::numeric_limits<double>::infinity(), 0};
  for (int i = 0; i < n_samples; ++i) {
    const double theta = 2 * contact::kPi * i / n_samples;
    const LiftSample s = lift_at(law, theta);
    if (!(s.d2s_m_per_rad2 < 0)) continue;
    const double w = std::sqrt((t.preload_N + t.spring_rate_N_per_m * s.s_m) / (t.moving_mass_kg * -s.d2s_m_per_rad2));
    if (w < j.omega_rad_per_s) j = {w, theta};
  }
  return j;
}

}  // namespace cam
