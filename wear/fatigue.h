// Rolling-contact fatigue damage in a wear life (docs/fatigue.md): Burstow's T-gamma damage function,
// accumulated per point of the reference body's surface by Miner's rule.
//
// Burstow's function (the rail industry's "Whole Life Rail Model" RCF damage function) gives the damage
// of one contact pass from the energy the contact dissipates per metre rolled, T-gamma (N = J/m; T the
// creep force, gamma the creepage): none below a threshold, rising linearly to a peak, then falling
// linearly to none where wear removes the surface material faster than cracks grow in it (the wear /
// fatigue competition is inside the function), and none beyond:
//   d(Tg) = 0                                             Tg <= threshold
//         = peak (Tg - threshold) / (peak_at - threshold) threshold < Tg <= peak_at
//         = peak (zero_at - Tg) / (zero_at - peak_at)      peak_at < Tg < zero_at
//         = 0                                             Tg >= zero_at
// A crack is taken to initiate where the damage summed over the passes (Miner) reaches 1.
//
// Per strip: the function is per contact; the wear loop applies it per strip j of the grid with
//   Tg_j = w e_j,  e_j the strip's dissipated energy per unit width per metre rolled (N/m), w the
// contact's lateral width: the T-gamma the whole contact would have if every strip dissipated as strip j
// (so that the width-weighted mean of Tg_j over the contact is the contact's T-gamma).
#pragma once

#include <Eigen/Core>

#include <string>

namespace wear {

enum class FatigueLaw { Burstow };
std::string to_string(FatigueLaw law);
// throws contact::SettingError ("", "law") naming the laws for anything else
FatigueLaw parse_fatigue_law(const std::string& name);

// Burstow's function's breakpoints and peak (docs/fatigue.md: their source and the variants quoted)
struct BurstowFunction {
  double threshold_N = 20;     // no damage at or below
  double peak_at_N = 65;       // the largest damage per pass there
  double zero_at_N = 175;      // no damage at or above (wear removes the cracks faster than they grow)
  double peak_damage = 1e-5;   // the damage of one pass at peak_at_N
};

// the damage of one pass at T-gamma Tg_N (>= 0; negative or NaN is treated as 0)
double burstow_damage_per_pass(const BurstowFunction& f, double Tgamma_N);

// throws contact::SettingError ("", KEY) for breakpoints out of order, negative, or a peak not in (0, 1]
void validate(const BurstowFunction& f);

struct FatigueSection {
  FatigueLaw law = FatigueLaw::Burstow;
  BurstowFunction burstow;
};

// each strip's T-gamma (N) from its dissipated energy per unit width (J/m) over a duty cycle that rolls rolled_m,
// for a contact contact_width_m wide (the header's Tg_j = w e_j); zero where the width or distance is not > 0
Eigen::ArrayXd strip_tgamma_N(const Eigen::ArrayXd& strip_energy_J_per_m, double rolled_m, double contact_width_m);

}  // namespace wear
