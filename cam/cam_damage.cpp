// The cam track's and the roller's fatigue damage per cam revolution (cam/cam_damage.h).
#include "cam/cam_damage.h"

#include <cmath>
#include <iterator>
#include <limits>

#include <spdlog/fmt/fmt.h>

#include "cam/cam_error.h"
#include "lib/number.h"
#include "lib/numeric.h"

namespace cam {

namespace {

// the lateral extent of the strips that carry the contact (pressure, or power where the record has no pressure)
double loaded_width_m(const AngleDissipation& a, const Eigen::ArrayXd& edges) {
  const Eigen::Index n = a.y_m.size();
  const bool pressure = a.mean_pressure_Pa.size() == n;
  Eigen::Index first = -1, last = -1;
  for (Eigen::Index j = 0; j < n; ++j)
    if (pressure ? a.mean_pressure_Pa(j) > 0 : a.power_W_per_m(j) > 0) {
      if (first < 0) first = j;
      last = j;
    }
  return first < 0 ? 0 : edges(last + 1) - edges(first);
}

}  // namespace

CamDamageRate damage_per_revolution(const RevolutionDissipation& rev, const CamWearGrid& g,
                                    const wear::FatigueSection& fatigue) {
  check_dissipation(rev, g);
  const std::size_t n = rev.size();
  const double L = g.circumference_m;
  CamDamageRate r;
  r.per_revolution.cam = Eigen::ArrayXXd::Zero(g.arc_cells, g.track_cells);
  r.per_revolution.roller = Eigen::ArrayXd::Zero(g.roller_cells);
  Eigen::ArrayXd lateral(g.track_cells);
  for (std::size_t k = 0; k < n; ++k) {
    const AngleDissipation& a = rev[k];
    const double arc_lo = a.cam_arc_m, arc_hi = k + 1 < n ? rev[k + 1].cam_arc_m : rev.front().cam_arc_m + L;
    const Eigen::ArrayXd edges = strip_edges(a.y_m);
    const double width = loaded_width_m(a, edges);
    const double V = std::abs(a.rolling_speed_m_per_s);
    if (!(width > 0) || !(V > 0)) continue;
    // a roller point's passes through the contact during the step
    const double roller_passes =
        std::abs(a.roller_surface_speed_m_per_s) * a.duration_s / (2 * contact::kPi * g.roller_radius_m);
    lateral.setZero();
    for (Eigen::Index j = 0; j < a.y_m.size(); ++j) {
      const double tgamma = width * a.power_W_per_m(j) / V;
      if (tgamma > r.max_tgamma_N) {
        r.max_tgamma_N = tgamma;
        r.max_tgamma_at_rad = a.theta_rad;
      }
      const double d = wear::burstow_damage_per_pass(fatigue.burstow, tgamma);
      if (d == 0) continue;
      const double dy = edges(j + 1) - edges(j);
      // damage x width onto the cells, then over the cells' widths: the mean over each cell
      const double y0 = edges(j) + 0.5 * g.track_width_m, y1 = edges(j + 1) + 0.5 * g.track_width_m;
      deposit(y0, y1, d * dy, g.track_cell_m(), g.track_cells, false, lateral.data());
      const double r0 = edges(j) + 0.5 * g.roller_width_m, r1 = edges(j + 1) + 0.5 * g.roller_width_m;
      deposit(r0, r1, d * dy * roller_passes, g.roller_cell_m(), g.roller_cells, false,
              r.per_revolution.roller.data());
    }
    lateral /= g.track_cell_m();
    // along the arc the step swept: each point of it passes the contact once per revolution
    for (int j = 0; j < g.track_cells; ++j)
      if (lateral(j) > 0)
        deposit(arc_lo, arc_hi, lateral(j) * (arc_hi - arc_lo), g.arc_cell_m(), g.arc_cells, true,
                &r.per_revolution.cam(0, j));
  }
  r.per_revolution.cam /= g.arc_cell_m();
  r.per_revolution.roller /= g.roller_cell_m();
  return r;
}

CamDamageMax max_damage(const CamWearGrid& g, const CamDamage& d) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CamDamageMax m;
  m.theta_rad = m.arc_m = m.y_m = nan;
  Eigen::Index i = 0, j = 0, k = 0;
  const double cam = d.cam.size() ? d.cam.maxCoeff(&i, &j) : 0;
  const double roller = d.roller.size() ? d.roller.maxCoeff(&k) : 0;
  if (!(cam > 0) && !(roller > 0)) return m;
  if (cam >= roller) {
    m.value = cam;
    m.body = "cam";
    m.arc_m = g.arc_m(static_cast<int>(i));
    m.y_m = g.track_y_m(static_cast<int>(j));
    if (g.cell_theta_rad.size() == g.arc_cells) m.theta_rad = g.cell_theta_rad(i);
  } else {
    m.value = roller;
    m.body = "roller";
    m.y_m = g.roller_y_m(static_cast<int>(k));
  }
  return m;
}

std::string damage_map_csv(const CamWearGrid& g, const CamDamage& d, double revolutions, const std::string& name) {
  std::string out = grid_csv_header(g, revolutions, name,
                           "the cam track's fatigue damage (Miner's sum, Burstow's T-gamma function); cam_angle_deg: "
                           "the cam angle at which the contact passes");
  out += "cam_angle_deg,cam_arc_m,y_m,damage\n";
  const bool angles = g.cell_theta_rad.size() == g.arc_cells;
  for (int i = 0; i < g.arc_cells; ++i) {
    const std::string angle = angles ? fmt::format("{:.8g}", g.cell_theta_rad(i) * kDegPerRad) : "nan";
    for (int j = 0; j < g.track_cells; ++j)
      fmt::format_to(std::back_inserter(out), "{},{:.10g},{:.10g},{:.10g}\n", angle, g.arc_m(i), g.track_y_m(j),
                     d.cam(i, j));
  }
  return out;
}

std::string roller_damage_csv(const CamWearGrid& g, const CamDamage& d, double revolutions, const std::string& name) {
  std::string out = grid_csv_header(g, revolutions, name, "the roller's fatigue damage (Miner's sum), even around it");
  out += "y_m,damage\n";
  for (int j = 0; j < g.roller_cells; ++j)
    fmt::format_to(std::back_inserter(out), "{:.10g},{:.10g}\n", g.roller_y_m(j), d.roller(j));
  return out;
}

}  // namespace cam
