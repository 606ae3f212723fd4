// The relaxed model (equations at the top of relaxed.h).
#include "lib/tangential/relaxed.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/history.h"
#include "lib/errors.h"
#include "lib/normal/hertz.h"
#include "lib/tangential/kalker.h"
#include "lib/tangential/relaxed_mix_table.h"
#include "lib/tangential/relaxed_shape.h"
#include "lib/tangential/relaxed_table.h"
#include "lib/tangential/relaxed_transient_table.h"
#include "lib/tangential/shift_run.h"
#include "lib/tangential/steady.h"

namespace contact {

namespace {

namespace T = relaxed_table;
namespace TT = relaxed_transient_table;
static_assert(TT::kNab == T::kNab, "the transient table's rows are the factors' a/b");

// linear interpolation in log(a/b) between the rows abs[0..n) of a table, clamped at its ends: (row, weight of
// row + 1)
std::pair<int, double> ab_bracket(const double* abs, int n, double ab) {
  if (n == 1 || !(ab > abs[0])) return {0, 0.0};
  if (ab >= abs[n - 1]) return {n - 2, 1.0};
  int i = 0;
  while (ab > abs[i + 1]) ++i;
  return {i, std::log(ab / abs[i]) / std::log(abs[i + 1] / abs[i])};
}
std::pair<int, double> ab_bracket(double ab) { return ab_bracket(T::kAb, T::kNab, ab); }

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

// each creepage's contribution to the saturation level, signed: u = G a b (C11 xi, C22 eta, C23 sqrt(ab) phi) / (3 mu N),
// e = |u| (docs/physics.md §3); none (all zero, valid false) without contact or friction
struct Levels {
  double xi = 0, eta = 0, phi = 0;  // u
  double scale_xi = 0, scale_eta = 0, scale_phi = 0;  // the creepage of level 1 in each direction
  bool valid = false;
  double e() const { return std::sqrt(xi * xi + eta * eta + phi * phi); }
};

Levels levels(const ContactPatch& patch, const ElasticPair& pair, const Creepages& c, double mu) {
  const double a = patch.a_m, b = patch.b_m, N = patch.normal_load_N;
  Levels l;
  if (!(a > 0 && b > 0 && N > 0 && mu > 0)) return l;
  const KalkerCoefficients C = kalker_coefficients(a, b, combined_poisson(pair));
  const double G = combined_shear_modulus_Pa(pair), scale = 3 * mu * N / (G * a * b);
  l.scale_xi = scale / C.C11;
  l.scale_eta = scale / C.C22;
  l.scale_phi = scale / (std::sqrt(a * b) * C.C23);
  l.xi = c.xi / l.scale_xi;
  l.eta = c.eta / l.scale_eta;
  l.phi = c.phi_per_m / l.scale_phi;
  l.valid = true;
  return l;
}

// the saturation level e = G a b |(C11 xi, C22 eta, C23 sqrt(ab) phi)| / (3 mu N) (-1: no contact or no friction)
double saturation_level(const ContactPatch& patch, const ElasticPair& pair, const Creepages& c, double mu) {
  const Levels l = levels(patch, pair, c, mu);
  return l.valid ? l.e() : -1;
}

namespace M = relaxed_mix_table;

// the share of the longitudinal spin rate at which a lateral one is set where it has none (relaxed.h: L3x)
constexpr double kTinyShare = 1e-12;

// the bracket of v in the ascending nodes xs[0..n), clamped at the ends: (node, weight of node + 1)
std::pair<int, double> bracket(const double* xs, int n, double v) {
  if (n == 1 || !(v > xs[0])) return {0, 0.0};
  if (v >= xs[n - 1]) return {n - 2, 1.0};
  int k = 0;
  while (v > xs[k + 1]) ++k;
  return {k, (v - xs[k]) / (xs[k + 1] - xs[k])};
}

// the table's correction per unit level D at (row ab, theta, psi in [0, 180) deg, e), linear in each; psi is
// periodic over 180 deg with the eta and phi components' signs flipped (the mirror y -> -y)
std::array<double, 4> mix_per_level(int iab, double theta_deg, double psi_deg, double e) {
  const auto [it, wt] = bracket(M::kThetaDeg, M::kNtheta, theta_deg);
  const auto [ie, we] = bracket(M::kE, M::kNe, e);
  // psi: the node below and above (above may be node 0 at 180 deg, mirrored)
  int ip = 0;
  while (ip + 1 < M::kNpsi && psi_deg >= M::kPsiDeg[ip + 1]) ++ip;
  const bool wraps = ip + 1 == M::kNpsi;
  const double upper = wraps ? 180.0 : M::kPsiDeg[ip + 1];
  const double wp = M::kNpsi == 1 ? 0.0 : std::clamp((psi_deg - M::kPsiDeg[ip]) / (upper - M::kPsiDeg[ip]), 0.0, 1.0);
  std::array<double, 4> d{0, 0, 0, 0};
  for (int a = 0; a < 2; ++a) {
    const double fa = a == 0 ? 1 - wt : wt;
    if (fa == 0 || it + a >= M::kNtheta) continue;
    for (int p = 0; p < 2; ++p) {
      const double fp = p == 0 ? 1 - wp : wp;
      if (fp == 0) continue;
      const int jp = p == 0 ? ip : (wraps ? 0 : ip + 1);
      const double mirror = p == 1 && wraps ? -1.0 : 1.0;
      for (int q = 0; q < 2; ++q) {
        const double fq = q == 0 ? 1 - we : we;
        if (fq == 0 || ie + q >= M::kNe) continue;
        const double(&v)[4] = M::kD[iab][it + a][jp][ie + q];
        const double f = fa * fp * fq;
        d[0] += f * v[0];
        for (int k = 1; k < 4; ++k) d[k] += f * mirror * v[k];
      }
    }
  }
  return d;
}

// the no-spin table's (D_xi, D_eta, D_moment) at (row ab, theta, e), linear in each
std::array<double, 3> no_spin_at(int iab, double theta_deg, double e) {
  const auto [it, wt] = bracket(M::kThetaDeg, M::kNtheta, theta_deg);
  const auto [ie, we] = bracket(M::kE, M::kNe, e);
  std::array<double, 3> d{0, 0, 0};
  for (int a = 0; a < 2; ++a)
    for (int q = 0; q < 2; ++q) {
      const double f = (a == 0 ? 1 - wt : wt) * (q == 0 ? 1 - we : we);
      if (f == 0 || it + a >= M::kNtheta || ie + q >= M::kNe) continue;
      for (int k = 0; k < 3; ++k) d[k] += f * M::kNoSpin[iab][it + a][ie + q][k];
    }
  return d;
}

// the mix correction in levels (relaxed.h, relaxed_mix_correction) of the levels l
RelaxedMix mix_correction_of(const Levels& l, double ab) {
  const double e = l.e();
  if (!l.valid || !(e > 0) || (l.eta == 0 && l.phi == 0)) return {};  // pure xi: none (its factor holds it)
  // the symmetries of a patch symmetric in y: F(-xi, eta, phi) = (-Fx, Fy, Mz)(xi, eta, phi), and the mirror
  // F(xi, -eta, -phi) = (Fx, -Fy, -Mz)(xi, eta, phi): the table holds xi >= 0 and psi in [0, 180) deg
  const double sx = l.xi < 0 ? -1.0 : 1.0;
  const double theta = std::acos(std::clamp(std::abs(l.xi) / e, 0.0, 1.0)) * 180 / kPi;
  double psi = std::atan2(l.phi, l.eta) * 180 / kPi, sm = 1;
  if (psi < 0) psi += 180, sm = -1;
  if (psi >= 180) psi -= 180, sm = -sm;
  std::array<double, 4> d{0, 0, 0, 0};
  const std::pair<int, double> br = ab_bracket(M::kAb, M::kNab, ab);
  const int row = br.first;
  const double wr = br.second;  // linear in log(a/b) between the table's rows, clamped at its ends
  if (l.phi == 0) {  // without spin: no spin parts, a moment added to Mz (relaxed.h)
    const std::array<double, 3> n0 = no_spin_at(row, theta, e);
    const std::array<double, 3> n1 = wr > 0 ? no_spin_at(row + 1, theta, e) : n0;
    const auto at = [&](int k) { return (1 - wr) * n0[k] + wr * n1[k]; };
    const double se = l.eta < 0 ? -1.0 : 1.0;
    return {sx * at(0) * e, se * at(1) * e, 0, 0, se * at(2) * e};
  }
  const std::array<double, 4> d0 = mix_per_level(row, theta, psi, e);
  const std::array<double, 4> d1 = wr > 0 ? mix_per_level(row + 1, theta, psi, e) : d0;
  for (int k = 0; k < 4; ++k) d[k] = ((1 - wr) * d0[k] + wr * d1[k]) * e;
  return {sx * d[0], sm * d[1], sm * d[2], sm * d[3]};
}

// the creepages the simplified theory is solved at, and its spin's longitudinal rate: phi_x y / L3 with
// phi_x = the imposed phi times its factor (the second spin flexibility; the lateral rate is c.phi x / L3)
struct Corrected {
  Creepages c;
  double phi_x_per_m = 0;
  double moment = 0;  // added to the march's Mz, times mu N sqrt(ab) (without imposed spin)
};

// the pure creepages' factors at the level of c, and the mix correction: `mix` (levels) in place of the table's
// where given
Corrected corrected(const ContactPatch& patch, const ElasticPair& pair, const Creepages& c, double mu,
                    const RelaxedMix* mix) {
  const Levels l = levels(patch, pair, c, mu);
  if (!l.valid) return {c, c.phi_per_m};
  const double e = l.e(), ab = patch.a_m / patch.b_m;
  Corrected r{{c.xi * factor(T::kE, T::kGx, ab, e), c.eta * factor(T::kE, T::kGy, ab, e),
               c.phi_per_m * factor(T::kEPhi, T::kGphi, ab, e)},
              c.phi_per_m * factor(T::kEPhi, T::kGphiX, ab, e)};
  const RelaxedMix d = mix ? *mix : mix_correction_of(l, ab);
  r.c.xi += d.xi * l.scale_xi;
  r.c.eta += d.eta * l.scale_eta;
  r.c.phi_per_m += d.phi_lateral * l.scale_phi;
  r.phi_x_per_m += d.phi_longitudinal * l.scale_phi;
  r.moment = d.moment;
  return r;
}

double creep_work_W(const TangentialSolution& s, const Creepages& c, double V) {
  return V * (c.xi * s.Fx_N + c.eta * s.Fy_N + c.phi_per_m * s.Mz_N_m);
}

// the flexibilities scaled by the patch's shape factor (relaxed_shape.h: the strips' linear forces those of the
// thin-contact limit for a patch that is not elliptic; S = 1 for Hertz patches)
void scale_to_shape(TangentialProblem& pb, const ContactPatch& patch) {
  const double S = relaxed_shape_factor(patch);
  if (S == 1.0) return;
  pb.flex.L1_m_per_Pa *= S;
  pb.flex.L2_m_per_Pa *= S;
  pb.flex.L3_m_per_Pa *= S;
  pb.L_m_per_Pa *= S;
}

// the steady model at the creepages c, its power scaled to the creep forces' work at `work_at`
TangentialSolution steady_at(const ContactPatch& patch, const ElasticPair& pair, const Creepages& c,
                             const Creepages& work_at, double mu, double V, bool fields,
                             const RelaxedMix* mix = nullptr) {
  SteadyOptions o;
  o.fields = fields;
  const Corrected cor = corrected(patch, pair, c, mu, mix);
  const Creepages& solved = cor.c;
  TangentialProblem pb = make_tangential_problem(patch, pair, solved, mu, V);
  scale_to_shape(pb, patch);
  // the spin's longitudinal traction rate phi_x y / L3 (the lateral one, phi x / L3, takes solved.phi):
  // solved.phi / L3x = phi_x / L3; none (L3x infinite) where the lateral one alone has spin (a mix correction)
  // (where the lateral rate has none and the longitudinal one has, phi is solved at a tiny value with L3x to match:
  // its lateral rate is below rounding)
  if (solved.phi_per_m == 0 && cor.phi_x_per_m != 0) pb.creepages.phi_per_m = kTinyShare * cor.phi_x_per_m;
  if (pb.creepages.phi_per_m != 0)
    pb.L3x_m_per_Pa = cor.phi_x_per_m != 0 ? pb.flex.L3_m_per_Pa * pb.creepages.phi_per_m / cor.phi_x_per_m
                                           : std::numeric_limits<double>::infinity();
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
  {  // the strips' shares of it (relaxed_shape.h): the saturation level and spin's share of the creep work
    const double muN = mu * patch.normal_load_N;
    const double level = muN > 0 ? std::hypot(s.Fx_N, s.Fy_N) / muN : 0.0;
    const double wx = std::abs(c.xi * s.Fx_N), wy = std::abs(c.eta * s.Fy_N), wphi = std::abs(c.phi_per_m * s.Mz_N_m);
    const double spin_share = wx + wy + wphi > 0 ? wphi / (wx + wy + wphi) : 0.0;
    redistribute_strip_power(s, patch, level, spin_share);
  }
  s.creep_work_W = creep_work_W(s, work_at, V) + offsets_W;
  // without imposed spin, the fitted moment (phi Mz is 0 in the work above)
  if (cor.moment != 0) s.Mz_N_m += cor.moment * mu * patch.normal_load_N * std::sqrt(patch.a_m * patch.b_m);
  return s;
}

}  // namespace

Creepages relaxation_lengths_m(double a_m, double b_m) {
  const double ab = a_m / b_m;
  return {over_ab(T::kSigmaX, ab) * a_m, over_ab(T::kSigmaY, ab) * a_m, over_ab(TT::kSigmaPhi1, ab) * a_m};
}

Creepages second_stage_lengths_m(double a_m, double b_m) {
  const double ab = a_m / b_m;
  return {0, over_ab(TT::kSigmaEta2, ab) * a_m, over_ab(TT::kSigmaPhi2, ab) * a_m};
}

double relaxed_xi_saturation_level(const ContactPatch& patch) {
  if (!(patch.a_m > 0 && patch.b_m > 0)) return 1;
  const double ab = patch.a_m / patch.b_m, S = relaxed_shape_factor(patch);
  // e g_x(e) increases with e on the table (CamCreepLaw.RelaxedLawSaturatesAtItsSaturationCreepage); bisection
  const auto f = [&](double e) { return e * factor(T::kE, T::kGx, ab, e) - S; };
  double lo = 0, hi = 1;
  while (f(hi) < 0) hi *= 2;
  for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0 ? lo : hi) = mid;
  }
  return hi;
}

double relaxed_xi_slope_factor(const ContactPatch& patch) {
  if (!(patch.a_m > 0 && patch.b_m > 0)) return 1;
  return factor(T::kE, T::kGx, patch.a_m / patch.b_m, 0.0) / relaxed_shape_factor(patch);
}

TangentialSolution solve_relaxed_steady(const ContactPatch& patch, const ElasticPair& pair, const Creepages& creepages,
                                        double mu, double speed_m_per_s, bool fields) {
  return steady_at(patch, pair, creepages, creepages, mu, speed_m_per_s, fields);
}

RelaxedMix relaxed_mix_correction(const ContactPatch& patch, const ElasticPair& pair, const Creepages& creepages,
                                  double mu) {
  return mix_correction_of(levels(patch, pair, creepages, mu), patch.a_m / patch.b_m);
}

TangentialSolution solve_relaxed_steady_with_mix(const ContactPatch& patch, const ElasticPair& pair,
                                                 const Creepages& creepages, const RelaxedMix& mix, double mu, double speed_m_per_s,
                                                 bool fields) {
  return steady_at(patch, pair, creepages, creepages, mu, speed_m_per_s, fields, &mix);
}

namespace {

// the relaxation lengths of both stages at the state's saturation level (the table's, or the state's overrides)
struct StageLengths {
  Creepages first, second;
};
StageLengths stage_lengths(const ContactPatch& patch, const ElasticPair& pair, double mu, const RelaxedState& state) {
  Creepages s1 = relaxation_lengths_m(patch.a_m, patch.b_m), s2 = second_stage_lengths_m(patch.a_m, patch.b_m);
  if (state.sigma_m.xi > 0) s1.xi = state.sigma_m.xi;
  if (state.sigma_m.eta > 0) s1.eta = state.sigma_m.eta;
  if (state.sigma_m.phi_per_m > 0) s1.phi_per_m = state.sigma_m.phi_per_m;
  if (state.sigma2_m.eta > 0) s2.eta = state.sigma2_m.eta;
  if (state.sigma2_m.phi_per_m > 0) s2.phi_per_m = state.sigma2_m.phi_per_m;
  const double e = saturation_level(patch, pair, state.effective, mu);
  const double p = state.exponent >= 0 ? state.exponent : over_ab(T::kExponent, patch.a_m / patch.b_m);
  // the smallest share of sigma kept as the contact saturates (full sliding: the steady state at once)
  constexpr double kMinShare = 1e-6;
  const double share = std::max(kMinShare, std::pow(1 - std::clamp(e, 0.0, 1.0), p));
  return {{s1.xi * share, s1.eta * share, s1.phi_per_m * share}, {0, s2.eta * share, s2.phi_per_m * share}};
}

// both stages advanced over dq towards the imposed c at the lengths sg, in closed form: the first
// d1 <- d1 e^(-dq/s1), the second d2 <- d2 e^(-dq/s2) + d1 s1/(s1 - s2) (e^(-dq/s1) - e^(-dq/s2)) (d the
// deviations from c; its limit d1 (dq/s) e^(-dq/s) at s1 = s2). xi has no second stage (it follows the first).
void relax_stages(RelaxedState& state, const Creepages& c, double dq, const StageLengths& sg) {
  auto two = [dq](double& x1, double& x2, double target, double s1, double s2) {
    const double d1 = x1 - target, d2 = x2 - target;
    if (d1 == 0 && d2 == 0) return;  // settled (a creepage not imposed: the pure-xi path's cost)
    const double e1 = std::exp(-dq / s1), e2 = std::exp(-dq / s2);
    const double w = std::abs(s1 - s2) <= 1e-6 * std::max(s1, s2) ? dq / s2 * e2 : s1 / (s1 - s2) * (e1 - e2);
    x1 = target + d1 * e1;
    x2 = target + d2 * e2 + d1 * w;
  };
  state.effective.xi = c.xi + (state.effective.xi - c.xi) * std::exp(-dq / sg.first.xi);
  state.lagged.xi = state.effective.xi;
  two(state.effective.eta, state.lagged.eta, c.eta, sg.first.eta, sg.second.eta);
  two(state.effective.phi_per_m, state.lagged.phi_per_m, c.phi_per_m, sg.first.phi_per_m, sg.second.phi_per_m);
}

// relaxed_step's relaxation of the state over dq_m (sigma at the step's start)
void relax_effective(const ContactPatch& patch, const ElasticPair& pair, const Creepages& c, double mu, double dq_m,
                     RelaxedState& state) {
  if (!(dq_m >= 0) || !std::isfinite(dq_m))
    throw std::invalid_argument("relaxed step: rolled distance must be >= 0 and finite");
  if (patch.a_m > 0 && patch.b_m > 0) relax_stages(state, c, dq_m, stage_lengths(patch, pair, mu, state));
}

// the model at the state: the steady model at the first stage and the second stage's corrections (relaxed.h);
// `imposed` the creepages whose work creep_work_W is
TangentialSolution transient_at(const ContactPatch& patch, const ElasticPair& pair, const RelaxedState& state,
                                const Creepages& imposed, double mu, double V, bool fields) {
  const Creepages& c1 = state.effective;
  const Creepages& c2 = state.lagged;
  TangentialSolution s = steady_at(patch, pair, c1, imposed, mu, V, fields);
  if (c1.eta != c2.eta || c1.phi_per_m != c2.phi_per_m) {
    const Levels l1 = levels(patch, pair, c1, mu), l2 = levels(patch, pair, c2, mu);
    if (l1.valid) {
      const double ab = patch.a_m / patch.b_m, muN = mu * patch.normal_load_N;
      const double Ap = std::isfinite(state.force_phi) ? state.force_phi : over_ab(TT::kForcePhi, ab);
      const double Ke = std::isfinite(state.moment_eta) ? state.moment_eta : over_ab(TT::kMomentEta, ab);
      const double Kp = std::isfinite(state.moment_phi) ? state.moment_phi : over_ab(TT::kMomentPhi, ab);
      const double slope = std::pow(1 - std::min(l1.e(), 1.0), 2);  // of 1 - (1 - e)^3, over its value at e = 0
      s.Fy_N += slope * Ap * (l2.phi - l1.phi) * muN;
      s.Mz_N_m += slope * (Ke * (l2.eta - l1.eta) + Kp * (l1.phi - l2.phi)) * muN * std::sqrt(patch.a_m * patch.b_m);
    }
  }
  return s;
}

}  // namespace

TangentialSolution relaxed_step(const ContactPatch& patch, const ElasticPair& pair, const Creepages& c, double mu,
                                double speed_m_per_s, double dq_m, RelaxedState& state, bool fields) {
  relax_effective(patch, pair, c, mu, dq_m, state);
  return transient_at(patch, pair, state, c, mu, speed_m_per_s, fields);
}

namespace {

// the largest saturation level of the difference between the effective and the imposed creepages at which the
// relaxed state counts as settled (the steady state to rounding: the forces it moves are below 1e-9 of mu N)
constexpr double kSettledLevel = 1e-10;
// ... and at which, when one creepage alone still relaxes, the rest of its exponential tail is summed in
// closed form: the effective creepages are advanced step by step as the steps would (their sigma shrinking with
// the saturation, no steady solve), and the power's difference to the steady state P(u) - P(0), u the deviation
// over that after the last step, is taken as quadratic in u (from the last step's power and one solve at u/2).
// The cubic term left grows as the level cubed: on a 0.05 s duty cycle the energies moved by 5e-11 at 1e-3,
// 1.3e-9 at 3e-3, 4e-8 at 1e-2 (RelaxedSkip.SteadyRunningSkippedChangesTheEnergiesBelowTenPerBillion)
constexpr double kTailLevel = 3e-3;

// One step of the roller's spin with the relaxed model, for the trial spin omega_end at the step's end
// (run_relaxed_inertia): its length, rolled distance, creepage, the relaxed step's solution and state after it.
struct InertiaTrial {
  TangentialSolution f;
  RelaxedState state;
  double dt_s = 0, dq_m = 0, V_m_per_s = 0, xi = 0;
  bool shortened = false;
};

}  // namespace

TransientResult run_relaxed_inertia(const TransientCase& c, const StepObserver& observe) {
  const RollerInertia& in = *c.inertia;
  const TransientSettings& set = c.settings;
  check_transient_inputs(c);
  check_history(in.path_speed_m_per_s, "path_speed_m_per_s");
  if (!(in.R1_m > 0) || !(in.J1_kg_m2 > 0)) throw SettingError("", "inertia", "R1_m and J1_kg_m2 must be positive");
  if (min_value(in.path_speed_m_per_s) < 0 || in.omega1_0_rad_per_s < 0)
    throw SettingError("", "inertia", "the path speed and the initial spin must be >= 0");
  if (!(set.dt_s > 0)) throw SettingError("", "dt_s", "an inertia run needs the longest step dt_s > 0");
  if (set.scheme != TransientScheme::Shift) throw SettingError("", "scheme", "an inertia run uses shift");
  if (c.patch && !(is_constant(c.inputs.normal_load_N) && c.inputs.normal_load_N.value[0] == c.patch->normal_load_N))
    throw SettingError("", "normal_load_N", "a run on a given contact patch needs the constant load of the patch, " +
                                                std::to_string(c.patch->normal_load_N) + " N");
  TransientResult res;
  res.grid = shift_run_grid(c);
  const Grid& g = res.grid;
  const double dx = g.dx_m, R1 = in.R1_m, J1 = in.J1_kg_m2;
  res.strip_energy_J_per_m = Eigen::ArrayXd::Zero(g.ny);
  res.final_state = rest_state(g);  // Satran's node state: not this model's (left at rest)
  std::vector<double> snaps = set.snapshot_times_s;
  std::sort(snaps.begin(), snaps.end());
  std::size_t next_snap = 0;
  RelaxedState state = relaxed_rest();
  double t = 0, q = 0, omega = in.omega1_0_rad_per_s, F_patch = std::numeric_limits<double>::quiet_NaN();
  int step = 0;
  bool has_whole_step = false, in_contact = false;
  ContactPatch patch;
  while (t < set.t_end_s * (1 - 1e-12)) {
    const double left = set.t_end_s - t, longest = set.dt_s;
    const double V_now = (omega * R1 + value_at(in.path_speed_m_per_s, t)) / 2;
    const double dt_guess = std::min({V_now > 0 ? dx / V_now : longest, longest, left});
    const double V2 = value_at(in.path_speed_m_per_s, t + dt_guess / 2);
    const double F = value_at(c.inputs.normal_load_N, t + dt_guess / 2);
    if (!(F == F_patch)) {
      patch = shift_run_contact(c, g, F);
      F_patch = F;
      in_contact = (patch.pressure_Pa > 0).any();
      if (!in_contact) state = relaxed_rest();  // out of contact: nothing is held
    }
    const bool fields = next_snap < snaps.size();
    // the step from the mean spin; returns the residual of the spin balance
    auto evaluate = [&](double omega_end, InertiaTrial& out) {
      const double omega_mid = (omega + omega_end) / 2;
      const double Vm = std::max(0.0, (omega_mid * R1 + V2) / 2);
      const double natural = std::min(Vm > 0 ? dx / Vm : longest, longest);
      out.dt_s = std::min(natural, left);
      out.dq_m = std::min(dx, Vm * out.dt_s);
      out.V_m_per_s = Vm;
      out.xi = Vm > 0 ? (V2 - omega_mid * R1) / Vm : 0;
      out.shortened = out.dt_s < natural * (1 - 1e-9);
      out.state = state;
      out.f = in_contact ? relaxed_step(patch, c.materials, {out.xi, 0, 0}, c.mu, Vm, out.dq_m, out.state, fields)
                         : no_contact_solution(g);
      return J1 * (omega_end - omega) - (-R1 * out.f.Fx_N - in.T_res_N_m) * out.dt_s;
    };
    // the bracket: the creep force is bounded by mu F
    InertiaTrial s;
    const double span = (c.mu * F * R1 + std::abs(in.T_res_N_m)) * longest / J1 * 1.01 + 1e-12;
    const double omega_end =
        implicit_roller_speed_rad_per_s([&](double w) { return evaluate(w, s); }, omega, span, t, "relaxed model");
    evaluate(omega_end, s);
    state = s.state;
    omega = omega_end;
    const TangentialSolution& f = s.f;
    TransientRecord rec;
    rec.step = ++step;
    rec.t_s = t + s.dt_s;  // as run_shift_steps: the step's end
    rec.q_m = q + s.dq_m;
    rec.dt_s = s.dt_s;
    rec.speed_m_per_s = s.V_m_per_s;
    rec.xi = s.xi;
    rec.normal_load_N = F;
    rec.omega1_rad_per_s = omega;
    rec.Fx_N = f.Fx_N;
    rec.Fy_N = f.Fy_N;
    rec.Mz_N_m = f.Mz_N_m;
    rec.power_W = f.power_W;
    rec.stick_fraction = f.stick_fraction;
    rec.balance_residual_W = std::numeric_limits<double>::quiet_NaN();  // a model has no discrete balance
    rec.cfl = s.dq_m / dx;
    rec.scheme = s.dq_m == 0 ? StepScheme::Standstill : StepScheme::Shift;  // not an upwind fallback: no nodes
    rec.shortened = s.shortened;
    if (!s.shortened || !has_whole_step) {
      res.end = rec;
      has_whole_step = !s.shortened;
    }
    t += s.dt_s;
    q += s.dq_m;
    add_shift_step(res, rec, f, patch, s.dt_s, t, snaps, next_snap, observe);
    if (!(s.dt_s > 0)) break;  // nothing left to advance
  }
  res.steps = step;
  res.t_end_s = t;
  res.q_end_m = q;
  return res;
}

namespace {

bool same_creepages(const Creepages& a, const Creepages& b) {
  return a.xi == b.xi && a.eta == b.eta && a.phi_per_m == b.phi_per_m;
}

// the solution f at the speed times k: slip velocities and powers scale, forces and tractions stay
TangentialSolution scaled_by_speed(const TangentialSolution& f, double k) {
  TangentialSolution s = f;
  s.slip_x_m_per_s *= k;
  s.slip_y_m_per_s *= k;
  s.power_W_per_m2 *= k;
  s.strip_power_W_per_m *= k;
  s.strip_creep_power_W_per_m *= k;
  s.strip_trailing_W_per_m *= k;
  s.power_W *= k;
  s.creep_work_W *= k;
  return s;
}

}  // namespace

TransientResult run_relaxed_transient(const TransientCase& c, const StepObserver& observe) {
  const TransientSettings& set = c.settings;
  check_transient_inputs(c);
  if (c.inertia) return run_relaxed_inertia(c, observe);
  if (set.scheme != TransientScheme::Shift)
    throw SettingError("", "scheme", "the relaxed model rolls by the shift scheme's steps; use scheme: shift (or "
                                     "solver.tangential: consistent for Satran's upwind and lax-friedrichs steps)");
  RelaxedState state = relaxed_rest();
  // the last solve of a duty cycle (skip_steady), its contact (the patch run_shift_steps keeps, and its load)
  struct Memo {
    bool valid = false;
    const ContactPatch* patch = nullptr;
    double load_N = 0;
    Creepages effective, lagged, imposed;
    double V = 0;
    TangentialSolution f;
  } memo;
  const ContactPatch* last = nullptr;  // the patch and imposed creepages of the last step
  Creepages imposed;
  ShiftSkip skip;
  // the relaxation lengths of the last step (sigma shrunk with the saturation, as relaxed_step does)
  auto sigmas = [&] { return stage_lengths(*last, c.materials, c.mu, state); };
  // the second stage's deviation (eta, phi)
  auto lag_deviation = [&] {
    return Creepages{0, state.lagged.eta - imposed.eta, state.lagged.phi_per_m - imposed.phi_per_m};
  };
  auto deviation = [&] {
    return Creepages{state.effective.xi - imposed.xi, state.effective.eta - imposed.eta,
                     state.effective.phi_per_m - imposed.phi_per_m};
  };
  // the one creepage still relaxing beyond kSettledLevel (0 xi, 1 eta, 2 phi), -1 if none, -2 if more than one
  auto relaxing = [&] {
    const Creepages d = deviation();
    int k = -1;
    const Creepages parts[3] = {{d.xi, 0, 0}, {0, d.eta, 0}, {0, 0, d.phi_per_m}};
    for (int i = 0; i < 3; ++i)
      if (saturation_level(*last, c.materials, parts[i], c.mu) > kSettledLevel) k = k == -1 ? i : -2;
    return k;
  };
  // settled: both stages are the imposed creepages to kSettledLevel, or xi alone relaxes within kTailLevel (the
  // tail's closed form below follows one deviation; eta and phi carry a second stage that it does not)
  skip.settled = [&] {
    if (!last) return false;
    const double e = saturation_level(*last, c.materials, deviation(), c.mu);
    const double e2 = saturation_level(*last, c.materials, lag_deviation(), c.mu);
    return e >= 0 && e2 <= kSettledLevel && (e <= kSettledLevel || (e <= kTailLevel && relaxing() == 0));
  };
  // the effective creepages advanced over n whole steps of dx as relaxed_step advances them (sigma at each step's
  // start from the saturation level of c_eff), without the steady solves; u1 and u2 get the sums over the steps of
  // u and u^2, u the relaxing creepage k's deviation over its value now. Once u is below kFrozenShare, sigma is
  // held (its change is then below 1e-4 of the tail level's share, as the skip before the quadratic tail took it)
  // and the rest is a geometric series.
  auto advance = [&](double n, int k, double* u1, double* u2) {
    constexpr double kFrozenShare = 1e-2;
    const double dx = last->grid.dx_m;
    auto dev_k = [&] {
      const Creepages d = deviation();
      return k == 0 ? d.xi : k == 1 ? d.eta : d.phi_per_m;
    };
    const double d0 = dev_k();
    double s1 = 0, s2 = 0, i = 0, u = 1;
    auto relax_all = [&](double dq, const StageLengths& sg) { relax_stages(state, imposed, dq, sg); };
    for (; i < n && std::abs(u) >= kFrozenShare; ++i) {
      relax_all(dx, sigmas());
      u = dev_k() / d0;
      s1 += u;
      s2 += u * u;
    }
    if (i < n) {  // the rest at sigma held: u r^j, j = 1 .. m
      const StageLengths sg = sigmas();
      const double m = n - i, r = std::exp(-dx / (k == 0 ? sg.first.xi : k == 1 ? sg.first.eta : sg.first.phi_per_m));
      s1 += u * r * (1 - std::pow(r, m)) / (1 - r);
      s2 += u * u * r * r * (1 - std::pow(r, 2 * m)) / (1 - r * r);
      relax_all(m * dx, sg);
    }
    if (u1) *u1 = s1;
    if (u2) *u2 = s2;
  };
  // the stretch's energy: the steady state's, plus the relaxing creepage's tail in closed form
  skip.energy = [&](double span_s, double rolled_m, const TangentialSolution& f, Eigen::ArrayXd& strip_J, double& J) {
    const int k = relaxing();
    if (k < 0 || !(rolled_m > 0)) return;
    const double V = rolled_m / span_s;
    const TangentialSolution ss = solve_relaxed_steady(*last, c.materials, imposed, c.mu, V, false);
    // the power halfway: at the imposed creepages plus half the deviation (the effective ones at u = 1/2)
    const Creepages d = deviation();
    const Creepages half{imposed.xi + d.xi / 2, imposed.eta + d.eta / 2, imposed.phi_per_m + d.phi_per_m / 2};
    const TangentialSolution hf = steady_at(*last, c.materials, half, imposed, c.mu, V, false);
    // P(u) - P(0) = a u + b u^2 through u = 1 (the last step) and u = 1/2; the steps' sum the stretch stands for,
    // the power taken at each step's end: (a sum u + b sum u^2) dt, the state advanced on a copy
    const double dx = last->grid.dx_m, n = std::round(rolled_m / dx), dt = span_s / n;
    const RelaxedState kept = state;
    double u1 = 0, u2 = 0;
    advance(n, k, &u1, &u2);
    state = kept;
    // a = 4 g(1/2) - g(1), b = 2 g(1) - 4 g(1/2): the weights of g(1/2) and of g(1)
    const double wa = 4 * (u1 - u2) * dt, w1 = (2 * u2 - u1) * dt;
    strip_J = ss.strip_power_W_per_m * span_s + (f.strip_power_W_per_m - ss.strip_power_W_per_m) * w1 +
              (hf.strip_power_W_per_m - ss.strip_power_W_per_m) * wa;
    J = ss.power_W * span_s + (f.power_W - ss.power_W) * w1 + (hf.power_W - ss.power_W) * wa;
  };
  // over the stretch the effective creepages relax on towards the imposed ones, as the steps would
  skip.skipped = [&](double rolled_m) {
    if (!last) return;
    const int k = relaxing();
    if (k >= 0) return advance(std::round(rolled_m / last->grid.dx_m), k, nullptr, nullptr);
    relax_stages(state, imposed, rolled_m, sigmas());  // settled: sigma held
  };
  return run_shift_steps(
      c, observe,
      [&](const ContactPatch& patch, const ShiftStep& s) {
        last = &patch;
        imposed = s.creepages;
        if (!set.skip_steady) return relaxed_step(patch, c.materials, s.creepages, c.mu, s.speed_m_per_s, s.dq_m, state, s.fields);
        // duty cycles (skip_steady): a step at the last solve's contact, effective and imposed creepages (a speed
        // ramp once settled) is that solve with the powers scaled by the speed: the model's forces do not depend
        // on V, its slip velocities and powers are proportional to it
        relax_effective(patch, c.materials, s.creepages, c.mu, s.dq_m, state);
        const bool same = memo.valid && memo.patch == &patch && memo.load_N == s.normal_load_N &&
                          same_creepages(memo.effective, state.effective) && same_creepages(memo.lagged, state.lagged) &&
                          same_creepages(memo.imposed, s.creepages) &&
                          !s.fields && memo.V > 0 && s.speed_m_per_s > 0;
        if (same) return scaled_by_speed(memo.f, s.speed_m_per_s / memo.V);
        TangentialSolution f = transient_at(patch, c.materials, state, s.creepages, c.mu, s.speed_m_per_s, s.fields);
        memo = {true, &patch, s.normal_load_N, state.effective, state.lagged, s.creepages, s.speed_m_per_s, f};
        return f;
      },
      [&](const Grid&) {  // out of contact: nothing is held
        state = relaxed_rest();
        last = nullptr;
        memo.valid = false;
      },
      skip);
}

}  // namespace contact
