// The wear of the cam track and of the roller over one cam revolution (docs/cam-follower.md §11), from
// the dissipated power the revolution's tangential solve hands over (cam/angle_dissipation.h), through
// the project's wear laws (wear/wear_law.h: energy, and archard as the energy law with k_E = K/(H mu)).
//
// The cam track. A point of the track at arc sigma (from the contact's position at theta = 0) and lateral
// y meets the contact once per revolution. While the contact's centre moves over it at the speed V along
// the cam, the point collects the energy per unit area int D dt = int D dx / V = P_l(y) / V (D the
// dissipated power per unit area, P_l its integral along the rolling direction: the power per unit
// width), so the depth per pass is k_E P_l(y) / V. Over angle step k, [theta_k, theta_k+1) of duration
// dt_k, the contact's centre sweeps the arc [sigma_k, sigma_k+1) and the step dissipates P_l dt_k per unit
// width; spread evenly over that arc it is a depth k_E P_l dt_k / (sigma_k+1 - sigma_k) = k_E P_l / V to
// first order in the step, with the arc covered per step varying with theta as the kinematics make it.
// The steps' arcs tile the circumference [0, L) exactly (the last one ends at sigma_0 + L), so the energy
// is deposited onto the fixed arc cells by overlap and the worn volume is k_E times the dissipated energy
// to rounding. Laterally the strips' energy is deposited onto the fixed lateral cells by overlap likewise
// (a strip j covers the half-way points to its neighbours). The map resolves the wear to the arc cells and
// the steps; it assigns each step's energy to the arc its centre sweeps, so variations of P_l / V over the
// contact's own length 2a are smeared (the map is exact where P_l / V is constant over 2a).
//
// The roller meets the contact all around (its surface passes through it many times per cam revolution at
// changing positions): its depth per cam revolution is spread evenly around it,
//   dh_r(y) = k_E sum_k P_l(y) dt_k / (2 pi R_r),
// wear::depth_per_duty_cycle with the duty cycle one cam revolution and the worn radius R_r. The track's
// cells use the same function with the energy a cell receives and the cell's length L / n_arc as the
// circumference it is spread over (2 pi R_w = L / n_arc): the wear law is written once, in wear/.
//
// The roller and the track share the lateral coordinate y (the roller centred on the track's centre
// line, as the revolution's solve assumes). kth and usfd need per-cell slip fields, which an angle step's
// record does not carry: refused (std::invalid_argument naming the law).
#pragma once

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

#include "cam/angle_dissipation.h"
#include "lib/normal/profile.h"
#include "wear/fatigue.h"
#include "wear/wear_case.h"
#include "wear/wear_law.h"

namespace contact {
class YamlMap;
}

namespace cam {

// The fixed grid the wear lives on: n_arc equal cells of the track's arc [0, L) (from the contact's place
// at theta = 0, in the direction the contact moves), n_track equal lateral cells over the track's width,
// n_roller over the roller's; a cell's depth is its mean.
struct CamWearGrid {
  double circumference_m = 0;    // L: the cam's surface length along the contact's path
  int arc_cells = 0;             // n_arc >= 1
  double track_width_m = 0;      // cells over [-w/2, w/2]
  int track_cells = 0;
  double roller_radius_m = 0;    // R_r, the roller's worn radius
  double roller_width_m = 0;
  int roller_cells = 0;
  Eigen::ArrayXd cell_theta_rad;  // (n_arc) the cam angle at which the contact's centre passes each arc
                                  // cell's centre (for the output; empty: not known)

  double arc_cell_m() const { return circumference_m / arc_cells; }
  double track_cell_m() const { return track_width_m / track_cells; }
  double roller_cell_m() const { return roller_width_m / roller_cells; }
  double track_y_m(int j) const { return -0.5 * track_width_m + (j + 0.5) * track_cell_m(); }
  double roller_y_m(int j) const { return -0.5 * roller_width_m + (j + 0.5) * roller_cell_m(); }
  double arc_m(int i) const { return (i + 0.5) * arc_cell_m(); }
};

// throws std::invalid_argument for a size <= 0 or not finite, or a cell count < 1
void check_grid(const CamWearGrid& g);

// the cam angle at each arc cell's centre, interpolated on the revolution's (theta, arc) pairs (periodic)
Eigen::ArrayXd cell_angles_rad(const CamWearGrid& g, const RevolutionDissipation& rev);

// which bodies wear, and by which law (archard reads mu, the roller-cam friction)
// With the lubricant's regime law fed back (cam/cam_lubrication.h, regime_wear_laws), per angle step k of the
// revolution's record: the friction mu_k its solves used and the factor f_k on the wear coefficient; the step's
// energy then wears f_k times as much, and under archard (k_E = K/(H mu)) with its own mu_k: its energy is weighted
// by f_k mu / mu_k before the law's k_E at mu. Empty: mu and factor 1 at every step.
struct CamWearLaws {
  std::optional<wear::WearLaw> cam, roller;
  double mu = 0;
  std::vector<double> mu_by_step, wear_factor_by_step;  // both empty, or one per angle step of the record
};

// the worn state: depths (m, into the material) on the grid's cells
struct CamWearState {
  Eigen::ArrayXXd cam_depth_m;    // (arc_cells x track_cells)
  Eigen::ArrayXd roller_depth_m;  // (roller_cells)
};
CamWearState unworn_state(const CamWearGrid& g);

// one revolution's wear: the depth per cam revolution on the grid, and the energy it came from
struct CamWearRate {
  CamWearState depth_per_revolution;
  double energy_J = 0;             // dissipated over the revolution (sum of P_l dy dt)
  double track_energy_J = 0;       // of it, what falls on the track's width (the rest is outside it)
  double roller_energy_J = 0;      // ... on the roller's width
};

// Checks the record: at least one step, thetas strictly increasing within [theta_0, theta_0 + 2 pi),
// arcs strictly increasing with the last below arc_0 + L, durations > 0, the strips' arrays of one size
// (>= 1; two or more strictly increasing centres, or one strip with its width unknown: refused), every
// value finite and the power >= 0. Throws std::invalid_argument naming the step and what.
void check_dissipation(const RevolutionDissipation& rev, const CamWearGrid& g);

// The depth per cam revolution from one revolution's dissipation (see the top). Throws
// std::invalid_argument for what check_dissipation and check_grid refuse and for a law the record cannot
// feed (kth, usfd).
CamWearRate wear_per_revolution(const RevolutionDissipation& rev, const CamWearGrid& g, const CamWearLaws& laws);

// Adds amount, spread evenly over [lo, hi) (hi > lo), onto the cells [i dx, (i + 1) dx), i in [0, n), of
// out by overlap. periodic: positions are taken modulo n dx (hi - lo <= n dx); otherwise what falls
// outside [0, n dx) is dropped. Returns what was deposited. (The wear map's and the damage map's.)
double deposit(double lo, double hi, double amount, double dx, int n, bool periodic, double* out);
// the edges of the strips whose centres are y (strictly increasing, >= 2): half-way between centres, the
// outer ones half a neighbouring spacing beyond
Eigen::ArrayXd strip_edges(const Eigen::ArrayXd& y);

// ---- the worn geometry ----

// linear interpolation weights between cell centres x_c = (c + 0.5) dx of n cells: x lies between cells c0 and c1,
// with weight w1 on c1; periodic wraps (the arc), otherwise constant beyond the outer centres (across)
void cell_weights(double x, double dx, int n, bool periodic, int& c0, int& c1, double& w1);

// the cam's worn depth at arc sigma (periodic, linear between arc cell centres) and lateral y (linear
// between lateral cell centres, constant beyond the outer ones)
double cam_depth_at(const CamWearGrid& g, const CamWearState& s, double arc_m, double y_m);
// the roller's worn depth at lateral y (likewise)
double roller_depth_at(const CamWearGrid& g, const CamWearState& s, double y_m);

// The lateral profiles the normal problem works on at the cam's arc sigma: the unworn ones (body 1 the
// roller, body 2 the track, as roller_and_track_profiles makes them) with each body's worn depth added at
// its nodes (z points into the material). What the revolution's solve calls at each angle.
contact::Profiles worn_profiles_at(const contact::Profiles& unworn, const CamWearGrid& g, const CamWearState& s,
                                   double arc_m);

// The recession of the cam surface under the roller along the contact normal at arc sigma: how much closer
// the bodies' unloaded surfaces come, min_y (g0 + h_cam + h_roller) - min_y g0 with g0 = z_roller + z_track
// the unworn lateral gap, over the profiles' lateral overlap (on the roller's nodes). >= 0.
double normal_recession_m(const contact::Profiles& unworn, const CamWearGrid& g, const CamWearState& s,
                          double arc_m);

// ---- output ----

// the header lines of a map on the grid (the case, what, the revolutions, the grid): the wear maps' and the damage's
std::string grid_csv_header(const CamWearGrid& g, double revolutions, const std::string& name, const std::string& what);
// The wear map at a revolution, one row per (arc cell, lateral cell), arc-major:
//   cam_angle_deg,cam_arc_m,y_m,depth_m
// cam_angle_deg the cam angle at which the contact passes the cell (nan when the grid does not know it),
// preceded by "# " comment lines: the case, the revolutions, the grid.
std::string wear_map_csv(const CamWearGrid& g, const CamWearState& s, double revolutions, const std::string& name);
// The roller's worn profile: y_m,depth_m (one row per lateral cell), with the same comment lines.
std::string roller_wear_csv(const CamWearGrid& g, const CamWearState& s, double revolutions, const std::string& name);

// ---- the case's wear inputs (the cam: section's wear: keys, docs/cam-follower.md §13) ----
//
//   wear:
//     cam:    { law: archard, archard_k: 1.0e-6, hardness_Pa: 6.5e9 }   # the track (and/or roller:)
//     roller: { law: archard, archard_k: 1.0e-6, hardness_Pa: 6.5e9 }
//     revolutions: 1.0e10           # the life budget in cam revolutions (required)
//     limits: { max_depth_m: 2.0e-5, max_lift_loss_m: 2.0e-5 }   # 0 = no such limit; one at least
//     stepping: { method: adaptive, rtol: 1.0e-3, ... }          # as wear.stepping (wear/wear_case.h)
//     arc_cells: 720                # cells along the cam's circumference
//     lateral_cells: 56             # across the track (and across the roller)
//     smoothing_wavelength_m: 5.0e-4   # cut-off of the rate's lateral Gaussian filter (as a wear case's)
//     snapshots_revolutions: [1.0e8, 1.0e9]   # wear maps written there (and at the start and end)
//     checkpoint_interval_s: 10     # wall time between checkpoints of `rollwear run` (0: every step)
//     fatigue: { law: burstow, threshold_N: 20, ... }   # as wear.fatigue (docs/fatigue.md): damage per cell, §19
struct CamWearSpec {
  CamWearLaws laws;  // mu is the case's cam.mu
  double revolutions = 0;
  double max_depth_m = 0;      // the life ends where the deepest wear of either body reaches it; 0 = none
  double max_lift_loss_m = 0;  // ... where the follower's lift has dropped by this much anywhere; 0 = none
  wear::WearStepping stepping;
  // stepping.scheme: the fixed steps' update (Euler's, or a second-order one: wear/integrator.h; §15)
  wear::IntegratorOptions::Scheme scheme = wear::IntegratorOptions::Scheme::Euler;
  // skip: the worn revolution's skip (cam/worn_revolution.h, WornRevolutionOptions; §15): every
  // skip_stride-th angle step solved, the steps between interpolated where the strip powers allow
  int skip_stride = 1;
  double skip_power_rtol = 0.01;
  int arc_cells = 720;
  int lateral_cells = 28;
  double smoothing_wavelength_m = 5e-4;  // the wear rate's lateral filter (wear/profile_update.h), 0 = none
  std::vector<double> snapshots_revolutions;
  double checkpoint_interval_s = 10;  // `rollwear run`: wall time between checkpoints (a wear case's default)
  // the track's and the roller's fatigue damage (cam/cam_damage.h), accumulated over the life, which ends at
  // damage 1 (wear::LifeEnd::Fatigue)
  std::optional<wear::FatigueSection> fatigue;
};

// reads the wear: section under cam: (the wear laws and the stepping with the keys of a wear case);
// throws contact::CaseError at the key's line
void read_cam_wear(contact::YamlMap& m, CamWearSpec& spec);

}  // namespace cam
