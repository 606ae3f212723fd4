// The contact model seam (lib/model/contact_model.h): every tangential scheme has its row, and the seam's
// solves are the models' own solvers to the bit, so that the commands, the wear loop and the cam, which call
// only the seam, solve what each model's own tests check.
#include "lib/model/contact_model.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lib/elastic.h"
#include "lib/normal/hertz.h"
#include "lib/tangential/exact.h"
#include "lib/tangential/relaxed.h"
#include "lib/tangential/steady.h"

namespace contact {
namespace {

const ElasticPair kSteel{{210e9, 0.28}, {210e9, 0.28}};
constexpr double kMu = 0.3, kV = 1.0;
constexpr TangentialScheme kSchemes[] = {TangentialScheme::Classic, TangentialScheme::Consistent,
                                         TangentialScheme::Exact, TangentialScheme::Relaxed};

// the paper's contact (cases/paper.yaml): Hertz, 1500 N
ContactPatch paper_patch(int n) {
  const Bodies bodies{{20e-3, 500e-3}, {25e-3, kFlat}};
  return solve_normal_hertz(bodies, kSteel, 1500, {n, n});
}

void expect_same(const TangentialSolution& a, const TangentialSolution& b) {
  EXPECT_EQ(a.Fx_N, b.Fx_N);
  EXPECT_EQ(a.Fy_N, b.Fy_N);
  EXPECT_EQ(a.Mz_N_m, b.Mz_N_m);
  EXPECT_EQ(a.power_W, b.power_W);
  EXPECT_EQ(a.creep_work_W, b.creep_work_W);
  ASSERT_EQ(a.strip_power_W_per_m.size(), b.strip_power_W_per_m.size());
  EXPECT_TRUE((a.strip_power_W_per_m == b.strip_power_W_per_m).all());
}

// Every scheme the case reader names has a model (its traits), and its name reads back; the transient
// summary names the exact theory's run by the model, the others by their transient scheme.
TEST(ContactModel, EverySchemeHasItsModel) {
  for (const TangentialScheme s : kSchemes) {
    EXPECT_NO_THROW(tangential_traits(s)) << to_string(s);
    EXPECT_EQ(parse_tangential_scheme(to_string(s)), s);
  }
  EXPECT_EQ(transient_run_name(TangentialScheme::Exact, TransientScheme::Shift), "exact");
  EXPECT_EQ(transient_run_name(TangentialScheme::Relaxed, TransientScheme::Shift), "shift");
  EXPECT_EQ(transient_run_name(TangentialScheme::Consistent, TransientScheme::Upwind), "upwind");
  // the cam takes the relaxed model, the simplified theory's consistent scheme and the exact theory
  EXPECT_TRUE(tangential_traits(TangentialScheme::Relaxed).cam);
  EXPECT_TRUE(tangential_traits(TangentialScheme::Consistent).cam);
  EXPECT_FALSE(tangential_traits(TangentialScheme::Classic).cam);
  EXPECT_TRUE(tangential_traits(TangentialScheme::Exact).cam);
}

// The steady solve through the seam is each model's own solver, to the bit; the exact theory's reported
// problem has no simplified coefficients (nan) and its solve's status.
TEST(ContactModel, SteadySolveIsEachModelsOwnSolver) {
  const ContactPatch patch = paper_patch(16);
  const Creepages k{1e-3, 2e-4, 0.5};
  const TangentialProblem problem = make_tangential_problem(patch, kSteel, k, kMu, kV);
  SteadyOptions options;
  options.fields = false;
  for (const TangentialScheme s : {TangentialScheme::Classic, TangentialScheme::Consistent}) {
    const SteadyModelSolution m = solve_tangential_steady(s, patch, kSteel, problem, false);
    EXPECT_TRUE(m.status.converged());
    expect_same(m.solution, solve_steady(patch, problem, s, options));
    EXPECT_EQ(m.problem.C.C11, problem.C.C11);
  }
  expect_same(solve_tangential_steady(TangentialScheme::Relaxed, patch, kSteel, problem, false).solution,
              solve_relaxed_steady(patch, kSteel, k, kMu, kV, false));
  const SteadyModelSolution exact = solve_tangential_steady(TangentialScheme::Exact, patch, kSteel, problem, false);
  const ExactSolution e =
      solve_exact_steady(patch, combined_shear_modulus_Pa(kSteel), combined_poisson(kSteel), k, kMu, kV);
  ASSERT_TRUE(exact.status.converged()) << exact.status.message;
  EXPECT_EQ(exact.status.message, e.status.message);
  expect_same(exact.solution, e.fields);
  EXPECT_TRUE(std::isnan(exact.problem.C.C11) && std::isnan(exact.problem.L_m_per_Pa));
}

// The cam's pure-xi factors: the relaxed model's slope and saturation level, 1 for the simplified theory.
TEST(ContactModel, PureXiFactorsAreTheRelaxedModelsOrOne) {
  const ContactPatch patch = paper_patch(16);
  EXPECT_EQ(xi_slope_factor(TangentialScheme::Relaxed, patch), relaxed_xi_slope_factor(patch));
  EXPECT_EQ(xi_saturation_factor(TangentialScheme::Relaxed, patch), relaxed_xi_saturation_level(patch));
  EXPECT_EQ(xi_slope_factor(TangentialScheme::Consistent, patch), 1.0);
  EXPECT_EQ(xi_saturation_factor(TangentialScheme::Consistent, patch), 1.0);
}

}  // namespace
}  // namespace contact
