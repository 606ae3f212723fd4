// Kalker's simplified theory ("bed of springs", docs/physics.md §3): the quantities shared by the steady
// solver and Satran. The state is u = L tau; the slip velocity of body 1 relative to body 2 is
//   s = c + du/dt - V du/dx,   c = V L ( xi/L1 - phi y/L3 ,  eta/L2 + phi x/L3 ),
// with the mean flexibility
//   L = (L1|xi| + L2|eta| + L3|phi| sqrt(ab)) / sqrt(xi^2 + eta^2 + phi^2 ab)   (L1 if all vanish).
// In stick (s = 0, steady) tau changes along x at the rate c/(V L), which does not depend on V or L:
//   d tau/dx = ( xi/L1 - phi y/L3 ,  eta/L2 + phi x/L3 ).
#pragma once

#include <string>

#include "lib/elastic.h"
#include "lib/tangential/kalker.h"
#include "lib/patch.h"

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
  Creepages creepages;
  double mu = 0;               // Coulomb friction coefficient
  double speed_m_per_s = 0;    // rolling speed V >= 0
};

// Kalker's coefficients at the patch's a/b, flexibilities with the combined G and nu (docs/physics.md §1)
TangentialProblem make_tangential_problem(const ContactPatch& patch, const ElasticPair& pair,
                                          const Creepages& creepages, double mu, double speed_m_per_s);

// Discretisations of the strip march.
//   Classic:    Kalker's FASTSIM as published, on the Cartesian cell centres (for comparison).
//   Consistent: node values at the cell edges and the exact strip ends; within each cell the stick
//               line is integrated exactly and its crossing with the semi-elliptic traction bound is
//               located exactly; the dissipated power is -integral(tau . s) of that reconstruction,
//               so the discrete energy balance of docs/physics.md §4 holds to rounding, strip by strip.
//   Exact:      not a scheme of the simplified theory: Kalker's exact theory on the half-space
//               (lib/tangential/exact.h), which the commands call in its place; solve_steady and
//               satran_step do not take it.
enum class TangentialScheme { Classic, Consistent, Exact };

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

}  // namespace contact
