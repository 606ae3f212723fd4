// The tables of docs/exact-theory.md §4, printed by Kalker's exact theory in-house
// (lib/tangential/exact.h): built with the bench preset (cmake --preset bench), not part of ctest.
//   exact_report coef        C11 C22 C23 at full stick on 20..160 cells, Richardson-extrapolated
//   exact_report c33         C33 (reported, not judged: it converges slowly)
//   exact_report mindlin     Cattaneo-Mindlin's stick radius in the shift mode, nu = 0 and 0.28, by shift and by force
//   exact_report sweep       steady forces, power and creep work over creepages (paper's contact, sphere)
//   exact_report transient N the start from rest at dq = dx on N x N: Fx/Fx_ss at q/a = 0.5, 2, 4, 8
//   exact_report narrow      a/b = 0.02: the centre strip's Fx against Carter's over grids
//   exact_report carter N R  plane strain, N cells, xi/xi_c = R: the solve's status, Fx and the power against Carter
//   exact_report paper [320] the paper's contact, xi = 1e-3: Fx, power and creep work on 20..160 (320)
//   exact_report power xi|spin|eta [N...]  the paper's contact (xi = 1e-3; + phi = 1 1/m; + eta = 1e-3) on the
//                            grids N (default 20 40 80 160): the total and per-strip power of the candidates
//                            (docs/exact-theory.md §4, "Dissipation") against the creep work, the finest grid
//                            and between successive grids (the observed order on each three)
#include "lib/tangential/exact.h"
#include "lib/elastic.h"
#include "lib/grid.h"
#include "lib/normal/hertz.h"
#include "lib/numeric.h"
#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>
using namespace contact;
ContactPatch ellipse_patch(double ab, int n) {
  HertzContact h; h.b_m = 1e-3; h.a_m = ab * h.b_m; h.p0_Pa = 1e9;
  h.normal_load_N = 2 * kPi * h.a_m * h.b_m * h.p0_Pa / 3;
  return hertz_patch(h, make_grid(h.a_m, h.b_m, {n, n}));
}
ContactPatch paper_patch(int n) {
  const Bodies bodies{{20e-3, 500e-3}, {25e-3, kFlat}};
  return solve_normal_hertz(bodies, {{210e9, 0.28}, {210e9, 0.28}}, 1500, {n, n});
}
int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: exact_report coef|c33|mindlin|sweep|transient N|paper [320]\n");
    return 2;
  }
  const std::string what = argv[1];
  if (what == "transient" && argc < 3) {
    std::fprintf(stderr, "usage: exact_report transient N\n");
    return 2;
  }
  if (what == "coef") {
    for (double ab : {0.2, 0.5, 1.0, 2.0, 5.0, -1.0}) {
      double C[3][6];
      int k = 0;
      for (int n : {20, 40, 80, 160}) {
        ContactPatch p = ab > 0 ? ellipse_patch(ab, n) : paper_patch(n);
        const double nu = ab > 0 ? 0.25 : 0.28, G = 80e9, a = p.a_m, b = p.b_m, c = 1e-6;
        ExactOptions o; o.stick_tol = 1e-9;
        C[0][k] = -solve_exact_steady(p, G, nu, {c, 0, 0}, 1e4, 1, o).fields.Fx_N / (G * a * b * c);
        C[1][k] = -solve_exact_steady(p, G, nu, {0, c, 0}, 1e4, 1, o).fields.Fy_N / (G * a * b * c);
        C[2][k] = -solve_exact_steady(p, G, nu, {0, 0, c / std::sqrt(a * b)}, 1e4, 1, o).fields.Fy_N / (G * a * b * c);
        ++k;
      }
      for (int i = 0; i < 3; ++i) {
        auto R = [&](int j) { return (8 * C[i][j + 2] - 6 * C[i][j + 1] + C[i][j]) / 3; };
        std::printf("a/b %s C%s: 20 %.4f 40 %.4f 80 %.4f 160 %.4f | R(20,40,80) %.4f R(40,80,160) %.4f\n",
                    ab > 0 ? std::to_string(ab).substr(0, 4).c_str() : "0.0882(paper,nu0.28)",
                    i == 0 ? "11" : i == 1 ? "22" : "23", C[i][0], C[i][1], C[i][2], C[i][3], R(0), R(1));
      }
    }
  } else if (what == "c33") {
    for (double ab : {1.0, -1.0}) {
      double C[4]; int k = 0;
      for (int n : {20, 40, 80, 160}) {
        ContactPatch p = ab > 0 ? ellipse_patch(ab, n) : paper_patch(n);
        const double nu = ab > 0 ? 0.25 : 0.28, G = 80e9, a = p.a_m, b = p.b_m, c = 1e-6;
        ExactOptions o; o.stick_tol = 1e-9;
        const double phi = c / std::sqrt(a * b);
        C[k++] = -solve_exact_steady(p, G, nu, {0, 0, phi}, 1e4, 1, o).fields.Mz_N_m / (G * a * b * a * b * phi);
      }
      std::printf("C33 %s: 20 %.4f 40 %.4f 80 %.4f 160 %.4f R(40,80,160) %.4f\n", ab > 0 ? "a/b 1 nu 0.25" : "paper", C[0], C[1], C[2], C[3], (8 * C[3] - 6 * C[2] + C[1]) / 3);
    }
  } else if (what == "mindlin") {
    for (double nu : {0.0, 0.28}) {
      const ElasticPair pair{{210e9, nu}, {210e9, nu}};
      const Bodies bodies{{10e-3, 10e-3}, {kFlat, kFlat}};
      for (int n : {40, 80, 160}) {
        const ContactPatch p = solve_normal_hertz(bodies, pair, 1000, {n, n});
        const double G = combined_shear_modulus_Pa(pair), a = p.a_m, mu = 0.3;
        // Mindlin's shift for |Fx| = mu Fn / 2, both bodies: 3 mu F (2 - nu) / (8 G a) [1 - (1/2)^(2/3)]
        const double shift = 3 * mu * 1000 * (2 - nu) / (8 * G * a) * (1 - std::pow(0.5, 2.0 / 3.0));
        const ExactSolution s = solve_exact_shift(p, G, combined_poisson(pair), shift, 0, mu, 1.0, nullptr);
        const double lr = -s.fields.Fx_N / (mu * 1000);
        const double c = a * std::cbrt(1 - lr);
        const double cg = std::sqrt((s.fields.state == 1).count() * p.grid.dx_m * p.grid.dy_m / kPi);
        std::printf("mindlin nu %.2f n %d: Fx/(mu Fn) %.5f, c_grid/a %.5f, (1-Fx/muFn)^(1/3) %.5f, dev %+.2f %%, %s\n", nu, n, lr, cg / a, c / a, 100 * (cg / c - 1), s.status.message.c_str());
        // driven by the force: Fx = -f mu Fn (the grid's Fn), the shift found
        const double Fn_grid = p.pressure_Pa.sum() * p.grid.dx_m * p.grid.dy_m;
        for (const double f : {0.5, 0.8}) {
          const auto t0 = std::chrono::steady_clock::now();
          const ExactShiftForce r = solve_exact_shift_force(p, G, combined_poisson(pair), -f * mu * Fn_grid, 0, mu, 1.0, nullptr);
          const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
          const double cf = a * std::cbrt(1 - f);
          const double cgf = std::sqrt((r.solution.fields.state == 1).count() * p.grid.dx_m * p.grid.dy_m / kPi);
          std::printf("mindlin by force nu %.2f n %d f %.1f: c_grid/c - 1 %+.2f %%, shift/Mindlin's - 1 %+.3f %%, %d shift solves, %.0f ms\n", nu, n, f, 100 * (cgf / cf - 1), 100 * (r.shift_x_m / (3 * mu * 1000 * (2 - nu) / (8 * G * a) * (1 - std::pow(1 - f, 2.0 / 3.0))) - 1), r.shift_solves, ms);
        }
      }
    }
  } else if (what == "carter" && argc >= 4) {
    const int n = std::atoi(argv[2]);
    const double r = std::atof(argv[3]);
    const double E = 210e9, nu = 0.28, G = E / (2 * (1 + nu)), mu = 0.3, p0 = 1e9, a = 0.25e-3;
    ContactPatch p;
    p.grid = make_grid(a, 1e-3, {n, 1});
    p.half_length_m = Eigen::ArrayXd::Constant(1, a);
    p.strip_peak_Pa = Eigen::ArrayXd::Constant(1, p0);
    fill_strip_pressures(p);
    const double xi_c = 2 * (1 - nu) * mu * p0 / G;
    ExactOptions o;
    o.plane_strain = true;
    const auto t0 = std::chrono::steady_clock::now();
    const ExactSolution s = solve_exact_steady(p, G, nu, {r * xi_c, 0, 0}, mu, 1.0, o);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const double a1 = a * (1 - r), Fx = -mu * kPi * a * p0 / 2 * (1 - (a1 / a) * (a1 / a));
    std::printf("carter n %d xi/xi_c %.2f: Fx/Fx_carter - 1 %+.2e, %s, %.0f ms\n", n, r,
                s.fields.Fx_N / p.grid.dy_m / Fx - 1, s.status.message.c_str(), ms);
    // the dissipation against Carter's, -V xi Fx (per unit width): the trapezoidal power (the creep work), the
    // upwind product and the centred slip on the slip cells only
    const double P_carter = -r * xi_c * Fx, dx = p.grid.dx_m;
    double centred = 0;
    for (int i = 0; i < n; ++i) {
      if (s.fields.state(i, 0) != 2) continue;
      const double um = i > 0 ? s.u_x_m(i - 1, 0) : s.u_behind_x_m(0);
      centred -= s.fields.tau_x_Pa(i, 0) * (r * xi_c + (um - s.u_x_m(i + 1, 0)) / (2 * dx)) * dx;
    }
    std::printf("  power/P_carter - 1: trapezoidal %+.3e, upwind %+.3e, centred on the slip cells %+.3e\n",
                s.fields.power_W / p.grid.dy_m / P_carter - 1, s.grid_power_W / p.grid.dy_m / P_carter - 1,
                centred / P_carter - 1);
  } else if (what == "narrow") {
    const double E = 210e9, nu = 0.28, G = E / (2 * (1 + nu)), mu = 0.3;
    for (const double ab : {0.02, 0.01}) {
      for (const auto& nn : {std::pair<int, int>{60, 21}, {120, 21}, {240, 21}, {120, 41}}) {
        HertzContact h;
        h.b_m = 1e-3;
        h.a_m = ab * h.b_m;
        h.p0_Pa = 1e9;
        h.normal_load_N = 2 * kPi * h.a_m * h.b_m * h.p0_Pa / 3;
        const ContactPatch q = hertz_patch(h, make_grid(h.a_m, h.b_m, {nn.first, nn.second}));
        const int centre = nn.second / 2;
        const double a = q.half_length_m(centre), p0 = q.strip_peak_Pa(centre), xi_c = 2 * (1 - nu) * mu * p0 / G;
        std::printf("narrow a/b %.2f %d x %d:", ab, nn.first, nn.second);
        for (const double r : {0.25, 0.5, 0.75}) {
          const auto t0 = std::chrono::steady_clock::now();
          const ExactSolution s = solve_exact_steady(q, G, nu, {r * xi_c, 0, 0}, mu, 1.0, exact_run_options());
          const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
          const double a1 = a * (1 - r), carter = -mu * kPi * a * p0 / 2 * (1 - (a1 / a) * (a1 / a));
          std::printf("  xi/xi_c %.2f: %+.4f (%.0f ms%s)", r, s.fields.strip_force_x_N_per_m(centre) / carter - 1, ms,
                      s.status.converged() ? "" : ", NOT CONVERGED");
        }
        std::printf("\n");
      }
    }
  } else if (what == "sweep") {
    const ElasticPair pair{{210e9, 0.28}, {210e9, 0.28}};
    const double G = combined_shear_modulus_Pa(pair), nu = combined_poisson(pair);
    const Bodies sphere{{10e-3, 10e-3}, {kFlat, kFlat}};
    for (int n : {40, 80}) {
      const ContactPatch pp = paper_patch(n);
      const ContactPatch ps = solve_normal_hertz(sphere, pair, 1000, {n, n});
      for (const ContactPatch* p : {&pp, &ps})
        for (Creepages c : {Creepages{1e-4, 0, 0}, Creepages{2e-3, 0, 0}, Creepages{5e-3, 0, 0}, Creepages{0, 1e-3, 0},
                            Creepages{0, 0, 1.0}, Creepages{1e-3, 1e-3, 0.5}, Creepages{-1e-3, 2e-3, -2.0}}) {
          auto t0 = std::chrono::steady_clock::now();
          ExactSolution s = solve_exact_steady(*p, G, nu, c, 0.3, 1.0);
          double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
          std::printf("%s %d xi %g eta %g phi %g: Fx %.3f Fy %.3f Mz %.5f P %.5f -W %.5f stick %.3f | %s | %.0f ms\n",
                      p == &pp ? "paper" : "sphere", n, c.xi, c.eta, c.phi_per_m, s.fields.Fx_N, s.fields.Fy_N,
                      s.fields.Mz_N_m, s.fields.power_W, -s.fields.creep_work_W, s.fields.stick_fraction,
                      s.status.message.c_str(), ms);
        }
    }
  } else if (what == "transient") {
    const ElasticPair pair{{210e9, 0.28}, {210e9, 0.28}};
    const double G = combined_shear_modulus_Pa(pair), nu = combined_poisson(pair);
    for (int n : {std::atoi(argv[2])}) {
      ContactPatch p = paper_patch(n);
      ExactSolution ss = solve_exact_steady(p, G, nu, {1e-3, 0, 0}, 0.3, 1.0);
      ExactSolution prev;
      // the steps' tolerances: 10^-argv[3] on the fixed-point residual, 10^-argv[4] the linear solves' floor
      const double tol = argc > 3 ? std::pow(10.0, -std::atof(argv[3])) : 1e-6;
      ExactOptions o; o.tol = tol; o.stick_tol = argc > 4 ? std::pow(10.0, -std::atof(argv[4])) : tol;
      double total_ms = 0; int steps = 0;
      const std::clock_t c0 = std::clock();
      std::printf("transient %dx%d (Fx_ss %.3f):", n, n, ss.fields.Fx_N);
      for (int k = 1; k <= 4 * n; ++k) {
        auto t0 = std::chrono::steady_clock::now();
        ExactSolution s = solve_exact_rolling_step(p, G, nu, {1e-3, 0, 0}, 0.3, 1.0, k == 1 ? nullptr : &prev, o);
        total_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        ++steps;
        if (!s.status.converged()) std::printf(" [step %d not converged]", k);
        prev = s;
        const double q_over_a = 2.0 * k / n;
        if (k == n / 4 || k == n || k == 2 * n || k == 4 * n) std::printf(" q/a %.1f: %.6f", q_over_a, s.fields.Fx_N / ss.fields.Fx_N);
      }
      std::printf("  (%.2f ms per step wall, %.2f ms CPU, tol %.0e, linear %.0e)\n", total_ms / steps,
                  1e3 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / steps, o.tol, o.stick_tol);
    }
  } else if (what == "power") {
    const ElasticPair pair{{210e9, 0.28}, {210e9, 0.28}};
    const double G = combined_shear_modulus_Pa(pair), nu = combined_poisson(pair);
    const std::string load = argc > 2 ? argv[2] : "xi";
    Creepages cr{1e-3, 0, 0};
    if (load == "spin") cr.phi_per_m = 1.0;
    if (load == "eta") cr.eta = 1e-3;
    std::vector<int> grids;
    for (int k = 3; k < argc; ++k) grids.push_back(std::atoi(argv[k]));
    if (grids.empty()) grids = {20, 40, 80, 160};
    // per grid: the candidates' strip powers (W/m)
    const char* names[] = {"upwind (grid)", "trapezoidal", "upwind rescaled", "creep per strip", "centred, slip only"};
    constexpr int kNames = 5;
    std::vector<std::vector<Eigen::ArrayXd>> strips(kNames);
    std::vector<double> work;
    for (const int n : grids) {
      const ContactPatch p = paper_patch(n);
      const std::clock_t c0 = std::clock();
      const ExactSolution s = solve_exact_steady(p, G, nu, cr, 0.3, 1.0);
      const double ms = 1e3 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
      const TangentialSolution& f = s.fields;
      const double W = -f.creep_work_W, dx = p.grid.dx_m, dy = p.grid.dy_m;
      work.push_back(W);
      // the centred slip w + (u_(i-1) - u_(i+1))/(2 dx) on the slip cells only
      Eigen::ArrayXd central = Eigen::ArrayXd::Zero(n);
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          if (f.state(i, j) != 2) continue;
          const double umx = i > 0 ? s.u_x_m(i - 1, j) : s.u_behind_x_m(j), umy = i > 0 ? s.u_y_m(i - 1, j) : s.u_behind_y_m(j);
          const double sx = cr.xi - cr.phi_per_m * p.grid.y_m(j) + (umx - s.u_x_m(i + 1, j)) / (2 * dx);
          const double sy = cr.eta + cr.phi_per_m * p.grid.x_m(i) + (umy - s.u_y_m(i + 1, j)) / (2 * dx);
          central(j) -= (f.tau_x_Pa(i, j) * sx + f.tau_y_Pa(i, j) * sy) * dx;
        }
      const Eigen::ArrayXd c[kNames] = {s.grid_strip_power_W_per_m, f.strip_power_W_per_m,
                                        s.grid_strip_power_W_per_m * (W / s.grid_power_W), f.strip_creep_power_W_per_m,
                                        central};
      std::printf("%s %dx%d: Fx %.4f N, creep work %.6e W, %.0f ms CPU\n", load.c_str(), n, n, f.Fx_N, W, ms);
      for (int k = 0; k < kNames; ++k) {
        strips[k].push_back(c[k]);
        std::printf("  %-20s total %.6e W, /work - 1 %+.3e\n", names[k], c[k].sum() * dy, c[k].sum() * dy / W - 1);
      }
    }
    // the strips summed onto the coarsest grid's (the grids nest: 2^k strips in one), per unit width
    const int nc = grids.front();
    auto coarse = [nc](const Eigen::ArrayXd& a) {
      const int m = static_cast<int>(a.size()) / nc;
      Eigen::ArrayXd c = Eigen::ArrayXd::Zero(nc);
      for (int k = 0; k < a.size(); ++k) c(k / m) += a(k) / m;
      return c;
    };
    const std::size_t last = grids.size() - 1;
    std::printf("creep work against the finest grid's:");
    for (std::size_t g = 0; g < last; ++g) std::printf(" %d: %+.3e", grids[g], work[g] / work[last] - 1);
    std::printf("\n");
    for (int k = 0; k < kNames; ++k) {
      const Eigen::ArrayXd ref = coarse(strips[k][last]);
      const double norm = ref.abs().sum();
      std::printf("%-20s L1 against %d:", names[k], grids[last]);
      for (std::size_t g = 0; g < last; ++g) std::printf(" %d: %.3e", grids[g], (coarse(strips[k][g]) - ref).abs().sum() / norm);
      std::vector<double> d;
      for (std::size_t g = 0; g < last; ++g) d.push_back((coarse(strips[k][g]) - coarse(strips[k][g + 1])).abs().sum() / norm);
      std::printf(" | successive:");
      for (std::size_t g = 0; g < d.size(); ++g) std::printf(" %.3e", d[g]);
      std::printf(" | order:");
      for (std::size_t g = 0; g + 1 < d.size(); ++g) std::printf(" (%d,%d,%d) %.2f", grids[g], grids[g + 1], grids[g + 2], std::log2(d[g] / d[g + 1]));
      // the shape (each grid's strips over its own total)
      std::printf(" | shape L1 against %d:", grids[last]);
      const Eigen::ArrayXd rs = ref / ref.sum();
      for (std::size_t g = 0; g < last; ++g) {
        const Eigen::ArrayXd a = coarse(strips[k][g]);
        std::printf(" %.3e", (a / a.sum() - rs).abs().sum() / rs.abs().sum());
      }
      std::printf("\n");
    }
  } else if (what == "paper") {
    const ElasticPair pair{{210e9, 0.28}, {210e9, 0.28}};
    for (int n : {20, 40, 80, 160, 320}) {
      if (n == 320 && argc < 3) continue;
      ContactPatch p = paper_patch(n);
      auto t0 = std::chrono::steady_clock::now();
      ExactSolution s = solve_exact_steady(p, combined_shear_modulus_Pa(pair), combined_poisson(pair), {1e-3, 0, 0}, 0.3, 1.0);
      double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      std::printf("paper %dx%d: Fx %.3f N, P %.5f W (grid %.5f W), -creep work %.5f W, P/work-1 %+.1e (grid %+.4f), stick %.3f, Newton %d, GMRES %d, %s, %.0f ms wall\n",
                  n, n, s.fields.Fx_N, s.fields.power_W, s.grid_power_W, -s.fields.creep_work_W,
                  s.fields.power_W / -s.fields.creep_work_W - 1, s.grid_power_W / -s.fields.creep_work_W - 1, s.fields.stick_fraction, s.active_set_iterations,
                  s.status.iterations, s.status.message.c_str(), ms);
    }
  }
}
