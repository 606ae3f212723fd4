// The fast tangential models against Kalker's exact theory in-house (docs/accuracy-vs-exact.md): one
// contact (Hertz ellipse of a/b, b = 1 mm, p0 = 1 GPa, steel 210 GPa / 0.28, mu 0.3, V 1 m/s) on an
// n x n grid, the exact solver (lib/tangential/exact.h), the simplified theory as it stands (steady
// solver, consistent scheme; Satran's shift steps) and the relaxed model (lib/tangential/relaxed.h).
// Built with the bench preset, not part of ctest; scripts/fast-model-compare runs it and plots.
//   fast_model_report steady AB N       steady solves over creepages (pure xi, eta, phi, mixes, ~50 % and
//                                       ~90 % of saturation): one line per solver and creepage
//   fast_model_report startup AB N K    start from rest at saturation level K (0.5 or 0.9) in xi, to q = 20a
//   fast_model_report step AB N DIR     from steady at 50 % to 90 % of saturation in DIR (xi, eta, phi)
//   fast_model_report fit AB N          the creepage factors of the relaxed model (lines "G", scripts/fit-relaxed)
//   fast_model_report fitsigma AB N DIR its relaxation length in DIR (line "Z", scripts/fit-relaxed)
//   fast_model_report heldtrace AB N NU K UXI UETA UPHI AXIS FACTOR  a held-out transient run traced (lines "Q")
//   fast_model_report fittransient AB N its transient law's second stage under eta and phi (line "R",
//                                       scripts/fit-relaxed --transient-only)
//   fast_model_report checkspin AB N    the relaxed model's spin between the fitted levels (lines "K")
//   fast_model_report linear AB N       the linear limit of Fy(phi), Mz(eta), Mz(phi) against Kalker's C23, C33
//   fast_model_report fitspin AB N      its two spin factors (lines "H", scripts/fit-relaxed --spin-only)
//   fast_model_report fitmix AB N       its mix corrections over directions and levels (lines "M", scripts/fit-relaxed)
//   fast_model_report checkmix AB N     the relaxed model at directions and levels between the fitted ones (lines "C")
//   fast_model_report cost AB N [REPS]  its steady solve and step against the consistent solve and Satran's (lines "X")
// FAST_MODEL_CASES=xi50,mix50 (say) in the environment: only those steady cases; FAST_MODEL_NU: Poisson's ratio.
// Lines: "S solver ab n label xi eta phi Fx Fy Mz P W ms" (W = -creep work), "J solver ab n label P_j...",
// "T solver ab n label q/a Fx Fy Mz P ms".
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "lib/elastic.h"
#include "lib/grid.h"
#include "lib/normal/hertz.h"
#include "lib/numeric.h"
#include "lib/tangential/exact.h"
#include "lib/tangential/relaxed.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/steady.h"

using namespace contact;

namespace {

// steel (E 210 GPa, nu 0.28); FAST_MODEL_NU=0.1 (say) in the environment: that Poisson's ratio for both bodies
// (the relaxed model's tables are fitted at 0.28: docs/accuracy-vs-exact.md, "Poisson's ratio")
ElasticPair pair_from_env() {
  const char* v = std::getenv("FAST_MODEL_NU");
  const double nu = v ? std::atof(v) : 0.28;
  return {{210e9, nu}, {210e9, nu}};
}
const ElasticPair kPair = pair_from_env();
constexpr double kMu = 0.3, kV = 1.0;

ContactPatch ellipse_patch(double ab, int n) {
  HertzContact h;
  h.b_m = 1e-3;
  h.a_m = ab * h.b_m;
  h.p0_Pa = 1e9;
  h.normal_load_N = 2 * kPi * h.a_m * h.b_m * h.p0_Pa / 3;
  return hertz_patch(h, make_grid(h.a_m, h.b_m, {n, n}));
}

// the creepage giving the share k of saturation in the simplified theory's closed form for a Hertz
// contact, |F|/(mu N) = 1 - (1 - e)^3, e = G a b C |c| / (3 mu N): e = 1 - (1 - k)^(1/3)
Creepages level(const ContactPatch& p, double k, double wx, double wy, double wphi) {
  const KalkerCoefficients C = kalker_coefficients(p.a_m, p.b_m, combined_poisson(kPair));
  const double G = combined_shear_modulus_Pa(kPair), a = p.a_m, b = p.b_m, N = p.normal_load_N;
  const double e = 1 - std::cbrt(1 - k);
  const double xi = 3 * kMu * N * e / (G * a * b * C.C11);
  const double eta = 3 * kMu * N * e / (G * a * b * C.C22);
  const double phi = 3 * kMu * N * e / (G * std::pow(a * b, 1.5) * C.C23);
  return {wx * xi, wy * eta, wphi * phi};
}

// FAST_MODEL_ONLY=1 in the environment: the fast models only (the exact lines kept from an earlier run)
bool with_exact() {
  const char* v = std::getenv("FAST_MODEL_ONLY");
  return !(v && std::string(v) == "1");
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void print_steady(const char* solver, double ab, int n, const std::string& label, const Creepages& c,
                  const TangentialSolution& s, double ms) {
  std::printf("S %s %g %d %s %.6e %.6e %.6e %.6e %.6e %.6e %.6e %.6e %.3f\n", solver, ab, n, label.c_str(), c.xi,
              c.eta, c.phi_per_m, s.Fx_N, s.Fy_N, s.Mz_N_m, s.power_W, -s.creep_work_W, ms);
  std::printf("J %s %g %d %s", solver, ab, n, label.c_str());
  for (int j = 0; j < s.strip_power_W_per_m.size(); ++j) std::printf(" %.6e", s.strip_power_W_per_m(j));
  std::printf("\n");
}

struct Labelled {
  std::string label;
  Creepages c;
};

std::vector<Labelled> steady_cases(const ContactPatch& p) {
  std::vector<Labelled> v;
  for (double k : {0.5, 0.9}) {
    const std::string s = k == 0.5 ? "50" : "90";
    v.push_back({"xi" + s, level(p, k, 1, 0, 0)});
    v.push_back({"eta" + s, level(p, k, 0, 1, 0)});
    v.push_back({"phi" + s, level(p, k, 0, 0, 1)});
    const double r2 = 1 / std::sqrt(2.0), r3 = 1 / std::sqrt(3.0);
    v.push_back({"xieta" + s, level(p, k, r2, r2, 0)});
    v.push_back({"xiphi" + s, level(p, k, r2, 0, r2)});
    v.push_back({"mix" + s, level(p, k, r3, r3, r3)});
    v.push_back({"mixneg" + s, level(p, k, -r3, r3, -r3)});
  }
  return v;
}

// one step of each transient model; returns the record's forces and power
struct Row {
  double Fx, Fy, Mz, P;
};

// a history of creepages over the rolled distance, stepped by dq = dx with each solver
void transient(double ab, int n, const std::string& label, const std::function<Creepages(double q)>& at,
               double q_end, bool from_steady) {
  const ContactPatch p = ellipse_patch(ab, n);
  const double G = combined_shear_modulus_Pa(kPair), nu = combined_poisson(kPair), dx = p.grid.dx_m, a = p.a_m;
  const int steps = static_cast<int>(std::lround(q_end / dx));
  auto print = [&](const char* solver, int k, const Row& r, double ms) {
    std::printf("T %s %g %d %s %.6f %.6e %.6e %.6e %.6e %.4f\n", solver, ab, n, label.c_str(), k * dx / a, r.Fx, r.Fy,
                r.Mz, r.P, ms);
  };
  if (with_exact()) {  // exact: solve_exact_rolling_step (dq = dx), from rest or from the steady state at q = 0
    ExactOptions o = exact_run_options();
    ExactSolution prev;
    bool have = false;
    if (from_steady) {
      prev = solve_exact_steady(p, G, nu, at(0), kMu, kV);
      have = true;
    }
    for (int k = 1; k <= steps; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      ExactSolution s = solve_exact_rolling_step(p, G, nu, at((k - 0.5) * dx), kMu, kV, have ? &prev : nullptr, o);
      const double ms = ms_since(t0);
      if (!s.status.converged()) std::printf("# exact step %d not converged: %s\n", k, s.status.message.c_str());
      print("exact", k, {s.fields.Fx_N, s.fields.Fy_N, s.fields.Mz_N_m, s.fields.power_W}, ms);
      prev = std::move(s);
      have = true;
    }
  }
  {  // the simplified theory: Satran's shift steps (consistent), from rest or after rolling 4a at q = 0's creepage
    TransientState st = rest_state(p.grid);
    auto step = [&](const Creepages& c) {
      const TangentialProblem pr = make_tangential_problem(p, kPair, c, kMu, kV);
      StepKinematics kin{dx / kV, dx, c.xi * dx, c.eta * dx, c.phi_per_m * dx};
      return satran_step(p, pr, kin, TransientScheme::Shift, st);
    };
    if (from_steady)
      for (int k = 0; k < 2 * n + 4; ++k) step(at(0));
    for (int k = 1; k <= steps; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      const StepResult r = step(at((k - 0.5) * dx));
      print("simplified", k, {r.Fx_N, r.Fy_N, r.Mz_N_m, r.dissipated_J / (dx / kV)}, ms_since(t0));
    }
  }
  {  // the relaxed model
    RelaxedState st = relaxed_rest();
    if (from_steady) st = relaxed_steady_state(at(0));
    for (int k = 1; k <= steps; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      const TangentialSolution s = relaxed_step(p, kPair, at((k - 0.5) * dx), kMu, kV, dx, st);
      print("relaxed", k, {s.Fx_N, s.Fy_N, s.Mz_N_m, s.power_W}, ms_since(t0));
    }
  }
}

// the saturation levels e = G a b C |c| / (3 mu N) the creepage factors are fitted at (scripts/fit-relaxed)
const std::vector<double> kFitE = {0.05, 0.1, 0.2, 0.3, 0.4, 0.55, 0.7, 0.85};
// those of the spin's two factors (finer where the exact Fy of spin peaks, e = 0.2-0.4; the first in the linear
// range, fitted in closed form)
const std::vector<double> kFitEPhi = {0.001, 0.01, 0.025, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.475, 0.55, 0.7, 0.85};

// the pure creepage of direction dir (0 xi, 1 eta, 2 phi) at the level e
Creepages at_level(const ContactPatch& p, int dir, double e) {
  const KalkerCoefficients C = kalker_coefficients(p.a_m, p.b_m, combined_poisson(kPair));
  const double G = combined_shear_modulus_Pa(kPair), a = p.a_m, b = p.b_m, N = p.normal_load_N;
  const double base = 3 * kMu * N * e / (G * a * b);
  if (dir == 0) return {base / C.C11, 0, 0};
  if (dir == 1) return {0, base / C.C22, 0};
  return {0, 0, base / (std::sqrt(a * b) * C.C23)};
}

double force_of(const TangentialSolution& s, int dir) { return dir == 0 ? s.Fx_N : s.Fy_N; }

// "G dir ab e factor F_exact F_simplified(1)": the factor m on the creepage with which the simplified
// theory's force equals the exact theory's (Fx for xi, Fy for eta and phi)
void fit_factors(double ab, int n) {
  const ContactPatch p = ellipse_patch(ab, n);
  const double G = combined_shear_modulus_Pa(kPair), nu = combined_poisson(kPair);
  for (int dir = 0; dir < 3; ++dir)
    for (double e : kFitE) {
      const Creepages c = at_level(p, dir, e);
      const ExactSolution ex = solve_exact_steady(p, G, nu, c, kMu, kV);
      const double target = force_of(ex.fields, dir);
      auto f = [&](double m) {
        const Creepages cm{m * c.xi, m * c.eta, m * c.phi_per_m};
        SteadyOptions o;
        o.fields = false;
        return force_of(solve_steady(p, make_tangential_problem(p, kPair, cm, kMu, kV), TangentialScheme::Consistent, o),
                        dir) - target;
      };
      // the factor in [0.5, 4] whose force is nearest the exact one (the force of spin is not monotonic in
      // phi: a scan, not a root), ties to the factor nearest 1
      double m = 1, best = std::abs(f(1));
      bool hit = best <= 2e-3 * std::abs(target);
      for (double t = 0.5; t <= 4.0 + 1e-9; t += 0.002) {
        const double d = std::abs(f(t));
        if (d <= 2e-3 * std::abs(target)) {  // a root: the one nearest 1
          if (!hit || std::abs(t - 1) < std::abs(m - 1)) m = t, best = d;
          hit = true;
        } else if (!hit && d < best) {
          best = d;
          m = t;
        }
      }
      std::printf("G %d %g %.4f %.6f %.6e %.6e %s\n", dir, ab, e, m, target, f(1) + target,
                  ex.status.converged() ? "" : "unconverged");
    }
}

// "H ab e g_phi g_phix score Fy_exact Mz_exact dFy dMz dFy(1,1) dMz(1,1)": the relaxed model's two spin factors
// under pure spin at the level e: g_phi on phi (the lateral rate phi x / L3, so Fy's flexibility) and g_phix on
// the longitudinal rate phi y / L3 (the second spin flexibility L3x = L3 g_phi / g_phix, so Mz's). score: the
// larger of |dFy| / (2 % |Fy_exact|) and |dMz| / (5 % |Mz_exact|) (the targets' ratio); dFy, dMz relative to
// the exact ones, with the factors and with none (the simplified theory). The forces of spin are not monotonic
// in either factor and several pairs fit a level: the pair minimises score + kSmooth |log of its distance to the
// previous level's pair| (1, 1 before the first), so that the table is smooth in e where it can be. At the first
// level (e = 1e-3, the linear range) the two factors are the ratios of the exact Fy and Mz to the simplified
// theory's: Kalker's C23 and C33 as the exact solver has them.
constexpr double kSmooth = 2.0;
// below this level: the linear range (the factors in closed form)
constexpr double kLinearLevel = 0.01;

void fit_spin(double ab, int n) {
  const ContactPatch p = ellipse_patch(ab, n);
  const double G = combined_shear_modulus_Pa(kPair), nu = combined_poisson(kPair);
  double pg = 1, px = 1;  // the previous level's pair
  for (double e : kFitEPhi) {
    const Creepages c = at_level(p, 2, e);
    const ExactSolution ex = solve_exact_steady(p, G, nu, c, kMu, kV);
    const double Fy = ex.fields.Fy_N, Mz = ex.fields.Mz_N_m;
    auto model = [&](double gphi, double gx) {
      TangentialProblem pb = make_tangential_problem(p, kPair, {0, 0, gphi * c.phi_per_m}, kMu, kV);
      pb.L3x_m_per_Pa = pb.flex.L3_m_per_Pa * gphi / gx;
      SteadyOptions o;
      o.fields = false;
      const TangentialSolution s = solve_steady(p, pb, TangentialScheme::Consistent, o);
      return std::pair<double, double>{(s.Fy_N - Fy) / std::abs(Fy), (s.Mz_N_m - Mz) / std::abs(Mz)};
    };
    auto score = [&](const std::pair<double, double>& d) {
      return std::max(std::abs(d.first) / 0.02, std::abs(d.second) / 0.05);
    };
    auto objective = [&](double g, double x) {
      return score(model(g, x)) + kSmooth * (std::abs(std::log(g / pg)) + std::abs(std::log(x / px)));
    };
    double bg = pg, bx = px, best = objective(pg, px);
    if (e < kLinearLevel) {
      // the linear range: Fy is proportional to the factor on phi and Mz to that on phi y / L3 (the lateral
      // traction of spin is even in x, so it has no moment): the ratios of the exact to the simplified ones
      const auto d0 = model(1, 1);
      bg = 1 / (1 + d0.first * std::abs(Fy) / Fy);
      bx = 1 / (1 + d0.second * std::abs(Mz) / Mz);
      best = -1;
    }
    // a coarse scan in log of both factors, then two finer ones around the best
    double step = 0.05;
    for (int pass = 0; pass < 3 && best >= 0; ++pass) {
      const double cg = std::log(bg), cx = std::log(bx);
      const double lo_g = pass == 0 ? std::log(0.5) : cg - 5 * step, hi_g = pass == 0 ? std::log(4.0) : cg + 5 * step;
      const double lo_x = pass == 0 ? std::log(0.05) : cx - 5 * step, hi_x = pass == 0 ? std::log(4.0) : cx + 5 * step;
      for (double lg = lo_g; lg <= hi_g + 1e-9; lg += step)
        for (double lx = lo_x; lx <= hi_x + 1e-9; lx += step) {
          const double v = objective(std::exp(lg), std::exp(lx));
          if (v < best) best = v, bg = std::exp(lg), bx = std::exp(lx);
        }
      step /= 5;
    }
    const auto d = model(bg, bx), d0 = model(1, 1);
    std::printf("H %g %.4f %.4f %.4f %.3f %.6e %.6e %+.5f %+.5f %+.5f %+.5f %s\n", ab, e, bg, bx, score(d), Fy, Mz,
                d.first, d.second, d0.first, d0.second, ex.status.converged() ? "" : "unconverged");
    std::fflush(stdout);
    pg = bg;
    px = bx;
  }
}

// "K ab e dFy dMz": the relaxed model as compiled (its table interpolated) under pure spin against the exact
// solver, at the levels between the fit's (their midpoints) and at 50 % and 90 % of saturation: the table's
// interpolation error (scripts/fit-relaxed prints it)
void check_spin(double ab, int n) {
  const ContactPatch p = ellipse_patch(ab, n);
  const double G = combined_shear_modulus_Pa(kPair), nu = combined_poisson(kPair);
  std::vector<double> es;
  for (std::size_t k = 0; k + 1 < kFitEPhi.size(); ++k) es.push_back((kFitEPhi[k] + kFitEPhi[k + 1]) / 2);
  es.push_back(1 - std::cbrt(0.5));
  es.push_back(1 - std::cbrt(0.1));
  for (double e : es) {
    const Creepages c = at_level(p, 2, e);
    const ExactSolution ex = solve_exact_steady(p, G, nu, c, kMu, kV);
    const TangentialSolution r = solve_relaxed_steady(p, kPair, c, kMu, kV, false);
    std::printf("K %g %.4f %+.5f %+.5f %s\n", ab, e, (r.Fy_N - ex.fields.Fy_N) / std::abs(ex.fields.Fy_N),
                (r.Mz_N_m - ex.fields.Mz_N_m) / std::abs(ex.fields.Mz_N_m), ex.status.converged() ? "" : "unconverged");
    std::fflush(stdout);
  }
}

// "L ab solver Fy(phi)/(G c^3 C23 phi) Mz(eta)/(G c^3 C23 eta) Mz(phi)/(G c^4 C33 phi)": the linear limit (e = 1e-3,
// c = sqrt(ab)) against Kalker's coefficients as the product has them (lib/tangential/kalker.h), for the exact
// solver, the simplified theory and the relaxed model; the signs as the solvers give them
void linear_limit(double ab, int n) {
  const ContactPatch p = ellipse_patch(ab, n);
  const double G = combined_shear_modulus_Pa(kPair), nu = combined_poisson(kPair), c = std::sqrt(p.a_m * p.b_m);
  const KalkerCoefficients C = kalker_coefficients(p.a_m, p.b_m, nu);
  const Creepages ce = at_level(p, 1, 1e-3), cp = at_level(p, 2, 1e-3);
  auto row = [&](const char* name, const TangentialSolution& se, const TangentialSolution& sp) {
    std::printf("L %g %s %.4f %.4f %.4f  C23 %.4f C33 %.4f\n", ab, name, sp.Fy_N / (G * c * c * c * C.C23 * cp.phi_per_m),
                se.Mz_N_m / (G * c * c * c * C.C23 * ce.eta), sp.Mz_N_m / (G * std::pow(c, 4) * C.C33 * cp.phi_per_m),
                C.C23, C.C33);
  };
  row("exact", solve_exact_steady(p, G, nu, ce, kMu, kV).fields, solve_exact_steady(p, G, nu, cp, kMu, kV).fields);
  row("simplified", solve_steady(p, make_tangential_problem(p, kPair, ce, kMu, kV)),
      solve_steady(p, make_tangential_problem(p, kPair, cp, kMu, kV)));
  row("relaxed", solve_relaxed_steady(p, kPair, ce, kMu, kV), solve_relaxed_steady(p, kPair, cp, kMu, kV));
}

// The mix corrections' directions (lib/tangential/relaxed_mix_table.h): theta, the angle of the creepage vector in
// levels u = G a b (C11 xi, C22 eta, C23 sqrt(ab) phi) / (3 mu N) from the xi axis, psi that of (eta, phi) in their
// plane (0: eta, 90: phi); psi over [0, 180) (the mirror y -> -y gives the rest), xi >= 0 (its sign's symmetry)
const std::vector<double> kMixTheta = {0, 15, 30, 45, 60, 75, 90};
const std::vector<double> kMixPsi = {0, 22.5, 45, 67.5, 90, 112.5, 135, 157.5};
// and its levels: the creepage factors' (kFitE) with one in the linear range (Mz under eta there) and one more
// where the forces of -xi, eta, -phi nearly cancel
const std::vector<double> kMixE = {0.005, 0.05, 0.1, 0.2, 0.3, 0.4, 0.475, 0.55, 0.7, 0.85};

// the creepages of level e in the direction (theta, psi) (degrees)
Creepages in_direction(const ContactPatch& p, double theta_deg, double psi_deg, double e) {
  const double t = theta_deg * kPi / 180, s = psi_deg * kPi / 180;
  const Creepages x = at_level(p, 0, 1), y = at_level(p, 1, 1), z = at_level(p, 2, 1);
  return {e * std::cos(t) * x.xi, e * std::sin(t) * std::cos(s) * y.eta, e * std::sin(t) * std::sin(s) * z.phi_per_m};
}

// the error of a model's steady solution against the exact one, in units of the targets: Fx and Fy over 2 % of
// the exact |(Fx, Fy)|, Mz over 5 % of the exact |Mz| (floored at 1e-3 |(Fx, Fy)| sqrt(ab), where Mz vanishes)
std::array<double, 3> in_targets(const TangentialSolution& m, const TangentialSolution& ex, const ContactPatch& p) {
  const double Fn = std::hypot(ex.Fx_N, ex.Fy_N);
  const double Mzs = std::max(std::abs(ex.Mz_N_m), 1e-3 * Fn * std::sqrt(p.a_m * p.b_m));
  return {(m.Fx_N - ex.Fx_N) / (0.02 * Fn), (m.Fy_N - ex.Fy_N) / (0.02 * Fn), (m.Mz_N_m - ex.Mz_N_m) / (0.05 * Mzs)};
}

// "M ab theta psi e Dxi Deta Dphi score0 score1 Fx Fy Mz": the relaxed model's mix correction per unit level D (the
// correction d = D e, lib/tangential/relaxed.h) at each direction and level e that meets the exact Fx, Fy, Mz:
// Levenberg-Marquardt on the three corrections (a square system), from the previous level's D (continuation in e),
// with a small pull towards it (smoothness where several fit). score0, score1: the largest error in units of the
// targets (in_targets) without a correction and with the fitted one; Fx Fy Mz: the exact solver's.
// Levenberg-Marquardt on the knobs `active` of the mix correction d (levels) from `start` so that resid(d) (errors
// in target units) vanishes, pulled with weight w towards no correction; returns d
template <class Resid>
Eigen::Vector4d fit_knobs(const Resid& resid, const Eigen::Vector4d& start, const Eigen::Vector4d& active, double w,
                          double step_h) {
  using V4 = Eigen::Vector4d;
  const V4 d_prev = V4::Zero();  // the pull is towards no correction: the least one that fits, smooth over directions
  auto cost = [&](const V4& dd, Eigen::VectorXd& r) {
    r = resid(dd);
    return r.squaredNorm() + (w * (dd - d_prev)).squaredNorm();
  };
  V4 d = start.cwiseProduct(active);
  Eigen::VectorXd r;
  double f = cost(d, r), lambda = 1e-3;
  for (int it = 0; it < 60 && r.cwiseAbs().maxCoeff() > 0.05; ++it) {
    Eigen::MatrixXd J(r.size(), 4);
    for (int k = 0; k < 4; ++k) {
      V4 dk = d;
      dk(k) += step_h * active(k);
      J.col(k) = active(k) != 0 ? Eigen::VectorXd((resid(dk) - r) / step_h) : Eigen::VectorXd::Zero(r.size());
    }
    // (J'J + w^2 + lambda diag) step = -(J'r + w^2 (d - d_prev)), on the active knobs
    Eigen::Matrix4d A = J.transpose() * J + w * w * Eigen::Matrix4d::Identity();
    const V4 g = (J.transpose() * r + w * w * (d - d_prev)).cwiseProduct(active);
    bool improved = false;
    for (int tries = 0; tries < 12 && !improved; ++tries) {
      Eigen::Matrix4d Md = A;
      Md.diagonal() *= 1 + lambda;
      const V4 dn = d + Md.ldlt().solve(-g).cwiseProduct(active);
      Eigen::VectorXd rn;
      const double fn = cost(dn, rn);
      if (fn < f) {
        d = dn, r = rn, f = fn, lambda = std::max(lambda / 3, 1e-9), improved = true;
      } else {
        lambda *= 4;
      }
    }
    if (!improved) break;
  }
  return d;
}

// "M ab theta psi e Dxi Deta Dphi,lat Dphi,long score0 score1 Fx Fy Mz": the relaxed model's mix correction per unit
// level D (the correction d = D e, lib/tangential/relaxed.h) at each direction and level e that meets the exact Fx,
// Fy, Mz: Levenberg-Marquardt on the four corrections, from the previous level's D (continuation in e), pulled
// towards none (among the corrections that fit, a small one: smooth over the directions and levels where it can be). score0, score1: the
// largest error in units of the targets (in_targets) without a correction and with the fitted one; Fx Fy Mz: the
// exact solver's. Without spin (psi = 0) also "N ab theta e Dxi Deta Dmoment score": the correction without the
// spin's parts (so that the march keeps its mirror skip and has no spin: the cost of a solve without spin), fitted
// to the exact Fx and Fy, and the exact Mz less that march's per unit level, in units of mu N sqrt(ab), which the
// model adds to its Mz.
void fit_mix(double ab, int n) {
  const ContactPatch p = ellipse_patch(ab, n);
  const double G = combined_shear_modulus_Pa(kPair), nu = combined_poisson(kPair);
  const double kPull = std::getenv("FIT_PULL") ? std::atof(std::getenv("FIT_PULL")) : 0.1;  // weight of |d - d_prev| / e
  using V4 = Eigen::Vector4d;
  for (double theta : kMixTheta)
    for (double psi : kMixPsi) {
      if (theta == 0 && psi != 0) continue;  // pure xi: one direction
      V4 D = V4::Zero(), Dn = V4::Zero();
      for (double e : kMixE) {
        const Creepages c = in_direction(p, theta, psi, e);
        const ExactSolution ex = solve_exact_steady(p, G, nu, c, kMu, kV);
        auto model = [&](const V4& d) {
          return solve_relaxed_steady_with_mix(p, kPair, c, {d(0), d(1), d(2), d(3)}, kMu, kV);
        };
        auto resid = [&](const V4& d) {
          const auto r = in_targets(model(d), ex.fields, p);
          return Eigen::VectorXd(Eigen::Vector3d(r[0], r[1], r[2]));
        };
        const double score0 = resid(V4::Zero()).cwiseAbs().maxCoeff();
        // pure xi and pure spin: none (the pure creepages' factors hold them; the spin's fitted down to its linear
        // range, below the levels here)
        const bool pure = theta == 0 || (theta == 90 && psi == 90);
        const V4 d = pure ? V4::Zero() : fit_knobs(resid, D * e, V4(1, 1, 1, 1), std::sqrt(kPull) / e, 1e-4 * e);
        D = d / e;
        std::printf("M %g %g %g %.4f %.5f %.5f %.5f %.5f %.3f %.3f %.6e %.6e %.6e %s\n", ab, theta, psi, e, D(0), D(1),
                    D(2), D(3), score0, resid(d).cwiseAbs().maxCoeff(), ex.fields.Fx_N, ex.fields.Fy_N, ex.fields.Mz_N_m,
                    ex.status.converged() ? "" : "unconverged");
        if (psi == 0) {  // without spin: xi and eta only, to Fx and Fy; then the ratio of the exact Mz to the march's
          auto resid2 = [&](const V4& dd) {
            const auto r = in_targets(model(dd), ex.fields, p);
            return Eigen::VectorXd(Eigen::Vector2d(r[0], r[1]));
          };
          const V4 dn = theta > 0 ? fit_knobs(resid2, Dn * e, V4(1, 1, 0, 0), std::sqrt(kPull) / e, 1e-4 * e) : V4::Zero();
          Dn = dn / e;
          const TangentialSolution m = model(dn);
          const double unit = kMu * p.normal_load_N * std::sqrt(p.a_m * p.b_m) * e;  // mu N sqrt(ab) e
          const double moment = theta > 0 ? (ex.fields.Mz_N_m - m.Mz_N_m) / unit : 0.0;
          TangentialSolution mr = m;
          mr.Mz_N_m += moment * unit;
          const auto r = in_targets(mr, ex.fields, p);
          std::printf("N %g %g %.4f %.5f %.5f %.5f %.3f\n", ab, theta, e, Dn(0), Dn(1), moment,
                      std::max({std::abs(r[0]), std::abs(r[1]), std::abs(r[2])}));
        }
        std::fflush(stdout);
      }
    }
}

// "C ab theta psi e errFx errFy errMz (simplified) errFx errFy errMz (relaxed)": the relaxed model as compiled at
// directions and levels between the fitted ones, against the exact solver, in % (Fx, Fy of |(Fx, Fy)|, Mz of |Mz|)
void check_mix(double ab, int n) {
  const ContactPatch p = ellipse_patch(ab, n);
  const double G = combined_shear_modulus_Pa(kPair), nu = combined_poisson(kPair);
  const double dirs[][2] = {{33, 20}, {60, 110}, {80, 160}, {15, 70}, {54.7356, 45}, {54.7356, 135}, {75, 60}};
  for (const auto& dir : dirs)
    for (double e : {0.15, 0.45, 0.65}) {
      const Creepages c = in_direction(p, dir[0], dir[1], e);
      const ExactSolution ex = solve_exact_steady(p, G, nu, c, kMu, kV);
      SteadyOptions o;
      o.fields = false;
      const TangentialSolution s = solve_steady(p, make_tangential_problem(p, kPair, c, kMu, kV), TangentialScheme::Consistent, o);
      const TangentialSolution r = solve_relaxed_steady(p, kPair, c, kMu, kV, false);
      const auto es = in_targets(s, ex.fields, p), er = in_targets(r, ex.fields, p);
      std::printf("C %g %g %g %.2f  %+.1f %+.1f %+.1f  %+.1f %+.1f %+.1f %s\n", ab, dir[0], dir[1], e, 2 * es[0], 2 * es[1],
                  5 * es[2], 2 * er[0], 2 * er[1], 5 * er[2], ex.status.converged() ? "" : "unconverged");
      std::fflush(stdout);
    }
}

// "X ab n case steady_consistent_us steady_relaxed_us ratio step_satran_us step_relaxed_us ratio step_moving_us ratio":
// the relaxed model against the consistent steady solve and Satran's shift step (fields off), medians of
// interleaved repetitions (the machine is shared: the ratios, not the times, are the measure); step_moving: a
// relaxed step with both stages relaxing (from the steady state at half the creepages), over the settled one
void cost(double ab, int n, int reps) {
  const ContactPatch p = ellipse_patch(ab, n);
  const double dx = p.grid.dx_m;
  for (const Labelled& l : steady_cases(p)) {
    if (l.label != "xi50" && l.label != "eta50" && l.label != "phi50" && l.label != "mix50" && l.label != "mixneg90")
      continue;
    std::vector<double> tc, tr, ts, tq, tt;
    SteadyOptions o;
    o.fields = false;
    const TangentialProblem pr = make_tangential_problem(p, kPair, l.c, kMu, kV);
    TransientState st = rest_state(p.grid);
    RelaxedState rs = relaxed_steady_state(l.c);
    // a step in a transient (from the steady state at half the creepages: both stages relaxing, the second
    // stage's corrections made)
    const RelaxedState half = relaxed_steady_state({l.c.xi / 2, l.c.eta / 2, l.c.phi_per_m / 2});
    const StepKinematics kin{dx / kV, dx, l.c.xi * dx, l.c.eta * dx, l.c.phi_per_m * dx};
    double sink = 0;
    for (int k = 0; k < reps; ++k) {
      auto t0 = std::chrono::steady_clock::now();
      sink += solve_steady(p, pr, TangentialScheme::Consistent, o).Fx_N;
      tc.push_back(ms_since(t0));
      t0 = std::chrono::steady_clock::now();
      sink += solve_relaxed_steady(p, kPair, l.c, kMu, kV, false).Fx_N;
      tr.push_back(ms_since(t0));
      t0 = std::chrono::steady_clock::now();
      sink += satran_step(p, pr, kin, TransientScheme::Shift, st).Fx_N;
      ts.push_back(ms_since(t0));
      t0 = std::chrono::steady_clock::now();
      sink += relaxed_step(p, kPair, l.c, kMu, kV, dx, rs, false).Fx_N;
      tq.push_back(ms_since(t0));
      RelaxedState moving = half;
      t0 = std::chrono::steady_clock::now();
      sink += relaxed_step(p, kPair, l.c, kMu, kV, dx, moving, false).Fx_N;
      tt.push_back(ms_since(t0));
    }
    auto med = [](std::vector<double> v) {
      std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
      return 1e3 * v[v.size() / 2];
    };
    const double c = med(tc), r = med(tr), s = med(ts), q = med(tq), t = med(tt);
    std::printf("X %g %d %s %.1f %.1f %.2f %.1f %.1f %.2f %.1f %.2f %s\n", ab, n, l.label.c_str(), c, r, r / c, s, q,
                q / s, t, t / q, sink == 0.123 ? "!" : "");
  }
}

// "Z dir ab sigma/a p maxerr unconverged": the relaxation length sigma0 and exponent p (sigma = sigma0 (1 - e_eff)^p)
// of direction dir that fit the exact start-up from rest at 50 % and 90 % of saturation best: the largest
// |F_model/F_model,ss - F_exact/F_exact,ss| over q <= 8a, both levels (the shapes: the steady forces are the
// creepage factors' business)
void fit_sigma(double ab, int n, int dir) {
  const ContactPatch p = ellipse_patch(ab, n);
  const double G = combined_shear_modulus_Pa(kPair), nu = combined_poisson(kPair), dx = p.grid.dx_m, a = p.a_m;
  const int steps = static_cast<int>(std::lround(8 * a / dx));
  std::vector<std::vector<double>> ex;
  std::vector<Creepages> cs;
  int unconverged = 0;
  for (double k : {0.5, 0.9}) {
    const double w[3] = {dir == 0 ? 1.0 : 0, dir == 1 ? 1.0 : 0, dir == 2 ? 1.0 : 0};
    const Creepages c = level(p, k, w[0], w[1], w[2]);
    cs.push_back(c);
    std::vector<double> f;
    ExactSolution prev;
    for (int s = 1; s <= steps; ++s) {
      ExactSolution e = solve_exact_rolling_step(p, G, nu, c, kMu, kV, s == 1 ? nullptr : &prev, exact_run_options());
      unconverged += !e.status.converged();
      f.push_back(force_of(e.fields, dir));
      prev = std::move(e);
    }
    const ExactSolution ss = solve_exact_steady(p, G, nu, c, kMu, kV);
    unconverged += !ss.status.converged();
    f.push_back(force_of(ss.fields, dir));  // the steady force last
    ex.push_back(f);
  }
  double best_s = 0, best_p = 0, best_err = 1e300;
  for (double pw = 0; pw <= 3.0 + 1e-9; pw += 0.25)
    for (double sig = 0.3; sig <= 5.0 + 1e-9; sig += 0.05) {
      double err = 0;
      for (std::size_t l = 0; l < cs.size(); ++l) {
        const double ss = force_of(solve_relaxed_steady(p, kPair, cs[l], kMu, kV, false), dir);
        RelaxedState st = relaxed_rest();
        (dir == 0 ? st.sigma_m.xi : dir == 1 ? st.sigma_m.eta : st.sigma_m.phi_per_m) = sig * a;
        st.exponent = pw;
        for (int s = 1; s <= steps; ++s) {
          const TangentialSolution r = relaxed_step(p, kPair, cs[l], kMu, kV, dx, st, false);
          err = std::max(err, std::abs(force_of(r, dir) / ss - ex[l][s - 1] / ex[l].back()));
        }
      }
      if (err < best_err) best_err = err, best_s = sig, best_p = pw;
    }
  std::printf("Z %d %g %.3f %.3f %.5f %d\n", dir, ab, best_s, best_p, best_err, unconverged);
}


// "R ab s_phi1 s_phi2 A_phi K_phi err_phi s_eta2 K_eta err_eta unconverged": the transient law's second stage
// (lib/tangential/relaxed.h): fitted to the exact start-ups from rest under pure phi and pure eta at 50 % and 90 %
// of saturation over q <= 8a. Spin: the first and second stages' lengths, A_phi and K_phi together, err_phi the
// largest of |Fy/Fy_ss model - exact| and |Mz/Mz_ss model - exact| over q and both levels; eta: its second stage
// and K_eta (its first stage is the table's, fitted on Fy), err_eta Mz's. A and K enter Fy and Mz linearly: for
// each pair of lengths the run is made once and they are scanned over it.
void fit_transient(double ab, int n) {
  const ContactPatch p = ellipse_patch(ab, n);
  const double G = combined_shear_modulus_Pa(kPair), nu = combined_poisson(kPair), dx = p.grid.dx_m, a = p.a_m;
  const int steps = static_cast<int>(std::lround(8 * a / dx));
  const double muN = kMu * p.normal_load_N, sab = std::sqrt(p.a_m * p.b_m);
  int unconverged = 0;
  struct Run {
    Creepages c;
    std::vector<double> Fy, Mz;  // exact over the steps, as shares of the exact steady value
    double Fy_ss = 0, Mz_ss = 0;  // the model's steady
  };
  auto exact_runs = [&](int dir) {
    std::vector<Run> v;
    for (double k : {0.5, 0.9}) {
      Run r;
      r.c = level(p, k, 0, dir == 1 ? 1.0 : 0, dir == 2 ? 1.0 : 0);
      const ExactSolution ss = solve_exact_steady(p, G, nu, r.c, kMu, kV);
      unconverged += !ss.status.converged();
      ExactSolution prev;
      for (int s = 1; s <= steps; ++s) {
        ExactSolution e = solve_exact_rolling_step(p, G, nu, r.c, kMu, kV, s == 1 ? nullptr : &prev, exact_run_options());
        unconverged += !e.status.converged();
        r.Fy.push_back(e.fields.Fy_N / ss.fields.Fy_N);
        r.Mz.push_back(e.fields.Mz_N_m / ss.fields.Mz_N_m);
        prev = std::move(e);
      }
      const TangentialSolution m = solve_relaxed_steady(p, kPair, r.c, kMu, kV, false);
      r.Fy_ss = m.Fy_N;
      r.Mz_ss = m.Mz_N_m;
      v.push_back(r);
    }
    return v;
  };
  // the model's run at the lengths s1 (first stage, 0: the table's), s2 with A = K = 0: Fy, Mz and the second
  // stage's factors hF, hM (dFy = A hF, dMz = K hM), each as shares of the model's steady value
  struct Model {
    std::vector<double> Fy, Mz, hF, hM;
  };
  const KalkerCoefficients C = kalker_coefficients(p.a_m, p.b_m, nu);
  const double unit = 3 * kMu * p.normal_load_N / (G * p.a_m * p.b_m);
  auto model_run = [&](const Run& r, int dir, double s1, double s2) {
    Model m;
    RelaxedState st = relaxed_rest();
    if (dir == 2 && s1 > 0) st.sigma_m.phi_per_m = s1 * a;
    (dir == 1 ? st.sigma2_m.eta : st.sigma2_m.phi_per_m) = s2 * a;
    st.moment_eta = st.moment_phi = st.force_phi = 0;
    for (int s = 1; s <= steps; ++s) {
      const TangentialSolution f = relaxed_step(p, kPair, r.c, kMu, kV, dx, st, false);
      m.Fy.push_back(f.Fy_N / r.Fy_ss);
      m.Mz.push_back(f.Mz_N_m / r.Mz_ss);
      const Creepages& c1 = st.effective;
      const double u1[3] = {c1.xi * C.C11 / unit, c1.eta * C.C22 / unit, c1.phi_per_m * sab * C.C23 / unit};
      const double e1 = std::sqrt(u1[0] * u1[0] + u1[1] * u1[1] + u1[2] * u1[2]);
      const double slope = std::pow(1 - std::min(e1, 1.0), 2);
      const double du = dir == 1 ? (st.lagged.eta - c1.eta) * C.C22 / unit
                                 : (st.lagged.phi_per_m - c1.phi_per_m) * sab * C.C23 / unit;  // lag - eff
      m.hF.push_back(slope * du * muN / r.Fy_ss);
      m.hM.push_back(slope * (dir == 1 ? du : -du) * muN * sab / r.Mz_ss);
    }
    return m;
  };
  // the best coefficient for Fy (moment false) or Mz over the runs: (coefficient, error)
  auto best = [&](const std::vector<Run>& rs, const std::vector<Model>& ms, bool moment) {
    double bk = 0, be = 1e300;
    for (double K = -6; K <= 6 + 1e-9; K += 0.02) {
      double e = 0;
      for (std::size_t l = 0; l < rs.size() && e < be; ++l)
        for (int s = 0; s < steps; ++s)
          e = std::max(e, moment ? std::abs(ms[l].Mz[s] + K * ms[l].hM[s] - rs[l].Mz[s])
                                 : std::abs(ms[l].Fy[s] + K * ms[l].hF[s] - rs[l].Fy[s]));
      if (e < be) be = e, bk = K;
    }
    return std::pair<double, double>{bk, be};
  };
  const std::vector<Run> phi = exact_runs(2), eta = exact_runs(1);
  double bp[5] = {0, 0, 0, 0, 1e300};
  for (double s1 = 0.1; s1 <= 4.0 + 1e-9; s1 += 0.1)
    for (double s2 = 0.1; s2 <= 3.0 + 1e-9; s2 += 0.1) {
      std::vector<Model> ms;
      for (const Run& r : phi) ms.push_back(model_run(r, 2, s1, s2));
      const auto [A, eF] = best(phi, ms, false);
      const auto [K, eM] = best(phi, ms, true);
      if (std::max(eF, eM) < bp[4]) bp[0] = s1, bp[1] = s2, bp[2] = A, bp[3] = K, bp[4] = std::max(eF, eM);
    }
  double be[3] = {0, 0, 1e300};
  for (double s2 = 0.1; s2 <= 3.0 + 1e-9; s2 += 0.05) {
    std::vector<Model> ms;
    for (const Run& r : eta) ms.push_back(model_run(r, 1, 0, s2));
    const auto [K, e] = best(eta, ms, true);
    if (e < be[2]) be[0] = s2, be[1] = K, be[2] = e;
  }
  std::printf("R %g %.3f %.3f %.3f %.3f %.5f %.3f %.3f %.5f %d\n", ab, bp[0], bp[1], bp[2], bp[3], bp[4], be[0], be[1],
              be[2], unconverged);
}

// the relaxed model's transient knobs from the environment (RELAXED_S1PHI, RELAXED_S2PHI, RELAXED_S2ETA in units of
// a, RELAXED_APHI, RELAXED_KPHI, RELAXED_KETA): in place of the table's where set (for trying the law, scripts/fit-relaxed)
void knobs_from_env(RelaxedState& st, double a) {
  auto get = [](const char* k, double& v) {
    if (const char* e = std::getenv(k)) v = std::atof(e);
  };
  double s1 = 0, s2 = 0, s2e = 0;
  get("RELAXED_S1PHI", s1);
  get("RELAXED_S2PHI", s2);
  get("RELAXED_S2ETA", s2e);
  st.sigma_m.phi_per_m = s1 * a;
  st.sigma2_m.phi_per_m = s2 * a;
  st.sigma2_m.eta = s2e * a;
  get("RELAXED_KPHI", st.moment_phi);
  get("RELAXED_KETA", st.moment_eta);
  get("RELAXED_APHI", st.force_phi);
}

// "Q q/a exact Fx Fy Mz relaxed Fx Fy Mz": a held-out run of tests/heldout_test.cpp traced (nu on both bodies, the
// share k of saturation, the direction u in levels; AXIS -1 a start from rest, 0-2 a step of xi, eta, phi from the
// steady state at that creepage times FACTOR), 40 x 40 cells to 12a; the exact steady forces first ("Q 0 ...")
void held_trace(double ab, int n, double nu, double k, const double u[3], int axis, double factor) {
  const ContactPatch p = ellipse_patch(ab, n);
  const ElasticPair pair{{210e9, nu}, {210e9, nu}};
  const double G = combined_shear_modulus_Pa(pair), nuc = combined_poisson(pair), dx = p.grid.dx_m;
  const KalkerCoefficients C = kalker_coefficients(p.a_m, p.b_m, nuc);
  const double e = 1 - std::cbrt(1 - k), unit = 3 * kMu * p.normal_load_N / (G * p.a_m * p.b_m);
  const Creepages c1{e * u[0] * unit / C.C11, e * u[1] * unit / C.C22,
                     e * u[2] * unit / (std::sqrt(p.a_m * p.b_m) * C.C23)};
  Creepages c0 = c1;
  if (axis == 0) c0.xi *= factor;
  if (axis == 1) c0.eta *= factor;
  if (axis == 2) c0.phi_per_m *= factor;
  const ExactSolution ss = solve_exact_steady(p, G, nuc, c1, kMu, kV);
  const TangentialSolution ms = solve_relaxed_steady(p, pair, c1, kMu, kV, false);
  std::printf("Q 0 %.6e %.6e %.6e %.6e %.6e %.6e\n", ss.fields.Fx_N, ss.fields.Fy_N, ss.fields.Mz_N_m, ms.Fx_N, ms.Fy_N,
              ms.Mz_N_m);
  ExactSolution prev;
  bool have = false;
  RelaxedState st = relaxed_rest();
  if (axis >= 0) {
    if (with_exact()) prev = solve_exact_steady(p, G, nuc, c0, kMu, kV);
    have = true;
    st = relaxed_steady_state(c0);
  }
  knobs_from_env(st, p.a_m);
  const int steps = static_cast<int>(std::lround(12 * p.a_m / dx));
  for (int s = 1; s <= steps; ++s) {
    double ex[3] = {0, 0, 0};
    if (with_exact()) {
      ExactSolution x = solve_exact_rolling_step(p, G, nuc, c1, kMu, kV, have ? &prev : nullptr, exact_run_options());
      ex[0] = x.fields.Fx_N, ex[1] = x.fields.Fy_N, ex[2] = x.fields.Mz_N_m;
      prev = std::move(x);
      have = true;
    }
    const TangentialSolution m = relaxed_step(p, pair, c1, kMu, kV, dx, st);
    std::printf("Q %.4f %.6e %.6e %.6e %.6e %.6e %.6e\n", s * dx / p.a_m, ex[0], ex[1], ex[2], m.Fx_N, m.Fy_N, m.Mz_N_m);
  }
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: fast_model_report steady AB N | startup AB N K | step AB N xi|eta|phi\n");
    return 2;
  }
  const std::string what = argv[1];
  const double ab = std::atof(argv[2]);
  const int n = std::atoi(argv[3]);
  const ContactPatch p = ellipse_patch(ab, n);
  const double G = combined_shear_modulus_Pa(kPair), nu = combined_poisson(kPair);
  if (what == "fit") {
    fit_factors(ab, n);
  } else if (what == "cost") {
    cost(ab, n, argc >= 5 ? std::atoi(argv[4]) : 200);
  } else if (what == "heldtrace" && argc >= 11) {
    const double u[3] = {std::atof(argv[6]), std::atof(argv[7]), std::atof(argv[8])};
    held_trace(ab, n, std::atof(argv[4]), std::atof(argv[5]), u, std::atoi(argv[9]), std::atof(argv[10]));
  } else if (what == "fittransient") {
    fit_transient(ab, n);
  } else if (what == "fitmix") {
    fit_mix(ab, n);
  } else if (what == "checkmix") {
    check_mix(ab, n);
  } else if (what == "checkspin") {
    check_spin(ab, n);
  } else if (what == "linear") {
    linear_limit(ab, n);
  } else if (what == "fitspin") {
    fit_spin(ab, n);
  } else if (what == "fitsigma" && argc >= 5) {
    const std::string dir = argv[4];
    fit_sigma(ab, n, dir == "xi" ? 0 : dir == "eta" ? 1 : 2);
  } else if (what == "steady") {
    const char* only = std::getenv("FAST_MODEL_CASES");  // a comma-separated list of labels: only those
    for (const Labelled& l : steady_cases(p)) {
      if (only && ("," + std::string(only) + ",").find("," + l.label + ",") == std::string::npos) continue;
      auto t0 = std::chrono::steady_clock::now();
      if (with_exact()) {
        const ExactSolution e = solve_exact_steady(p, G, nu, l.c, kMu, kV);
        const double ms_e = ms_since(t0);
        if (!e.status.converged())
          std::printf("# exact %s not converged: %s\n", l.label.c_str(), e.status.message.c_str());
        print_steady("exact", ab, n, l.label, l.c, e.fields, ms_e);
      }
      t0 = std::chrono::steady_clock::now();
      const TangentialSolution s = solve_steady(p, make_tangential_problem(p, kPair, l.c, kMu, kV));
      print_steady("simplified", ab, n, l.label, l.c, s, ms_since(t0));
      t0 = std::chrono::steady_clock::now();
      const TangentialSolution r = solve_relaxed_steady(p, kPair, l.c, kMu, kV);
      print_steady("relaxed", ab, n, l.label, l.c, r, ms_since(t0));
    }
  } else if (what == "startup" && argc >= 5) {
    const double k = std::atof(argv[4]);
    const Creepages c = level(p, k, 1, 0, 0);
    transient(ab, n, "startup" + std::string(k < 0.7 ? "50" : "90"), [c](double) { return c; }, 20 * p.a_m, false);
  } else if (what == "step" && argc >= 5) {
    const std::string dir = argv[4];
    const double w[3] = {dir == "xi" ? 1.0 : 0, dir == "eta" ? 1.0 : 0, dir == "phi" ? 1.0 : 0};
    const Creepages c0 = level(p, 0.5, w[0], w[1], w[2]), c1 = level(p, 0.9, w[0], w[1], w[2]);
    transient(ab, n, "step" + dir, [c0, c1](double q) { return q <= 0 ? c0 : c1; }, 12 * p.a_m, true);
  } else {
    std::fprintf(stderr, "fast_model_report: unknown mode %s\n", what.c_str());
    return 2;
  }
}
