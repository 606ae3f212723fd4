// A roller's life with a lubricant (wear/wear_loop.h WearModel::lubrication, docs/lubrication-and-temperature.md §2):
// the regime law at the unworn contact's film sets the life's mu and wear factor, per condition of a collective. A
// boundary film is the dry life with mu_b to the bit; a full film wears at the full-film factor (the life longer by
// its inverse, to the integrator's tolerance); each condition takes the law at its own film; bad sections refused.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "lib/errors.h"
#include "lib/io/case_run.h"
#include "lib/lubrication/regime.h"
#include "tests/temp_dir.h"
#include "tests/test_text.h"
#include "wear/collective.h"
#include "wear/dang_van_life.h"
#include "wear/wear_loop.h"
#include "wear/wear_output.h"

namespace wear {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = ROLLWEAR_SOURCE_DIR;

class WearLubrication : public rollwear_test::TempDirTest {
 protected:
  WearCase read(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return read_wear_case(p.string());
  }
};

// the shipped paper-wear case on a 40 x 40 grid to a 10 um depth, with `lubricant` (a section, or empty) and the
// friction mu given; its film is h_min 0.09 um at 1 m/s
std::string paper_wear(const std::string& lubricant, const std::string& mu = "0.3", const std::string& extra = "") {
  return rollwear_test::replaced(rollwear_test::read_text(kSource / "cases" / "paper-wear.yaml"),
                                 {{"nx: 80, ny: 80", "nx: 40, ny: 40"},
                                  {"max_depth_m: 1.0e-4", "max_depth_m: 1.0e-5"},
                                  {"friction:   { mu: 0.3 }", "friction:   { mu: " + mu + " }\n" + lubricant},
                                  {"  snapshots_revolutions: [1.0e7, 3.0e7, 1.0e8]\n", extra}});
}

std::string lubricant(const std::string& Rq, const std::string& full_film_factor = "0.0") {
  return "lubricant:\n  viscosity_Pa_s: 0.01\n  pressure_viscosity_1_per_Pa: 2.0e-8\n"
         "  roughness_Rq_m: { body1: " + Rq + ", body2: " + Rq + " }\n"
         "  friction: { boundary: 0.3, mixed: 0.1, full_film: 0.05 }\n"
         "  wear_factor: { boundary: 1.0, mixed: 0.5, full_film: " + full_film_factor + " }\n";
}

LifeResult life_of(const WearCase& c) {
  const WearModel m = make_wear_model(c);
  WearCache cache;
  return run_life(m, c, LifeStart{}, LifeHooks{}, cache);
}

// Rough surfaces (Rq 0.3 um each: lambda 0.2): boundary, mu_b = 0.3 and the factor 1. The lubricated case with
// friction.mu 0.1 lives the dry case's life with mu 0.3, to the bit.
TEST_F(WearLubrication, BoundaryFilmIsTheDryLifeWithTheBoundaryFriction) {
  const WearCase lub = read("lub.yaml", paper_wear(lubricant("0.3e-6"), "0.1"));
  const WearCase dry = read("dry.yaml", paper_wear("", "0.3"));
  const WearModel m = make_wear_model(lub);
  ASSERT_TRUE(m.lubrication.has_value());
  EXPECT_LT(m.lubrication->lambda, 1);
  EXPECT_EQ(m.mu, 0.3);
  EXPECT_EQ(m.wear_factor, 1.0);
  const LifeResult a = life_of(lub), b = life_of(dry);
  EXPECT_NE(b.ended_by, LifeEnd::NotRun);
  EXPECT_EQ(a.ended_by, b.ended_by);
  EXPECT_EQ(a.N, b.N);
  ASSERT_EQ(a.state.size(), b.state.size());
  EXPECT_TRUE((a.state.array() == b.state.array()).all());
  // the report says what the life used
  WearReport r;
  r.case_name = "lub";
  r.life = a;
  const std::string text = wear_report_text(m, r);
  EXPECT_NE(text.find("lubrication_regime: boundary\n"), std::string::npos) << text;
  EXPECT_NE(text.find("mu_used: 0.3\n"), std::string::npos) << text;
  EXPECT_NE(text.find("wear_factor_used: 1\n"), std::string::npos) << text;
}

// Dang Van's index on the final worn contact (wear/dang_van_life.h) is solved with the friction the life ran on: the
// boundary regime's mu 0.3 of the lubricated case whose friction.mu is 0.1 gives the dry mu-0.3 life's index to the
// bit, and not the index at friction.mu 0.1 on the same worn state
TEST_F(WearLubrication, DangVanOnTheFinalContactTakesTheRegimesFriction) {
  const auto with_dang_van = [](std::string t) {
    const std::string roller = "body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28";
    const std::size_t at = t.find(roller);
    EXPECT_NE(at, std::string::npos);
    if (at != std::string::npos) t.insert(at + roller.size(), ", dang_van: { a: 0.3, b_Pa: 300.0e6 }");
    return t;
  };
  const WearCase lub = read("lub.yaml", with_dang_van(paper_wear(lubricant("0.3e-6"), "0.1")));
  const WearCase dry = read("dry.yaml", with_dang_van(paper_wear("", "0.3")));
  const WearCase dry_01 = read("dry01.yaml", with_dang_van(paper_wear("", "0.1")));
  const LifeResult a = life_of(lub), b = life_of(dry);
  ASSERT_TRUE((a.state.array() == b.state.array()).all());
  const std::vector<LifeDangVan> da = dang_van_on_worn(make_wear_model(lub), lub, a.state);
  const std::vector<LifeDangVan> db = dang_van_on_worn(make_wear_model(dry), dry, b.state);
  const std::vector<LifeDangVan> d01 = dang_van_on_worn(make_wear_model(dry_01), dry_01, a.state);
  ASSERT_EQ(da.size(), 1u);
  ASSERT_EQ(db.size(), 1u);
  ASSERT_EQ(d01.size(), 1u);
  EXPECT_EQ(da[0].field.index_max, db[0].field.index_max);
  EXPECT_GT(std::abs(da[0].field.index_max / d01[0].field.index_max - 1), 0.01)
      << da[0].field.index_max << " " << d01[0].field.index_max;
}

// Smooth surfaces (Rq 1 nm: lambda 60): full film, mu_f = 0.05 and the factor 0.25: four times the life with mu 0.05
// and no lubricant (the rate is a quarter of it at every state; the adaptive steps to their rtol of 1e-3).
TEST_F(WearLubrication, FullFilmWearsLessByTheFactor) {
  const WearCase lub = read("lub.yaml", paper_wear(lubricant("1.0e-9", "0.25"), "0.3"));
  const WearCase dry = read("dry.yaml", paper_wear("", "0.05"));
  const WearModel m = make_wear_model(lub);
  EXPECT_GT(m.lubrication->lambda, 3);
  EXPECT_EQ(m.mu, 0.05);
  EXPECT_EQ(m.wear_factor, 0.25);
  const LifeResult a = life_of(lub), b = life_of(dry);
  EXPECT_EQ(a.ended_by, b.ended_by);
  EXPECT_NEAR(a.N / b.N, 4.0, 4.0 * 3e-3);
}

// A collective at 1 and 20 m/s (h_min 0.09 and about 0.7 um; Rq 0.2 um each): the conditions' films differ, and
// each condition's model takes the law at its own lambda (lubrication_of on the condition's case).
TEST_F(WearLubrication, EachConditionOfACollectiveTakesTheLawAtItsOwnFilm) {
  const WearCase c = read("coll.yaml", paper_wear(lubricant("0.2e-6"), "0.3",
                                                  "  collective:\n    - { weight: 0.5 }\n"
                                                  "    - { weight: 0.5, kinematics: { speed_m_per_s: 20.0 } }\n"));
  const WearModel m = make_wear_model(c);
  ASSERT_EQ(m.conditions.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const WearCase ck = condition_case(c, k);
    contact::ContactCase unworn = ck.contact;
    unworn.solver.normal = contact::NormalChoice::Auto;
    const contact::ContactLubrication l = contact::lubrication_of(ck.contact, contact::solve_normal_of(unworn).patch);
    const contact::RegimeFriction r =
        contact::regime_friction(l.lambda, ck.contact.lubricant->by_regime, ck.contact.lubricant->thresholds);
    EXPECT_EQ(m.conditions[k].lubrication->lambda, l.lambda) << k;
    EXPECT_EQ(m.conditions[k].mu, r.mu) << k;
    EXPECT_EQ(m.conditions[k].wear_factor, r.wear_factor) << k;
  }
  EXPECT_LT(m.conditions[0].lubrication->lambda, 1);  // boundary at 1 m/s
  EXPECT_GT(m.conditions[1].lubrication->lambda, 1);  // mixed at 20 m/s
  EXPECT_LT(m.conditions[1].mu, m.conditions[0].mu);
  EXPECT_LT(m.conditions[1].wear_factor, m.conditions[0].wear_factor);
  WearReport rep;
  rep.case_name = "coll";
  rep.life = life_of(c);
  EXPECT_NE(rep.life.ended_by, LifeEnd::NotRun);
  const std::string text = wear_report_text(m, rep);
  EXPECT_NE(text.find("condition1_mu_used: 0.3\n"), std::string::npos) << text;
  EXPECT_NE(text.find("condition2_lubrication_regime: mixed\n"), std::string::npos) << text;
}

// A lubricant with a transient duty cycle, or with a dry-measured map law: refused at the key's line.
TEST_F(WearLubrication, RefusalsNameFileLineAndKey) {
  std::string t = paper_wear(lubricant("0.2e-6"));
  const std::string law = "body1: { law: archard, archard_k: 1.0e-4, hardness_Pa: 6.0e9 }";
  t.replace(t.find(law), law.size(), "body1: { law: usfd }");
  try {
    read("usfd.yaml", t);
    FAIL() << "accepted";
  } catch (const contact::CaseError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("usfd.yaml:"), std::string::npos) << m;
    EXPECT_NE(m.find("wear.body1.law, lubricant: the usfd law's map is measured on dry contacts"), std::string::npos)
        << m;
  }
}

}  // namespace
}  // namespace wear
