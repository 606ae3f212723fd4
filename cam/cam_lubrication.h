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
//   fatigue          with cam.roller.shear_yield_Pa or cam.track.shear_yield_Pa (k, docs/cam-follower.md §18): the
//                    indicators of lib/subsurface/shakedown.h (fatigue_indicators) on the angle's patch and the same
//                    steady solution: mu_eff = |F_t|/F_n, p0, Johnson's shakedown margin (line or point contact by the
//                    patch's b/a, shakedown_contact_of) and Ekberg's FI_surf, per body given
//   friction by regime  with cam.lubricant.friction_by_regime: true, the regime law of lib/lubrication/regime.h
//                    (Johnson, Greenwood and Poon's load sharing: mu and the wear factor from the asperity load share
//                    f_a(lambda)) at each angle's lambda is fed back: the angle's mu reaches the roller's motion, the
//                    transient, the tangential solves and the wear's k_E = K/(H mu), and its wear factor scales the
//                    angle's wear (with_regime_friction, regime_wear_laws)
// Without any of these keys nothing here runs and every output is the dry case's, byte for byte.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cam/cam_life.h"
#include "cam/cam_wear.h"
#include "cam/creep_law.h"
#include "cam/revolution.h"
#include "cam/roller_dynamics.h"
#include "cam/roller_motion.h"
#include "lib/io/case.h"
#include "lib/subsurface/shakedown.h"

namespace cam {

// cam.roller.shear_yield_Pa and cam.track.shear_yield_Pa: the shear yield stress k of each body (0: not given)
struct CamFatigueSpec {
  double roller_shear_yield_Pa = 0, cam_shear_yield_Pa = 0;
  bool any() const { return roller_shear_yield_Pa > 0 || cam_shear_yield_Pa > 0; }
};

// cam.lubricant (the film, lambda, regime), cam.thermal (the flash temperature; body1 the roller, body2 the cam) and
// the bodies' shear yield stresses (the fatigue indicators)
struct CamLubricationSpec {
  std::optional<contact::LubricantSection> lubricant;
  std::optional<contact::ThermalSection> thermal;
  CamFatigueSpec fatigue;
  bool friction_by_regime = false;  // cam.lubricant.friction_by_regime: the regime law's mu and wear factor used
  bool any() const { return lubricant.has_value() || thermal.has_value() || fatigue.any(); }
};

enum class CamBody { Roller, Cam };
const char* to_string(CamBody b);

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
  double regime_mu = kNaN, regime_wear_factor = kNaN;  // the case's values of the angle's regime (per regime)
  contact::RegimeFriction law;  // the regime law at lambda (lib/lubrication/regime.h regime_friction)
  double mu_used = kNaN;        // the friction the revolution's solves used at this angle (mu_at)
  // with cam.thermal
  double power_W = kNaN;          // the steady solution's dissipated power: the heat
  double flash_max_K = kNaN;      // Blok's flash temperature (the maximum, equal on both surfaces)
  double heat_share_roller = kNaN;
  double peclet_roller = kNaN, peclet_cam = kNaN;  // Jaeger's L = v a / (2 kappa) of each surface
  double transit_s = kNaN;        // 2a / min(v_cam, v_roller): the longest passage of a surface point
  double contact_temperature_C = kNaN;  // bulk + flash, with bulk_temperature_C
  double scuffing_margin_K = kNaN;      // critical - (bulk + flash), with critical_temperature_C
  // with a body's shear_yield_Pa: fatigue_indicators (lib/subsurface/shakedown.h) of the steady solution on the patch
  double traction_coefficient = kNaN;   // mu_eff = |F_t| / F_n of the steady solution
  double p0_Pa = kNaN;                  // the patch's peak pressure
  contact::ShakedownContact shakedown_contact = contact::ShakedownContact::Point;  // by the patch's b/a
  double shakedown_margin_roller = kNaN, fi_surf_roller = kNaN;  // with cam.roller.shear_yield_Pa
  double shakedown_margin_cam = kNaN, fi_surf_cam = kNaN;        // with cam.track.shear_yield_Pa
};

struct RevolutionLubrication {
  std::vector<AngleLubrication> angles;
  // with cam.lubricant: the angle of the least lambda (the worst film), the steps per regime, outside the fit
  std::size_t min_lambda = 0;
  std::array<int, 3> regime_steps{};
  int outside_fit_steps = 0;
  // with friction_by_regime: the largest |law.mu - mu_used| over the angles (the feedback's one pass, below)
  double max_mu_mismatch = 0;
  // with cam.thermal: the angle of the largest flash temperature, the least Peclet number of either surface, and
  // the quasi-steady measure: the largest change of the flash temperature during one passage (transit_s), over the
  // revolution's largest flash temperature (central differences over the angle steps)
  std::size_t max_flash = 0;
  double min_peclet = std::numeric_limits<double>::infinity();
  double thermal_unsteadiness = 0;
  std::size_t thermal_unsteadiness_at = 0;
  // with a shear yield stress: the least shakedown margin over the angles and the bodies given (where, which body),
  // the largest FI_surf likewise, the largest mu_eff
  std::size_t min_shakedown_at = 0, max_fi_surf_at = 0, max_traction_at = 0;
  CamBody min_shakedown_body = CamBody::Roller, max_fi_surf_body = CamBody::Roller;
  double min_shakedown_margin = std::numeric_limits<double>::infinity();
  double max_fi_surf = -std::numeric_limits<double>::infinity();
};

// One angle: the film on the row's geometry with the roller's state, and (with cam.thermal and `heat`, the steady
// solution at the roller's creepage with its fields) the flash temperature of heat.power_W_per_m2 on patch.grid;
// with a shear yield stress and `heat`, the fatigue indicators of that solution on patch.
// Throws std::invalid_argument naming the angle when a surface does not move forward through the contact (with
// cam.lubricant or cam.thermal).
AngleLubrication angle_lubrication(const CamLubricationSpec& spec, const CamModel& m, const RevolutionRow& row,
                                   const RollerAngle& roller, const contact::ContactPatch& patch,
                                   const contact::TangentialSolution* heat);

// Every angle of the periodic revolution: the angle's contact under the motion's F_n with law (the case's creep law,
// roller_dynamics_of(settings).law), the creepage carrying the motion's F_t where law is not the motion's own.
RevolutionLubrication revolution_lubrication(const CamLubricationSpec& spec, const CamModel& m, const Revolution& r,
                                             const RollerMotion& motion, const CreepLawSettings& law);

// cam.lubricant.friction_by_regime (docs/cam-follower.md §17): the regime law's mu and wear factor per angle step
struct RegimeFeedback {
  std::vector<double> mu, wear_factor, asperity_share;
};
// the law at each angle of l (regime_friction at its lambda, the case's boundary and full-film values)
RegimeFeedback regime_feedback(const CamLubricationSpec& spec, const RevolutionLubrication& l);
// The model whose solves use the regime's friction per angle step: the film on m's periodic revolution (its
// revolution and the roller's motion with m's friction, dynamics as the case asks), the law's mu at each angle put in
// m.mu_by_step. One pass: the film depends on the friction only through the roller's slip (u = V - w/2, w/V below
// 1e-3 where the roller rolls) and the loads, so the film of the returned model's motion differs little; the
// revolution's lubrication on that motion reports the difference (max_mu_mismatch). feedback (if given) receives
// the law's values. Without friction_by_regime, m itself. Throws as run_revolution, periodic_motion and
// revolution_lubrication; std::runtime_error for a jump or a motion that is not periodic.
CamModel with_regime_friction(const CamLubricationSpec& spec, const CamModel& m, const RollerDynamicsSettings& dynamics,
                              RegimeFeedback* feedback = nullptr);
// the wear laws with the feedback's per-angle friction and wear factor (cam/cam_wear.h CamWearLaws)
CamWearLaws regime_wear_laws(CamWearLaws laws, const RegimeFeedback& f);
// the life's set-up (cam/cam_life.h set_up_cam_life) with the regime law fed back when lubrication asks for it: the
// model with_regime_friction, the wear laws regime_wear_laws; else set_up_cam_life's own
std::unique_ptr<CamLifeSetup> set_up_lubricated_cam_life(const std::string& name, const CamLubricationSpec& lubrication,
                                                         const CamModel& m, const CamWearSpec& spec,
                                                         const RollerDynamicsSettings& dynamics);

// the printed lines (`rollwear cam`, `rollwear run`): the film's and the temperature's extremes and where
std::string lubrication_summary(const CamLubricationSpec& spec, const RevolutionLubrication& l);
// the per-angle columns added to a table: the header's part (",name,...") and a row's (",value,...")
std::string lubrication_csv_header(const CamLubricationSpec& spec);
std::string lubrication_csv_cells(const CamLubricationSpec& spec, const AngleLubrication& a);
// the life report's lines ("key: value\n"): the margins beside the wear life
std::string lubrication_report_text(const CamLubricationSpec& spec, const RevolutionLubrication& l);

// The life's failure modes side by side (docs/cam-follower.md §18): a margin statement, not a damage integration.
// The shakedown and scuffing margins are the unworn periodic revolution's; the wear life is the life's end. Names
// first_failure among surface fatigue (the least shakedown margin < 0: ratchetting from the first revolutions),
// scuffing (the Blok margin < 0: at the first pass of the hottest angle; named before fatigue when both are
// exceeded) and the wear life (wear_limit_reached: the life ended at a wear limit after life_revolutions), with the
// others' margins; damage_reached: the life ended at fatigue damage 1 (Miner, docs/cam-follower.md §19) after
// life_revolutions, named after scuffing and surface fatigue (those are exceeded from the first revolutions) and in
// place of the wear life. Empty without a shear yield stress, a scuffing margin or damage (nothing to compare).
std::string first_failure_text(const CamLubricationSpec& spec, const RevolutionLubrication& l,
                               bool wear_limit_reached, const std::string& wear_end, double life_revolutions,
                               bool damage_reached = false);

}  // namespace cam
