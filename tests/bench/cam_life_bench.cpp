// The cost of a cam's worn revolution and of its life (docs/cam-follower.md §15). A plain program:
//   cam_life_bench CASE.yaml [worn_depth_m = 8e-6] [repeats = 5] [life-only]
//   cam_life_bench CASE.yaml map REFERENCE.csv ANGLE_STEPS STRIDE POWER_RTOL [ARC_CELLS]   a map's error (below)
//   cam_life_bench CASE.yaml life [variants = all [load_rtol|default [check_every]]]   the case's whole life (its own
//       stepping) with each of the savings on or off ("skip": both and the case's skip): life, evaluations, CPU; with
//       check_every, every check_every-th
//       evaluation compared with the cold revolution on the same state (angles on another root counted)
// 1. sets up the case's life (the unworn periodic revolution), CPU timed;
// 2. wears the case to worn_depth_m (Euler's fixed-depth steps of 1e-6 m, the producer with shared contacts and
//    warm starts, no skip, whatever the case's stepping and skip): a worn state;
// 3. on that state, CPU per revolution (median of the repeats) of worn_revolution_dissipation (cold: every
//    angle solved from scratch, the reference) and of WornRevolution with each saving on or off, a warm
//    evaluation taken on the state scaled by 1 + 1e-3 after one on the state itself (as the life's next
//    evaluation would), with the normal solves, F(delta) and creep-law evaluations per revolution and the
//    largest difference of a strip power (of the largest strip power) and of the energy against the reference.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "cam/cam_case.h"
#include "cam/cam_life.h"
#include "cam/revolution_dissipation.h"
#include "cam/worn_revolution.h"
#include "tests/bench/cam_bench_life.h"

namespace {

double cpu_s() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

// an angle whose contact is another one than the reference's (another root of the semi-Hertzian load
// equation, docs/cam-follower.md §15): its strip pressures differ by more than this of the largest, some
// thousand times what the solves' tolerances (load_rtol 1e-6, shared contacts 4e-5) leave
constexpr double kOtherContactRtol = 1e-3;

struct Difference {
  double power = 0, energy = 0;
  int other_contacts = 0;  // angles whose contact differs from the reference's by more than kOtherContactRtol
};
Difference difference(const cam::RevolutionDissipation& a, const cam::RevolutionDissipation& ref) {
  double pmax = 0, dmax = 0, qmax = 0;
  for (std::size_t k = 0; k < ref.size(); ++k) {
    pmax = std::max(pmax, ref[k].power_W_per_m.abs().maxCoeff());
    dmax = std::max(dmax, (a[k].power_W_per_m - ref[k].power_W_per_m).abs().maxCoeff());
    qmax = std::max(qmax, ref[k].mean_pressure_Pa.abs().maxCoeff());
  }
  int other = 0;
  for (std::size_t k = 0; k < ref.size(); ++k)
    if (a[k].mean_pressure_Pa.size() != ref[k].mean_pressure_Pa.size() ||
        (a[k].mean_pressure_Pa - ref[k].mean_pressure_Pa).abs().maxCoeff() > kOtherContactRtol * qmax)
      ++other;
  const double e = cam::dissipation_totals(a).energy_J, e_ref = cam::dissipation_totals(ref).energy_J;
  return {dmax / pmax, std::abs(e / e_ref - 1), other};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: cam_life_bench CASE.yaml [worn_depth_m] [repeats]\n");
    return 2;
  }
  spdlog::set_level(spdlog::level::warn);
  const bool whole_life = argc > 2 && std::string(argv[2]) == "life";
  const bool map_mode = argc > 2 && std::string(argv[2]) == "map";
  const double worn_depth = argc > 2 && !whole_life && !map_mode ? std::stod(argv[2]) : 8e-6;
  const int repeats = argc > 3 && !whole_life && !map_mode ? std::stoi(argv[3]) : 5;
  const bool life_only = argc > 4 && std::string(argv[4]) == "life-only";  // the life's evaluator alone (to profile)
  const cam::CamCase c = cam::read_cam_case(argv[1]);
  if (!c.wear) {
    std::fprintf(stderr, "%s: no cam.wear section\n", argv[1]);
    return 2;
  }
  const cam::RollerDynamicsSettings dynamics = cam::roller_dynamics_of(c.solver);  // as rollwear run reads the case

  if (map_mode) {
    // cam_life_bench CASE map REFERENCE.csv ANGLE_STEPS STRIDE POWER_RTOL: the wear map after 4e9 revolutions
    // on 180 x 56 cells, Euler's 32 and 64 steps of revolutions extrapolated, as the converged reference
    // tests/data/reference/cam-wear-map.csv is made (at 1440 angle steps, every angle solved), against it:
    // the largest error of each body's map, of its deepest wear
    if (argc < 7) {
      std::fprintf(stderr, "usage: cam_life_bench CASE map REFERENCE.csv ANGLE_STEPS STRIDE POWER_RTOL\n");
      return 2;
    }
    const int angle_steps = std::stoi(argv[4]);
    // ARC_CELLS (optional, 180 by default): on another map than the reference's, the skip's map is compared
    // with the map of every angle solved (stride 1), at 4e9 revolutions in 64 steps, on ARC_CELLS x 112 cells
    const int arc_cells = argc > 7 ? std::stoi(argv[7]) : 180;
    const auto map = [&](int steps, int stride = -1) {
      cam::CamModel model = c.model;
      model.angle_steps = angle_steps;
      cam::CamWearSpec spec = *c.wear;
      spec.arc_cells = arc_cells;
      spec.lateral_cells = arc_cells == 180 ? 56 : 112;
      spec.revolutions = 4e9;
      spec.max_depth_m = 1e-3;
      spec.max_lift_loss_m = 0;
      spec.stepping.method = wear::IntegratorOptions::Method::FixedStep;
      spec.stepping.step_revolutions = 4e9 / steps;
      spec.skip_stride = stride > 0 ? stride : std::stoi(argv[5]);
      spec.skip_power_rtol = std::stod(argv[6]);
      const std::unique_ptr<cam::CamLifeSetup> u = cam::set_up_cam_life(c.name, model, spec, dynamics);
      const cam::CamLifeResult life = cam::run_cam_life(u->life, u->producer());
      return life.state;
    };
    if (arc_cells != 180) {
      double t1 = cpu_s();
      const cam::CamWearState all = map(64, 1);
      const double cpu_all = cpu_s() - t1;
      t1 = cpu_s();
      const cam::CamWearState skip = map(64);
      std::printf("map at %d angle steps on %d x 112 cells, 4e9 revolutions in 64 steps: skip stride %s (power_rtol %s) "
                  "against every angle solved: largest difference %.4f of the track's deepest wear, %.4f of the "
                  "roller's (%.1f s CPU against %.1f s)\n",
                  angle_steps, arc_cells, argv[5], argv[6],
                  (skip.cam_depth_m - all.cam_depth_m).abs().maxCoeff() / all.cam_depth_m.maxCoeff(),
                  (skip.roller_depth_m - all.roller_depth_m).abs().maxCoeff() / all.roller_depth_m.maxCoeff(),
                  cpu_s() - t1, cpu_all);
      return 0;
    }
    const double t_map = cpu_s();
    const cam::CamWearState coarse = map(32), fine = map(64);
    const double cpu = cpu_s() - t_map;
    Eigen::ArrayXXd cam_ref(180, 56);
    Eigen::ArrayXd roller_ref(56);
    {
      std::FILE* in = std::fopen(argv[3], "r");
      if (!in) {
        std::fprintf(stderr, "cannot read %s\n", argv[3]);
        return 2;
      }
      char line[65536];
      int row = 0;
      while (std::fgets(line, sizeof line, in)) {
        if (line[0] == '#' || line[0] == '\n') continue;
        const bool is_cam = line[0] == 'c';
        char* p = line + (is_cam ? 3 : 6);
        for (int j = 0; j < 56; ++j) (is_cam ? cam_ref(row, j) : roller_ref(j)) = std::strtod(p, &p);
        if (is_cam) ++row;
      }
      std::fclose(in);
    }
    const Eigen::ArrayXXd cam = 2 * fine.cam_depth_m - coarse.cam_depth_m;
    const Eigen::ArrayXd roller = 2 * fine.roller_depth_m - coarse.roller_depth_m;
    std::printf("map at %d angle steps, skip stride %s (power_rtol %s), 4e9 revolutions: largest error %.4f of the "
                "track's deepest wear, %.4f of the roller's (Euler 32 and 64 steps extrapolated: %.1f s CPU)\n",
                angle_steps, argv[5], argv[6], (cam - cam_ref).abs().maxCoeff() / cam_ref.maxCoeff(),
                (roller - roller_ref).abs().maxCoeff() / roller_ref.maxCoeff(), cpu);
    return 0;
  }

  double t0 = cpu_s();
  const std::unique_ptr<cam::CamLifeSetup> setup = cam::set_up_cam_life(c.name, c.model, *c.wear, dynamics);
  std::printf("set-up (unworn periodic revolution): %.3f s CPU\n", cpu_s() - t0);

  if (whole_life) {
    const std::string which = argc > 3 ? argv[3] : "all";
    if (argc > 4 && std::string(argv[4]) != "default")
      setup->dynamics.law.normal_load_rtol = std::stod(argv[4]);  // the worn solves' load tolerance
    // every check_every-th worn evaluation also solved cold (worn_revolution_dissipation, history-free): the
    // angles whose contact is another root than the cold one's, counted (0: no check)
    const long check_every = argc > 5 ? std::stol(argv[5]) : 0;
    const struct {
      const char* name;
      cam::WornRevolutionOptions o;
    } variants[] = {{"neither", {false, false}},
                    {"shared", {true, false}},
                    {"warm", {false, true}},
                    {"both", {true, true}},
                    {"skip", {true, true, true, c.wear->skip_stride, c.wear->skip_power_rtol}}};  // the case's skip
    for (const auto& v : variants) {
      if (which != "all" && which != v.name) continue;
      cam::WornRevolution ev(setup->model, setup->revolution, setup->motion.motion, setup->unworn_profiles,
                             setup->life.grid, setup->dynamics.law, v.o);
      long checks = 0, checks_differing = 0, other_total = 0;
      int other_max = 0;
      double power_max = 0, energy_max = 0;
      double revolution_cpu = 0;  // in the worn revolutions themselves
      const cam::DissipationOf producer = [&](const cam::CamWearState& st) {
        if ((st.cam_depth_m == 0).all() && (st.roller_depth_m == 0).all()) return setup->unworn;
        const double t_rev = cpu_s();
        cam::RevolutionDissipation d = ev(st);
        revolution_cpu += cpu_s() - t_rev;
        if (check_every > 0 && ev.stats().evaluations % check_every == 0) {
          const cam::RevolutionDissipation cold =
              cam::worn_revolution_dissipation(setup->model, setup->revolution, setup->motion.motion,
                                               setup->unworn_profiles, setup->life.grid, st, setup->dynamics.law);
          const Difference diff = difference(d, cold);
          ++checks;
          if (diff.other_contacts > 0) ++checks_differing;
          other_total += diff.other_contacts;
          other_max = std::max(other_max, diff.other_contacts);
          power_max = std::max(power_max, diff.power);
          energy_max = std::max(energy_max, diff.energy);
        }
        return d;
      };
      t0 = cpu_s();
      const cam::CamLifeResult life = cam::run_cam_life(setup->life, producer);
      const double cpu = cpu_s() - t0;
      const cam::WornRevolutionStats& st = ev.stats();
      std::printf("%-8s life %.6g revolutions (%s), %ld steps, %ld evaluations, %.2f s CPU, %.1f ms/revolution; "
                  "%.1f ms of it in the worn revolution; per revolution %.1f normal solves, %.1f F(delta), %.1f creep law; "
                  "%ld cold retries\n",
                  v.name, life.N, wear::to_string(life.ended_by).c_str(), life.steps, life.revolutions_solved, cpu,
                  1e3 * cpu / std::max<long>(1, life.revolutions_solved),
                  1e3 * revolution_cpu / std::max<long>(1, st.evaluations),
                  static_cast<double>(st.contacts_solved) / std::max<long>(1, st.evaluations),
                  static_cast<double>(st.approach_evaluations) / std::max<long>(1, st.evaluations),
                  static_cast<double>(st.creep_evaluations) / std::max<long>(1, st.evaluations), st.cold_retries);
      if (checks > 0)
        std::printf("  against the cold revolution at %ld evaluations (CPU above includes them): %ld with other contacts,"
                    " %ld angles in all, at most %d in one; largest power difference %.2e, energy %.2e\n",
                    checks, checks_differing, other_total, other_max, power_max, energy_max);
    }
    return 0;
  }

  t0 = cpu_s();
  const cam::CamLifeResult worn = bench::cam_worn_to_depth(*setup, worn_depth);
  std::printf("worn to %.3g m in %ld steps (%ld revolutions solved): %.3f s CPU\n", worn.max_depth_m, worn.steps,
              worn.revolutions_solved, cpu_s() - t0);
  const cam::CamWearState& s = worn.state;
  cam::CamWearState s2 = s;
  s2.cam_depth_m *= 1 + 1e-3;
  s2.roller_depth_m *= 1 + 1e-3;

  {
    // along the track: the largest change of a row from the one before, of the deepest wear
    const Eigen::ArrayXXd& h = s.cam_depth_m;
    const double hmax = h.abs().maxCoeff();
    for (int i = 1; i < h.rows(); i += 30)
      std::printf("arc cell %d (cam angle %.1f deg): row change %.2e of the deepest wear\n", i,
                  setup->life.grid.cell_theta_rad.size() ? setup->life.grid.cell_theta_rad(i) * 57.29577951308232 : 0.0,
                  (h.row(i) - h.row(i - 1)).abs().maxCoeff() / hmax);
  }
  std::vector<double> t;
  cam::RevolutionDissipation ref, ref2;
  for (int k = 0; k < (life_only ? 1 : std::max(1, repeats / 2)); ++k) {
    t0 = cpu_s();
    ref = cam::worn_revolution_dissipation(setup->model, setup->revolution, setup->motion.motion,
                                           setup->unworn_profiles, setup->life.grid, s, setup->dynamics.law);
    t.push_back(cpu_s() - t0);
  }
  ref2 = cam::worn_revolution_dissipation(setup->model, setup->revolution, setup->motion.motion, setup->unworn_profiles,
                                          setup->life.grid, s2, setup->dynamics.law);
  std::printf("%-34s %8.1f ms/revolution  (energy %.9g J)\n", "reference (cold, every angle)", 1e3 * median(t),
              cam::dissipation_totals(ref).energy_J);

  const struct {
    const char* name;
    cam::WornRevolutionOptions o;
  } variants[] = {{"neither", {false, false}},
                  {"shared contacts", {true, false}},
                  {"warm starts", {false, true}},
                  {"both (the life's)", {true, true}},
                  {"both, skip 2 (0.01)", {true, true, true, 2, 0.01}},
                  {"both, skip 2 (0.2)", {true, true, true, 2, 0.2}},
                  {"both, skip 2 (1: always)", {true, true, true, 2, 1}},
                  {"both, skip 4 (0.2)", {true, true, true, 4, 0.2}},
                  {"both, skip 4 (0.5)", {true, true, true, 4, 0.5}},
                  {"both, skip 4 (1: always)", {true, true, true, 4, 1}}};
  for (const auto& v : variants) {
    if (life_only && !(v.o.share_contacts && v.o.warm_start && v.o.skip_stride == 1)) continue;
    cam::WornRevolution ev(setup->model, setup->revolution, setup->motion.motion, setup->unworn_profiles,
                           setup->life.grid, setup->dynamics.law, v.o);
    std::vector<double> tw;
    Difference d1, d2;
    cam::WornRevolutionStats before;
    for (int k = 0; k < repeats; ++k) {
      const cam::RevolutionDissipation a = ev(s);  // the first on s is cold for warm starts
      d1 = difference(a, ref);
      before = ev.stats();
      t0 = cpu_s();
      const cam::RevolutionDissipation b = ev(s2);
      tw.push_back(cpu_s() - t0);
      d2 = difference(b, ref2);
    }
    const cam::WornRevolutionStats& st = ev.stats();
    if (v.o.share_contacts) std::printf("angle steps with the inputs of the step before: %ld\n", st.same_input_angles);
    std::printf("%-34s %8.1f ms/revolution  solves %ld, F(delta) %ld, creep law %ld per revolution;"
                " against the reference: power %.2e, energy %.2e, %d other contacts (on s), %.2e, %.2e, %d (on s2);"
                " %ld cold retries, %ld interpolated\n",
                v.name, 1e3 * median(tw), st.contacts_solved - before.contacts_solved,
                st.approach_evaluations - before.approach_evaluations, st.creep_evaluations - before.creep_evaluations,
                d1.power, d1.energy, d1.other_contacts, d2.power, d2.energy, d2.other_contacts, st.cold_retries,
                (st.interpolated_angles - before.interpolated_angles));
  }
  {
    // the warm start's floor: the same state twice, each angle's search starting at its own root
    cam::WornRevolution ev(setup->model, setup->revolution, setup->motion.motion, setup->unworn_profiles,
                           setup->life.grid, setup->dynamics.law, {false, true});
    ev(s);
    const cam::WornRevolutionStats before = ev.stats();
    t0 = cpu_s();
    ev(s);
    const double t_same = cpu_s() - t0;
    std::printf("%-34s %8.1f ms/revolution  solves %ld, F(delta) %ld, creep law %ld per revolution\n",
                "warm, the same state again", 1e3 * t_same, ev.stats().contacts_solved - before.contacts_solved,
                ev.stats().approach_evaluations - before.approach_evaluations,
                ev.stats().creep_evaluations - before.creep_evaluations);
  }
  return 0;
}
