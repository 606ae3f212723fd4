// Kalker's simplified theory ("bed of springs", docs/physics.md §3): the quantities shared by the steady
// solver and Satran. The state is u = L tau; the slip velocity of body 1 relative to body 2 is
//   s = c + du/dt - V du/dx,   c = V L ( xi/L1 - phi y/L3 ,  eta/L2 + phi x/L3 ),
// with the mean flexibility
//   L = (L1|xi| + L2|eta| + L3|phi| sqrt(ab)) / sqrt(xi^2 + eta^2 + phi^2 ab)   (L1 if all vanish).
// In stick (s = 0, steady) tau changes along x at the rate c/(V L), which does not depend on V or L:
//   d tau/dx = ( xi/L1 - phi y/L3 ,  eta/L2 + phi x/L3 ).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "lib/elastic.h"
#include "lib/tangential/kalker.h"
#include "lib/patch.h"
#include "lib/numeric.h"

namespace contact {

struct Creepages {
  double xi = 0;         // longitudinal, (v2 - v1)/V
  double eta = 0;        // lateral
  double phi_per_m = 0;  // spin
};

double mean_flexibility_m_per_Pa(const Flexibilities& f, const Creepages& c, double a_m, double b_m);

// Everything the tangential solvers need besides the patch.
struct TangentialProblem {
  KalkerCoefficients C;   // at the patch's a/b and the combined nu (kept for reports)
  Flexibilities flex;
  double L_m_per_Pa = 0;  // mean flexibility
  // the spin's flexibility in the longitudinal traction (the -phi y term) where != 0, else flex.L3: the relaxed
  // model's second spin flexibility (lib/tangential/relaxed.h; negative or infinite where its mix correction
  // turns or removes the lateral rate's spin); make_tangential_problem leaves it 0
  double L3x_m_per_Pa = 0;
  Creepages creepages;
  double mu = 0;               // Coulomb friction coefficient
  double speed_m_per_s = 0;    // rolling speed V >= 0
};

// Kalker's coefficients at the patch's a/b, flexibilities with the combined G and nu (docs/physics.md §1)
TangentialProblem make_tangential_problem(const ContactPatch& patch, const ElasticPair& pair,
                                          const Creepages& creepages, double mu, double speed_m_per_s);

// The tangential models a case chooses (solver.tangential); lib/model/contact_model.h turns the choice into
// the model's solves, in one place (a new model: a value here, its row there, its implementation and tests).
//   Classic:    Kalker's FASTSIM as published, on the Cartesian cell centres (for comparison).
//   Consistent: node values at the cell edges and the exact strip ends; within each cell the stick
//               line is integrated exactly and its crossing with the semi-elliptic traction bound is
//               located exactly; the dissipated power is -integral(tau . s) of that reconstruction,
//               so the discrete energy balance of docs/physics.md §4 holds to rounding, strip by strip.
//   (Classic and Consistent are the discretisations of the strip march, solve_steady's and Satran's.)
//   Exact:      not a scheme of the simplified theory: Kalker's exact theory on the half-space
//               (lib/tangential/exact.h); solve_steady and satran_step do not take it.
//   Relaxed:    the consistent scheme wrapped to match the exact theory (lib/tangential/relaxed.h: creepages
//               relaxed over the rolled distance, calibrated creepage factors, power scaled to the creep
//               forces' work); solve_steady does not take it.
enum class TangentialScheme { Classic, Consistent, Exact, Relaxed };

// the scheme of a case without solver.tangential: the relaxed model, matched to the exact theory
// (docs/accuracy-vs-exact.md); consistent (the simplified theory) and classic stay selectable
constexpr TangentialScheme kDefaultTangentialScheme = TangentialScheme::Relaxed;

std::string to_string(TangentialScheme scheme);

// Skip for a symmetric case (docs/accuracy-and-speed.md). Without spin the creep rates
// (xi/L1, eta/L2) are the same on every strip, so on a patch that is its own mirror image in y = 0
// the solution is too: strip ny - 1 - j is a copy of strip j. Mirror images within kMirrorTol: the
// strips' positions, half lengths, peaks and Heathcote offsets agree to that fraction of their
// largest value (a Hertz patch is symmetric to a few ulps, a worn one to its rounding), and the two
// strips have the same grid nodes inside them (a copied node never lands outside its strip). Returns the
// first strip that is a copy (ny - ny/2), or ny when the skip does not apply (spin, an asymmetric
// patch, or skip false).
constexpr double kMirrorTol = 1e-12;
int first_mirrored_strip(const ContactPatch& patch, double phi_per_m, bool skip = true);
// throws std::invalid_argument naming the valid schemes
TangentialScheme parse_tangential_scheme(const std::string& name);

struct TangentialSolution {
  // fields on the grid, (nx x ny), column j = strip j; tractions act on body 1
  Eigen::ArrayXXd tau_x_Pa, tau_y_Pa;            // mean over the full cell
  Eigen::ArrayXXd slip_x_m_per_s, slip_y_m_per_s;  // mean over the part of the cell in contact
  Eigen::ArrayXXd power_W_per_m2;                // dissipated power per unit area, mean over the cell
  Eigen::ArrayXXi state;                         // 0 outside, 1 stick, 2 slip (larger share of the cell)

  // per strip (ny)
  Eigen::ArrayXd strip_power_W_per_m;      // P_l(y_j) = -integral of tau . s dx
  Eigen::ArrayXd strip_creep_power_W_per_m;  // -integral of tau . c dx
  Eigen::ArrayXd strip_trailing_W_per_m;   // V L |tau(-a_j)|^2 / 2, carried out at the trailing edge
  Eigen::ArrayXd strip_force_x_N_per_m;    // integral of tau_x dx
  Eigen::ArrayXd strip_force_y_N_per_m;    // integral of tau_y dx

  // totals
  double Fx_N = 0, Fy_N = 0;
  double Mz_N_m = 0;        // integral of (x tau_y - y tau_x) dA
  double power_W = 0;       // total dissipated power
  double creep_work_W = 0;  // V (xi Fx + eta Fy + phi Mz), the work of the creep forces
  double stick_fraction = 0;  // stick area / contact area
};

// What one strip adds to the patch's totals, per unit width: the steady solver's strips and a
// Satran step's alike.
struct StripTotals {
  double Fx = 0, Fy = 0, Mz = 0;  // integrals of tau_x, tau_y and x tau_y - y tau_x along the strip
  double dissipated = 0;          // a power (steady, W/m) or a step's energy (Satran, J/m)
  double stick_length = 0;
  double counted_length = 0;  // node or cell-centre schemes: the length their points stand for (0: the exact 2 a_j)
};

struct PatchTotals {
  double Fx_N = 0, Fy_N = 0, Mz_N_m = 0;
  double dissipated = 0;      // W or J, as the strips'
  double stick_fraction = 0;  // the stick share of the length the scheme counts (node schemes: dx per node)
};

// The strips in contact (a_j > 0) summed into the patch's totals, each times dy. `Strip` is StripTotals
// or a struct derived from it.
template <class Strip>
PatchTotals patch_totals(const ContactPatch& patch, const std::vector<Strip>& strips) {
  const Grid& g = patch.grid;
  PatchTotals t;
  double stick_area = 0, area = 0;
  for (int j = 0; j < g.ny; ++j) {
    if (!(patch.half_length_m(j) > 0)) continue;
    const StripTotals& s = strips[j];
    t.Fx_N += s.Fx * g.dy_m;
    t.Fy_N += s.Fy * g.dy_m;
    t.Mz_N_m += s.Mz * g.dy_m;
    t.dissipated += s.dissipated * g.dy_m;
    stick_area += s.stick_length * g.dy_m;
    area += (s.counted_length > 0 ? s.counted_length : 2 * patch.half_length_m(j)) * g.dy_m;
  }
  t.stick_fraction = area > 0 ? stick_area / area : 0;
  return t;
}

// the text of a broken strip invariant (strip_totals_hold): the strip's numbers and what they are held to
std::string strip_invariant_text(const ContactPatch& patch, double mu, int j, const StripTotals& s, bool bounded,
                                 double energy_scale);

// The invariants of one strip's totals: when `bounded`, the traction's resultant within mu times
// the strip's load (the exact mu pi/2 p_j a_j for path integrals, mu p_j times the counted length for node
// or cell-centre sums); when `energy_scale` > 0, no negative dissipation beyond 1e-9 of that scale (the size
// of the terms the dissipation is the difference of). The solvers test every strip and assert once per
// solve or step (ROLLWEAR_ASSERT), naming the first strip that broke one (strip_invariant_text): the
// steady strips of a small grid cost some 2000 instructions each, and the checks must stay within 1 %.
constexpr double kStripRounding = 1e-9;  // the sums run over at most a few thousand terms
inline double strip_load_N_per_m(const ContactPatch& patch, int j, const StripTotals& s) {
  return s.counted_length > 0 ? patch.strip_peak_Pa(j) * s.counted_length
                              : kPi / 2 * patch.strip_peak_Pa(j) * patch.half_length_m(j);
}
// (a nan fails the comparisons; an infinity the bound, or the patch's totals, which the solvers assert finite:
// a sum of finite strips of this size is finite, a nan or an infinity stays one)
inline bool strip_totals_hold(const ContactPatch& patch, double mu, int j, const StripTotals& s, bool bounded,
                              double energy_scale) {
  const double limit = mu * strip_load_N_per_m(patch, j, s) * (1 + kStripRounding);
  const bool within = !bounded || s.Fx * s.Fx + s.Fy * s.Fy <= limit * limit;
  const bool dissipates = !(energy_scale > 0) || s.dissipated >= -kStripRounding * energy_scale;
  return within & dissipates;
}
inline bool patch_totals_finite(const PatchTotals& t) {
  return std::isfinite(t.Fx_N + t.Fy_N + t.Mz_N_m + t.dissipated + t.stick_fraction);
}

// The patch's totals once the solver has tested its strips as it went (hold: strip_totals_hold was true for
// every strip in contact): asserts that, naming the first broken strip, and the totals finite, once per
// solve or step. energy_scale(j) is the strip's dissipation scale (0: not checked).
template <class Strip, class EnergyScale>
PatchTotals checked_patch_totals(const ContactPatch& patch, double mu, const std::vector<Strip>& strips, bool hold,
                                 bool bounded, EnergyScale energy_scale) {
  ROLLWEAR_ASSERT(hold, [&] {
    for (int j = 0; j < patch.grid.ny; ++j)
      if (patch.half_length_m(j) > 0 && !strip_totals_hold(patch, mu, j, strips[j], bounded, energy_scale(j)))
        return strip_invariant_text(patch, mu, j, strips[j], bounded, energy_scale(j));
    return std::string();
  }());
  const PatchTotals t = patch_totals(patch, strips);
  ROLLWEAR_ASSERT(patch_totals_finite(t), fmt::format("totals not finite: Fx {} Fy {} Mz {} dissipated {}", t.Fx_N,
                                                      t.Fy_N, t.Mz_N_m, t.dissipated));
  return t;
}

}  // namespace contact
