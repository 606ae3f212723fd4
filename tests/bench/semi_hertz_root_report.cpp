// The semi-Hertzian load equation F(delta) = F on worn gaps, rule against rule (docs/semi-hertz.md, "Steep F
// on a nearly conformal worn gap"). A plain program:
//   semi_hertz_root_report roller [galerkin_points = 8]
//       the stored worn roller (tests/data/semi_hertz/paper_wear_phi1_worn_roller.csv on a flat path, 1500 N):
//       per rule, F(delta) scanned in steps of 1e-11 m over +-1 % of the cold root (its largest fall, of the
//       load), the cold root and warm roots from starts 0.98 ... 1.02 of it, and both against the half-space
//       solver on one grid (approach, peak pressure, loaded width, per-strip load).
//   semi_hertz_root_report cam CASE.yaml [depth_m = 8e-6] [angle_every = 4] [scan_steps = 2000] [fine_angle]
//       the cam case worn to depth_m (fixed-depth steps of 1e-6 m, as cam_life_bench), then at every
//       angle_every-th angle, per rule: the cold root, warm roots from 0.98 ... 1.02 of it (how many land on
//       another root), F(delta) over +-5 % of the root in scan_steps steps (falls counted, the largest fall of
//       the load), and for fine_angle (an angle index) a scan in steps of 1e-11 m over +-1 % and the
//       half-space comparison there.
//   semi_hertz_root_report hertz
//       the Galerkin rule against Hertz on the crowned roller (as SemiHertzConstantCurvature), per outer points
//       and cells: errors of a, b, p0, delta, and the CPU per solve.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "cam/cam_case.h"
#include "cam/cam_life.h"
#include "cam/cam_wear.h"
#include "cam/kinematics.h"
#include "lib/normal/halfspace.h"
#include "lib/normal/hertz.h"
#include "lib/normal/semi_hertz.h"
#include "tests/bench/cam_bench_life.h"

namespace {

using contact::ApproachRule;
using contact::SemiHertzOptions;
using contact::SemiHertzResult;

double cpu_s() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Rule {
  const char* name;
  SemiHertzOptions o;
};

std::vector<Rule> rules(const SemiHertzOptions& base, int points) {
  SemiHertzOptions c = base, g = base;
  c.continuous_rule = true;
  g.galerkin_rule = true;
  g.galerkin_points = points;
  return {{"continuous", c}, {"galerkin", g}};
}

struct Scan {
  int falls = 0;            // steps where F falls
  double largest_fall = 0;  // the largest fall from a running maximum, of the load
  double at_m = 0;          // where it ends
  int crossings = 0;        // sign changes of F - load
};

Scan scan(const contact::Profiles& pr, double Rx1, double Rx2, const contact::ElasticPair& pair, double load,
          double lo, double hi, int steps, const SemiHertzOptions& o) {
  Eigen::ArrayXd d(steps + 1);
  for (int k = 0; k <= steps; ++k) d(k) = lo + (hi - lo) * k / steps;
  const Eigen::ArrayXd F = contact::semi_hertz_load_N(pr, Rx1, Rx2, pair, d, o);
  Scan s;
  double peak = F(0);
  for (int k = 1; k <= steps; ++k) {
    if (F(k) < F(k - 1)) ++s.falls;
    if ((F(k) - load) * (F(k - 1) - load) < 0) ++s.crossings;
    peak = std::max(peak, F(k));
    if ((peak - F(k)) / load > s.largest_fall) {
      s.largest_fall = (peak - F(k)) / load;
      s.at_m = d(k);
    }
  }
  return s;
}

// warm starts from these multiples of the cold root: how many land elsewhere (relative difference > kOtherRoot)
constexpr double kOtherRoot = 1e-6;
const double kStarts[] = {0.98, 0.99, 0.995, 0.999, 1.001, 1.005, 1.01, 1.02};

int other_roots(const contact::Profiles& pr, double Rx1, double Rx2, const contact::ElasticPair& pair, double load,
                const contact::GridSpec& grid, SemiHertzOptions o, const SemiHertzResult& cold, double* worst,
                int* evaluations) {
  int other = 0;
  for (double f : kStarts) {
    o.initial_approach_m = f * cold.approach_m;
    const SemiHertzResult w = contact::solve_semi_hertz(pr, Rx1, Rx2, pair, load, grid, o);
    *evaluations += w.status.iterations;
    const double d = std::abs(w.approach_m / cold.approach_m - 1);
    *worst = std::max(*worst, d);
    if (d > kOtherRoot || !w.status.converged()) ++other;
  }
  return other;
}

// the half-space on a box holding both rules' contacts; each rule solved on the same strips (fixed grid)
void against_halfspace(const contact::Profiles& pr, double Rx1, double Rx2, const contact::ElasticPair& pair,
                       double load, const std::vector<Rule>& rs, const SemiHertzOptions& base) {
  double ylo = 1e9, yhi = -1e9, hx = 0;
  std::vector<SemiHertzResult> first;
  for (const Rule& r : rs) {
    first.push_back(contact::solve_semi_hertz(pr, Rx1, Rx2, pair, load, {1, 80}, r.o));
    ylo = std::min(ylo, first.back().contact_y_min_m);
    yhi = std::max(yhi, first.back().contact_y_max_m);
    hx = std::max(hx, first.back().patch.grid.half_x_m);
  }
  const double lo = std::max(pr.body1.y_m(0), pr.body2.y_m(0));
  const double hi = std::min(pr.body1.y_m(pr.body1.y_m.size() - 1), pr.body2.y_m(pr.body2.y_m.size() - 1));
  const double margin = 0.1 * (yhi - ylo);
  ylo = std::max(lo, ylo - margin);
  yhi = std::min(hi, yhi + margin);
  const int nx = 64, ny = 256;
  const contact::Grid grid = contact::make_grid(1.4 * hx, (yhi - ylo) / 2, {nx, ny});
  const double centre = (ylo + yhi) / 2, A = (1 / Rx1 + 1 / Rx2) / 2;
  Eigen::ArrayXXd gap(nx, ny);
  for (int j = 0; j < ny; ++j) {
    const double y = centre + grid.y_m(j);
    const double h = contact::profile_z(pr.body1, y) + contact::profile_z(pr.body2, y);
    for (int i = 0; i < nx; ++i) gap(i, j) = h + A * grid.x_m(i) * grid.x_m(i);
  }
  gap -= gap.minCoeff();
  const double t0 = cpu_s();
  const contact::HalfspaceSolution hs =
      contact::solve_halfspace(grid, gap, contact::effective_modulus_Pa(pair), load);
  Eigen::ArrayXd q_hs = hs.pressure_Pa.colwise().sum().transpose() * grid.dx_m * grid.dy_m;
  int loaded = 0;
  for (int j = 0; j < ny; ++j) loaded += q_hs(j) > 0;
  std::printf("  half-space %dx%d over y [%.4e, %.4e] m (%.1f s, %s): approach %.6e m, peak %.4e Pa, loaded width %.4e m\n",
              nx, ny, ylo, yhi, cpu_s() - t0, hs.status.converged() ? "converged" : "NOT converged", hs.approach_m,
              hs.pressure_Pa.maxCoeff(), loaded * grid.dy_m);
  for (const Rule& r : rs) {
    SemiHertzOptions o = r.o;
    o.fixed_grid_y_lo_m = ylo;
    o.fixed_grid_y_hi_m = yhi;
    const SemiHertzResult s = contact::solve_semi_hertz(pr, Rx1, Rx2, pair, load, {1, ny}, o);
    Eigen::ArrayXd q = contact::kPi / 2 * s.patch.strip_peak_Pa * s.patch.half_length_m * grid.dy_m;
    double width = 0;
    for (int j = 0; j < ny; ++j) width += q(j) > 0 ? grid.dy_m : 0;
    const double qmax = q_hs.maxCoeff();
    const double strip_err = (q - q_hs).abs().maxCoeff() / qmax;
    const double strip_rms = std::sqrt((q - q_hs).square().mean()) / qmax;
    std::printf("  %-10s approach %.6e m (%+.2f %%), peak p0 %.4e Pa (%+.1f %%), loaded width %.4e m (%+.1f %%), "
                "per-strip load: largest error %.1f %%, rms %.2f %% of the half-space's largest; %d patches, %s\n",
                r.name, s.approach_m, 100 * (s.approach_m / hs.approach_m - 1), s.patch.p0_Pa,
                100 * (s.patch.p0_Pa / hs.pressure_Pa.maxCoeff() - 1), width,
                100 * (width / (loaded * grid.dy_m) - 1), 100 * strip_err, 100 * strip_rms, s.patches,
                s.status.message.c_str());
  }
  (void)base;
}

void report_roots(const char* what, const contact::Profiles& pr, double Rx1, double Rx2, const contact::ElasticPair& pair,
                  double load, const contact::GridSpec& grid, const std::vector<Rule>& rs, int fine) {
  for (const Rule& r : rs) {
    double t0 = cpu_s();
    const SemiHertzResult cold = contact::solve_semi_hertz(pr, Rx1, Rx2, pair, load, grid, r.o);
    const double t_cold = cpu_s() - t0;
    double worst = 0;
    int evals = 0;
    const int other = other_roots(pr, Rx1, Rx2, pair, load, grid, r.o, cold, &worst, &evals);
    std::printf("%s %-10s cold root %.9e m (%d evaluations, %.2f ms, slope %.3g), p0 %.5e Pa; warm from 0.98..1.02: %d of %zu "
                "elsewhere (largest %.2e), %.1f evaluations each\n",
                what, r.name, cold.approach_m, cold.status.iterations, 1e3 * t_cold, cold.approach_slope,
                cold.patch.p0_Pa, other, std::size(kStarts), worst, static_cast<double>(evals) / std::size(kStarts));
    if (fine > 0) {
      const double d = cold.approach_m, lo = 0.99 * d, hi = 1.01 * d;
      const int steps = static_cast<int>((hi - lo) / 1e-11);
      t0 = cpu_s();
      const Scan s = scan(pr, Rx1, Rx2, pair, load, lo, hi, steps, r.o);
      std::printf("    F(delta) in %d steps of 1e-11 m over [%.6e, %.6e] m: %d falls, largest %.3e of the load at "
                  "%.9e m, %d crossings of the load (%.1f us per evaluation)\n",
                  steps, lo, hi, s.falls, s.largest_fall, s.at_m, s.crossings, 1e6 * (cpu_s() - t0) / (steps + 1));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_level(spdlog::level::err);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // progress lines as they come
  const std::string mode = argc > 1 ? argv[1] : "";
  const contact::ElasticPair steel{{210e9, 0.28}, {210e9, 0.28}};
  if (mode == "roller") {
    const int points = argc > 2 ? std::stoi(argv[2]) : 8;
    const contact::Profiles pr{
        contact::read_profile_csv(std::string(ROLLWEAR_SOURCE_DIR) + "/tests/data/semi_hertz/paper_wear_phi1_worn_roller.csv"),
        contact::flat_profile(0.030)};
    const std::vector<Rule> rs = rules({}, points);
    report_roots("roller", pr, 0.020, 0.025, steel, 1500, {80, 80}, rs, 1);
    // the window of the old rule's non-monotone stretch (docs/semi-hertz.md)
    for (const Rule& r : rs) {
      const Scan s = scan(pr, 0.020, 0.025, steel, 1500, 2.0870e-5, 2.0890e-5, 2000, r.o);
      std::printf("  %-10s over [2.0870e-5, 2.0890e-5] m in 1e-11 m steps: %d falls, largest %.3e of the load, %d crossings\n",
                  r.name, s.falls, s.largest_fall, s.crossings);
      const Scan w = scan(pr, 0.020, 0.025, steel, 1500, 1.5e-5, 3e-5, 15000, r.o);
      std::printf("  %-10s over [1.5e-5, 3e-5] m in 1e-9 m steps: %d falls, largest %.3e of the load, %d crossings\n",
                  r.name, w.falls, w.largest_fall, w.crossings);
    }
    against_halfspace(pr, 0.020, 0.025, steel, 1500, rs, {});
    return 0;
  }
  if (mode == "hertz") {
    for (int cells : {16, 32, 64}) {
      for (int points : {2, 4, 8, 16}) {
        double worst = 0, cpu = 0;
        for (double Ry : {0.05, 0.2, 0.5, 2.0})
          for (double F : {100.0, 1500.0, 1e4}) {
            SemiHertzOptions o;
            o.galerkin_rule = true;
            o.galerkin_points = points;
            o.quadrature_cells = cells;
            o.pressure_fields = false;
            const contact::Profiles pr{contact::crowned_profile(Ry, 0.020), contact::flat_profile(0.030)};
            const double t0 = cpu_s();
            const SemiHertzResult r = contact::solve_semi_hertz(pr, 0.020, 0.025, steel, F, {1, 60}, o);
            cpu += cpu_s() - t0;
            const contact::HertzContact h = contact::solve_hertz({{0.020, Ry}, {0.025, contact::kFlat}}, steel, F);
            worst = std::max({worst, std::abs(r.patch.a_m / h.a_m - 1), std::abs(r.patch.b_m / h.b_m - 1),
                              std::abs(r.patch.p0_Pa / h.p0_Pa - 1), std::abs(r.approach_m / h.approach_m - 1)});
          }
        std::printf("galerkin cells %2d points %2d: largest error of a, b, p0, delta against Hertz %.2e (%.0f us per solve)\n",
                    cells, points, worst, 1e6 * cpu / 12);
      }
    }
    return 0;
  }
  if (mode == "cam" && argc > 2) {
    const double depth = argc > 3 ? std::stod(argv[3]) : 8e-6;
    const int every = argc > 4 ? std::stoi(argv[4]) : 4;
    const int steps = argc > 5 ? std::stoi(argv[5]) : 2000;
    const int fine_angle = argc > 6 ? std::stoi(argv[6]) : -1;
    const int points = argc > 7 ? std::stoi(argv[7]) : 8;
    const bool only_galerkin = std::getenv("SH_ONLY_G") != nullptr;
    const cam::CamCase c = cam::read_cam_case(argv[2]);
    const cam::RollerDynamicsSettings dynamics = cam::roller_dynamics_of(c.solver);  // as rollwear run reads the case
    const std::unique_ptr<cam::CamLifeSetup> setup = cam::set_up_cam_life(c.name, c.model, *c.wear, dynamics);
    // the worn state, kept in SH_STATE (a scratch file of this program) to look again without wearing again
    cam::CamWearState state = cam::unworn_state(setup->life.grid);
    const char* keep = std::getenv("SH_STATE");
    std::FILE* in = keep ? std::fopen(keep, "rb") : nullptr;
    if (in) {
      const std::size_t n1 = static_cast<std::size_t>(state.cam_depth_m.size()), n2 = static_cast<std::size_t>(state.roller_depth_m.size());
      const bool ok = std::fread(state.cam_depth_m.data(), sizeof(double), n1, in) == n1 &&
                      std::fread(state.roller_depth_m.data(), sizeof(double), n2, in) == n2;
      std::fclose(in);
      if (!ok) return 1;
      std::printf("worn state read from %s (deepest %.3g m)\n", keep, state.cam_depth_m.maxCoeff());
    } else {
      const cam::CamLifeResult worn = bench::cam_worn_to_depth(*setup, depth);
      std::printf("worn to %.3g m in %ld steps\n", worn.max_depth_m, worn.steps);
      state = worn.state;
      if (keep) {
        std::FILE* out = std::fopen(keep, "wb");
        std::fwrite(state.cam_depth_m.data(), sizeof(double), static_cast<std::size_t>(state.cam_depth_m.size()), out);
        std::fwrite(state.roller_depth_m.data(), sizeof(double), static_cast<std::size_t>(state.roller_depth_m.size()), out);
        std::fclose(out);
      }
    }
    double b_min = 1e9;
    for (const cam::RevolutionRow& row : setup->revolution.rows) b_min = std::min(b_min, row.contact.b_m);
    const cam::CreepLawSettings law =
        cam::worn_contact_settings(setup->unworn_profiles, setup->life.grid, setup->dynamics.law,
                                   2 * b_min / setup->dynamics.law.grid.ny);
    SemiHertzOptions base;
    base.pressure_fields = false;
    base.fixed_grid_y_lo_m = law.fixed_grid_y_lo_m;
    base.fixed_grid_y_hi_m = law.fixed_grid_y_hi_m;
    std::vector<Rule> rs = rules(base, points);
    if (only_galerkin) rs.erase(rs.begin());
    const contact::ElasticPair& pair = setup->model.bodies.pair;
    const double Rr = setup->model.geometry.roller_radius_m;
    struct Totals {
      int angles = 0, other = 0, angles_other = 0, nonmono = 0, multi = 0, evals = 0;
      double worst_fall = 0, worst_other = 0, cpu = 0;
      int worst_angle = -1;
    };
    std::vector<Totals> tot(rs.size());
    for (std::size_t i = 0; i < setup->revolution.rows.size(); i += static_cast<std::size_t>(every)) {
      const cam::RevolutionRow& row = setup->revolution.rows[i];
      const contact::Profiles pr = cam::worn_profiles_at(setup->unworn_profiles, setup->life.grid, state,
                                                         row.contact_arc_m);
      const double Rc = cam::cam_radius_m(row.kin), load = setup->motion.motion.angles[i].normal_N;
      for (std::size_t k = 0; k < rs.size(); ++k) {
        Totals& t = tot[k];
        const double t0 = cpu_s();
        const SemiHertzResult cold = contact::solve_semi_hertz(pr, Rr, Rc, pair, load, law.grid, rs[k].o);
        t.cpu += cpu_s() - t0;
        t.evals += cold.status.iterations;
        double worst = 0;
        int evals = 0;
        const int other = other_roots(pr, Rr, Rc, pair, load, law.grid, rs[k].o, cold, &worst, &evals);
        const Scan s = scan(pr, Rr, Rc, pair, load, 0.95 * cold.approach_m, 1.05 * cold.approach_m, steps, rs[k].o);
        ++t.angles;
        t.other += other;
        t.angles_other += other > 0;
        t.worst_other = std::max(t.worst_other, worst);
        t.nonmono += s.falls > 0;
        t.multi += s.crossings > 1;
        if (s.largest_fall > t.worst_fall) {
          t.worst_fall = s.largest_fall;
          t.worst_angle = static_cast<int>(i);
        }
        if (s.falls > 0 || other > 0)
          std::printf("angle %4zu %-10s root %.6e m, %d patches: warm elsewhere %d (largest %.2e); scan: %d falls, "
                      "largest %.2e of the load at %.6e m, %d crossings\n",
                      i, rs[k].name, cold.approach_m, cold.patches, other, worst, s.falls, s.largest_fall, s.at_m,
                      s.crossings);
      }
      if (static_cast<int>(i) == fine_angle) {
        if (const char* dump = std::getenv("SH_DUMP")) {  // the angle's worn gap, for a closer look
          for (int body = 1; body <= 2; ++body) {
            std::FILE* f = std::fopen((std::string(dump) + "_body" + std::to_string(body) + ".csv").c_str(), "w");
            const std::string text = contact::profile_csv(body == 1 ? pr.body1 : pr.body2);
            std::fputs(text.c_str(), f);
            std::fclose(f);
          }
          std::printf("dumped angle %zu: Rx1 %.17g Rx2 %.17g load %.17g\n", i, Rr, Rc, load);
        }
        report_roots("fine", pr, Rr, Rc, pair, load, law.grid, rs, 1);
        against_halfspace(pr, Rr, Rc, pair, load, rs, base);
      }
    }
    for (std::size_t k = 0; k < rs.size(); ++k) {
      const Totals& t = tot[k];
      std::printf("%-10s %d angles: %d with a non-monotone F over +-5 %% (%d steps), %d crossing the load more than once, "
                  "largest fall %.3e of the load (angle %d); warm starts elsewhere: %d of %d (%d angles), largest %.2e; "
                  "cold %.2f evaluations, %.1f us per solve\n",
                  rs[k].name, t.angles, t.nonmono, steps, t.multi, t.worst_fall, t.worst_angle, t.other,
                  t.angles * static_cast<int>(std::size(kStarts)), t.angles_other, t.worst_other,
                  static_cast<double>(t.evals) / t.angles, 1e6 * t.cpu / t.angles);
    }
    return 0;
  }
  std::fprintf(stderr, "usage: semi_hertz_root_report roller [points] | hertz | cam CASE.yaml [depth_m] [angle_every] "
                       "[scan_steps] [fine_angle] [points]\n");
  return 2;
}
