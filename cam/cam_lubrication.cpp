// The lubricant film and the flash temperature at every cam angle (cam/cam_lubrication.h).
#include "cam/cam_lubrication.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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
  if (!(a.cam_speed_m_per_s > 0 && a.roller_speed_m_per_s > 0))
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
    AngleContact c = angle_contact(m.bodies, profiles, m.geometry.roller_radius_m, row.kin, roller.normal_N, m.mu, law);
    if (!own_creepage) {  // the creepage carrying the motion's F_t with this law, on this contact (as the dissipation)
      const CreepageForForce xi = creepage_for_force(c, roller.tangential_N);
      if (xi.found) {
        roller.xi = xi.xi;
        roller.slip_speed_m_per_s = xi.xi * roller.speed_m_per_s;
      }
    }
    if (spec.thermal) {
      if (c.normal.patch.pressure_Pa.size() == 0) contact::fill_strip_pressures(c.normal.patch);  // the fields need it
      const contact::TangentialSolution heat = steady_creep(c, roller.xi, roller.speed_m_per_s, true);
      out.angles.push_back(angle_lubrication(spec, m, row, roller, c.normal.patch, &heat));
    } else {
      out.angles.push_back(angle_lubrication(spec, m, row, roller, c.normal.patch, nullptr));
    }
  }
  const std::size_t n = out.angles.size();
  if (spec.lubricant) {
    for (std::size_t i = 0; i < n; ++i) {
      const AngleLubrication& a = out.angles[i];
      if (a.lambda < out.angles[out.min_lambda].lambda) out.min_lambda = i;
      ++out.regime_steps[static_cast<int>(a.regime)];
      if (!a.within_fit_range) ++out.outside_fit_steps;
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
  return out;
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
    out += "friction: the revolution's solves use cam.mu; the regime's mu and wear factor are reported per angle\n";
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
  return out;
}

std::string lubrication_csv_header(const CamLubricationSpec& spec) {
  std::string h;
  if (!spec.any()) return h;
  h += ",cam_surface_speed_m_per_s,roller_surface_speed_m_per_s,entrainment_m_per_s,Rx_m,ellipticity_k";
  if (spec.lubricant) h += ",h_min_m,h_central_m,lambda,lubrication_regime,regime_mu,regime_wear_factor";
  if (spec.thermal)
    h += ",heat_W,flash_max_K,heat_share_roller,peclet_roller,peclet_cam,transit_s,contact_temperature_C,"
         "scuffing_margin_K";
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
  }
  if (spec.thermal)
    for (double v : {a.power_W, a.flash_max_K, a.heat_share_roller, a.peclet_roller, a.peclet_cam, a.transit_s,
                     a.contact_temperature_C, a.scuffing_margin_K})
      cell(out, v);
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
  }
  if (spec.thermal) {
    const AngleLubrication& t = l.angles[l.max_flash];
    out += fmt::format("max_flash_K: {:.6g}\nmax_flash_at_deg: {:.6g}\n", t.flash_max_K, deg(t.theta_rad));
    if (spec.lubricant) out += fmt::format("regime_at_max_flash: {}\n", contact::to_string(t.regime));
    if (!std::isnan(t.contact_temperature_C))
      out += fmt::format("max_contact_temperature_C: {:.6g}\n", t.contact_temperature_C);
    if (!std::isnan(t.scuffing_margin_K)) out += fmt::format("scuffing_margin_K: {:.6g}\n", t.scuffing_margin_K);
  }
  return out;
}

}  // namespace cam
