// The cam track's wear map and the roller's wear over one revolution (cam/cam_wear.h), against closed
// forms on synthetic dissipation records (docs/cam-follower.md §11).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "cam/cam_wear.h"
#include "lib/numeric.h"

namespace {

using cam::AngleDissipation;
using cam::CamWearGrid;
using cam::CamWearLaws;
using cam::RevolutionDissipation;

// the closed forms below are exact sums of a few terms: rounding only
constexpr double kRoundingRtol = 1e-12;

constexpr double kL = 0.25;       // circumference, m
constexpr double kTrackW = 0.012; // m
constexpr double kRollerW = 0.010;
constexpr double kRollerR = 0.013;
constexpr double kOmega = 60.0;   // rad/s
constexpr double kE = 2e-14;      // k_E, m^3/J

CamWearGrid grid(int arc_cells, int lateral_cells) {
  CamWearGrid g;
  g.circumference_m = kL;
  g.arc_cells = arc_cells;
  g.track_width_m = kTrackW;
  g.track_cells = lateral_cells;
  g.roller_radius_m = kRollerR;
  g.roller_width_m = kRollerW;
  g.roller_cells = lateral_cells;
  return g;
}

CamWearLaws energy_laws() {
  CamWearLaws l;
  l.cam = wear::WearLaw{};
  l.cam->law = wear::WearLawKind::Energy;
  l.cam->k_E_m3_per_J = kE;
  l.roller = l.cam;
  return l;
}

// strips of equal width exactly covering [-w/2, w/2]
Eigen::ArrayXd strips(double width_m, int n) {
  Eigen::ArrayXd y(n);
  for (int j = 0; j < n; ++j) y(j) = -0.5 * width_m + (j + 0.5) * width_m / n;
  return y;
}

// n equal angle steps; the arc swept per step proportional to speed(theta), the arcs tiling [0, L):
// V_k = arc_k / dt_k; the power per unit width power(k, y)
template <class Speed, class Power>
RevolutionDissipation revolution(int n, Speed speed, Power power, const Eigen::ArrayXd& y, double arc0_m = 0) {
  const double dt = 2 * contact::kPi / n / kOmega;
  std::vector<double> weight(n);
  double total = 0;
  for (int k = 0; k < n; ++k) total += weight[k] = speed(2 * contact::kPi * k / n);
  RevolutionDissipation rev(n);
  double arc = arc0_m;
  for (int k = 0; k < n; ++k) {
    AngleDissipation& a = rev[k];
    a.theta_rad = 2 * contact::kPi * k / n;
    a.duration_s = dt;
    a.cam_arc_m = arc;
    const double swept = kL * weight[k] / total;
    a.rolling_speed_m_per_s = swept / dt;
    a.roller_surface_speed_m_per_s = a.rolling_speed_m_per_s;
    arc += swept;
    a.y_m = y;
    a.power_W_per_m.resize(y.size());
    for (Eigen::Index j = 0; j < y.size(); ++j) a.power_W_per_m(j) = power(k, a.rolling_speed_m_per_s, y(j));
  }
  return rev;
}

// Uniform P_l / V: the map is uniform, depth k_E P_l / V per revolution, though the arc each step sweeps
// varies threefold over the revolution; the roller's depth is k_E sum P_l dt / (2 pi R_r).
TEST(CamWear, UniformPowerOverSpeedWearsTheTrackUniformly) {
  const CamWearGrid g = grid(90, 12);
  const double c = 3.0;  // P_l / V, J/m^2
  const RevolutionDissipation rev = revolution(
      360, [](double th) { return 2 + std::sin(th); }, [&](int, double V, double) { return c * V; }, strips(kTrackW, 24));
  const cam::CamWearRate r = cam::wear_per_revolution(rev, g, energy_laws());
  const Eigen::ArrayXXd& h = r.depth_per_revolution.cam_depth_m;
  EXPECT_NEAR(h.minCoeff(), kE * c, kRoundingRtol * kE * c);
  EXPECT_NEAR(h.maxCoeff(), kE * c, kRoundingRtol * kE * c);
  // energy: sum over steps of P_l w dt = c w sum(V dt) = c w L, all of it on the track
  EXPECT_NEAR(r.energy_J, c * kTrackW * kL, kRoundingRtol * c * kTrackW * kL);
  EXPECT_NEAR(r.track_energy_J, r.energy_J, kRoundingRtol * r.energy_J);
  // the roller: its cells under the strips (its width is within the track's) get c L per unit width
  const double roller = kE * c * kL / (2 * contact::kPi * kRollerR);
  EXPECT_NEAR(r.depth_per_revolution.roller_depth_m.minCoeff(), roller, kRoundingRtol * roller);
  EXPECT_NEAR(r.depth_per_revolution.roller_depth_m.maxCoeff(), roller, kRoundingRtol * roller);
}

// One angle step dissipates: the depth is k_E P_l dt / (arc swept) over its arc and zero elsewhere, the
// cells its arc's ends cut carrying their overlap's share. Checked on a step inside the circumference and,
// with the revolution's arcs starting at 0.37 L, on a step whose arc wraps over sigma = L.
TEST(CamWear, SingleAngleStepWearsOnlyItsArc) {
  const CamWearGrid g = grid(100, 4);  // arc cells of 2.5 mm
  const int n = 37;                     // steps sweep L/37 = 6.76 mm: cells cut at both ends
  const double P = 50.0;
  for (const int hot : {5, 23}) {
    const double arc0 = hot == 5 ? 0.0 : 0.37 * kL;  // step 23 then covers [0.9916 L, 1.0187 L)
    const RevolutionDissipation rev = revolution(
        n, [](double) { return 1.0; }, [&](int k, double, double) { return k == hot ? P : 0.0; },
        strips(kTrackW, 8), arc0);
    const cam::CamWearRate r = cam::wear_per_revolution(rev, g, energy_laws());
    const double lo = rev[hot].cam_arc_m, hi = lo + kL / n;
    const double inside = kE * P * rev[hot].duration_s / (kL / n);
    const double ds = g.arc_cell_m();
    for (int i = 0; i < g.arc_cells; ++i) {
      // the cell's overlap with [lo, hi) modulo L
      double overlap = 0;
      for (double shift : {-kL, 0.0, kL})
        overlap += std::max(0.0, std::min(hi, (i + 1) * ds + shift) - std::max(lo, i * ds + shift));
      const double want = inside * overlap / ds;
      for (int j = 0; j < g.track_cells; ++j)
        ASSERT_NEAR(r.depth_per_revolution.cam_depth_m(i, j), want, kRoundingRtol * inside)
            << "step " << hot << " cell " << i;
    }
    EXPECT_GT(r.depth_per_revolution.cam_depth_m.maxCoeff(), 0.99 * inside);
  }
}

// Whatever the power's shape, the track's worn volume is k_E times the energy falling on it (energy
// deposited by overlap, never lost), and archard is the energy law with k_E = K / (H mu).
TEST(CamWear, WornVolumeIsTheEnergyLawsAndArchardIsItsSpecialCase) {
  const CamWearGrid g = grid(73, 9);
  const auto power = [](int k, double V, double y) { return (1 + 0.5 * std::cos(0.3 * k)) * V * (1e-4 - y * y) * 1e5; };
  // strips narrower than the track and off its cell boundaries, reaching beyond the roller's width
  const RevolutionDissipation rev = revolution(
      200, [](double th) { return 1.5 + std::cos(2 * th); }, power, strips(0.0105, 17));
  const cam::CamWearRate r = cam::wear_per_revolution(rev, g, energy_laws());
  const double volume = r.depth_per_revolution.cam_depth_m.sum() * g.arc_cell_m() * g.track_cell_m();
  EXPECT_NEAR(volume, kE * r.track_energy_J, kRoundingRtol * kE * r.track_energy_J);
  EXPECT_NEAR(r.track_energy_J, r.energy_J, kRoundingRtol * r.energy_J);  // the strips lie within the track
  EXPECT_LT(r.roller_energy_J, r.energy_J);                               // but not within the roller

  CamWearLaws archard;
  archard.mu = 0.1;
  archard.cam = wear::WearLaw{};
  archard.cam->law = wear::WearLawKind::Archard;
  archard.cam->archard_k = 1e-6;
  archard.cam->hardness_Pa = 5e9;
  CamWearLaws energy;
  energy.cam = wear::WearLaw{};
  energy.cam->k_E_m3_per_J = 1e-6 / (5e9 * 0.1);
  const Eigen::ArrayXXd a = cam::wear_per_revolution(rev, g, archard).depth_per_revolution.cam_depth_m;
  const Eigen::ArrayXXd e = cam::wear_per_revolution(rev, g, energy).depth_per_revolution.cam_depth_m;
  EXPECT_LE((a - e).abs().maxCoeff(), kRoundingRtol * e.maxCoeff());
  EXPECT_EQ(cam::wear_per_revolution(rev, g, archard).depth_per_revolution.roller_depth_m.abs().maxCoeff(), 0.0);
}

TEST(CamWear, RefusesWhatTheRecordCannotFeedAndBadRecords) {
  const CamWearGrid g = grid(10, 4);
  RevolutionDissipation rev = revolution(
      12, [](double) { return 1.0; }, [](int, double, double) { return 1.0; }, strips(kTrackW, 4));
  CamWearLaws kth;
  kth.cam = wear::WearLaw{};
  kth.cam->law = wear::WearLawKind::Kth;
  kth.cam->hardness_Pa = 5e9;
  EXPECT_THROW(cam::wear_per_revolution(rev, g, kth), std::invalid_argument);
  RevolutionDissipation back = rev;
  back[3].theta_rad = back[2].theta_rad;
  EXPECT_THROW(cam::wear_per_revolution(back, g, energy_laws()), std::invalid_argument);
  RevolutionDissipation negative = rev;
  negative[4].power_W_per_m(1) = -1;
  EXPECT_THROW(cam::wear_per_revolution(negative, g, energy_laws()), std::invalid_argument);
  RevolutionDissipation beyond = rev;
  beyond.back().cam_arc_m = kL + 1e-6;
  EXPECT_THROW(cam::wear_per_revolution(beyond, g, energy_laws()), std::invalid_argument);
  EXPECT_NO_THROW(cam::wear_per_revolution(rev, g, energy_laws()));
}

// The worn profiles carry each body's depth at its nodes; the recession under a crowned roller on a flat
// track is the two depths at the crown's top, y = 0.
TEST(CamWear, WornProfilesAndTheRecessionReadTheDepths) {
  CamWearGrid g = grid(20, 6);
  cam::CamWearState s = cam::unworn_state(g);
  for (int i = 0; i < g.arc_cells; ++i)
    for (int j = 0; j < g.track_cells; ++j) s.cam_depth_m(i, j) = 1e-6 * (1 + i);  // grows along the arc
  s.roller_depth_m.setConstant(2e-7);
  contact::Profiles unworn;
  unworn.body1 = contact::crowned_profile(0.5, kRollerW);
  unworn.body2 = contact::flat_profile(kTrackW);
  // at an arc cell's centre, the cell's depth; half-way between two centres, their mean
  const double at5 = g.arc_m(5), between = 0.5 * (g.arc_m(5) + g.arc_m(6));
  EXPECT_NEAR(cam::cam_depth_at(g, s, at5, 0.001), 6e-6, 1e-18);
  EXPECT_NEAR(cam::cam_depth_at(g, s, between, -0.004), 6.5e-6, 1e-18);
  // periodic: before the first centre, between the last cell and the first
  EXPECT_NEAR(cam::cam_depth_at(g, s, 0.0, 0.0), 0.5 * (1e-6 + 20e-6), 1e-18);
  const contact::Profiles worn = cam::worn_profiles_at(unworn, g, s, at5);
  EXPECT_NEAR(worn.body2.z_m(7) - unworn.body2.z_m(7), 6e-6, 1e-18);
  EXPECT_NEAR(worn.body1.z_m(100) - unworn.body1.z_m(100), 2e-7, 1e-18);
  EXPECT_NEAR(cam::normal_recession_m(unworn, g, s, at5), 6e-6 + 2e-7, 1e-15);
}

TEST(CamWear, CellAnglesFollowTheArcs) {
  const CamWearGrid g = grid(8, 2);
  // the first half of the revolution sweeps 3/4 of the circumference
  const RevolutionDissipation rev = revolution(
      4, [](double th) { return th < contact::kPi ? 3.0 : 1.0; }, [](int, double, double) { return 0.0; },
      strips(kTrackW, 2));
  const Eigen::ArrayXd theta = cam::cell_angles_rad(g, rev);
  // arc cell 0's centre L/16 lies 1/6 into step 0's arc (3L/8): theta = (pi/2)/6
  EXPECT_NEAR(theta(0), contact::kPi / 12, 1e-14);
  // cell 7's centre 15L/16 lies half-way into the last step's arc (L/8): theta = 3pi/2 + pi/4
  EXPECT_NEAR(theta(7), 1.75 * contact::kPi, 1e-14);
}

}  // namespace
