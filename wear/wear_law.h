// Wear laws (docs/physics.md §6): the depth removed per duty cycle at each strip y_j of the
// worn body, whose life is counted in its revolutions (radius R_w). A revolution carries each
// surface point of the worn body through the contact once; a duty cycle's wear is spread evenly
// around the circumference.
//
// energy   worn volume = k_E x dissipated energy. A duty cycle that dissipates E_l(y_j) per unit
//          width (steady: P_l(y_j) x time; Satran: strip_energy_J_per_m) removes
//            dh_j = k_E E_l(y_j) / (2 pi R_w).
// archard  worn volume = (K/H) x normal force x sliding distance, local rate (K/H) p |s|. With
//          constant mu, p |s| = -tau.s / mu wherever s != 0, so Archard is the energy law with
//            k_E = K / (H mu)
//          and uses the same energy-consistent E_l (never a separate p |s| sum, which would carry
//          the discretisation's power error, docs/physics.md §5). mu = 0 has no energy equivalent.
// kth      Archard with K from the KTH wear map (Jendel 2002): regions of p/H and of the sliding
//          speed |s|. Per cell (i, j) of a stretch of rolling at speed V, a surface point spends
//          dt_cell = dx/V in the cell, so the depth per passage of strip j is
//            dh_j = sum_i K(p_ij/H, |s_ij|)/H * (p |s|)_ij * dx / V.
//          The region is chosen from the cell's mean pressure p_ij and the magnitude |s_ij| of its
//          cell-mean slip velocity (the slip itself is singular at a Hertzian trailing edge; its
//          cell mean is finite).
// usfd     University of Sheffield, wheel/rail: wear rate W(T gamma/A) in ug per metre rolled per
//          mm^2 of contact, applied per cell with T gamma/A -> (|tau| |s|)_ij / V (tau in N/mm^2 =
//          MPa, s and V in m/s, so T gamma/A in N/mm^2). Per passage (a surface point spends dx of
//          rolled distance in a cell):
//            dh_j = sum_i W((|tau| |s|)_ij / V) * dx * 1e-3 / rho
//          (W in ug/(m mm^2) times dx in m is ug/mm^2 = 1e-9 kg / 1e-6 m^2 = 1e-3 kg/m^2; / rho
//          in kg/m^3 gives m).
//
// The cell products (p |s|)_ij and (|tau| |s|)_ij. In slip tau = -mu p s/|s|, so |tau| |s| = -tau.s
// = mu p |s|: both are the cell's dissipated power density D_ij = mean over the cell of -tau.s,
// which the consistent steady scheme writes (power_W_per_m2) and whose strip sums are its
// energy-consistent P_l exactly. With it, (p |s|)_ij = D_ij / mu, and KTH with one K for every
// region is Archard (the energy law with k_E = K/(H mu)) to rounding; USFD's mild branch is an
// energy law too. Without it (Satran snapshots carry no power field, or mu = 0), the product of the
// cell means is used: p_ij |s_ij| and |tau_ij| |s_ij|. That product is biased at first order in dx
// (tau and p are full-cell means, s the mean over the part in contact, and both vary steeply at the
// trailing edge): on the paper's case, pure xi = 1e-3, it is 9 %, 4.5 %, 2.1 % high on 40, 80, 160
// cells (docs/wear-laws.md).
//
// Passages per duty cycle: a stretch of duration T at rolling speed V rolls q = V T, i.e.
// q / (2 pi R_w) revolutions (to O(creepage): the worn body's surface speed is V (1 +- xi/2)).
// KTH per duty cycle is therefore sum_i K/H p |s| dx T / (2 pi R_w), which holds at V = 0 too
// (sliding at standstill); USFD is per metre rolled and needs V > 0 where anything slips.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "lib/enum_names.h"
#include "lib/patch.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/tangential.h"

namespace wear {

// ---- energy law ----

// dh_j = k_E E_l(y_j) / (2 pi R_w): depth per duty cycle per strip (m). energy_J_per_m (ny) is the
// dissipated energy per unit width over the duty cycle. Throws std::invalid_argument for
// k_E < 0, R_w <= 0 or a non-finite input.
Eigen::ArrayXd depth_from_energy(const Eigen::ArrayXd& energy_J_per_m, double k_E_m3_per_J,
                                 double worn_radius_m);

// ---- Archard, through the energy law ----

// k_E = K / (H mu) (m^3/J), Archard's coefficient K (dimensionless), hardness H. Throws
// std::invalid_argument for mu <= 0: Archard with mu = 0 has no energy equivalent (nothing is
// dissipated while p |s| still counts sliding).
double archard_energy_coefficient_m3_per_J(double archard_k, double hardness_Pa, double mu);

// ---- the per-cell fields the local laws (kth, usfd) read ----

// a stretch of rolling with constant fields: a steady solution held for duration_s, or the step
// means of a Satran snapshot
struct CellFields {
  // (nx x ny), column j = strip j
  Eigen::ArrayXXd pressure_Pa;                     // mean over the full cell, 0 outside
  Eigen::ArrayXXd tau_x_Pa, tau_y_Pa;              // mean over the full cell; act on body 1
  Eigen::ArrayXXd slip_x_m_per_s, slip_y_m_per_s;  // mean over the part of the cell in contact
  Eigen::ArrayXXd power_W_per_m2;  // D: mean over the cell of -tau.s; empty = not available (then the
                                   // product of the cell means stands in for it, biased at O(dx))
  double mu = 0;             // friction the fields were solved with: (p |s|) = D / mu when mu > 0
  double dx_m = 0;           // cell length along x (rolling)
  double speed_m_per_s = 0;  // rolling speed V >= 0
  double duration_s = 0;     // time the stretch lasts within the duty cycle, >= 0
};

// the fields of a steady solution, power included (solved with SteadyOptions::fields = true; throws
// std::invalid_argument naming the missing field otherwise); mu of its TangentialProblem
CellFields cell_fields(const contact::ContactPatch& patch, const contact::TangentialSolution& solution,
                       double mu, double speed_m_per_s, double duration_s);
// the fields of a Satran snapshot on the run's grid (no power field: cell-mean products, see above)
CellFields cell_fields(const contact::Snapshot& snapshot, const contact::Grid& grid, double mu,
                       double speed_m_per_s, double duration_s);

// the cell's (|tau| |s|) in W/m^2: D_ij, or |tau_ij| |s_ij| of the cell means without a power field
double cell_dissipation_W_per_m2(const CellFields& fields, int i, int j);
// the cell's (p |s|) in Pa m/s: D_ij / mu, or p_ij |s_ij| of the cell means without a power field or mu
double cell_pressure_slip_Pa_m_per_s(const CellFields& fields, int i, int j);

// ---- KTH wear map (Jendel 2002) ----

// K by region (the values are the commonly quoted ones, see docs/wear-laws.md for which are
// unverified); boundaries: p/H > pressure_ratio -> catastrophic at any speed; else |s| below
// slip_speed_low -> mild (slow), up to slip_speed_high (inclusive) -> severe, above -> mild (fast)
struct KthWearMap {
  double pressure_ratio = 0.8;              // p/H above which wear is catastrophic (seizure)
  double slip_speed_low_m_per_s = 0.2;      // mild -> severe
  double slip_speed_high_m_per_s = 0.7;     // severe -> mild (oxidative, fast)
  double K_mild_slow = 5e-4;                // K1, quoted as 1-10e-4
  double K_severe = 35e-4;                  // K2, quoted as 30-40e-4
  double K_mild_fast = 5e-4;                // K3, quoted as 1-10e-4
  double K_catastrophic = 350e-4;           // K4, quoted as 300-400e-4
};

enum class KthRegion { MildSlow, Severe, MildFast, Catastrophic };
constexpr contact::EnumTable<KthRegion, 4> kKthRegionNames = {{{KthRegion::MildSlow, "mild (slow)"},
                                                               {KthRegion::Severe, "severe"},
                                                               {KthRegion::MildFast, "mild (fast)"},
                                                               {KthRegion::Catastrophic, "catastrophic"}}};
std::string to_string(KthRegion region);

KthRegion kth_region(const KthWearMap& map, double pressure_over_hardness, double slip_speed_m_per_s);
double kth_coefficient(const KthWearMap& map, double pressure_over_hardness, double slip_speed_m_per_s);

// dh_j = sum_i K(p_ij/H, |s_ij|)/H * (p |s|)_ij * dx / V: depth per passage per strip (m).
// Throws std::invalid_argument for V <= 0 (no passage) or H <= 0.
Eigen::ArrayXd kth_depth_per_passage(const CellFields& fields, const KthWearMap& map, double hardness_Pa);

// ---- USFD T gamma/A wear function ----

// W(x), x = T gamma/A in N/mm^2, W in ug/(m mm^2). The published function (R8T wheel steel) is
//   W = 5.3 x (x < 10.4),  55.0 (10.4 <= x <= 77.2),  61.9 x - 4778.7 (x > 77.2),
// which is discontinuous: 55.12 -> 55.0 at 10.4 and 55.0 -> -0.02 at 77.2 (its last branch starts
// at zero). Convention here, the continuous non-decreasing envelope of the three branches:
//   W = max( min(mild_slope x, severe), catastrophic_slope x - catastrophic_offset ),
// equal to the published function except on [10.377, 10.4) (55.0 instead of up to 55.12) and on
// (77.2, 78.09) (55.0 instead of 0 .. 55); the breakpoints follow from the coefficients.
struct UsfdWearFunction {
  double mild_slope = 5.3;                           // ug/(m mm^2) per N/mm^2
  double severe_ug_per_m_mm2 = 55.0;                 // plateau
  double catastrophic_slope = 61.9;                  // ug/(m mm^2) per N/mm^2
  double catastrophic_offset_ug_per_m_mm2 = 4778.7;
};

enum class UsfdRegion { Mild, Severe, Catastrophic };
constexpr contact::EnumTable<UsfdRegion, 3> kUsfdRegionNames = {
    {{UsfdRegion::Mild, "mild"}, {UsfdRegion::Severe, "severe"}, {UsfdRegion::Catastrophic, "catastrophic"}}};
std::string to_string(UsfdRegion region);

UsfdRegion usfd_region(const UsfdWearFunction& f, double Tgamma_over_A_N_per_mm2);
double usfd_wear_rate_ug_per_m_mm2(const UsfdWearFunction& f, double Tgamma_over_A_N_per_mm2);

// dh_j = sum_i W((|tau| |s|)_ij / V) * dx * 1e-3 / rho: depth per passage per strip (m). Throws
// std::invalid_argument for V <= 0 where a cell slips (T gamma/A is per metre rolled) or rho <= 0.
Eigen::ArrayXd usfd_depth_per_passage(const CellFields& fields, const UsfdWearFunction& f,
                                      double density_kg_per_m3);

// ---- the wear law of a case, and the depth per duty cycle ----

enum class WearLawKind { Energy, Archard, Kth, Usfd };
// the names of wear.bodyN.law, in the order messages list them
constexpr contact::EnumTable<WearLawKind, 4> kWearLawNames = {{{WearLawKind::Energy, "energy"},
                                                               {WearLawKind::Archard, "archard"},
                                                               {WearLawKind::Kth, "kth"},
                                                               {WearLawKind::Usfd, "usfd"}}};
std::string to_string(WearLawKind kind);
// throws contact::SettingError (a std::invalid_argument) naming the valid laws
WearLawKind parse_wear_law(const std::string& name);

struct WearLaw {                         // the case's wear section (YAML keys = field names)
  WearLawKind law = WearLawKind::Energy;  // energy | archard | kth | usfd (kWearLawNames)
  double k_E_m3_per_J = 0;               // energy: > 0
  double archard_k = 0;                  // archard: (0, 1]
  double hardness_Pa = 0;                // archard, kth: > 0 (of the worn body)
  double density_kg_per_m3 = 7850;       // usfd: > 0 (steel)
  KthWearMap kth;                        // kth
  UsfdWearFunction usfd;                 // usfd
};

// checks the parameters the chosen law reads; throws std::invalid_argument naming the parameter
// ("wear.archard_k: must be in (0, 1], got 0")
void validate(const WearLaw& law);

// what a duty cycle produced
struct DutyCycle {
  double worn_radius_m = 0;             // R_w of the worn body
  double mu = 0;                        // friction of the tangential solution (archard)
  Eigen::ArrayXd strip_energy_J_per_m;  // (ny) dissipated energy per unit width (energy, archard)
  std::vector<CellFields> stretches;    // the fields over the cycle (kth, usfd), on one grid
};

// depth per duty cycle per strip (m): energy and archard from strip_energy_J_per_m, kth and usfd
// from the stretches (each counted for its own revolutions, V T / (2 pi R_w)). Validates the law;
// throws std::invalid_argument for R_w <= 0 or when the input the law needs is missing.
Eigen::ArrayXd depth_per_duty_cycle(const WearLaw& law, const DutyCycle& duty);

}  // namespace wear
