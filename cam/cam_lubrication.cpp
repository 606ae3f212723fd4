// The lubricant film and the flash temperature at every cam angle (cam/cam_lubrication.h).
#include "cam/cam_lubrication.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include <spdlog/fmt/fmt.h>

#include "cam/cam_error.h"
#include "lib/elastic.h"
#include "lib/number.h"
#include "lib/numeric.h"

namespace cam {

namespace {

double deg(double rad) { return rad * kDegPerRad; }

void cell(std::string& out, double v) {
  out += ',';
  contact::append_round_trip(out, v);
}

}  // namespace

const char* to_string(CamBody b) { return b == CamBody::Roller ? "roller" : "cam"; }

AngleLubrication angle_lubrication(const CamLubricationSpec& spec, const CamModel& m, const RevolutionRow& row,
                                   const RollerAngle& roller, const contact::ContactPatch& patch,
                                   const contact::TangentialSolution* heat) {
  AngleLubrication a;
  a.theta_rad = row.kin.theta_rad;
  a.normal_load_N = roller.normal_N;
  a.cam_speed_m_per_s = row.kin.rolling_speed_m_per_s;
  a.roller_speed_m_per_s = roller_surface_speed_m_per_s(a.cam_speed_m_per_s, roller.slip_speed_m_per_s);
  a.entrainment_m_per_s = 0.5 * (a.cam_speed_m_per_s + a.roller_speed_m_per_s);
  a.Rx_m = 1 / (1 / m.geometry.roller_radius_m + row.kin.cam_curvature_per_m);
  a.ellipticity_k = patch.b_m / patch.a_m;
  if ((spec.lubricant || spec.thermal) && !(a.cam_speed_m_per_s > 0 && a.roller_speed_m_per_s > 0))
    throw std::invalid_argument(fmt::format(
        "cam angle {:.6g} deg: the film and the flash temperature need both surfaces moving through the contact, "
        "got the cam's {:.6g} m/s and the roller's {:.6g} m/s", deg(a.theta_rad), a.cam_speed_m_per_s,
        a.roller_speed_m_per_s));
  if (spec.lubricant) {
    const contact::LubricantSection& lub = *spec.lubricant;
    const double E_prime = contact::ehl_reduced_modulus_Pa(contact::effective_modulus_Pa(m.bodies.pair));
    a.film = contact::film_point_contact(lub.lubricant, a.Rx_m, a.ellipticity_k, E_prime, a.normal_load_N,
                                         a.entrainment_m_per_s);
    a.within_fit_range = a.ellipticity_k >= contact::kHamrockDowsonMinEllipticity &&
                         a.ellipticity_k <= contact::kHamrockDowsonMaxEllipticity;
    a.lambda = contact::film_parameter(a.film.h_min_m, lub.Rq1_m, lub.Rq2_m);
    a.regime = contact::regime_of(a.lambda, lub.thresholds);
    a.regime_mu = lub.by_regime.mu[static_cast<int>(a.regime)];
    a.regime_wear_factor = lub.by_regime.wear_factor[static_cast<int>(a.regime)];
    a.law = contact::regime_friction(a.lambda, lub.by_regime, lub.thresholds);
  }
  if (spec.thermal && heat) {
    const contact::ThermalSection& th = *spec.thermal;
    const contact::FlashTemperature f =
        contact::flash_temperature(patch.grid, heat->power_W_per_m2, a.roller_speed_m_per_s, a.cam_speed_m_per_s,
                                   th.body1, th.body2, patch.a_m);
    a.power_W = heat->power_W_per_m2.sum() * patch.grid.dx_m * patch.grid.dy_m;
    a.flash_max_K = f.max_rise_K;
    a.heat_share_roller = f.share_body1;
    a.peclet_roller = f.peclet_body1;
    a.peclet_cam = f.peclet_body2;
    a.transit_s = 2 * patch.a_m / std::min(a.cam_speed_m_per_s, a.roller_speed_m_per_s);
    if (th.bulk_temperature_C) a.contact_temperature_C = *th.bulk_temperature_C + a.flash_max_K;
    if (th.critical_temperature_C)
      a.scuffing_margin_K =
          contact::blok_scuffing_margin_K(*th.bulk_temperature_C, a.flash_max_K, *th.critical_temperature_C);
  }
  if (spec.fatigue.any() && heat) {  // lib/subsurface/shakedown.h on the angle's patch and steady solution
    const CamFatigueSpec& k = spec.fatigue;
    for (const auto& [k_Pa, margin, fi] :
         {std::tuple{k.roller_shear_yield_Pa, &a.shakedown_margin_roller, &a.fi_surf_roller},
          std::tuple{k.cam_shear_yield_Pa, &a.shakedown_margin_cam, &a.fi_surf_cam}}) {
      if (!(k_Pa > 0)) continue;
      const contact::FatigueIndicators f = contact::fatigue_indicators(patch, *heat, k_Pa);
      a.traction_coefficient = f.traction_coefficient;
      a.shakedown_contact = f.contact;
      *margin = f.margin;
      *fi = f.FI_surf;
    }
    a.p0_Pa = patch.p0_Pa;
  }
  return a;
}

RevolutionLubrication revolution_lubrication(const CamLubricationSpec& spec, const CamModel& m, const Revolution& r,
                                             const RollerMotion& motion, const CreepLawSettings& law) {
  if (motion.angles.size() != r.rows.size())
    throw std::invalid_argument(fmt::format("revolution_lubrication: the roller's motion has {} angles, the "
                                            "revolution {} rows", motion.angles.size(), r.rows.size()));
  RevolutionLubrication out;
  if (!spec.any()) return out;
  const contact::Profiles profiles = roller_and_track_profiles(m.bodies);
  const bool own_creepage = is_motion_law(law);
  out.angles.reserve(r.rows.size());
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const RevolutionRow& row = r.rows[i];
    RollerAngle roller = motion.angles[i];
    AngleContact c = angle_contact(m.bodies, profiles, m.geometry.roller_radius_m, row.kin, roller.normal_N, mu_at(m, i), law);
    if (!own_creepage) {  // the creepage carrying the motion's F_t with this law, on this contact (as the dissipation)
      const CreepageForForce xi = creepage_for_force(c, roller.tangential_N);
      if (xi.found) {
        roller.xi = xi.xi;
        roller.slip_speed_m_per_s = xi.xi * roller.speed_m_per_s;
      }
    }
    if (spec.thermal || spec.fatigue.any()) {
      if (c.normal.patch.pressure_Pa.size() == 0) contact::fill_strip_pressures(c.normal.patch);  // the fields need it
      const contact::TangentialSolution heat = steady_creep(c, roller.xi, roller.speed_m_per_s, true);
      out.angles.push_back(angle_lubrication(spec, m, row, roller, c.normal.patch, &heat));
    } else {
      out.angles.push_back(angle_lubrication(spec, m, row, roller, c.normal.patch, nullptr));
    }
    out.angles.back().mu_used = mu_at(m, i);
  }
  const std::size_t n = out.angles.size();
  if (spec.lubricant) {
    for (std::size_t i = 0; i < n; ++i) {
      const AngleLubrication& a = out.angles[i];
      if (a.lambda < out.angles[out.min_lambda].lambda) out.min_lambda = i;
      ++out.regime_steps[static_cast<int>(a.regime)];
      if (!a.within_fit_range) ++out.outside_fit_steps;
      if (spec.friction_by_regime) out.max_mu_mismatch = std::max(out.max_mu_mismatch, std::abs(a.law.mu - a.mu_used));
    }
  }
  if (spec.thermal) {
    for (std::size_t i = 0; i < n; ++i) {
      const AngleLubrication& a = out.angles[i];
      if (a.flash_max_K > out.angles[out.max_flash].flash_max_K) out.max_flash = i;
      out.min_peclet = std::min({out.min_peclet, a.peclet_roller, a.peclet_cam});
    }
    // the quasi-steady measure: the flash temperature's change during one passage, of the revolution's largest
    const double top = out.angles[out.max_flash].flash_max_K;
    const double dt = 2 * contact::kPi / m.angle_steps / m.omega_rad_per_s;
    if (top > 0 && n >= 3) {
      for (std::size_t i = 0; i < n; ++i) {
        const AngleLubrication& a = out.angles[i];
        const double rate = (out.angles[(i + 1) % n].flash_max_K - out.angles[(i + n - 1) % n].flash_max_K) / (2 * dt);
        const double e = a.transit_s * std::abs(rate) / top;
        if (e > out.thermal_unsteadiness) out.thermal_unsteadiness = e, out.thermal_unsteadiness_at = i;
      }
    }
  }
  if (spec.fatigue.any()) {
    for (std::size_t i = 0; i < n; ++i) {
      const AngleLubrication& a = out.angles[i];
      if (a.traction_coefficient > out.angles[out.max_traction_at].traction_coefficient) out.max_traction_at = i;
      for (const auto& [body, margin, fi] : {std::tuple{CamBody::Roller, a.shakedown_margin_roller, a.fi_surf_roller},
                                             std::tuple{CamBody::Cam, a.shakedown_margin_cam, a.fi_surf_cam}}) {
        if (std::isnan(margin)) continue;
        if (margin < out.min_shakedown_margin)
          out.min_shakedown_margin = margin, out.min_shakedown_at = i, out.min_shakedown_body = body;
        if (fi > out.max_fi_surf) out.max_fi_surf = fi, out.max_fi_surf_at = i, out.max_fi_surf_body = body;
      }
    }
  }
  return out;
}

RegimeFeedback regime_feedback(const CamLubricationSpec& spec, const RevolutionLubrication& l) {
  if (!spec.lubricant) throw std::invalid_argument("regime feedback: needs cam.lubricant");
  RegimeFeedback f;
  for (const AngleLubrication& a : l.angles) {
    const contact::RegimeFriction r = contact::regime_friction(a.lambda, spec.lubricant->by_regime,
                                                               spec.lubricant->thresholds);
    f.mu.push_back(r.mu);
    f.wear_factor.push_back(r.wear_factor);
    f.asperity_share.push_back(r.asperity_share);
  }
  return f;
}

CamModel with_regime_friction(const CamLubricationSpec& spec, const CamModel& m, const RollerDynamicsSettings& dynamics,
                              RegimeFeedback* feedback) {
  if (!spec.friction_by_regime) return m;
  if (!spec.lubricant) throw std::invalid_argument("friction by regime: needs cam.lubricant");
  const Revolution r = run_revolution(m);
  if (r.status != RevolutionStatus::Complete)
    throw std::runtime_error("friction by regime: the follower jumps; no film to take the friction from");
  const PeriodicMotion motion = periodic_motion(m, r, dynamics);
  if (!motion.converged)
    throw std::runtime_error("friction by regime: the roller's motion with cam.mu is not periodic");
  CamLubricationSpec film_only;
  film_only.lubricant = spec.lubricant;
  const RegimeFeedback f = regime_feedback(film_only, revolution_lubrication(film_only, m, r, motion.motion, dynamics.law));
  CamModel out = m;
  out.mu_by_step = f.mu;
  if (feedback) *feedback = f;
  return out;
}

CamWearLaws regime_wear_laws(CamWearLaws laws, const RegimeFeedback& f) {
  laws.mu_by_step = f.mu;
  laws.wear_factor_by_step = f.wear_factor;
  return laws;
}

std::unique_ptr<CamLifeSetup> set_up_lubricated_cam_life(const std::string& name, const CamLubricationSpec& lubrication,
                                                         const CamModel& m, const CamWearSpec& spec,
                                                         const RollerDynamicsSettings& dynamics) {
  if (!lubrication.friction_by_regime) return set_up_cam_life(name, m, spec, dynamics);
  RegimeFeedback f;
  const CamModel model = with_regime_friction(lubrication, m, dynamics, &f);
  CamWearSpec s = spec;
  s.laws = regime_wear_laws(s.laws, f);
  return set_up_cam_life(name, model, s, dynamics);
}

std::string lubrication_summary(const CamLubricationSpec& spec, const RevolutionLubrication& l) {
  std::string out;
  if (l.angles.empty()) return out;
  if (spec.lubricant) {
    const AngleLubrication& w = l.angles[l.min_lambda];
    double h_min = w.film.h_min_m, h_max = w.film.h_min_m, k_min = w.ellipticity_k, k_max = w.ellipticity_k;
    double u_min = w.entrainment_m_per_s, u_max = u_min;
    for (const AngleLubrication& a : l.angles) {
      h_min = std::min(h_min, a.film.h_min_m), h_max = std::max(h_max, a.film.h_min_m);
      k_min = std::min(k_min, a.ellipticity_k), k_max = std::max(k_max, a.ellipticity_k);
      u_min = std::min(u_min, a.entrainment_m_per_s), u_max = std::max(u_max, a.entrainment_m_per_s);
    }
    out += fmt::format("film (Hamrock-Dowson): h_min {:.4g} to {:.4g} um, entrainment {:.4g} to {:.4g} m/s, "
                       "ellipticity k {:.4g} to {:.4g}{}\n",
                       h_min * 1e6, h_max * 1e6, u_min, u_max, k_min, k_max,
                       l.outside_fit_steps > 0
                           ? fmt::format(" (outside the formula's fitted k in [1, 8] at {} angle steps)", l.outside_fit_steps)
                           : std::string());
    out += fmt::format("lambda: min {:.4g} at cam angle {:.4g} deg (h_min {:.4g} um, h_c {:.4g} um, F_n {:.5g} N, "
                       "regime {}: mu {:.4g}, wear factor {:.4g}); angle steps boundary {}, mixed {}, full film {}\n",
                       w.lambda, deg(w.theta_rad), w.film.h_min_m * 1e6, w.film.h_central_m * 1e6, w.normal_load_N,
                       contact::to_string(w.regime), w.regime_mu, w.regime_wear_factor,
                       l.regime_steps[static_cast<int>(contact::LubricationRegime::Boundary)],
                       l.regime_steps[static_cast<int>(contact::LubricationRegime::Mixed)],
                       l.regime_steps[static_cast<int>(contact::LubricationRegime::FullFilm)]);
    if (spec.friction_by_regime) {
      const auto [mu_lo, mu_hi] = std::minmax_element(l.angles.begin(), l.angles.end(), [](const auto& x, const auto& y) {
        return x.mu_used < y.mu_used;
      });
      const auto [wf_lo, wf_hi] = std::minmax_element(l.angles.begin(), l.angles.end(), [](const auto& x, const auto& y) {
        return x.law.wear_factor < y.law.wear_factor;
      });
      out += fmt::format("friction by regime (load sharing, docs/lubrication-and-temperature.md §2): the solves use mu "
                         "{:.4g} to {:.4g} (at {:.4g} and {:.4g} deg), the wear factor {:.4g} to {:.4g} (at {:.4g} and "
                         "{:.4g} deg); the law on this motion's film differs from the mu used by {:.3g} at most\n",
                         mu_lo->mu_used, mu_hi->mu_used, deg(mu_lo->theta_rad), deg(mu_hi->theta_rad),
                         wf_lo->law.wear_factor, wf_hi->law.wear_factor, deg(wf_lo->theta_rad), deg(wf_hi->theta_rad),
                         l.max_mu_mismatch);
    } else {
      out += "friction: the revolution's solves use cam.mu; the regime's mu and wear factor are reported per angle\n";
    }
  }
  if (spec.thermal) {
    const AngleLubrication& t = l.angles[l.max_flash];
    out += fmt::format("flash temperature (Blok, quasi-steady): max {:.4g} K at cam angle {:.4g} deg (heat {:.4g} W, "
                       "{:.3g} of it into the roller; cam {:.4g} m/s, roller {:.4g} m/s)",
                       t.flash_max_K, deg(t.theta_rad), t.power_W, t.heat_share_roller, t.cam_speed_m_per_s,
                       t.roller_speed_m_per_s);
    if (!std::isnan(t.contact_temperature_C)) out += fmt::format("; contact temperature {:.5g} C", t.contact_temperature_C);
    out += '\n';
    if (!std::isnan(t.scuffing_margin_K))
      out += fmt::format("scuffing margin (Blok's critical temperature {:.5g} C): {:.5g} K\n",
                         t.scuffing_margin_K + t.contact_temperature_C, t.scuffing_margin_K);
    out += fmt::format("quasi-steady temperature: Peclet number >= {:.3g}; the flash temperature changes by at most "
                       "{:.3g} of its maximum during one passage through the contact (at {:.4g} deg)\n",
                       l.min_peclet, l.thermal_unsteadiness, deg(l.angles[l.thermal_unsteadiness_at].theta_rad));
  }
  if (spec.fatigue.any()) {
    const AngleLubrication& w = l.angles[l.min_shakedown_at];
    const AngleLubrication& f = l.angles[l.max_fi_surf_at];
    const AngleLubrication& t = l.angles[l.max_traction_at];
    const double k = l.min_shakedown_body == CamBody::Roller ? spec.fatigue.roller_shear_yield_Pa
                                                             : spec.fatigue.cam_shear_yield_Pa;
    out += fmt::format("shakedown (Johnson, {} contact at b/a {:.4g}): least margin {:.4g} on the {} (k {:.4g} MPa) at "
                       "cam angle {:.4g} deg (p0 {:.5g} MPa, p0/k {:.4g}, mu_eff {:.4g}){}\n",
                       contact::to_string(w.shakedown_contact), w.ellipticity_k, l.min_shakedown_margin,
                       to_string(l.min_shakedown_body), k * 1e-6, deg(w.theta_rad), w.p0_Pa * 1e-6, w.p0_Pa / k,
                       w.traction_coefficient,
                       l.min_shakedown_margin < 0 ? ": beyond shakedown, ratchetting/surface fatigue expected" : "");
    out += fmt::format("surface fatigue index FI_surf (Ekberg): max {:.4g} on the {} at cam angle {:.4g} deg ({}); "
                       "mu_eff max {:.4g} at {:.4g} deg\n",
                       l.max_fi_surf, to_string(l.max_fi_surf_body), deg(f.theta_rad),
                       l.max_fi_surf > 0 ? "> 0: beyond the surface limit" : "< 0: inside the surface limit",
                       t.traction_coefficient, deg(t.theta_rad));
  }
  return out;
}

std::string lubrication_csv_header(const CamLubricationSpec& spec) {
  std::string h;
  if (!spec.any()) return h;
  h += ",cam_surface_speed_m_per_s,roller_surface_speed_m_per_s,entrainment_m_per_s,Rx_m,ellipticity_k";
  if (spec.lubricant) h += ",h_min_m,h_central_m,lambda,lubrication_regime,regime_mu,regime_wear_factor";
  if (spec.lubricant && spec.friction_by_regime) h += ",asperity_share,law_mu,mu_used,wear_factor_used";
  if (spec.thermal)
    h += ",heat_W,flash_max_K,heat_share_roller,peclet_roller,peclet_cam,transit_s,contact_temperature_C,"
         "scuffing_margin_K";
  if (spec.fatigue.any()) {
    h += ",traction_coefficient,p0_Pa,shakedown_contact";
    if (spec.fatigue.roller_shear_yield_Pa > 0) h += ",shakedown_margin_roller,fi_surf_roller";
    if (spec.fatigue.cam_shear_yield_Pa > 0) h += ",shakedown_margin_cam,fi_surf_cam";
  }
  return h;
}

std::string lubrication_csv_cells(const CamLubricationSpec& spec, const AngleLubrication& a) {
  std::string out;
  if (!spec.any()) return out;
  for (double v : {a.cam_speed_m_per_s, a.roller_speed_m_per_s, a.entrainment_m_per_s, a.Rx_m, a.ellipticity_k})
    cell(out, v);
  if (spec.lubricant) {
    cell(out, a.film.h_min_m);
    cell(out, a.film.h_central_m);
    cell(out, a.lambda);
    out += ',';
    out += contact::to_string(a.regime);
    cell(out, a.regime_mu);
    cell(out, a.regime_wear_factor);
    if (spec.friction_by_regime)
      for (double v : {a.law.asperity_share, a.law.mu, a.mu_used, a.law.wear_factor}) cell(out, v);
  }
  if (spec.thermal)
    for (double v : {a.power_W, a.flash_max_K, a.heat_share_roller, a.peclet_roller, a.peclet_cam, a.transit_s,
                     a.contact_temperature_C, a.scuffing_margin_K})
      cell(out, v);
  if (spec.fatigue.any()) {
    cell(out, a.traction_coefficient);
    cell(out, a.p0_Pa);
    out += ',';
    out += contact::to_string(a.shakedown_contact);
    if (spec.fatigue.roller_shear_yield_Pa > 0) cell(out, a.shakedown_margin_roller), cell(out, a.fi_surf_roller);
    if (spec.fatigue.cam_shear_yield_Pa > 0) cell(out, a.shakedown_margin_cam), cell(out, a.fi_surf_cam);
  }
  return out;
}

std::string lubrication_report_text(const CamLubricationSpec& spec, const RevolutionLubrication& l) {
  std::string out;
  if (l.angles.empty()) return out;
  if (spec.lubricant) {
    const AngleLubrication& w = l.angles[l.min_lambda];
    out += fmt::format("min_lambda: {:.6g}\nmin_lambda_at_deg: {:.6g}\nregime_at_min_lambda: {}\n"
                       "h_min_at_min_lambda_m: {:.6g}\nboundary_angle_steps: {}\nmixed_angle_steps: {}\n"
                       "full_film_angle_steps: {}\n",
                       w.lambda, deg(w.theta_rad), contact::to_string(w.regime), w.film.h_min_m,
                       l.regime_steps[static_cast<int>(contact::LubricationRegime::Boundary)],
                       l.regime_steps[static_cast<int>(contact::LubricationRegime::Mixed)],
                       l.regime_steps[static_cast<int>(contact::LubricationRegime::FullFilm)]);
    if (spec.friction_by_regime) {
      double mu_lo = l.angles[0].mu_used, mu_hi = mu_lo, wf_lo = l.angles[0].law.wear_factor, wf_hi = wf_lo;
      for (const AngleLubrication& a : l.angles) {
        mu_lo = std::min(mu_lo, a.mu_used), mu_hi = std::max(mu_hi, a.mu_used);
        wf_lo = std::min(wf_lo, a.law.wear_factor), wf_hi = std::max(wf_hi, a.law.wear_factor);
      }
      out += fmt::format("min_mu_used: {:.6g}\nmax_mu_used: {:.6g}\nmin_wear_factor_used: {:.6g}\n"
                         "max_wear_factor_used: {:.6g}\nmax_mu_mismatch: {:.6g}\n",
                         mu_lo, mu_hi, wf_lo, wf_hi, l.max_mu_mismatch);
    }
  }
  if (spec.thermal) {
    const AngleLubrication& t = l.angles[l.max_flash];
    out += fmt::format("max_flash_K: {:.6g}\nmax_flash_at_deg: {:.6g}\n", t.flash_max_K, deg(t.theta_rad));
    if (spec.lubricant) out += fmt::format("regime_at_max_flash: {}\n", contact::to_string(t.regime));
    if (!std::isnan(t.contact_temperature_C))
      out += fmt::format("max_contact_temperature_C: {:.6g}\n", t.contact_temperature_C);
    if (!std::isnan(t.scuffing_margin_K)) out += fmt::format("scuffing_margin_K: {:.6g}\n", t.scuffing_margin_K);
  }
  if (spec.fatigue.any()) {
    const AngleLubrication& w = l.angles[l.min_shakedown_at];
    const AngleLubrication& f = l.angles[l.max_fi_surf_at];
    out += fmt::format("shakedown_margin: {:.6g}\nshakedown_worst_deg: {:.6g}\nshakedown_worst_body: {}\n"
                       "shakedown_contact: {}\np0_at_shakedown_worst_Pa: {:.6g}\nfi_surf_max: {:.6g}\n"
                       "fi_surf_max_deg: {:.6g}\nfi_surf_max_body: {}\ntraction_coefficient_max: {:.6g}\n",
                       l.min_shakedown_margin, deg(w.theta_rad), to_string(l.min_shakedown_body),
                       contact::to_string(w.shakedown_contact), w.p0_Pa, l.max_fi_surf, deg(f.theta_rad),
                       to_string(l.max_fi_surf_body), l.angles[l.max_traction_at].traction_coefficient);
  }
  return out;
}

std::string first_failure_text(const CamLubricationSpec& spec, const RevolutionLubrication& l, bool wear_limit_reached,
                               const std::string& wear_end, double life_revolutions, bool damage_reached) {
  if (l.angles.empty()) return {};
  const bool fatigue = spec.fatigue.any();
  const double scuffing = spec.thermal ? l.angles[l.max_flash].scuffing_margin_K : AngleLubrication::kNaN;
  const bool has_scuffing = !std::isnan(scuffing);
  if (!fatigue && !has_scuffing && !damage_reached) return {};
  const std::string fatigue_margin =
      fatigue ? fmt::format("shakedown margin {:.4g} ({} at {:.4g} deg)", l.min_shakedown_margin,
                            to_string(l.min_shakedown_body), deg(l.angles[l.min_shakedown_at].theta_rad))
              : "surface fatigue not assessed (no shear_yield_Pa)";
  const std::string scuffing_margin = has_scuffing ? fmt::format("scuffing margin {:.4g} K at {:.4g} deg", scuffing,
                                                                 deg(l.angles[l.max_flash].theta_rad))
                                                   : "scuffing not assessed (no critical_temperature_C)";
  const std::string wear =
      wear_limit_reached ? fmt::format("wear life {:.4g} revolutions ({})", life_revolutions, wear_end)
      : damage_reached   ? fmt::format("no wear limit before fatigue at {:.4g} revolutions", life_revolutions)
                         : fmt::format("no wear limit within {:.4g} revolutions ({})", life_revolutions, wear_end);
  std::string mode, note, others;
  if (has_scuffing && scuffing < 0) {
    mode = "scuffing";
    note = "the flash temperature exceeds the critical temperature at the first pass of the hottest angle";
    others = fatigue_margin + "; " + wear;
  } else if (fatigue && l.min_shakedown_margin < 0) {
    mode = "surface-fatigue";
    note = "beyond shakedown: ratchetting/surface fatigue expected from the first revolutions";
    others = scuffing_margin + "; " + wear;
  } else if (damage_reached) {
    mode = "fatigue";
    note = fmt::format("fatigue damage 1 (Miner) at {:.4g} revolutions, before any wear limit", life_revolutions);
    others = fatigue_margin + "; " + scuffing_margin + "; " + wear;
  } else if (wear_limit_reached) {
    mode = "wear";
    note = fmt::format("the wear limit ({}) at {:.4g} revolutions, {} (margins of the unworn revolution)", wear_end,
                       life_revolutions, fatigue && has_scuffing ? "inside shakedown and below the critical temperature"
                                         : fatigue           ? "inside shakedown"
                                                             : "below the critical temperature");
    others = fatigue_margin + "; " + scuffing_margin;
  } else {
    mode = "none";
    note = fmt::format("no failure mode reached: {}, no wear limit within the budget",
                       fatigue && has_scuffing ? "inside shakedown, below the critical temperature"
                       : fatigue              ? "inside shakedown"
                                              : "below the critical temperature");
    others = fatigue_margin + "; " + scuffing_margin + "; " + wear;
  }
  return fmt::format("first_failure: {}\nfirst_failure_note: {}\nother_margins: {}\n", mode, note, others);
}

}  // namespace cam
