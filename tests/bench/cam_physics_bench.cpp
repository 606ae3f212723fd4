// The cam's revolution on the exact physics against the product's models (docs/cam-follower.md §16). A plain program:
//   cam_physics_bench CASE.yaml DIR [SNAPSHOT = last] [NX = 32] [NY = 32] [MODELS = sc,hc,hx] [STRIDE = case's]
//   cam_physics_bench CASE.yaml DIR SNAPSHOT NX NY check   the cam's half-space against the library's at six angles
// DIR a `rollwear run CASE -o DIR` folder: its wear map and roller wear number SNAPSHOT (snapshots/*_KKKK.csv) is
// the worn state. For each model (sc: semi-Hertz (auto) + consistent, hc: half-space + consistent, hx: half-space +
// exact, sx: semi-Hertz (auto) + exact, hr: half-space + relaxed) on cam.tangential nx x ny:
//   1. the life's set-up (set_up_cam_life: the unworn revolution, the roller's motion), CPU timed;
//   2. the worn state's revolution by the life's evaluator (WornRevolution, the case's skip or STRIDE, power_rtol
//      the case's), cold (its first evaluation), CPU timed, with its solves; then warm, on the state x 1.001 (the
//      life's next evaluation, from this one's approaches and creepages);
// and prints the dissipated energy per revolution of both, from the strips' power (what the wear reads).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "cam/cam_case.h"
#include "cam/cam_life.h"
#include "cam/revolution_dissipation.h"
#include "cam/worn_revolution.h"
#include "lib/normal/normal.h"
#include "lib/tangential/tangential.h"
#include "tests/bench/cam_bench_life.h"

namespace {

double cpu_s() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Model {
  std::string code;
  contact::NormalChoice normal;
  contact::TangentialScheme scheme;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: cam_physics_bench CASE.yaml DIR [SNAPSHOT] [NX] [NY] [MODELS] [STRIDE]\n");
    return 2;
  }
  spdlog::set_level(std::getenv("CAM_BENCH_DEBUG") ? spdlog::level::debug : spdlog::level::err);
  const cam::CamCase c = cam::read_cam_case(argv[1]);
  if (!c.wear) {
    std::fprintf(stderr, "%s: no cam.wear section\n", argv[1]);
    return 2;
  }
  const int snapshot = argc > 3 ? std::stoi(argv[3]) : -1;
  const int nx = argc > 4 ? std::stoi(argv[4]) : 32, ny = argc > 5 ? std::stoi(argv[5]) : 32;
  const std::string models = argc > 6 ? argv[6] : "sc,hc,hx";
  cam::CamWearSpec spec = *c.wear;
  if (argc > 7) spec.skip_stride = std::stoi(argv[7]);
  if (models == "check") {
    // the cam's half-space (its fixed lattice) against the library's (solve_normal, the semi-Hertzian box enlarged
    // by 25 %) on the worn profiles at six angles: approach, peak, the strips' load centroid and spread, and the
    // consistent model's power at the creepage for the motion's F_t on each
    cam::CamSolverSettings solver = c.solver;
    solver.nx = nx;
    solver.ny = ny;
    solver.scheme = contact::TangentialScheme::Consistent;
    solver.normal = contact::NormalChoice::Halfspace;
    const std::unique_ptr<cam::CamLifeSetup> setup =
        cam::set_up_cam_life(c.name, c.model, spec, cam::roller_dynamics_of(solver));
    std::string which;
    const cam::CamWearState s = bench::cam_state_of_folder(argv[2], setup->life.grid, which, snapshot);
    double b_min = 1e300;
    for (const cam::RevolutionRow& row : setup->revolution.rows) b_min = std::min(b_min, row.contact.b_m);
    const cam::CreepLawSettings fixed = cam::worn_contact_settings(setup->unworn_profiles, setup->life.grid,
                                                                   setup->dynamics.law, 2 * b_min / ny);
    const auto moments = [](const cam::AngleContact& a, double& centroid, double& spread) {
      const contact::ContactPatch& p = a.normal.patch;
      const Eigen::ArrayXd L = p.strip_peak_Pa * p.half_length_m;  // the strips' loads, (pi/2) dy aside
      const Eigen::ArrayXd y = a.normal.grid_y0_m + p.grid.y_m;
      centroid = (L * y).sum() / L.sum();
      spread = std::sqrt((L * (y - centroid).square()).sum() / L.sum());
    };
    for (const double deg : {25.0, 41.5, 75.0, 120.0, 194.5, 300.0}) {
      const std::size_t i = static_cast<std::size_t>(std::lround(deg / 360 * setup->revolution.rows.size()));
      const cam::RevolutionRow& row = setup->revolution.rows[i];
      const cam::RollerAngle& ra = setup->motion.motion.angles[i];
      const contact::Profiles worn = cam::worn_profiles_at(setup->unworn_profiles, setup->life.grid, s, row.contact_arc_m);
      cam::CreepLawSettings lib = fixed;
      lib.normal = contact::NormalChoice::Auto;  // placeholder: the library's half-space below
      const cam::AngleContact mine =
          cam::angle_contact(c.model.bodies, worn, c.model.geometry.roller_radius_m, row.kin, ra.normal_N, c.model.mu, fixed);
      contact::NormalProblem np;
      np.choice = contact::NormalChoice::Halfspace;
      np.bodies.body1.Rx_m = c.model.geometry.roller_radius_m;
      np.bodies.body2.Rx_m = cam::cam_radius_m(row.kin);
      np.profiles = &worn;
      np.pair = c.model.bodies.pair;
      np.normal_load_N = ra.normal_N;
      np.grid = {2 * nx, 4 * ny};
      np.semi_hertz.pressure_fields = false;
      np.semi_hertz.continuous_rule = true;
      np.worn = true;
      cam::AngleContact theirs = mine;
      theirs.normal = contact::solve_normal_converged(np);
      theirs.problem = contact::make_tangential_problem(theirs.normal.patch, c.model.bodies.pair, {}, c.model.mu, 0);
      theirs.roller_depth_m = cam::roller_depth_m(worn, theirs.normal.grid_y0_m, theirs.normal.patch.grid);
      theirs.track_depth_m = cam::track_depth_m(worn, theirs.normal.grid_y0_m, theirs.normal.patch.grid);
      // the semi-Hertzian contact on the same lattice as the life's (auto on worn profiles)
      cam::AngleContact semi = cam::angle_contact(c.model.bodies, worn, c.model.geometry.roller_radius_m, row.kin,
                                                  ra.normal_N, c.model.mu, lib);
      double cm, sm, ct, st, cs, ss;
      moments(mine, cm, sm);
      moments(theirs, ct, st);
      moments(semi, cs, ss);
      const auto power = [&](const cam::AngleContact& a) {
        const cam::CreepageForForce q = cam::creepage_for_force(a, ra.tangential_N);
        return cam::steady_creep(a, q.found ? q.xi : ra.xi, ra.speed_m_per_s).power_W;
      };
      // the exact theory on the cam's half-space contact: its strips' power and its creep work
      cam::AngleContact exact = mine;
      exact.scheme = contact::TangentialScheme::Exact;
      const cam::CreepageForForce qx = cam::creepage_for_force(exact, ra.tangential_N);
      const contact::TangentialSolution sx = cam::steady_creep(exact, qx.found ? qx.xi : ra.xi, ra.speed_m_per_s);
      std::printf("%6.1f deg exact theory on the cam's half-space: power %.4g W, creep work %.4g W (%d steady solves)\n",
                  deg, sx.power_W, -sx.creep_work_W, qx.evaluations);
      std::printf("%6.1f deg F_n %.1f N: approach %.4e / %.4e / %.4e m, p0 %.4g / %.4g / %.4g MPa, load centroid %.4f / %.4f "
                  "/ %.4f mm, spread %.4f / %.4f / %.4f mm, power %.4g / %.4g / %.4g W (cam lattice %dx%d / library %dx%d / "
                  "semi-Hertz)\n",
                  deg, ra.normal_N, mine.normal.patch.approach_m, theirs.normal.patch.approach_m,
                  semi.normal.patch.approach_m, 1e-6 * mine.normal.patch.p0_Pa, 1e-6 * theirs.normal.patch.p0_Pa,
                  1e-6 * semi.normal.patch.p0_Pa, 1e3 * cm, 1e3 * ct, 1e3 * cs, 1e3 * sm, 1e3 * st, 1e3 * ss, power(mine),
                  power(theirs), power(semi), mine.normal.patch.grid.nx, mine.normal.patch.grid.ny,
                  theirs.normal.patch.grid.nx, theirs.normal.patch.grid.ny);
    }
    return 0;
  }
  const std::vector<Model> all = {{"sc", contact::NormalChoice::Auto, contact::TangentialScheme::Consistent},
                                  {"hc", contact::NormalChoice::Halfspace, contact::TangentialScheme::Consistent},
                                  {"hx", contact::NormalChoice::Halfspace, contact::TangentialScheme::Exact},
                                  {"sx", contact::NormalChoice::Auto, contact::TangentialScheme::Exact},
                                  {"hr", contact::NormalChoice::Halfspace, contact::TangentialScheme::Relaxed}};
  std::stringstream list(models);
  std::string code;
  std::printf("case %s, worn state from %s, grid %d x %d, skip stride %d (power_rtol %g)\n", argv[1], argv[2], nx, ny,
              spec.skip_stride, spec.skip_power_rtol);
  while (std::getline(list, code, ',')) {
    const Model* m = nullptr;
    for (const Model& x : all)
      if (x.code == code) m = &x;
    if (!m) {
      std::fprintf(stderr, "unknown model %s (sc, hc, hx, sx, hr)\n", code.c_str());
      return 2;
    }
    cam::CamSolverSettings solver = c.solver;
    solver.nx = nx;
    solver.ny = ny;
    solver.scheme = m->scheme;
    solver.normal = m->normal;
    double t0 = cpu_s();
    const std::unique_ptr<cam::CamLifeSetup> setup =
        cam::set_up_cam_life(c.name, c.model, spec, cam::roller_dynamics_of(solver));
    const double cpu_setup = cpu_s() - t0;
    std::string which;
    const cam::CamWearState s = bench::cam_state_of_folder(argv[2], setup->life.grid, which, snapshot);
    const cam::WornRevolutionStats before = setup->worn->stats();
    t0 = cpu_s();
    const cam::RevolutionDissipation d = (*setup->worn)(s);
    const double cpu_worn = cpu_s() - t0;
    const cam::WornRevolutionStats& st = setup->worn->stats();
    std::printf("%s (%s + %s): set-up %.3g s CPU, unworn revolution %.6g J; worn (%s, deepest %.3g um): %.6g J, "
                "%.3g s CPU, %ld angle steps (%ld interpolated), %ld normal solves, %ld creep-law solves\n",
                m->code.c_str(), contact::to_string(m->normal), contact::to_string(m->scheme).c_str(), cpu_setup,
                cam::dissipation_totals(setup->unworn).energy_J, which.c_str(),
                1e6 * std::max(s.cam_depth_m.maxCoeff(), s.roller_depth_m.maxCoeff()),
                cam::dissipation_totals(d).energy_J, cpu_worn, st.angles - before.angles,
                st.interpolated_angles - before.interpolated_angles, st.contacts_solved - before.contacts_solved,
                st.creep_evaluations - before.creep_evaluations);
    // the life's next evaluation: the state scaled by 1 + 1e-3, warm-started from this one (approaches, creepages)
    cam::CamWearState s2 = s;
    s2.cam_depth_m *= 1 + 1e-3;
    s2.roller_depth_m *= 1 + 1e-3;
    const cam::WornRevolutionStats mid = setup->worn->stats();
    t0 = cpu_s();
    const cam::RevolutionDissipation d2 = (*setup->worn)(s2);
    const double cpu_warm = cpu_s() - t0;
    const cam::WornRevolutionStats& st2 = setup->worn->stats();
    std::printf("%s   warm (the state x 1.001): %.6g J, %.3g s CPU, %ld normal solves, %ld creep-law solves\n",
                m->code.c_str(), cam::dissipation_totals(d2).energy_J, cpu_warm,
                st2.contacts_solved - mid.contacts_solved, st2.creep_evaluations - mid.creep_evaluations);
    std::fflush(stdout);
  }
  return 0;
}
