// Rolling-contact fatigue damage of the cam track and of the roller over one cam revolution (docs/cam-follower.md
// §19), Burstow's T-gamma function (wear/fatigue.h, docs/fatigue.md) accumulated by Miner's rule, per track cell of
// the cam and per lateral cell of the roller, from the dissipation the revolution's tangential solve hands over
// (cam/angle_dissipation.h), the same record the wear map reads.
//
// T-gamma per strip. At angle step k the contact dissipates P_l(y_j) per unit width in strip j while it rolls at
// V_k along the cam (rolling_speed_m_per_s): the strip's energy per unit width per metre rolled is P_l(y_j) / V_k,
// and, as the roller's wear loop does (wear::strip_tgamma_N), strip j's T-gamma is the contact's lateral width w_k
// (the extent of the strips that carry pressure) times it: Tg_kj = w_k P_l(y_j) / V_k, the T-gamma the whole
// contact would have if every strip dissipated as strip j (T gamma = F_t xi = P / V for the whole contact).
//
// The cam track. A point at arc sigma and lateral y passes the contact once per cam revolution, while the
// contact's centre sweeps the arc of the angle step whose arc holds sigma: its damage per revolution is
// d(Tg_kj) of that step and of the strip over y. The steps' damages per pass are put onto the fixed cells as the
// mean over each cell (laterally over the strips' overlap with the cell, then along the arc over the steps'
// swept arcs): a cell's damage per revolution is the mean of its points' (the wear map's deposit, with the
// damage times the length in place of the energy).
//
// The roller. Its surface passes the contact many times per cam revolution, at every angle: in step k a
// point of it passes v_r,k dt_k / (2 pi R_r) times (v_r the contact's speed along the roller's surface), each
// pass doing d(Tg_kj): dD_r(y)/dN = sum_k d(Tg_kj) v_r,k dt_k / (2 pi R_r), laterally the mean over the cell.
//
// Wear and fatigue. As in the roller's life (docs/fatigue.md §1), the falling branch of Burstow's function is
// the wear-fatigue competition: the damage is not removed as the surface wears (that would count it twice), and
// the damage does not act back on the wear.
#pragma once

#include <Eigen/Core>

#include <string>

#include "cam/angle_dissipation.h"
#include "cam/cam_wear.h"
#include "wear/fatigue.h"

namespace cam {

struct CamDamage {
  Eigen::ArrayXXd cam;     // (arc_cells x track_cells) Miner's sum per track cell
  Eigen::ArrayXd roller;   // (roller_cells) per lateral cell of the roller
};

struct CamDamageRate {
  CamDamage per_revolution;  // dD/dN, N the cam revolutions
  double max_tgamma_N = 0;   // the largest strip T-gamma over the revolution
  double max_tgamma_at_rad = 0;  // its cam angle
};

// the damage per cam revolution of the revolution's dissipation on grid g; throws std::invalid_argument for a
// dissipation check_dissipation refuses
CamDamageRate damage_per_revolution(const RevolutionDissipation& rev, const CamWearGrid& g,
                                    const wear::FatigueSection& fatigue);

// where the damage is largest (the cam's cells before the roller's at a tie)
struct CamDamageMax {
  double value = 0;
  std::string body;      // "cam" or "roller" ("" without any damage)
  double theta_rad = 0;  // the cam: the cam angle at which the contact passes the cell (NaN unknown); the roller: NaN
  double arc_m = 0;      // the cam: the cell's arc; the roller: NaN
  double y_m = 0;        // the cell's lateral centre (the track's or the roller's)
};
CamDamageMax max_damage(const CamWearGrid& g, const CamDamage& d);

// the track's damage per cell (cam_angle_deg, cam_arc_m, y_m, damage) and the roller's (y_m, damage), with the
// wear maps' header lines
std::string damage_map_csv(const CamWearGrid& g, const CamDamage& d, double revolutions, const std::string& name);
std::string roller_damage_csv(const CamWearGrid& g, const CamDamage& d, double revolutions, const std::string& name);

}  // namespace cam
