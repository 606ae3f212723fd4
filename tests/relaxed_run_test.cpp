// The relaxed model's transient runs (lib/tangential/relaxed.h): the roller's inertia against closed forms
// (gross sliding: d omega/dt = mu F R1 / J1; small oscillations about free rolling: the linear system of the
// roller's spin and the model's own relaxation, solved in closed form), the steady stretch skipped in wear duty
// cycles against the same run stepped through, and a standstill.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "lib/elastic.h"
#include "lib/history.h"
#include "lib/errors.h"
#include "lib/normal/hertz.h"
#include "lib/numeric.h"
#include "lib/tangential/relaxed.h"
#include "lib/tangential/satran.h"

namespace contact {
namespace {

const ElasticPair kSteel{{210e9, 0.28}, {210e9, 0.28}};
const Bodies kPaperBodies{{20e-3, 500e-3}, {25e-3, kFlat}};  // cases/paper.yaml
constexpr double kMu = 0.3, kLoad = 1500;
constexpr double kR1 = 0.020, kJ1 = 3.9458e-5;  // cases/roller-spinup.yaml's roller

// the paper's contact with the roller of cases/roller-spinup.yaml, path at V2, roller at omega0
TransientCase spinup_case(double V2, double omega0, double t_end_s, double dt_s, int n) {
  TransientCase c;
  c.bodies = kPaperBodies;
  c.materials = kSteel;
  c.mu = kMu;
  c.inputs.normal_load_N = constant_history(kLoad);
  RollerInertia in;
  in.R1_m = kR1;
  in.J1_kg_m2 = kJ1;
  in.omega1_0_rad_per_s = omega0;
  in.path_speed_m_per_s = constant_history(V2);
  c.inertia = in;
  c.settings.t_end_s = t_end_s;
  c.settings.dt_s = dt_s;
  c.settings.grid = {n, n};
  return c;
}

std::vector<TransientRecord> records_of(const TransientCase& c, TransientResult* out = nullptr) {
  std::vector<TransientRecord> recs;
  const TransientResult r = run_relaxed_transient(c, [&](const TransientRecord& rec, const Eigen::ArrayXd&) {
    recs.push_back(rec);
  });
  if (out) *out = r;
  return recs;
}

// Gross sliding (the roller at rest under a path at 1 m/s, xi = 2): once the effective creepage has caught up
// (a few steps), |Fx| = mu F and the roller spins up at mu F R1 / J1 = 2.28e5 rad/s^2 (closed form).
TEST(RelaxedInertia, GrossSlidingSpinsTheRollerUpAtMuFR1OverJ1) {
  const std::vector<TransientRecord> recs = records_of(spinup_case(1.0, 0.0, 1e-4, 2e-6, 20));
  ASSERT_EQ(recs.size(), 50u);
  // the full-slip force of the model on its grid: mu times the load the strips carry, within rounding of mu F
  constexpr double kSlidingForceTol = 1e-6;
  for (std::size_t k = 5; k < recs.size(); ++k)
    EXPECT_NEAR(recs[k].Fx_N, -kMu * kLoad, kSlidingForceTol * kMu * kLoad) << "step " << recs[k].step;
  const double rate = (recs.back().omega1_rad_per_s - recs[9].omega1_rad_per_s) / (recs.back().t_s - recs[9].t_s);
  EXPECT_NEAR(rate, kMu * kLoad * kR1 / kJ1, kSlidingForceTol * kMu * kLoad * kR1 / kJ1);
}

// Small oscillations about free rolling (T_res = 0): with u = omega1 R1 - V2 and the model's linear force
// Fx = -k xi_eff (k its own slope at xi -> 0), xi = -u/V and d xi_eff/dt = V (xi - xi_eff)/sigma, the roller obeys
//   u'' = R1^2 k xi_eff' / J1,  a damped oscillator: lambda^2 + (V/sigma) lambda + R1^2 k / (J1 sigma) = 0,
// u(t) = u0 e^{-alpha t} (cos wd t + alpha/wd sin wd t) from xi_eff(0) = 0 (closed form). The run (first order in
// dt: the force at the step's end) converges to it: error over one period 1/2 of the coarse step's at dt/2.
TEST(RelaxedInertia, SmallOscillationAboutFreeRollingIsTheLinearClosedForm) {
  constexpr double V2 = 1.0, eps = 1e-5;  // omega1 R1 = V2 (1 - eps) at t = 0: xi = 1e-5, far below saturation
  const ContactPatch patch = solve_normal_hertz(kPaperBodies, kSteel, kLoad, {20, 20});
  const double xi_lin = 1e-7;
  const double k = -solve_relaxed_steady(patch, kSteel, {xi_lin, 0, 0}, kMu, V2, false).Fx_N / xi_lin;
  const double sigma = relaxation_lengths_m(patch.a_m, patch.b_m).xi;
  const double alpha = V2 / (2 * sigma), w0 = std::sqrt(kR1 * kR1 * k / (kJ1 * sigma));
  ASSERT_GT(w0, alpha);  // under-damped
  const double wd = std::sqrt(w0 * w0 - alpha * alpha), period = 2 * kPi / wd, u0 = -eps * V2;
  auto u_exact = [&](double t) { return u0 * std::exp(-alpha * t) * (std::cos(wd * t) + alpha / wd * std::sin(wd * t)); };
  std::vector<double> errors;
  for (const double dt : {1e-6, 5e-7}) {
    const std::vector<TransientRecord> recs =
        records_of(spinup_case(V2, V2 * (1 - eps) / kR1, period, dt, 20));
    double worst = 0;
    for (const TransientRecord& r : recs) worst = std::max(worst, std::abs(r.omega1_rad_per_s * kR1 - V2 - u_exact(r.t_s)));
    errors.push_back(worst / std::abs(u0));
  }
  // at dt = 5e-7 s (about 270 steps a period) the run within 5 % of u0 of the closed form; first order in dt
  constexpr double kOscillationTol = 0.05;
  EXPECT_LT(errors[1], kOscillationTol) << "dt 1e-6: " << errors[0] << ", 5e-7: " << errors[1];
  EXPECT_NEAR(errors[0] / errors[1], 2.0, 0.3) << "dt 1e-6: " << errors[0] << ", 5e-7: " << errors[1];
  std::cout << "period " << period << " s, damping " << alpha << " 1/s; error / u0 at dt 1e-6 s " << errors[0]
            << ", at 5e-7 s " << errors[1] << "\n";
}

// A duty cycle as the wear loop runs it (start, run, stop, standstill): steady running skipped once the effective
// creepage has settled (its last 1e-4 of saturation level summed in closed form, a geometric series linearised
// about the steady state) changes the dissipated energy and every strip's by less than 1e-8, in far fewer steps
// (measured: 9e-10, 238 steps against 3909; with the stretch at the last step's power instead: -1.4e-3, fails).
TEST(RelaxedSkip, SteadyRunningSkippedChangesTheEnergiesBelowTenPerBillion) {
  TransientCase c;
  c.bodies = kPaperBodies;
  c.materials = kSteel;
  c.mu = kMu;
  c.inputs.normal_load_N = constant_history(kLoad);
  c.inputs.xi = constant_history(1e-3);
  c.inputs.speed_m_per_s = History{{0, 1e-3, 0.05, 0.051}, {0, 1.8, 1.8, 0}};
  c.settings.t_end_s = 0.052;
  c.settings.grid = {20, 20};
  TransientResult stepped, skipped;
  records_of(c, &stepped);
  c.settings.skip_steady = true;
  records_of(c, &skipped);
  constexpr double kSkipTol = 1e-8;
  EXPECT_NEAR(skipped.dissipated_J, stepped.dissipated_J, kSkipTol * stepped.dissipated_J);
  EXPECT_LT((skipped.strip_energy_J_per_m - stepped.strip_energy_J_per_m).abs().maxCoeff(),
            kSkipTol * stepped.strip_energy_J_per_m.abs().maxCoeff());
  EXPECT_NEAR(skipped.q_end_m, stepped.q_end_m, 1e-12 * stepped.q_end_m);
  EXPECT_NEAR(skipped.t_end_s, stepped.t_end_s, 1e-12);
  EXPECT_LT(skipped.steps * 2, stepped.steps);
  std::cout << "steps " << stepped.steps << " stepped, " << skipped.steps << " with the skip; energy "
            << stepped.dissipated_J << " J, difference " << skipped.dissipated_J / stepped.dissipated_J - 1 << "\n";
}

// A duty cycle's stop (the speed ramped down at a constant creepage, the effective creepage settled) reuses the
// last solve with its powers scaled by the speed (the model's forces do not depend on V): each step of the ramp
// is the stepped run's (no reuse) to rounding, forces and per-strip powers alike.
TEST(RelaxedSkip, SettledSpeedRampIsTheSteppedRunsToRounding) {
  TransientCase c;
  c.bodies = kPaperBodies;
  c.materials = kSteel;
  c.mu = kMu;
  c.inputs.normal_load_N = constant_history(kLoad);
  c.inputs.xi = constant_history(1e-3);
  c.inputs.speed_m_per_s = History{{0, 1e-3, 0.05, 0.051}, {0, 1.8, 1.8, 0}};
  c.settings.t_end_s = 0.052;
  c.settings.grid = {20, 20};
  struct Step {
    double t, V, Fx, P;
    Eigen::ArrayXd strips;
  };
  auto ramp_down = [&](bool skip) {
    c.settings.skip_steady = skip;
    std::vector<Step> steps;
    run_relaxed_transient(c, [&](const TransientRecord& r, const Eigen::ArrayXd& strip_W) {
      if (r.t_s > 0.05 && r.speed_m_per_s > 0 && !r.skipped) steps.push_back({r.t_s, r.speed_m_per_s, r.Fx_N, r.power_W, strip_W});
    });
    return steps;
  };
  const std::vector<Step> stepped = ramp_down(false), reused = ramp_down(true);
  ASSERT_EQ(stepped.size(), reused.size());
  ASSERT_GT(stepped.size(), 20u);
  // rounding: the stepped run's solver takes the speed into its slip and power sums at every step (4e-12 of the
  // strip powers measured at full speed, 4e-10 at the ramp's slowest step), the reuse scales by the speeds' ratio
  constexpr double kRoundingTol = 1e-9;
  for (std::size_t k = 0; k < stepped.size(); ++k) {
    EXPECT_NEAR(reused[k].t, stepped[k].t, 1e-12);  // the skip adds its span in one sum
    EXPECT_NEAR(reused[k].Fx, stepped[k].Fx, kRoundingTol * std::abs(stepped[k].Fx)) << "step " << k;
    EXPECT_NEAR(reused[k].P, stepped[k].P, kRoundingTol * stepped[k].P) << "step " << k;
    EXPECT_LT((reused[k].strips - stepped[k].strips).abs().maxCoeff(), kRoundingTol * stepped[k].strips.abs().maxCoeff())
        << "step " << k;
  }
  EXPECT_LT(stepped.back().V, stepped.front().V / 5);  // the ramp itself, down to an eighth of the speed
}

// V = 0 (a standstill after rolling): nothing rolls, so the effective creepage and the force are held and
// nothing is dissipated (the model's power is -V xi_eff Fx).
TEST(RelaxedSkip, StandstillHoldsTheForceAndDissipatesNothing) {
  TransientCase c;
  c.bodies = kPaperBodies;
  c.materials = kSteel;
  c.mu = kMu;
  c.inputs.normal_load_N = constant_history(kLoad);
  c.inputs.xi = constant_history(1e-3);
  c.inputs.speed_m_per_s = History{{0, 1e-4, 2e-4}, {1.0, 1.0, 0.0}};  // rolls 150 um, then stops
  c.settings.t_end_s = 4e-4;
  c.settings.dt_s = 2e-5;  // the standing steps
  c.settings.grid = {20, 20};
  const std::vector<TransientRecord> recs = records_of(c);
  int standing = 0;
  double held = 0;
  for (const TransientRecord& r : recs) {
    if (r.scheme != StepScheme::Standstill) {
      held = r.Fx_N;
      continue;
    }
    ++standing;
    EXPECT_EQ(r.Fx_N, held) << "step " << r.step;
    EXPECT_EQ(r.power_W, 0.0) << "step " << r.step;
  }
  EXPECT_GE(standing, 9);
  EXPECT_LT(held, 0);
}

// Satran's upwind and Lax-Friedrichs steps are not the relaxed model's: refused naming the key
TEST(RelaxedSkip, OtherSchemesAreRefusedAtTheirKey) {
  TransientCase c = spinup_case(1.0, 0.0, 1e-4, 2e-6, 10);
  c.inertia.reset();
  c.inputs.xi = constant_history(1e-3);
  c.settings.scheme = TransientScheme::Upwind;
  try {
    run_relaxed_transient(c);
    FAIL() << "no error";
  } catch (const SettingError& e) {
    EXPECT_EQ(e.key, "scheme");
  }
}

// first_mirrored_strip remembers its last patch on the thread (the relaxed transient's steps all solve on one):
// the same patch changed in place, or another patch, is checked again
TEST(RelaxedSkip, MirrorCheckSeesAPatchChangedInPlace) {
  ContactPatch p = solve_normal_hertz(kPaperBodies, kSteel, kLoad, {20, 20});
  const int ny = p.grid.ny;
  EXPECT_EQ(first_mirrored_strip(p, 0.0), ny - ny / 2);
  p.half_length_m(0) *= 1.1;  // no longer its own mirror image
  EXPECT_EQ(first_mirrored_strip(p, 0.0), ny);
  p.half_length_m(0) /= 1.1;
  p.strip_xi_offset = Eigen::ArrayXd::LinSpaced(ny, -1e-4, 2e-4);  // asymmetric Heathcote offsets
  EXPECT_EQ(first_mirrored_strip(p, 0.0), ny);
  p.strip_xi_offset = Eigen::ArrayXd();
  EXPECT_EQ(first_mirrored_strip(solve_normal_hertz(kPaperBodies, kSteel, kLoad, {20, 21}), 0.0), 21 - 21 / 2);
  EXPECT_EQ(first_mirrored_strip(p, 0.5), ny);  // spin: never
}

}  // namespace
}  // namespace contact
