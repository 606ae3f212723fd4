// Burstow's damage function and the strips' T-gamma (fatigue.h, docs/fatigue.md).
#include "wear/fatigue.h"

#include <cmath>
#include <optional>

#include "lib/enum_names.h"
#include "lib/errors.h"
#include "lib/number.h"

namespace wear {

namespace {
constexpr contact::EnumTable<FatigueLaw, 1> kFatigueLaws = {{{FatigueLaw::Burstow, "burstow"}}};
}  // namespace

std::string to_string(FatigueLaw law) { return contact::enum_name(kFatigueLaws, law); }

FatigueLaw parse_fatigue_law(const std::string& name) {
  if (const std::optional<FatigueLaw> law = contact::enum_from_name(kFatigueLaws, name)) return *law;
  throw contact::SettingError("", "law", "must be " + contact::enum_names_list(kFatigueLaws) + ", got '" +
                                             contact::clipped(name) + "'");
}

double burstow_damage_per_pass(const BurstowFunction& f, double Tg) {
  if (!(Tg > f.threshold_N) || Tg >= f.zero_at_N) return 0;
  if (Tg <= f.peak_at_N) return f.peak_damage * (Tg - f.threshold_N) / (f.peak_at_N - f.threshold_N);
  return f.peak_damage * (f.zero_at_N - Tg) / (f.zero_at_N - f.peak_at_N);
}

void validate(const BurstowFunction& f) {
  using contact::round_trip;
  if (!(f.threshold_N >= 0) || !std::isfinite(f.threshold_N))
    throw contact::SettingError("", "threshold_N", "must be >= 0 and finite, got " + round_trip(f.threshold_N));
  if (!(f.peak_at_N > f.threshold_N) || !std::isfinite(f.peak_at_N))
    throw contact::SettingError("", "peak_at_N", "must be above threshold_N = " + round_trip(f.threshold_N) +
                                                     " and finite, got " + round_trip(f.peak_at_N));
  if (!(f.zero_at_N > f.peak_at_N) || !std::isfinite(f.zero_at_N))
    throw contact::SettingError("", "zero_at_N", "must be above peak_at_N = " + round_trip(f.peak_at_N) +
                                                     " and finite, got " + round_trip(f.zero_at_N));
  if (!(f.peak_damage > 0 && f.peak_damage <= 1))
    throw contact::SettingError("", "peak_damage", "must be in (0, 1] (the damage of one pass), got " +
                                                       round_trip(f.peak_damage));
}

Eigen::ArrayXd strip_tgamma_N(const Eigen::ArrayXd& strip_energy_J_per_m, double rolled_m, double contact_width_m) {
  if (!(rolled_m > 0) || !(contact_width_m > 0)) return Eigen::ArrayXd::Zero(strip_energy_J_per_m.size());
  return strip_energy_J_per_m * (contact_width_m / rolled_m);
}

}  // namespace wear
