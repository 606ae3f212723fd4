// Rolling-contact fatigue in the wear life (wear/fatigue.h, docs/fatigue.md): Burstow's function against its
// published breakpoints and straight lines, Miner's sum against its closed form (constant conditions: D = N d, the
// located fatigue life 1/d), the shipped case's competition of wear and fatigue, the shakedown margin against
// Johnson's map, and the section's keys refused with file, line and key.
#include "wear/fatigue.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "lib/errors.h"
#include "lib/io/case_run.h"
#include "lib/subsurface/shakedown.h"
#include "wear/dang_van_life.h"
#include "wear/wear_case.h"
#include "wear/wear_loop.h"
#include "wear/wear_output.h"
#include "tests/test_text.h"

namespace wear {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = ROLLWEAR_SOURCE_DIR;

using rollwear_test::read_text;

// the shipped fatigue case's text with one piece replaced
std::string fatigue_case_text(const std::string& from = "", const std::string& to = "") {
  std::string text = read_text(kSource / "cases" / "paper-wear-fatigue.yaml");
  if (!from.empty()) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  return text;
}

WearCase case_of(const std::string& text) { return read_wear_case_text(text, "fatigue.yaml", kSource / "cases"); }

// Published: Burstow's function as the straight lines of its tabulation (docs/fatigue.md), no damage up to 20 N,
// 2.22e-7 Tg - 4.44e-6 up to 65 N, -9.09e-8 Tg + 1.59e-5 up to 175 N, none beyond; the lines' coefficients are
// rounded to 3 digits, so they agree with the breakpoints' form to 1e-8 (0.1 % of the peak).
TEST(Fatigue, BurstowFunctionReproducesItsPublishedBreakpointsAndLines) {
  const BurstowFunction f;
  EXPECT_EQ(burstow_damage_per_pass(f, 0), 0);
  EXPECT_EQ(burstow_damage_per_pass(f, 20), 0);
  EXPECT_DOUBLE_EQ(burstow_damage_per_pass(f, 65), 1e-5);
  EXPECT_EQ(burstow_damage_per_pass(f, 175), 0);
  EXPECT_EQ(burstow_damage_per_pass(f, 500), 0);
  EXPECT_EQ(burstow_damage_per_pass(f, -3), 0);
  EXPECT_EQ(burstow_damage_per_pass(f, std::nan("")), 0);
  for (double Tg = 20; Tg <= 65; Tg += 2.5)
    EXPECT_NEAR(burstow_damage_per_pass(f, Tg), 2.22e-7 * Tg - 4.44e-6, 1e-8) << Tg;
  for (double Tg = 65; Tg <= 175; Tg += 5)
    EXPECT_NEAR(burstow_damage_per_pass(f, Tg), -9.09e-8 * Tg + 1.59e-5, 1e-8) << Tg;
  // its keys move the breakpoints
  const BurstowFunction g{15, 50, 100, 2e-5};
  EXPECT_DOUBLE_EQ(burstow_damage_per_pass(g, 32.5), 1e-5);
  EXPECT_DOUBLE_EQ(burstow_damage_per_pass(g, 75), 1e-5);
  EXPECT_THROW(validate(BurstowFunction{65, 20, 175, 1e-5}), contact::SettingError);
  EXPECT_THROW(validate(BurstowFunction{20, 65, 175, 0}), contact::SettingError);
}

// Closed form (Miner under constant conditions): with the wear made negligible (archard_k 1e-16: depths of 1e-17 m,
// the contact the same to 1e-12) every pass does the same damage d_i at node i, so D_i = N d_i at every step and
// the life ends by fatigue at N = 1 / max d_i, located by the integrator's root finding (its tolerance is 1e-13 of
// N; a root left at a step's end misses it by the step, here up to 2e4 revolutions).
TEST(Fatigue, DamageUnderConstantConditionsIsRevolutionsTimesDamagePerPassAndItsLifeIsLocated) {
  WearCase c = case_of(fatigue_case_text("archard_k: 1.0e-4", "archard_k: 1.0e-16"));
  c.contact.solver.nx = c.contact.solver.ny = 40;
  c.contact.solver.normal = contact::NormalChoice::SemiHertz;  // one normal model, worn or not
  c.wear.snapshots_revolutions.clear();
  c.wear.limits.edge = false;
  const WearModel m = make_wear_model(c);
  ASSERT_GT(m.nD, 0);
  WearCache cache;
  const WearRate r = wear_rate(m, initial_state(m), cache);
  const Eigen::VectorXd d = r.dstate_dN.segment(m.damage_index(), m.nD) / m.damage_scale_m;
  const double d_max = d.maxCoeff();
  ASSERT_GT(d_max, 1e-7);  // inside Burstow's damaging range (T-gamma of tens of N)
  EXPECT_GT(r.contact.max_tgamma_N, 20);
  EXPECT_LT(r.contact.max_tgamma_N, 175);
  long checked = 0;
  LifeHooks hooks;
  hooks.on_step = [&](const LifeStep& s) {
    const Eigen::VectorXd D = s.state->segment(m.damage_index(), m.nD) / m.damage_scale_m;
    for (int i = 0; i < m.nD; ++i) EXPECT_NEAR(D(i), s.N * d(i), 1e-9 * s.N * d_max) << "node " << i << " N " << s.N;
    ++checked;
    return true;
  };
  WearCache life_cache;
  const LifeResult life = run_life(m, c, LifeStart{}, hooks, life_cache);
  EXPECT_EQ(life.ended_by, LifeEnd::Fatigue) << life.message;
  EXPECT_NEAR(life.N * d_max, 1.0, 1e-9) << "N " << life.N << ", 1/d " << 1 / d_max;
  EXPECT_NEAR(max_damage(m, life.state), 1.0, 1e-9);
  EXPECT_GT(checked, 0);
  EXPECT_LT(max_depth_m(m, life.state), 1e-15);
}

// Per strip, T-gamma_j = w e_j (wear/fatigue.h): the width-weighted mean of the strips' T-gamma over the contact is
// the contact's dissipated power over its speed, P/V (its T-gamma), to rounding
TEST(Fatigue, StripTgammaAveragesToTheContactsTgamma) {
  WearCase c = case_of(fatigue_case_text());
  c.contact.solver.nx = c.contact.solver.ny = 40;
  const WearModel m = make_wear_model(c);
  WearCache cache;
  const WearRate r = wear_rate(m, initial_state(m), cache);
  const NormalState n = solved_normal_state(m, initial_state(m), cache);
  const double w = n.contact_y_max_m - n.contact_y_min_m;
  const Eigen::ArrayXd Tg = strip_tgamma_N(r.strip_energy_J_per_m, 2 * M_PI * m.reference_radius_m, w);
  const double mean = (Tg * r.strip_dy_m).sum() / w;
  EXPECT_NEAR(mean / (r.contact.power_W / m.speed_m_per_s), 1.0, 1e-12);
  EXPECT_NEAR(Tg.maxCoeff(), r.contact.max_tgamma_N, 1e-12 * r.contact.max_tgamma_N);
}

// The shipped case: at 10 % slip the roller's surface reaches damage 1 before the wear reaches its depth limit;
// the report gives the other mode's margin (the depth's fraction of its limit) at that moment. At 5 % slip the
// competition turns: the edge limit ends the life with the damage short of 1.
TEST(Fatigue, ShippedCaseEndsByFatigueWithTheDepthsMarginAndSlowerSlipByWearWithTheDamages) {
  WearCase c = case_of(fatigue_case_text());
  c.contact.solver.nx = c.contact.solver.ny = 40;
  const WearModel m = make_wear_model(c);
  WearCache cache;
  const LifeResult life = run_life(m, c, LifeStart{}, {}, cache);
  EXPECT_EQ(life.ended_by, LifeEnd::Fatigue) << life.message;
  EXPECT_NEAR(max_damage(m, life.state), 1.0, 1e-9);
  const double depth_fraction = max_depth_m(m, life.state) / c.wear.limits.max_depth_m;
  EXPECT_GT(depth_fraction, 0.1);
  EXPECT_LT(depth_fraction, 1.0);
  WearReport report;
  report.case_name = m.name;
  report.life = life;
  const std::string text = wear_report_text(m, report);
  EXPECT_NE(text.find("ended_by: fatigue\n"), std::string::npos) << text;
  EXPECT_NE(text.find("max_damage: 1"), std::string::npos) << text;
  EXPECT_NE(text.find("depth_fraction: 0."), std::string::npos) << text;

  WearCase slow = case_of(fatigue_case_text("xi: 0.1,", "xi: 0.05,"));
  slow.contact.solver.nx = slow.contact.solver.ny = 40;
  const WearModel ms = make_wear_model(slow);
  WearCache cs;
  const LifeResult ls = run_life(ms, slow, LifeStart{}, {}, cs);
  EXPECT_TRUE(ls.ended_by == LifeEnd::Edge || ls.ended_by == LifeEnd::MaxDepth) << ls.message;
  EXPECT_GT(max_damage(ms, ls.state), 0.1);
  EXPECT_LT(max_damage(ms, ls.state), 1.0);
}

// Johnson's map (lib/subsurface/shakedown.h): the report's shakedown margin is limit(f) / (p0/k) - 1 of the end's
// contact, f = |Fx|/Fz; with wear.limits.shakedown and a k that puts the unworn load beyond the map, the life ends
// there at its start; with a k that keeps it inside, it goes on to its other limits
TEST(Fatigue, ShakedownMarginIsJohnsonsAndEndsTheLifeWhenAsked) {
  for (const double k_Pa : {2.0e8, 5.0e8}) {
    WearCase c = case_of(fatigue_case_text("body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28 }",
                                           "body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28, shear_yield_Pa: " +
                                               std::to_string(k_Pa) + " }"));
    c.contact.solver.nx = c.contact.solver.ny = 40;
    c.wear.limits.shakedown = true;
    const WearModel m = make_wear_model(c);
    WearCache cache;
    const WearRate r = wear_rate(m, initial_state(m), cache);
    const double f = std::abs(r.contact.Fx_N) / m.normal_load_N;
    const double limit = contact::shakedown_limit_p0_over_k(contact::shakedown_contact_of(r.contact.a_m, r.contact.b_m), f);
    EXPECT_NEAR(r.contact.shakedown_margin, limit * k_Pa / r.contact.p0_Pa - 1, 1e-12);
    WearCache life_cache;
    const LifeResult life = run_life(m, c, LifeStart{}, {}, life_cache);
    if (r.contact.shakedown_margin < 0) {
      EXPECT_EQ(life.ended_by, LifeEnd::Shakedown) << life.message;
      EXPECT_EQ(life.N, 0);
    } else {
      EXPECT_NE(life.ended_by, LifeEnd::Shakedown) << life.message;
      EXPECT_GT(life.contact.shakedown_margin, 0);
    }
  }
}

// Blok's criterion in the life (lib/thermal, docs/lubrication-and-temperature.md): the scuffing margin is
// critical - (bulk + flash); with wear.limits.scuffing a critical temperature (100 C) below the unworn contact's
// (80 C bulk + about 26 K flash) ends the life there, one far above it lets the life run on with a positive margin (the
// worn contact spreads its heat: the flash temperature falls as the crown wears)
TEST(Fatigue, ScuffingMarginIsBloksAndEndsTheLifeWhenAsked) {
  const std::string thermal =
      "thermal:\n"
      "  body1: { conductivity_W_per_m_K: 46, density_kg_per_m3: 7850, specific_heat_J_per_kg_K: 470 }\n"
      "  body2: { conductivity_W_per_m_K: 46, density_kg_per_m3: 7850, specific_heat_J_per_kg_K: 470 }\n"
      "  bulk_temperature_C: 80\n  critical_temperature_C: CRIT\n";
  double unworn_rise = 0;  // K
  for (const double critical_C : {100.0, 1000.0}) {
    std::string text = fatigue_case_text() + thermal;
    text.replace(text.find("CRIT"), 4, std::to_string(critical_C));
    WearCase c = case_of(text);
    c.contact.solver.nx = c.contact.solver.ny = 24;
    c.wear.limits.scuffing = true;
    const WearModel m = make_wear_model(c);
    WearCache cache;
    const WearRate r = wear_rate(m, initial_state(m), cache);
    ASSERT_GT(r.contact.flash_rise_K, 1);
    EXPECT_NEAR(r.contact.scuffing_margin_K, critical_C - (80 + r.contact.flash_rise_K), 1e-9);
    unworn_rise = r.contact.flash_rise_K;
    // the same contact as `rollwear contact` solves it (lib/io/case_run.h): the same flash temperature
    const contact::ContactRun cr = contact::solve_contact_case(c.contact, false);
    ASSERT_TRUE(cr.thermal.has_value());
    EXPECT_NEAR(r.contact.flash_rise_K / cr.thermal->flash.max_rise_K, 1.0, 1e-12);
    WearCache life_cache;
    const LifeResult life = run_life(m, c, LifeStart{}, {}, life_cache);
    if (critical_C == 100.0) {
      EXPECT_LT(r.contact.scuffing_margin_K, 0);
      EXPECT_EQ(life.ended_by, LifeEnd::Scuffing) << life.message;
      EXPECT_EQ(life.N, 0);
    } else {
      EXPECT_NE(life.ended_by, LifeEnd::Scuffing) << life.message;
      EXPECT_GT(life.contact.scuffing_margin_K, 0);
      EXPECT_LT(life.contact.flash_rise_K, unworn_rise);
    }
  }
  std::cout << "unworn flash rise at 10 % slip: " << unworn_rise << " K\n";
}

// Bad keys: the reader's error names the file, the line and the key
TEST(Fatigue, BadKeysNameFileLineAndKey) {
  const auto message = [](const std::string& text) {
    try {
      case_of(text);
    } catch (const contact::CaseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string fatigue_line = "  fatigue: { law: burstow, threshold_N: 20, peak_at_N: 65, zero_at_N: 175, peak_damage: 1.0e-5 }";
  std::string m = message(fatigue_case_text(fatigue_line, "  fatigue: { law: wohler }"));
  EXPECT_NE(m.find("fatigue.yaml:27:"), std::string::npos) << m;
  EXPECT_NE(m.find("wear.fatigue.law: must be burstow, got 'wohler'"), std::string::npos) << m;
  m = message(fatigue_case_text(fatigue_line, "  fatigue: { law: burstow, peak_at_N: 10 }"));
  EXPECT_NE(m.find("fatigue.yaml:27:"), std::string::npos) << m;
  EXPECT_NE(m.find("wear.fatigue.peak_at_N: must be above threshold_N = 20"), std::string::npos) << m;
  m = message(fatigue_case_text(fatigue_line, "  fatigue: { law: burstow, peak_damage: 2 }"));
  EXPECT_NE(m.find("wear.fatigue.peak_damage: must be in (0, 1]"), std::string::npos) << m;
  m = message(fatigue_case_text(fatigue_line, "  fatigue: { law: burstow, treshold_N: 15 }"));
  EXPECT_NE(m.find("fatigue.yaml:27:"), std::string::npos) << m;
  EXPECT_NE(m.find("treshold_N"), std::string::npos) << m;
  m = message(fatigue_case_text(fatigue_line, "  fatigue: { threshold_N: 15 }"));
  EXPECT_NE(m.find("wear.fatigue.law"), std::string::npos) << m;
  m = message(fatigue_case_text("limits: { max_depth_m: 1.0e-4, edge: true }",
                                "limits: { max_depth_m: 1.0e-4, edge: true, shakedown: true }"));
  EXPECT_NE(m.find("fatigue.yaml:24:"), std::string::npos) << m;
  EXPECT_NE(m.find("wear.limits.shakedown, bodies.body1.shear_yield_Pa"), std::string::npos) << m;
}

// A load collective's Dang Van index is its conditions' largest, with that condition (1-based): each condition's own
// contact solved alone (solve_contact_case) gives the indices; the heavy condition (2500 N against 1500 N) the larger
TEST(Fatigue, DangVanOfACollectiveIsItsWorstConditions) {
  std::string text = read_text(kSource / "cases" / "collective-duty-mix.yaml");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28", "body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28, dang_van: { a: 0.3, b_Pa: 300.0e6 }");
  replace("nx: 40, ny: 40", "nx: 24, ny: 24");
  replace("{ weight: 0.70 }", "{ weight: 0.75 }");
  text = text.substr(0, text.find("    - weight: 0.05")) + text.substr(text.find("output:"));  // the transient condition
  const WearCase c = read_wear_case_text(text, "collective.yaml", kSource / "cases");
  ASSERT_EQ(c.wear.collective.size(), 2u);
  const WearModel m = make_wear_model(c);
  const std::vector<LifeDangVan> got = dang_van_on_worn(m, c, initial_state(m));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].body, 1);
  std::vector<double> alone;
  for (const WearCondition& k : c.wear.collective) {
    const contact::ContactRun run = contact::solve_contact_case(k.contact, true);
    alone.push_back(contact::subsurface_of_contact(k.contact, run)[0].dang_van->index_max);
  }
  EXPECT_GT(alone[1], alone[0]);
  EXPECT_EQ(got[0].condition, 2);
  EXPECT_EQ(got[0].field.index_max, alone[1]);
}

// Dang Van's index on a life's final worn contact is of steady rolling: with a transient duty cycle the key is
// refused at its line (wear/dang_van_life.h)
TEST(Fatigue, DangVanWithATransientDutyCycleIsRefusedAtItsKey) {
  std::string text = read_text(kSource / "cases" / "start-stop-wear.yaml");
  const std::string path = "body2: { Rx_m: 0.025, E_Pa: 210.0e9, nu: 0.28";
  ASSERT_NE(text.find(path), std::string::npos);
  text.insert(text.find(path) + path.size(), ", dang_van: { a: 0.3, b_Pa: 300.0e6 }");
  try {
    read_wear_case_text(text, "transient.yaml", kSource / "cases");
    ADD_FAILURE() << "a transient life with dang_van was read";
  } catch (const contact::CaseError& e) {
    EXPECT_EQ(e.location.key, "bodies.body2.dang_van");
    EXPECT_NE(std::string(e.what()).find("transient.yaml:17:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("steady rolling"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace wear
