// The quasi-steady dissipation over the revolution (docs/cam-follower.md §8): at every angle step the
// steady tangential solution (lib/tangential/steady.h through cam/creep_law.h) on that angle's contact at
// the roller's creepage xi(theta) and rolling speed V(theta) of its motion (cam/roller_motion.h), its strip
// powers P_l(y_j) (W/m) taken as the step's mean (the rows sit at the steps' starts: the rectangle rule in
// angle). Where the roller skids its xi is large and the steady solution tends to full slip, mu p |w|:
// the same law that drove its dynamics. Strips at y = grid_y0 + y_j from the track's centre line (both
// profiles are centred on it); mean_pressure = pi p_j/4 (the semi-ellipse's mean over 2 a_j), 0 outside.
#pragma once

#include "cam/angle_dissipation.h"
#include "cam/creep_law.h"
#include "cam/revolution.h"
#include "cam/roller_motion.h"

namespace cam {

struct DissipationTotals {
  double energy_J = 0;          // sum over the steps of the power times the duration: one revolution's
  double max_power_W = 0;
  double max_power_theta_rad = 0;
};

// With a law that is not the motion's own (is_motion_law: the exact theory, the half-space) each row's creepage is
// the one whose steady force on its contact is the motion's F_t (creepage_for_force; the motion's where the law
// cannot give it), as the worn revolution's rows (cam/cam_life.h).
// throws std::invalid_argument when the motion does not match the revolution
RevolutionDissipation revolution_dissipation(const CamModel& m, const Revolution& r, const RollerMotion& motion,
                                             const CreepLawSettings& s = {});

// a strip's power of either sign within this fraction of the largest strip's (or of the full slide's mean
// mu F_n V / 2b, whichever is larger) is rounding, taken as 0
constexpr double kStripPowerRounding = 1e-9;

// one angle step: the contact c of row `row`, the roller's state there
AngleDissipation angle_dissipation(const AngleContact& c, const RevolutionRow& row, const RollerAngle& roller,
                                   double duration_s);
// the same from the steady solution already solved there (steady_creep(c, roller.xi, roller.speed_m_per_s))
AngleDissipation angle_dissipation(const AngleContact& c, const RevolutionRow& row, const RollerAngle& roller,
                                   double duration_s, const contact::TangentialSolution& steady);

// one angle step's place and speeds (its angle, duration, arc, the two surfaces' speeds), no strips yet: what
// every solve of the step (quasi-steady or transient) fills in the same way
AngleDissipation angle_step(const RevolutionRow& row, const RollerAngle& roller, double duration_s);

// the total power of one step (W): sum of power_W_per_m times the strip width
double total_power_W(const AngleDissipation& d);

DissipationTotals dissipation_totals(const RevolutionDissipation& d);

}  // namespace cam
