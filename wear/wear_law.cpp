// Wear laws (docs/physics.md §6); the formulas and their units are at the top of wear/wear_law.h.
//
// Every law returns the depth per duty cycle per strip. The energy law and Archard read the strip
// energies E_l(y_j), so their worn volume, summed over the strips and around the circumference, is
// k_E times the dissipated energy to rounding:
//   sum_j dh_j dy 2 pi R_w = k_E sum_j E_l(y_j) dy.
// KTH and USFD are sums over cells of the fields the tangential solver wrote; a stretch of duration
// T at speed V counts V T / (2 pi R_w) passages.
#include "wear/wear_law.h"
#include "lib/number.h"
#include "lib/numeric.h"
#include "lib/errors.h"

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace wear {

using contact::kPi;

namespace {

// 1 ug/mm^2 = 1e-9 kg / 1e-6 m^2 = 1e-3 kg/m^2
constexpr double kKg_per_m2_per_ug_per_mm2 = 1e-3;
// 1 Pa = 1e-6 N/mm^2 (MPa)
constexpr double kN_per_mm2_per_Pa = 1e-6;

std::string number(double v) { return contact::six_digits(v); }  // lib/number.h

[[noreturn]] void fail(const std::string& key, const std::string& range, double got) {
  throw contact::SettingError("wear", key, "must be " + range + ", got " + number(got));
}

// lo < v <= hi (lo_open) or lo <= v <= hi
void check_range(const std::string& key, double v, double lo, double hi, bool lo_open, const std::string& range) {
  const bool ok = std::isfinite(v) && (lo_open ? v > lo : v >= lo) && v <= hi;
  if (!ok) fail(key, range, v);
}

// where: "kth: " or "duty cycle stretch 2: "
void check_stretch(const CellFields& f, const std::string& where) {
  const Eigen::Index nx = f.pressure_Pa.rows(), ny = f.pressure_Pa.cols();
  auto same = [&](const Eigen::ArrayXXd& a, const char* name) {
    if (a.rows() != nx || a.cols() != ny)
      throw std::invalid_argument(where + name + " is " + std::to_string(a.rows()) + " x " +
                                  std::to_string(a.cols()) + ", pressure_Pa " + std::to_string(nx) + " x " +
                                  std::to_string(ny));
  };
  same(f.tau_x_Pa, "tau_x_Pa");
  same(f.tau_y_Pa, "tau_y_Pa");
  same(f.slip_x_m_per_s, "slip_x_m_per_s");
  same(f.slip_y_m_per_s, "slip_y_m_per_s");
  if (f.power_W_per_m2.size() > 0) same(f.power_W_per_m2, "power_W_per_m2");
  if (!(f.mu >= 0) || !std::isfinite(f.mu)) throw std::invalid_argument(where + "mu must be >= 0, got " + number(f.mu));
  if (!(f.dx_m > 0) || !std::isfinite(f.dx_m))
    throw std::invalid_argument(where + "dx_m must be > 0, got " + number(f.dx_m));
  if (!(f.speed_m_per_s >= 0) || !std::isfinite(f.speed_m_per_s))
    throw std::invalid_argument(where + "speed_m_per_s must be >= 0, got " + number(f.speed_m_per_s));
  if (!(f.duration_s >= 0) || !std::isfinite(f.duration_s))
    throw std::invalid_argument(where + "duration_s must be >= 0, got " + number(f.duration_s));
}

// sum_i K(p/H, |s|)/H (p |s|) dx: worn volume per unit width per unit time of each strip (m^2/s)
Eigen::ArrayXd kth_volume_rate_m2_per_s(const CellFields& f, const KthWearMap& map, double H) {
  const int nx = static_cast<int>(f.pressure_Pa.rows()), ny = static_cast<int>(f.pressure_Pa.cols());
  Eigen::ArrayXd rate = Eigen::ArrayXd::Zero(ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double p = f.pressure_Pa(i, j);
      const double s = std::hypot(f.slip_x_m_per_s(i, j), f.slip_y_m_per_s(i, j));
      if (!(p > 0) || !(s > 0)) continue;  // out of contact, or stick: no sliding
      // the region from the cell means, the sliding work from the cell's dissipated power
      rate(j) += kth_coefficient(map, p / H, s) / H * cell_pressure_slip_Pa_m_per_s(f, i, j) * f.dx_m;
    }
  return rate;
}

}  // namespace

// ---- energy law ----

Eigen::ArrayXd depth_from_energy(const Eigen::ArrayXd& energy_J_per_m, double k_E_m3_per_J, double worn_radius_m) {
  if (!(k_E_m3_per_J >= 0) || !std::isfinite(k_E_m3_per_J))
    throw std::invalid_argument("depth_from_energy: k_E_m3_per_J must be >= 0, got " + number(k_E_m3_per_J));
  if (!(worn_radius_m > 0) || !std::isfinite(worn_radius_m))
    throw std::invalid_argument("depth_from_energy: worn_radius_m must be > 0, got " + number(worn_radius_m));
  if (!energy_J_per_m.allFinite()) throw std::invalid_argument("depth_from_energy: energy_J_per_m is not finite");
  // the duty cycle's worn volume per unit width, spread around the circumference
  return k_E_m3_per_J * energy_J_per_m / (2 * kPi * worn_radius_m);
}

// ---- Archard ----

double archard_energy_coefficient_m3_per_J(double archard_k, double hardness_Pa, double mu) {
  if (mu == 0)
    throw std::invalid_argument(
        "archard: mu = 0 has no energy equivalent (k_E = K/(H mu) is infinite: a frictionless contact "
        "dissipates nothing while Archard's K/H p |s| still counts sliding); give mu > 0");
  if (!(mu > 0) || !std::isfinite(mu)) throw std::invalid_argument("archard: mu must be > 0, got " + number(mu));
  if (!(archard_k >= 0) || !std::isfinite(archard_k))
    throw std::invalid_argument("archard: archard_k must be >= 0, got " + number(archard_k));
  if (!(hardness_Pa > 0) || !std::isfinite(hardness_Pa))
    throw std::invalid_argument("archard: hardness_Pa must be > 0, got " + number(hardness_Pa));
  // p |s| = -tau.s / mu where s != 0
  return archard_k / (hardness_Pa * mu);
}

// ---- cell fields ----

CellFields cell_fields(const contact::ContactPatch& patch, const contact::TangentialSolution& solution,
                       double mu, double speed_m_per_s, double duration_s) {
  const contact::Grid& g = patch.grid;
  auto need = [&](const Eigen::ArrayXXd& a, const char* name) {
    if (a.rows() != g.nx || a.cols() != g.ny)
      throw std::invalid_argument(std::string("cell_fields: the tangential solution's ") + name + " is " +
                                  std::to_string(a.rows()) + " x " + std::to_string(a.cols()) + ", the grid " +
                                  std::to_string(g.nx) + " x " + std::to_string(g.ny) +
                                  " (solve with SteadyOptions::fields = true)");
  };
  need(patch.pressure_Pa, "pressure_Pa (patch)");
  need(solution.tau_x_Pa, "tau_x_Pa");
  need(solution.tau_y_Pa, "tau_y_Pa");
  need(solution.slip_x_m_per_s, "slip_x_m_per_s");
  need(solution.slip_y_m_per_s, "slip_y_m_per_s");
  need(solution.power_W_per_m2, "power_W_per_m2");
  return {patch.pressure_Pa,       solution.tau_x_Pa,       solution.tau_y_Pa, solution.slip_x_m_per_s,
          solution.slip_y_m_per_s, solution.power_W_per_m2, mu,                g.dx_m,
          speed_m_per_s,           duration_s};
}

CellFields cell_fields(const contact::Snapshot& snapshot, const contact::Grid& grid, double mu,
                       double speed_m_per_s, double duration_s) {
  for (const Eigen::ArrayXXd* a : {&snapshot.pressure_Pa, &snapshot.tau_x_Pa, &snapshot.tau_y_Pa,
                                   &snapshot.slip_x_m_per_s, &snapshot.slip_y_m_per_s})
    if (a->rows() != grid.nx || a->cols() != grid.ny)
      throw std::invalid_argument("cell_fields: a snapshot field is " + std::to_string(a->rows()) + " x " +
                                  std::to_string(a->cols()) + ", the grid " + std::to_string(grid.nx) + " x " +
                                  std::to_string(grid.ny));
  return {snapshot.pressure_Pa,     snapshot.tau_x_Pa, snapshot.tau_y_Pa, snapshot.slip_x_m_per_s,
          snapshot.slip_y_m_per_s,  Eigen::ArrayXXd(),  mu,                 grid.dx_m,
          speed_m_per_s,            duration_s};
}

double cell_dissipation_W_per_m2(const CellFields& f, int i, int j) {
  if (f.power_W_per_m2.size() > 0) return std::max(0.0, f.power_W_per_m2(i, j));
  return std::hypot(f.tau_x_Pa(i, j), f.tau_y_Pa(i, j)) * std::hypot(f.slip_x_m_per_s(i, j), f.slip_y_m_per_s(i, j));
}

double cell_pressure_slip_Pa_m_per_s(const CellFields& f, int i, int j) {
  if (f.power_W_per_m2.size() > 0 && f.mu > 0) return std::max(0.0, f.power_W_per_m2(i, j)) / f.mu;
  return f.pressure_Pa(i, j) * std::hypot(f.slip_x_m_per_s(i, j), f.slip_y_m_per_s(i, j));
}

// ---- KTH wear map ----

std::string to_string(KthRegion region) { return contact::enum_name(kKthRegionNames, region); }

KthRegion kth_region(const KthWearMap& map, double pressure_over_hardness, double slip_speed_m_per_s) {
  if (pressure_over_hardness > map.pressure_ratio) return KthRegion::Catastrophic;
  if (slip_speed_m_per_s < map.slip_speed_low_m_per_s) return KthRegion::MildSlow;
  if (slip_speed_m_per_s <= map.slip_speed_high_m_per_s) return KthRegion::Severe;
  return KthRegion::MildFast;
}

double kth_coefficient(const KthWearMap& map, double pressure_over_hardness, double slip_speed_m_per_s) {
  switch (kth_region(map, pressure_over_hardness, slip_speed_m_per_s)) {
    case KthRegion::MildSlow: return map.K_mild_slow;
    case KthRegion::Severe: return map.K_severe;
    case KthRegion::MildFast: return map.K_mild_fast;
    case KthRegion::Catastrophic: return map.K_catastrophic;
  }
  return 0;
}

Eigen::ArrayXd kth_depth_per_passage(const CellFields& fields, const KthWearMap& map, double hardness_Pa) {
  check_stretch(fields, "kth: ");
  if (!(hardness_Pa > 0) || !std::isfinite(hardness_Pa))
    throw std::invalid_argument("kth: hardness_Pa must be > 0, got " + number(hardness_Pa));
  if (!(fields.speed_m_per_s > 0))
    throw std::invalid_argument("kth: a passage needs a rolling speed > 0, got " + number(fields.speed_m_per_s) +
                                " m/s");
  // dt_cell = dx / V
  return kth_volume_rate_m2_per_s(fields, map, hardness_Pa) / fields.speed_m_per_s;
}

// ---- USFD T gamma/A ----

std::string to_string(UsfdRegion region) { return contact::enum_name(kUsfdRegionNames, region); }

UsfdRegion usfd_region(const UsfdWearFunction& f, double x) {
  const double mild = f.mild_slope * x;
  const double catastrophic = f.catastrophic_slope * x - f.catastrophic_offset_ug_per_m_mm2;
  if (catastrophic > std::min(mild, f.severe_ug_per_m_mm2)) return UsfdRegion::Catastrophic;
  return mild < f.severe_ug_per_m_mm2 ? UsfdRegion::Mild : UsfdRegion::Severe;
}

double usfd_wear_rate_ug_per_m_mm2(const UsfdWearFunction& f, double x) {
  // the continuous non-decreasing envelope of the published branches (wear/wear_law.h)
  return std::max(std::min(f.mild_slope * x, f.severe_ug_per_m_mm2),
                  f.catastrophic_slope * x - f.catastrophic_offset_ug_per_m_mm2);
}

Eigen::ArrayXd usfd_depth_per_passage(const CellFields& fields, const UsfdWearFunction& f, double density_kg_per_m3) {
  check_stretch(fields, "usfd: ");
  if (!(density_kg_per_m3 > 0) || !std::isfinite(density_kg_per_m3))
    throw std::invalid_argument("usfd: density_kg_per_m3 must be > 0, got " + number(density_kg_per_m3));
  const double V = fields.speed_m_per_s;
  const int nx = static_cast<int>(fields.pressure_Pa.rows()), ny = static_cast<int>(fields.pressure_Pa.cols());
  Eigen::ArrayXd depth = Eigen::ArrayXd::Zero(ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double D_W_per_m2 = cell_dissipation_W_per_m2(fields, i, j);  // |tau| |s|
      if (!(D_W_per_m2 > 0)) continue;  // nothing slips here: W(0) = 0
      if (!(V > 0))
        throw std::invalid_argument("usfd: T gamma/A is per metre rolled and needs a rolling speed > 0 where the "
                                    "contact slips, got V = " + number(V) + " m/s");
      // T gamma/A = |tau| |s| / V: W/m^2 / (m/s) = N/m^2 = Pa, times 1e-6 -> N/mm^2; W dx in ug/mm^2
      const double W = usfd_wear_rate_ug_per_m_mm2(f, D_W_per_m2 / V * kN_per_mm2_per_Pa);
      depth(j) += W * fields.dx_m * kKg_per_m2_per_ug_per_mm2 / density_kg_per_m3;
    }
  return depth;
}

// ---- the wear law of a case ----

std::string to_string(WearLawKind kind) { return contact::enum_name(kWearLawNames, kind); }

WearLawKind parse_wear_law(const std::string& name) {
  if (const std::optional<WearLawKind> k = contact::enum_from_name(kWearLawNames, name)) return *k;
  throw contact::SettingError("wear", "law", "unknown wear law '" + contact::clipped(name) + "' (valid: " +
                                                contact::enum_names_list(kWearLawNames) + ")");
}

void validate(const WearLaw& law) {
  // ranges wide enough for any metal, narrow enough to catch a unit slip: k_E in mm^3/(N m) reads
  // 1e9 times too large, hardness in GPa or HV and density in g/cm^3 read far too small
  switch (law.law) {
    case WearLawKind::Energy:
      check_range("k_E_m3_per_J", law.k_E_m3_per_J, 0, 1e-6, true, "in (0, 1e-6] m^3/J");
      break;
    case WearLawKind::Archard:
      check_range("archard_k", law.archard_k, 0, 1, true, "in (0, 1]");
      check_range("hardness_Pa", law.hardness_Pa, 1e8, 1e11, false, "in [1e8, 1e11] Pa");
      break;
    case WearLawKind::Kth: {
      check_range("hardness_Pa", law.hardness_Pa, 1e8, 1e11, false, "in [1e8, 1e11] Pa");
      const KthWearMap& m = law.kth;
      check_range("kth.pressure_ratio", m.pressure_ratio, 0, 10, true, "in (0, 10]");
      check_range("kth.slip_speed_low_m_per_s", m.slip_speed_low_m_per_s, 0, 1e3, true, "in (0, 1e3] m/s");
      check_range("kth.slip_speed_high_m_per_s", m.slip_speed_high_m_per_s, m.slip_speed_low_m_per_s, 1e3, true,
                  "in (kth.slip_speed_low_m_per_s = " + number(m.slip_speed_low_m_per_s) + ", 1e3] m/s");
      check_range("kth.K_mild_slow", m.K_mild_slow, 0, 1, false, "in [0, 1]");
      check_range("kth.K_severe", m.K_severe, 0, 1, false, "in [0, 1]");
      check_range("kth.K_mild_fast", m.K_mild_fast, 0, 1, false, "in [0, 1]");
      check_range("kth.K_catastrophic", m.K_catastrophic, 0, 1, false, "in [0, 1]");
      break;
    }
    case WearLawKind::Usfd: {
      check_range("density_kg_per_m3", law.density_kg_per_m3, 100, 3e4, false, "in [100, 3e4] kg/m^3");
      const UsfdWearFunction& f = law.usfd;
      check_range("usfd.mild_slope", f.mild_slope, 0, 1e6, true, "in (0, 1e6] ug/(m mm^2) per N/mm^2");
      check_range("usfd.severe_ug_per_m_mm2", f.severe_ug_per_m_mm2, 0, 1e8, false, "in [0, 1e8] ug/(m mm^2)");
      check_range("usfd.catastrophic_slope", f.catastrophic_slope, 0, 1e6, false,
                  "in [0, 1e6] ug/(m mm^2) per N/mm^2");
      check_range("usfd.catastrophic_offset_ug_per_m_mm2", f.catastrophic_offset_ug_per_m_mm2, 0, 1e9, false,
                  "in [0, 1e9] ug/(m mm^2)");
      break;
    }
  }
}

Eigen::ArrayXd depth_per_duty_cycle(const WearLaw& law, const DutyCycle& duty) {
  validate(law);
  const WearLawKind kind = law.law;
  const double R_w = duty.worn_radius_m;
  if (!(R_w > 0) || !std::isfinite(R_w))
    throw std::invalid_argument("duty cycle: worn_radius_m must be > 0, got " + number(R_w));
  const double circumference_m = 2 * kPi * R_w;

  Eigen::ArrayXd depth_m;
  if (kind == WearLawKind::Energy || kind == WearLawKind::Archard) {
    if (duty.strip_energy_J_per_m.size() == 0)
      throw std::invalid_argument("wear law " + to_string(law.law) + ": the duty cycle has no strip_energy_J_per_m");
    // archard: the energy law with k_E = K/(H mu), on the same energy-consistent E_l
    const double k_E = kind == WearLawKind::Energy
                           ? law.k_E_m3_per_J
                           : archard_energy_coefficient_m3_per_J(law.archard_k, law.hardness_Pa, duty.mu);
    depth_m = depth_from_energy(duty.strip_energy_J_per_m, k_E, R_w);
  } else {
    if (duty.stretches.empty())
      throw std::invalid_argument("wear law " + to_string(law.law) +
                                  ": the duty cycle has no per-cell fields (stretches)");
    const Eigen::Index nx = duty.stretches.front().pressure_Pa.rows(), ny = duty.stretches.front().pressure_Pa.cols();
    depth_m = Eigen::ArrayXd::Zero(ny);
    for (std::size_t k = 0; k < duty.stretches.size(); ++k) {
      const CellFields& f = duty.stretches[k];
      check_stretch(f, "duty cycle stretch " + std::to_string(k) + ": ");
      if (f.pressure_Pa.rows() != nx || f.pressure_Pa.cols() != ny)
        throw std::invalid_argument("duty cycle stretch " + std::to_string(k) + ": grid " +
                                    std::to_string(f.pressure_Pa.rows()) + " x " + std::to_string(f.pressure_Pa.cols()) +
                                    ", stretch 0 on " + std::to_string(nx) + " x " + std::to_string(ny));
      if (f.duration_s == 0) continue;
      if (kind == WearLawKind::Kth) {
        // per passage (rate / V) times V T / (2 pi R_w) passages; holds at V = 0 (sliding at standstill)
        depth_m += kth_volume_rate_m2_per_s(f, law.kth, law.hardness_Pa) * f.duration_s / circumference_m;
      } else {
        const double passages = f.speed_m_per_s * f.duration_s / circumference_m;
        depth_m += usfd_depth_per_passage(f, law.usfd, law.density_kg_per_m3) * passages;
      }
    }
  }
  spdlog::debug("wear law {}: max depth {:.3e} m per duty cycle over {} strips, R_w {:.4g} m", to_string(law.law),
                depth_m.size() > 0 ? depth_m.maxCoeff() : 0.0, depth_m.size(), R_w);
  return depth_m;
}

}  // namespace wear
