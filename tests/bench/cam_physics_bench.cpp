// The cam's revolution on the exact physics against the product's models (docs/cam-follower.md §16). A plain program:
//   cam_physics_bench CASE.yaml DIR [SNAPSHOT = last] [NX = 32] [NY = 32] [MODELS = sc,hc,hx] [STRIDE = case's]
// DIR a `rollwear run CASE -o DIR` folder: its wear map and roller wear number SNAPSHOT (snapshots/*_KKKK.csv) is
// the worn state. For each model (sc: semi-Hertz (auto) + consistent, hc: half-space + consistent, hx: half-space +
// exact, sx: semi-Hertz (auto) + exact, hr: half-space + relaxed) on cam.tangential nx x ny:
//   1. the life's set-up (set_up_cam_life: the unworn revolution, the roller's motion), CPU timed;
//   2. the worn state's revolution by the life's evaluator (WornRevolution, the case's skip or STRIDE, power_rtol
//      the case's), cold (its first evaluation), CPU timed, with its solves;
// and prints the dissipated energy per revolution of both, from the strips' power (what the wear reads).
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
    std::fflush(stdout);
  }
  return 0;
}
