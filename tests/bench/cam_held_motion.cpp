// What holding the roller's motion, the loads and the kinematics at the unworn revolution costs at the end of
// a cam's life (docs/cam-follower.md, "What is outside the model"). A plain program:
//   cam_held_motion CASE.yaml [DIR [TABLE.csv]]
//   cam_held_motion CASE.yaml life     two whole lives (fixed depth steps of 1e-6 m, cold evaluations): the
//       life's, the motion held, and one that solves the revolution and the roller's motion on the worn lift
//       (3. and 4. below) at every evaluation
// 1. sets up the case's life (the unworn periodic revolution and the roller's motion: what the life holds);
// 2. the worn state at the end of the life: the last wear map of DIR/snapshots (a `rollwear run CASE -o DIR`
//    folder), else the case's life run here with fixed depth steps of 1e-6 m (its limits; docs §15);
// 3. the worn cam's lift: the follower's centre lowered at every angle step by the lift loss, the recession of
//    the bodies' surfaces along the contact normal over cos phi (cam_life.h lift_loss_m, docs §12), the lift
//    law a periodic quintic spline through those values (make_table_law: s' and s'' are the spline's, a
//    smoothed finite difference of the worn lift); the same spline through the unworn lift, as a control;
// 4. on each lift, the revolution (run_revolution: kinematics, phi, loads, contact) and the roller's periodic
//    motion (periodic_motion), then the quasi-steady dissipation of the worn state as the life computes it
//    (worn_revolution_dissipation's loop, cold, the strips fixed by the held revolution);
// 5. prints the largest change of F_n, phi, s'' and of the dissipation (the revolution's energy, each angle
//    step's energy) against the held values; TABLE.csv, if named, gets them per angle step. The wear's own effect is the worn spline against the unworn one
//    (the spline's error cancels); the unworn spline against the held law is that error.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "cam/cam_case.h"
#include "cam/cam_life.h"
#include "cam/creep_law.h"
#include "cam/revolution_dissipation.h"
#include "tests/bench/cam_bench_life.h"

namespace {

namespace fs = std::filesystem;
constexpr double kDeg = 57.29577951308232;

double cpu_s() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// the life's quasi-steady dissipation of state s on revolution r with motion (worn_revolution_dissipation's
// loop, cam/cam_life.cpp), its strips fixed by the held revolution's narrowest contact: all three revolutions
// are evaluated on the same strips, so that only the kinematics, loads and motion differ
cam::RevolutionDissipation dissipation(const cam::CamModel& m, const cam::Revolution& r, const cam::RollerMotion& motion,
                                       const contact::Profiles& unworn, const cam::CamWearGrid& g,
                                       const cam::CamWearState& s, const cam::CreepLawSettings& fixed) {
  const double duration = 2 * contact::kPi / m.angle_steps / m.omega_rad_per_s;
  cam::RevolutionDissipation out;
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const cam::RevolutionRow& row = r.rows[i];
    const contact::Profiles worn = cam::worn_profiles_at(unworn, g, s, row.contact_arc_m);
    const cam::AngleContact c =
        cam::angle_contact(m.bodies, worn, m.geometry.roller_radius_m, row.kin, motion.angles[i].normal_N, m.mu, fixed);
    cam::RollerAngle roller = motion.angles[i];
    const cam::CreepageForForce xi = cam::creepage_for_force(c, roller.tangential_N);
    if (xi.found) {
      roller.xi = xi.xi;
      roller.slip_speed_m_per_s = xi.xi * roller.speed_m_per_s;
    }
    out.push_back(cam::angle_dissipation(c, row, roller, duration));
  }
  return out;
}

struct Lift {
  const char* name;
  cam::CamModel model;
  cam::Revolution revolution;
  cam::PeriodicMotion motion;
  cam::RevolutionDissipation worn;  // the dissipation of the worn state on this lift
};

// the largest changes of the kinematics and loads of b against a, per angle step
void compare_loads(const Lift& a, const Lift& b) {
  double dFn = 0, dFn_rel = 0, dphi = 0, dd2s = 0, d2s_max = 0, dFt = 0, at_Fn = 0, at_phi = 0;
  std::vector<double> rel;
  for (std::size_t k = 0; k < a.revolution.rows.size(); ++k) {
    const cam::RevolutionRow &ra = a.revolution.rows[k], &rb = b.revolution.rows[k];
    const double Fa = a.motion.motion.angles[k].normal_N, Fb = b.motion.motion.angles[k].normal_N;
    if (std::abs(Fb - Fa) > dFn) {
      dFn = std::abs(Fb - Fa);
      at_Fn = ra.kin.theta_rad;
    }
    rel.push_back(std::abs(Fb / Fa - 1));
    dFn_rel = std::max(dFn_rel, rel.back());
    dFt = std::max(dFt, std::abs(b.motion.motion.angles[k].tangential_N - a.motion.motion.angles[k].tangential_N));
    const double p = std::abs(rb.kin.pressure_angle_rad - ra.kin.pressure_angle_rad);
    if (p > dphi) {
      dphi = p;
      at_phi = ra.kin.theta_rad;
    }
    dd2s = std::max(dd2s, std::abs(rb.kin.lift.d2s_m_per_rad2 - ra.kin.lift.d2s_m_per_rad2));
    d2s_max = std::max(d2s_max, std::abs(ra.kin.lift.d2s_m_per_rad2));
  }
  std::sort(rel.begin(), rel.end());
  std::printf("%s against %s:\n", b.name, a.name);
  std::printf("  F_n: largest change %.4g N at cam angle %.1f deg, %.3g of the local F_n (median %.2g, 90 %% of the "
              "steps below %.2g); F_t: %.3g N at most\n",
              dFn, at_Fn * kDeg, dFn_rel, rel[rel.size() / 2], rel[rel.size() * 9 / 10], dFt);
  std::printf("  phi: largest change %.3g deg at cam angle %.1f deg\n", dphi * kDeg, at_phi * kDeg);
  std::printf("  s'': largest change %.3g m/rad^2 (%.3g of max |s''| %.4g)\n", dd2s, dd2s / d2s_max, d2s_max);
}

// the change of the dissipation b against a: the revolution's energy, an angle step's power
void compare_dissipation(const char* what, const cam::RevolutionDissipation& a, const cam::RevolutionDissipation& b) {
  double dP = 0, P_max = 0, at_P = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double Pa = cam::total_power_W(a[k]), Pb = cam::total_power_W(b[k]);
    P_max = std::max(P_max, std::abs(Pa));
    if (std::abs(Pb - Pa) > dP) {
      dP = std::abs(Pb - Pa);
      at_P = a[k].theta_rad;
    }
  }
  const double Ea = cam::dissipation_totals(a).energy_J, Eb = cam::dissipation_totals(b).energy_J;
  std::printf("  %-44s revolution %.6g J against %.6g J (%+.3g %%); an angle step's power by %.3g of the peak at "
              "most (cam angle %.1f deg)\n",
              what, Eb, Ea, 100 * (Eb / Ea - 1), dP / P_max, at_P * kDeg);
}

// the lift at the angle steps through a periodic quintic spline (make_table_law, not refused: the fit's
// departure from the lift's central differences, of their largest, is returned in fit), and its revolution and
// roller's periodic motion; throws std::runtime_error on a jump or a motion that is not periodic
Lift lift_through_spline(const char* name, const cam::CamModel& base, const std::vector<double>& lift,
                         const cam::RollerDynamicsSettings& dynamics, double& fit) {
  Lift l{name, base, {}, {}, {}};
  l.model.law = cam::make_table_law(lift, std::numeric_limits<double>::max());
  const double h = 2 * contact::kPi / static_cast<double>(lift.size());
  const std::size_t n = lift.size();
  double dev = 0, cd_max = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double cd = (lift[(k + 1) % n] - 2 * lift[k] + lift[(k + n - 1) % n]) / (h * h);
    cd_max = std::max(cd_max, std::abs(cd));
    dev = std::max(dev, std::abs(cam::lift_at(l.model.law, static_cast<double>(k) * h).d2s_m_per_rad2 - cd));
  }
  fit = dev / cd_max;
  l.revolution = cam::run_revolution(l.model);
  if (l.revolution.status != cam::RevolutionStatus::Complete) throw std::runtime_error(std::string(name) + ": the follower jumps");
  l.motion = cam::periodic_motion(l.model, l.revolution, dynamics);
  if (!l.motion.converged) throw std::runtime_error(std::string(name) + ": the roller's motion is not periodic");
  return l;
}

// the worn cam's lift on state s: the unworn revolution's lift less the lift loss at each angle step
std::vector<double> worn_lift_of(const cam::CamLifeSetup& u, const cam::CamWearState& s) {
  const cam::Revolution& r = u.revolution;
  const Eigen::ArrayXd loss = cam::lift_loss_m(u.unworn_profiles, u.life.grid, s, cam::lift_loss_samples(r));
  std::vector<double> lift(r.rows.size());
  for (std::size_t k = 0; k < r.rows.size(); ++k) lift[k] = r.rows[k].kin.lift.s_m - loss(static_cast<Eigen::Index>(k));
  return lift;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: cam_held_motion CASE.yaml [DIR [TABLE.csv] | life]\n");
    return 2;
  }
  spdlog::set_level(spdlog::level::warn);
  try {
    const cam::CamCase c = cam::read_cam_case(argv[1]);
    if (!c.wear) {
      std::fprintf(stderr, "%s: no cam.wear section\n", argv[1]);
      return 2;
    }
    const cam::RollerDynamicsSettings dynamics = cam::roller_dynamics_of(c.solver);  // as rollwear run reads the case
    double t0 = cpu_s();
    const std::unique_ptr<cam::CamLifeSetup> setup = cam::set_up_cam_life(c.name, c.model, *c.wear, dynamics);
    const cam::CamWearGrid& g = setup->life.grid;
    std::printf("set-up (unworn periodic revolution): %.2f s CPU\n", cpu_s() - t0);

    // the strips of the held revolution (the life's), for every dissipation below
    double b_min = std::numeric_limits<double>::infinity();
    for (const cam::RevolutionRow& row : setup->revolution.rows) b_min = std::min(b_min, row.contact.b_m);
    const cam::CreepLawSettings fixed =
        cam::worn_contact_settings(setup->unworn_profiles, g, dynamics.law, 2 * b_min / dynamics.law.grid.ny);

    if (argc > 2 && std::string(argv[2]) == "life") {
      // two whole lives, fixed depth steps of 1e-6 m, cold evaluations: the life's (the motion held) and one
      // whose every evaluation solves the revolution and the roller's motion on the worn lift again
      const cam::CamLifeModel model = bench::cam_bench_life(*setup).model;
      const auto unworn = [](const cam::CamWearState& st) {
        return (st.cam_depth_m == 0).all() && (st.roller_depth_m == 0).all();
      };
      const cam::DissipationOf held_rate = [&](const cam::CamWearState& st) {
        if (unworn(st)) return setup->unworn;
        return dissipation(setup->model, setup->revolution, setup->motion.motion, setup->unworn_profiles, g, st, fixed);
      };
      const cam::DissipationOf resolved_rate = [&](const cam::CamWearState& st) {
        if (unworn(st)) return setup->unworn;
        double fit = 0;
        const Lift l = lift_through_spline("worn lift", setup->model, worn_lift_of(*setup, st), dynamics, fit);
        return dissipation(l.model, l.revolution, l.motion.motion, setup->unworn_profiles, g, st, fixed);
      };
      double N_held = 0;
      for (const auto& [name, rate] : {std::pair<const char*, const cam::DissipationOf*>{"motion held", &held_rate},
                                       {"motion on the worn lift", &resolved_rate}}) {
        t0 = cpu_s();
        const cam::CamLifeResult life = cam::run_cam_life(model, *rate);
        if (N_held == 0) N_held = life.N;
        std::printf("%-24s life %.6g revolutions (%+.2f %%), ended by %s, %ld steps, %ld evaluations, dissipated %.6g "
                    "J, max depth %.4g m; %.1f s CPU\n",
                    name, life.N, 100 * (life.N / N_held - 1), wear::to_string(life.ended_by).c_str(), life.steps,
                    life.revolutions_solved, life.energy_J, life.max_depth_m, cpu_s() - t0);
        if (life.ended_by == wear::LifeEnd::Failed) std::printf("  %s\n", life.message.c_str());
      }
      return 0;
    }

    // the worn state at the end of the life
    cam::CamWearState s;
    if (argc > 2) {
      std::string which;
      s = bench::cam_state_of_folder(argv[2], g, which);
      std::printf("worn state: %s\n", which.c_str());
    } else {
      const bench::CamBenchLife b = bench::cam_bench_life(*setup);
      const cam::CamLifeModel& model = b.model;
      t0 = cpu_s();
      const cam::CamLifeResult life = cam::run_cam_life(model, b.producer);
      if (life.ended_by == wear::LifeEnd::Failed || life.ended_by == wear::LifeEnd::NotRun) {
        std::fprintf(stderr, "the life failed: %s\n", life.message.c_str());
        return 1;
      }
      s = life.state;
      std::printf("worn state: the life with fixed depth steps of 1e-6 m, %.6g revolutions, ended by %s (%.1f s CPU)\n",
                  life.N, wear::to_string(life.ended_by).c_str(), cpu_s() - t0);
    }
    const cam::Revolution& r = setup->revolution;
    const cam::LiftLoss loss_max = cam::max_lift_loss(setup->unworn_profiles, g, s, cam::lift_loss_samples(r));
    std::printf("max depth: track %.4g m, roller %.4g m; max lift loss %.4g m at cam angle %.1f deg\n",
                s.cam_depth_m.maxCoeff(), s.roller_depth_m.maxCoeff(), loss_max.max_m, loss_max.at_theta_rad * kDeg);

    // the unworn and the worn lift at the angle steps, each through a periodic quintic spline
    const Eigen::ArrayXd loss = cam::lift_loss_m(setup->unworn_profiles, g, s, cam::lift_loss_samples(r));
    std::vector<double> unworn_lift(r.rows.size());
    for (std::size_t k = 0; k < r.rows.size(); ++k) unworn_lift[k] = r.rows[k].kin.lift.s_m;
    Lift held{"held (the life's)", setup->model, r, setup->motion, {}};
    double fit_unworn = 0, fit_worn = 0;
    Lift spline = lift_through_spline("unworn lift, spline", setup->model, unworn_lift, dynamics, fit_unworn);
    Lift worn = lift_through_spline("worn lift, spline", setup->model, worn_lift_of(*setup, s), dynamics, fit_worn);
    for (const Lift* l : {&spline, &worn})
      std::printf("%s: the spline's s'' departs from the central differences by %.3g of their largest; "
                  "periodic after %d revolutions, sliding at %d of %zu steps\n",
                  l->name, l == &worn ? fit_worn : fit_unworn, l->motion.revolutions, l->motion.sliding_steps,
                  l->revolution.rows.size());

    compare_loads(spline, worn);  // the wear's effect on the kinematics and loads
    compare_loads(held, spline);  // the spline's own error

    // the dissipation on each, on the strips of the held revolution (as the life's): on the worn state, and on
    // the unworn surfaces (s = 0, where the semi-Hertzian load equation has one root)
    const cam::CamWearState unworn_surfaces = cam::unworn_state(g);
    for (const cam::CamWearState* state : {static_cast<const cam::CamWearState*>(&s), &unworn_surfaces}) {
      t0 = cpu_s();
      for (Lift* l : {&held, &spline, &worn})
        l->worn = dissipation(l->model, l->revolution, l->motion.motion, setup->unworn_profiles, g, *state, fixed);
      std::printf("dissipation on %s (%.1f s CPU):\n",
                  state == &s ? "the worn state" : "the unworn surfaces, s = 0", cpu_s() - t0);
      if (state == &s) {
        const cam::RevolutionDissipation ref = cam::worn_revolution_dissipation(
            setup->model, r, setup->motion.motion, setup->unworn_profiles, g, s, dynamics.law);
        compare_dissipation("held: the life's worn_revolution_dissipation", ref, held.worn);
      }
      compare_dissipation("the worn lift against the unworn (splines)", spline.worn, worn.worn);
      compare_dissipation("the unworn spline against the held law", held.worn, spline.worn);
      // control: the held revolution with every F_n scaled by 1 + eps, the dissipation's own sensitivity
      for (const double eps : {1e-4, -1e-4, 1e-3, -1e-3}) {
        cam::RollerMotion scaled = held.motion.motion;
        for (cam::RollerAngle& a : scaled.angles) a.normal_N *= 1 + eps;
        char name[64];
        std::snprintf(name, sizeof name, "control: the held F_n x (1 %+g)", eps);
        compare_dissipation(name, held.worn,
                            dissipation(held.model, held.revolution, scaled, setup->unworn_profiles, g, *state, fixed));
      }
      if (state == &s && argc > 3) {
        std::ofstream out(argv[3]);
        out << "cam_angle_deg,lift_loss_m,d2s_held_m_per_rad2,d2s_worn_m_per_rad2,normal_held_N,normal_worn_N,"
               "phi_held_deg,phi_worn_deg,power_held_W,power_worn_W\n";
        for (std::size_t k = 0; k < r.rows.size(); ++k) {
          char line[512];
          std::snprintf(line, sizeof line, "%.6g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n",
                        r.rows[k].kin.theta_rad * kDeg, loss(static_cast<Eigen::Index>(k)),
                        spline.revolution.rows[k].kin.lift.d2s_m_per_rad2,
                        worn.revolution.rows[k].kin.lift.d2s_m_per_rad2, spline.motion.motion.angles[k].normal_N,
                        worn.motion.motion.angles[k].normal_N, spline.revolution.rows[k].kin.pressure_angle_rad * kDeg,
                        worn.revolution.rows[k].kin.pressure_angle_rad * kDeg, cam::total_power_W(spline.worn[k]),
                        cam::total_power_W(worn.worn[k]));
          out << line;
        }
      }
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cam_held_motion: %s\n", e.what());
    return 1;
  }
}
