// The lubricant film and the flash temperature at every cam angle (docs/cam-follower.md §17): a cam case's
// optional cam.lubricant and cam.thermal sections (the keys of a contact case's lubricant: and thermal:,
// docs/lubrication-and-temperature.md §4), evaluated on the periodic revolution (cam/periodic_revolution.h)
// angle by angle with the contact-level functions of lib/lubrication/ and lib/thermal/.
//
// At each angle, body 1 the roller, body 2 the cam:
//   surface speeds   v_cam = V (the cam's surface through the contact, cam/kinematics.h),
//                    v_roller = V - w (w the roller's slip over the cam, cam/roller_motion.h)
//   entrainment      u = (v_cam + v_roller)/2 = V - w/2 (the motion's mean speed)
//   reduced radius   1/Rx = 1/R_r + kappa_cam (along rolling; kappa_cam < 0 on a concave flank, 0 flat)
//   ellipticity      k = b/a of the angle's contact (lateral over rolling semi-axis)
//   film             Hamrock and Dowson's point formulas on Rx, k, E' = 2 E*, F_n and u (film_point_contact)
//   lambda, regime   against the composite roughness sqrt(Rq_roller^2 + Rq_cam^2), the case's thresholds
//   flash            Blok's partition of the steady tangential solution's power density at the roller's creepage
//                    (the same law and contact as the quasi-steady dissipation, cam/revolution_dissipation.h),
//                    each surface at its own speed (flash_temperature): quasi-steady per angle, justified where the
//                    Peclet numbers are large and the flash temperature changes little during one passage of a
//                    surface point through the contact (the unsteadiness below, printed)
//   scuffing         Blok's margin, critical - (bulk + flash), with the case's temperatures
// Without either section nothing here runs and every output is the dry case's, byte for byte.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cam/creep_law.h"
#include "cam/revolution.h"
#include "cam/roller_motion.h"
#include "lib/io/case.h"

namespace cam {

// cam.lubricant (the film, lambda, regime) and cam.thermal (the flash temperature; body1 the roller, body2 the cam)
struct CamLubricationSpec {
  std::optional<contact::LubricantSection> lubricant;
  std::optional<contact::ThermalSection> thermal;
  bool any() const { return lubricant.has_value() || thermal.has_value(); }
};

struct AngleLubrication {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double theta_rad = 0;
  double normal_load_N = 0;
  double cam_speed_m_per_s = 0, roller_speed_m_per_s = 0;  // the surfaces' speeds through the contact
  double entrainment_m_per_s = 0;                          // their mean
  double Rx_m = 0;                                         // the reduced radius along rolling
  double ellipticity_k = 0;                                // b/a
  // with cam.lubricant
  contact::FilmThickness film;
  bool within_fit_range = true;  // k in Hamrock and Dowson's [1, 8]
  double lambda = kNaN;
  contact::LubricationRegime regime = contact::LubricationRegime::Boundary;
  double regime_mu = kNaN, regime_wear_factor = kNaN;
  // with cam.thermal
  double power_W = kNaN;          // the steady solution's dissipated power: the heat
  double flash_max_K = kNaN;      // Blok's flash temperature (the maximum, equal on both surfaces)
  double heat_share_roller = kNaN;
  double peclet_roller = kNaN, peclet_cam = kNaN;  // Jaeger's L = v a / (2 kappa) of each surface
  double transit_s = kNaN;        // 2a / min(v_cam, v_roller): the longest passage of a surface point
  double contact_temperature_C = kNaN;  // bulk + flash, with bulk_temperature_C
  double scuffing_margin_K = kNaN;      // critical - (bulk + flash), with critical_temperature_C
};

struct RevolutionLubrication {
  std::vector<AngleLubrication> angles;
  // with cam.lubricant: the angle of the least lambda (the worst film), the steps per regime, outside the fit
  std::size_t min_lambda = 0;
  std::array<int, 3> regime_steps{};
  int outside_fit_steps = 0;
  // with cam.thermal: the angle of the largest flash temperature, the least Peclet number of either surface, and
  // the quasi-steady measure: the largest change of the flash temperature during one passage (transit_s), over the
  // revolution's largest flash temperature (central differences over the angle steps)
  std::size_t max_flash = 0;
  double min_peclet = std::numeric_limits<double>::infinity();
  double thermal_unsteadiness = 0;
  std::size_t thermal_unsteadiness_at = 0;
};

// One angle: the film on the row's geometry with the roller's state, and (with cam.thermal and `heat`, the steady
// solution at the roller's creepage with its fields) the flash temperature of heat.power_W_per_m2 on patch.grid.
// Throws std::invalid_argument naming the angle when a surface does not move forward through the contact.
AngleLubrication angle_lubrication(const CamLubricationSpec& spec, const CamModel& m, const RevolutionRow& row,
                                   const RollerAngle& roller, const contact::ContactPatch& patch,
                                   const contact::TangentialSolution* heat);

// Every angle of the periodic revolution: the angle's contact under the motion's F_n with law (the case's creep law,
// roller_dynamics_of(settings).law), the creepage carrying the motion's F_t where law is not the motion's own.
RevolutionLubrication revolution_lubrication(const CamLubricationSpec& spec, const CamModel& m, const Revolution& r,
                                             const RollerMotion& motion, const CreepLawSettings& law);

// the printed lines (`rollwear cam`, `rollwear run`): the film's and the temperature's extremes and where
std::string lubrication_summary(const CamLubricationSpec& spec, const RevolutionLubrication& l);
// the per-angle columns added to a table: the header's part (",name,...") and a row's (",value,...")
std::string lubrication_csv_header(const CamLubricationSpec& spec);
std::string lubrication_csv_cells(const CamLubricationSpec& spec, const AngleLubrication& a);
// the life report's lines ("key: value\n"): the margins beside the wear life
std::string lubrication_report_text(const CamLubricationSpec& spec, const RevolutionLubrication& l);

}  // namespace cam
