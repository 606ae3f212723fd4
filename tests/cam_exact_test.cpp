// The cam's contact on the exact physics (cam/halfspace_contact.h, cam/creep_law.h with the exact theory;
// docs/cam-follower.md §16): the half-space contact at an angle against Hertz's closed form on the unworn crowned
// roller and flat track, within the half-space's grid error (docs/halfspace.md), and independent of the window it
// is solved on; the exact creep law's linear coefficient against Kalker's C11 (Richardson over three grids, as
// docs/exact-theory.md checks the exact solver) and its saturation at mu times the grid's load; the case keys.
#include <gtest/gtest.h>

#include "tests/cam_shipped_law.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "cam/cam_case.h"
#include "cam/creep_law.h"
#include "cam/halfspace_contact.h"
#include "cam/revolution.h"
#include "cam/revolution_dissipation.h"
#include "cam/roller_motion.h"
#include "lib/errors.h"
#include "lib/normal/hertz.h"
#include "lib/numeric.h"
#include "lib/tangential/kalker.h"
#include "tests/log_capture.h"
#include "tests/temp_dir.h"

namespace {

using namespace cam;
using contact::kPi;
namespace fs = std::filesystem;

constexpr double kDeg = kPi / 180;
constexpr double kInf = std::numeric_limits<double>::infinity();

// the shipped case's roller and track: a crowned roller (R 0.5 m across) on a flat track, steel on steel
RollerAndTrack shipped_bodies() { return {0.011, 0.5, 0.014, kInf, {{2.1e11, 0.3}, {2.1e11, 0.3}}}; }

// the kinematics on the base circle (r_b 40 mm, roller 13 mm, radial follower) at 300 deg
CamKinematics dwell_kinematics() {
  const LiftLaw law = shipped_lift_law();
  CamGeometry g;
  g.base_radius_m = 0.04;
  g.roller_radius_m = 0.013;
  return cam_kinematics(g, lift_at(law, 300 * kDeg), 300 * kDeg, 62.8);
}

contact::HertzContact dwell_hertz(double load_N) {
  const contact::Bodies radii{{0.013, 0.5}, {cam_radius_m(dwell_kinematics()), kInf}};
  return contact::solve_hertz(radii, shipped_bodies().pair, load_N);
}

// On the unworn crowned roller and flat track the half-space contact is Hertz's to the grid's error: 24 cells over
// the contact's length and 24 strips over its width (between the 16 and 32 rows of docs/halfspace.md's tables:
// approach within 0.1 %, the patch's a, b within 1.6 % and p0 within 2.4 % there); the strips carry the load.
TEST(CamHalfspace, UnwornContactIsHertzWithinTheGridError) {
  const RollerAndTrack bodies = shipped_bodies();
  const contact::Profiles profiles = roller_and_track_profiles(bodies);
  const double F = 150;
  const contact::HertzContact h = dwell_hertz(F);
  HalfspaceAngleSettings s;
  s.grid = {24, 24};
  HalfspaceAngleStats stats;
  const contact::NormalSolution n =
      halfspace_angle_normal(bodies, profiles, 0.013, cam_radius_m(dwell_kinematics()), F, s, &stats);
  ASSERT_TRUE(n.solve_converged);
  EXPECT_EQ(n.solver, contact::NormalSolverKind::Halfspace);
  EXPECT_FALSE(n.reaches_edge);
  EXPECT_EQ(n.patches, 1);
  EXPECT_NEAR(n.patch.approach_m / h.approach_m, 1, 2e-3);
  EXPECT_NEAR(n.patch.a_m / h.a_m, 1, 0.02);
  EXPECT_NEAR(n.patch.b_m / h.b_m, 1, 0.02);
  EXPECT_NEAR(n.patch.p0_Pa / h.p0_Pa, 1, 0.03);
  const contact::ContactPatch& p = n.patch;
  EXPECT_NEAR(p.pressure_Pa.sum() * p.grid.dx_m * p.grid.dy_m / F, 1, 1e-6);
  // the contact is centred on the crown's vertex (y = 0): the strips' centroid is its Heathcote reference
  EXPECT_NEAR(n.on_profiles.reference_y_m, 0, 0.5 * p.grid.dy_m);
  EXPECT_EQ(stats.solves, 1);  // Hertz's approach, 1.1 times, held the contact at once
}

// The lattice does not move with the window: started from a tenth of the approach (three enlargements of the
// window) or from twice it, the solution is the same to the solver's tolerance; and on a fixed lateral window
// (the life's) the strips lie at lo + (j + 1/2) dy whatever the contact.
TEST(CamHalfspace, SolutionDoesNotDependOnTheWindow) {
  const RollerAndTrack bodies = shipped_bodies();
  const contact::Profiles profiles = roller_and_track_profiles(bodies);
  const double F = 300, Rc = cam_radius_m(dwell_kinematics());
  const contact::HertzContact h = dwell_hertz(F);
  HalfspaceAngleSettings s;
  s.grid = {16, 16};
  s.fixed_y_lo_m = -0.0055;
  s.fixed_y_hi_m = 0.0055;
  s.fixed_strips = 2 * static_cast<int>(std::ceil(0.0055 / (2 * h.b_m / 16)));
  const double dy = 0.011 / s.fixed_strips;
  HalfspaceAngleStats small_stats, large_stats;
  s.initial_approach_m = 0.1 * h.approach_m;
  contact::NormalSolution small;
  {
    const rollwear_test::ExpectWarnings cut;  // the half-space solver warns of each cut window (docs/halfspace.md)
    small = halfspace_angle_normal(bodies, profiles, 0.013, Rc, F, s, &small_stats);
  }
  s.initial_approach_m = 2 * h.approach_m;
  const contact::NormalSolution large = halfspace_angle_normal(bodies, profiles, 0.013, Rc, F, s, &large_stats);
  EXPECT_GT(small_stats.solves, 1);
  EXPECT_EQ(large_stats.solves, 1);
  EXPECT_GT(large_stats.window_nx * large_stats.window_ny, small_stats.window_nx * small_stats.window_ny);
  // the patches (the loaded cells' box) are the same cells
  ASSERT_EQ(small.patch.grid.nx, large.patch.grid.nx);
  ASSERT_EQ(small.patch.grid.ny, large.patch.grid.ny);
  EXPECT_DOUBLE_EQ(small.grid_y0_m, large.grid_y0_m);
  EXPECT_NEAR(small.patch.approach_m / large.patch.approach_m, 1, 1e-7);
  EXPECT_LT((small.patch.strip_peak_Pa - large.patch.strip_peak_Pa).abs().maxCoeff(), 1e-6 * large.patch.p0_Pa);
  // strip j of the patch at the fixed lattice's centres
  for (int j = 0; j < large.patch.grid.ny; ++j) {
    const double k = (large.grid_y0_m + large.patch.grid.y_m(j) - s.fixed_y_lo_m) / dy - 0.5;
    EXPECT_NEAR(k, std::round(k), 1e-6) << j;
  }
}

// The exact creep law in its linear range: the creepage carrying 1e-4 of mu F_n (no Heathcote slip) gives
// C11 = -F/(G a b xi); over 20, 40 and 80 cells its Richardson extrapolation (docs/exact-theory.md) is Kalker's C11
// at the contact's a/b within 1 % (the exact solver's own check on Hertz patches); the inversion finds the creepage
// to its tolerance.
TEST(CamExactCreepLaw, SmallForceGivesKalkersC11) {
  const RollerAndTrack bodies = shipped_bodies();
  const contact::Profiles profiles = roller_and_track_profiles(bodies);
  const double F = 150, mu = 0.1;
  double C[3] = {0, 0, 0};
  double a_over_b = 0, C11_kalker = 0;
  const int cells[3] = {20, 40, 80};
  for (int k = 0; k < 3; ++k) {
    CreepLawSettings s;
    s.grid = {cells[k], cells[k]};
    s.heathcote_slip = false;
    s.scheme = contact::TangentialScheme::Exact;
    const AngleContact c = angle_contact(bodies, profiles, 0.013, dwell_kinematics(), F, mu, s);
    const double force = -1e-4 * mu * F;
    const CreepageForForce q = creepage_for_force(c, force);
    ASSERT_TRUE(q.found);
    EXPECT_NEAR(steady_creep_force_N(c, q.xi), force, creep_force_tolerance_N(c));
    const contact::ContactPatch& p = c.normal.patch;
    C[k] = -force / (c.G_Pa * p.a_m * p.b_m * q.xi);
    a_over_b = p.a_m / p.b_m;
    C11_kalker = c.problem.C.C11;  // Kalker's table at the patch's a/b and nu (lib/tangential/kalker.h)
  }
  const double richardson = (8 * C[2] - 6 * C[1] + C[0]) / 3;
  EXPECT_LT(a_over_b, 1);  // the crowned roller's contact is longer across than along
  EXPECT_NEAR(richardson / C11_kalker, 1, 0.01) << C[0] << " " << C[1] << " " << C[2];
  EXPECT_GT(C[0], C[1]);  // first order from above, as the exact solver's table
  EXPECT_GT(C[1], C[2]);
}

// Saturation: at a gross creepage every cell slides and the force is mu times the grid's load, which the patch's
// cells carry exactly (mu F_n), to the solver's tolerance; the sign opposes the creepage.
TEST(CamExactCreepLaw, SaturatesAtMuTimesTheLoad) {
  const RollerAndTrack bodies = shipped_bodies();
  const contact::Profiles profiles = roller_and_track_profiles(bodies);
  const double F = 150, mu = 0.1;
  CreepLawSettings s;
  s.grid = {20, 20};
  s.scheme = contact::TangentialScheme::Exact;
  s.normal = contact::NormalChoice::Halfspace;
  const AngleContact c = angle_contact(bodies, profiles, 0.013, dwell_kinematics(), F, mu, s);
  const contact::ContactPatch& p = c.normal.patch;
  const double grid_load = p.pressure_Pa.sum() * p.grid.dx_m * p.grid.dy_m;
  EXPECT_NEAR(grid_load / F, 1, 1e-6);
  const double xi_sat = 3 * mu * F / (c.G_Pa * p.a_m * p.b_m * c.problem.C.C11);
  for (const double sign : {1.0, -1.0}) {
    const contact::TangentialSolution sol = steady_creep(c, sign * 20 * xi_sat, 1.0);
    EXPECT_NEAR(sol.Fx_N / (-sign * mu * grid_load), 1, 1e-6);
    EXPECT_NEAR(sol.stick_fraction, 0, 1e-12);
  }
  // just below it the law still sticks somewhere and carries less
  const double half = steady_creep_force_N(c, 0.3 * xi_sat);
  EXPECT_LT(std::abs(half), 0.99 * mu * F);
  EXPECT_GT(std::abs(half), 0.3 * mu * F);
}

// The exact solve's strips carry rounding of either sign where nothing slips: within 1e-9 of the step's scale it is
// taken as 0 (also when the whole step dissipates next to nothing), a real negative power is kept for the wear to
// refuse.
TEST(CamExactCreepLaw, StripRoundingIsZeroARealNegativePowerIsKept) {
  const RollerAndTrack bodies = shipped_bodies();
  const contact::Profiles profiles = roller_and_track_profiles(bodies);
  CreepLawSettings s;
  s.grid = {8, 8};
  s.scheme = contact::TangentialScheme::Consistent;
  const AngleContact c = angle_contact(bodies, profiles, 0.013, dwell_kinematics(), 150, 0.1, s);
  RevolutionRow row;
  RollerAngle roller;
  roller.speed_m_per_s = 2.5;
  contact::TangentialSolution sol;
  sol.strip_power_W_per_m = Eigen::ArrayXd::Zero(c.normal.patch.grid.ny);
  sol.strip_power_W_per_m(0) = -3e-18;  // all of the step's power is rounding
  EXPECT_EQ(angle_dissipation(c, row, roller, 1e-4, sol).power_W_per_m(0), 0.0);
  sol.strip_power_W_per_m(1) = 10;
  sol.strip_power_W_per_m(2) = -1e-3;  // 1e-4 of the largest: not rounding
  const AngleDissipation d = angle_dissipation(c, row, roller, 1e-4, sol);
  EXPECT_EQ(d.power_W_per_m(0), 0.0);
  EXPECT_EQ(d.power_W_per_m(2), -1e-3);
}

// cam.normal.solver and cam.tangential.scheme: exact and halfspace read; hertz, an unknown solver and classic refused
// at their line, naming the key
using CamExactCaseTest = rollwear_test::TempDirTest;
TEST_F(CamExactCaseTest, NormalSolverAndExactSchemeReadBadOnesRefusedAtTheirKey) {
  std::stringstream in;
  in << std::ifstream(fs::path(ROLLWEAR_SOURCE_DIR) / "cases" / "cam-follower.yaml").rdbuf();
  const std::string shipped = in.str();
  const std::string key = "  tangential: { scheme: consistent }";
  ASSERT_NE(shipped.find(key), std::string::npos);
  const auto with = [&](const std::string& lines) {
    std::string t = shipped;
    t.replace(t.find(key), key.size(), lines);
    return t;
  };
  const fs::path f = dir_ / "c.yaml";
  {
    std::ofstream(f) << with("  tangential: { scheme: exact }\n  normal: { solver: halfspace }");
    const CamCase c = read_cam_case(f.string());
    EXPECT_EQ(c.solver.scheme, contact::TangentialScheme::Exact);
    EXPECT_EQ(c.solver.normal, contact::NormalChoice::Halfspace);
  }
  {
    std::ofstream(f) << shipped;
    EXPECT_EQ(read_cam_case(f.string()).solver.normal, contact::NormalChoice::Auto);
  }
  {  // the shipped exact case
    const CamCase c = read_cam_case((fs::path(ROLLWEAR_SOURCE_DIR) / "cases" / "cam-follower-exact.yaml").string());
    EXPECT_EQ(c.solver.scheme, contact::TangentialScheme::Exact);
    EXPECT_EQ(c.solver.normal, contact::NormalChoice::Halfspace);
    EXPECT_EQ(c.model.angle_steps, 720);
    ASSERT_TRUE(c.wear.has_value());
  }
  const auto refused = [&](const std::string& lines, const std::string& bad, const std::string& key_path,
                           const std::string& also) {
    const std::string t = with(lines);
    std::ofstream(f) << t;
    const int line = 1 + static_cast<int>(std::count(t.begin(), t.begin() + static_cast<long>(t.find(bad)), '\n'));
    try {
      read_cam_case(f.string());
      ADD_FAILURE() << "accepted: " << lines;
    } catch (const contact::CaseError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(f.string() + ":" + std::to_string(line) + ":", 0), 0u) << what;
      EXPECT_NE(what.find(key_path), std::string::npos) << what;
      EXPECT_NE(what.find(also), std::string::npos) << what;
    }
  };
  refused("  tangential: { scheme: exact }\n  normal: { solver: hertz }", "hertz", "cam.normal.solver",
          "semi-hertz or halfspace");
  refused("  tangential: { scheme: exact }\n  normal: { solver: boussinesq }", "boussinesq", "cam.normal.solver",
          "must be auto");
  refused("  tangential: { scheme: exact }\n  normal: { solvr: halfspace }", "solvr", "cam.normal.solvr",
          "unknown key");
  refused("  tangential: { scheme: classic }", "classic", "cam.tangential.scheme", "does not take classic");
}

}  // namespace
