// The relaxed model (equations at the top of relaxed.h).
#include "lib/tangential/relaxed.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "lib/io/errors.h"
#include "lib/normal/hertz.h"
#include "lib/tangential/kalker.h"
#include "lib/tangential/relaxed_table.h"
#include "lib/tangential/shift_run.h"
#include "lib/tangential/steady.h"

namespace contact {

namespace {

namespace T = relaxed_table;

// linear interpolation in log(a/b) between the table's rows, clamped at its ends: (row, weight of row + 1)
std::pair<int, double> ab_bracket(double ab) {
  if (T::kNab == 1 || !(ab > T::kAb[0])) return {0, 0.0};
  if (ab >= T::kAb[T::kNab - 1]) return {T::kNab - 2, 1.0};
  int i = 0;
  while (ab > T::kAb[i + 1]) ++i;
  return {i, std::log(ab / T::kAb[i]) / std::log(T::kAb[i + 1] / T::kAb[i])};
}

double over_ab(const double (&v)[T::kNab], double ab) {
  const auto [i, w] = ab_bracket(ab);
  return T::kNab == 1 ? v[0] : (1 - w) * v[i] + w * v[i + 1];
}

// linear interpolation over the levels es[0..n) of the saturation level, held constant outside
double over_e(const double* es, const double* v, int n, double e) {
  if (n == 1 || !(e > es[0])) return v[0];
  if (e >= es[n - 1]) return v[n - 1];
  int k = 0;
  while (e > es[k + 1]) ++k;
  const double w = (e - es[k]) / (es[k + 1] - es[k]);
  return (1 - w) * v[k] + w * v[k + 1];
}

// a factor of the table over a/b (rows) and the levels es (columns)
template <int Ne>
double factor(const double (&es)[Ne], const double (&g)[T::kNab][Ne], double ab, double e) {
  const auto [i, w] = ab_bracket(ab);
  if (T::kNab == 1) return over_e(es, g[0], Ne, e);
  return (1 - w) * over_e(es, g[i], Ne, e) + w * over_e(es, g[i + 1], Ne, e);
}

// the saturation level e = G a b |(C11 xi, C22 eta, C23 sqrt(ab) phi)| / (3 mu N) (-1: no contact or no friction)
double saturation_level(const ContactPatch& patch, const ElasticPair& pair, const Creepages& c, double mu) {
  const double a = patch.a_m, b = patch.b_m, N = patch.normal_load_N;
  if (!(a > 0 && b > 0 && N > 0 && mu > 0)) return -1;
  const KalkerCoefficients C = kalker_coefficients(a, b, combined_poisson(pair));
  const double G = combined_shear_modulus_Pa(pair), scale = G * a * b / (3 * mu * N);
  const double ex = scale * C.C11 * std::abs(c.xi), ey = scale * C.C22 * std::abs(c.eta),
               ep = scale * std::sqrt(a * b) * C.C23 * std::abs(c.phi_per_m);
  return std::sqrt(ex * ex + ey * ey + ep * ep);
}

// the creepages the simplified theory is solved at, and the factor on the spin's longitudinal rate phi y / L3
// (the second spin flexibility: L3x = L3 / that factor, with phi the imposed spin)
struct Corrected {
  Creepages c;
  double spin_x = 1;
};

Corrected corrected(const ContactPatch& patch, const ElasticPair& pair, const Creepages& c, double mu) {
  const double e = saturation_level(patch, pair, c, mu), ab = patch.a_m / patch.b_m;
  if (e < 0) return {c, 1};
  return {{c.xi * factor(T::kE, T::kGx, ab, e), c.eta * factor(T::kE, T::kGy, ab, e),
           c.phi_per_m * factor(T::kEPhi, T::kGphi, ab, e)},
          factor(T::kEPhi, T::kGphiX, ab, e)};
}

double creep_work_W(const TangentialSolution& s, const Creepages& c, double V) {
  return V * (c.xi * s.Fx_N + c.eta * s.Fy_N + c.phi_per_m * s.Mz_N_m);
}

// the steady model at the creepages c, its power scaled to the creep forces' work at `work_at`
TangentialSolution steady_at(const ContactPatch& patch, const ElasticPair& pair, const Creepages& c,
                             const Creepages& work_at, double mu, double V, bool fields) {
  SteadyOptions o;
  o.fields = fields;
  const Corrected cor = corrected(patch, pair, c, mu);
  const Creepages& solved = cor.c;
  TangentialProblem pb = make_tangential_problem(patch, pair, solved, mu, V);
  // the spin's longitudinal traction rate phi y / L3x with the imposed phi times its own factor (the lateral
  // one, phi x / L3, takes solved.phi): solved.phi / L3x = c.phi spin_x / L3
  if (solved.phi_per_m != 0 && c.phi_per_m != 0)
    pb.L3x_m_per_Pa = pb.flex.L3_m_per_Pa * (solved.phi_per_m / c.phi_per_m) / cor.spin_x;
  TangentialSolution s = solve_steady(patch, pb, TangentialScheme::Consistent, o);
  // the work of the strips' Heathcote offsets (xi_j - xi, docs/physics.md §2.4), which the solver's creep work
  // holds beside that of the uniform creepages
  const double offsets_W = s.creep_work_W - creep_work_W(s, solved, V);
  const double target = -(creep_work_W(s, c, V) + offsets_W);  // what the exact theory dissipates at steady state
  if (s.power_W > 0 && target >= 0) {
    const double k = target / s.power_W;
    s.strip_power_W_per_m *= k;
    if (fields) s.power_W_per_m2 *= k;
    s.power_W = target;
  }
  s.creep_work_W = creep_work_W(s, work_at, V) + offsets_W;
  return s;
}

}  // namespace

Creepages relaxation_lengths_m(double a_m, double b_m) {
  const double ab = a_m / b_m;
  return {over_ab(T::kSigmaX, ab) * a_m, over_ab(T::kSigmaY, ab) * a_m, over_ab(T::kSigmaPhi, ab) * a_m};
}

TangentialSolution solve_relaxed_steady(const ContactPatch& patch, const ElasticPair& pair, const Creepages& creepages,
                                        double mu, double speed_m_per_s, bool fields) {
  return steady_at(patch, pair, creepages, creepages, mu, speed_m_per_s, fields);
}

TangentialSolution relaxed_step(const ContactPatch& patch, const ElasticPair& pair, const Creepages& c, double mu,
                                double speed_m_per_s, double dq_m, RelaxedState& state, bool fields) {
  if (!(dq_m >= 0) || !std::isfinite(dq_m))
    throw std::invalid_argument("relaxed step: rolled distance must be >= 0 and finite");
  if (patch.a_m > 0 && patch.b_m > 0) {
    Creepages sigma = relaxation_lengths_m(patch.a_m, patch.b_m);
    if (state.sigma_m.xi > 0) sigma.xi = state.sigma_m.xi;
    if (state.sigma_m.eta > 0) sigma.eta = state.sigma_m.eta;
    if (state.sigma_m.phi_per_m > 0) sigma.phi_per_m = state.sigma_m.phi_per_m;
    const double e = saturation_level(patch, pair, state.effective, mu);
    const double p = state.exponent >= 0 ? state.exponent : over_ab(T::kExponent, patch.a_m / patch.b_m);
    // the smallest share of sigma kept as the contact saturates (full sliding: the steady state at once)
    constexpr double kMinShare = 1e-6;
    const double share = std::max(kMinShare, std::pow(1 - std::clamp(e, 0.0, 1.0), p));
    sigma.xi *= share;
    sigma.eta *= share;
    sigma.phi_per_m *= share;
    auto relax = [dq_m](double& eff, double target, double s) { eff = target + (eff - target) * std::exp(-dq_m / s); };
    relax(state.effective.xi, c.xi, sigma.xi);
    relax(state.effective.eta, c.eta, sigma.eta);
    relax(state.effective.phi_per_m, c.phi_per_m, sigma.phi_per_m);
  }
  return steady_at(patch, pair, state.effective, c, mu, speed_m_per_s, fields);
}

TransientResult run_relaxed_transient(const TransientCase& c, const StepObserver& observe) {
  const TransientSettings& set = c.settings;
  check_transient_inputs(c);
  if (c.inertia) throw SettingError("", "inertia", "the relaxed model's run has no roller inertia (Satran's has)");
  if (set.scheme != TransientScheme::Shift)
    throw SettingError("", "scheme", "the relaxed model rolls by the shift scheme's steps; use scheme: shift");
  RelaxedState state = relaxed_rest();
  return run_shift_steps(
      c, observe,
      [&](const ContactPatch& patch, const ShiftStep& s) {
        return relaxed_step(patch, c.materials, s.creepages, c.mu, s.speed_m_per_s, s.dq_m, state, s.fields);
      },
      [&](const Grid&) { state = relaxed_rest(); });  // out of contact: nothing is held
}

}  // namespace contact
