// Semi-Hertzian normal problem on arbitrary lateral profiles (docs/physics.md §2): Kik & Piotrowski's
// virtual penetration (KP, 2008) with an equivalent-ellipse correction of the penetration ratio and
// of the strip length, so that on a profile of constant curvature it reproduces Hertz exactly (up to
// quadrature): in the spirit of CONTACT's KPEC, written from the equations below (docs/semi-hertz.md).
//
// Geometry: gap h(y) = z1(y) + z2(y) - min (profile.h), piecewise linear on the union of both
// profiles' nodes over the overlap of their extents; rolling curvature A = (1/Rx1 + 1/Rx2)/2.
// For an approach delta:
//   equivalent ellipse  B_e = eps delta / b_e^2,  b_e = (3/4) integral (eps delta - h)_+ dy / (eps delta)
//                       (exact for h = B y^2: then B_e = B), and
//   eps = eps_y(A, B_e) = B b^2/delta of Hertz's ellipse with curvatures A, B_e (fixed point),
//   eps_x = A a^2/delta = 1 - eps (Johnson's relations: A a^2 + B b^2 = delta);
//   virtual interpenetration  g(y) = eps delta - h(y);  contact where g > 0;
//   strip half-length         a(y) = sqrt(eps_x g(y) / (eps A))   (Hertz: a sqrt(1 - y^2/b^2));
//   pressure                  p(x, y) = p0 sqrt(g(y) / (eps delta)) sqrt(1 - x^2/a(y)^2);
//   p0 from Boussinesq at the reference point (0, y0): u_z = delta - h(y0), i.e.
//     delta - h(y0) = (1/(pi E*)) integral p(x, y) / sqrt(x^2 + (y - y0)^2) dA,
//   y0 the centroid of g_+ over the patch holding the gap's minimum (Hertz: the centre).
// Along a strip, integral sqrt(1 - x^2/a^2) / sqrt(x^2 + eta^2) dx = 2 (sqrt(a^2 + eta^2)/a) (K(k) - E(k)),
// k^2 = a^2/(a^2 + eta^2); its log singularity at eta = 0 is integrated exactly. The load
// F(delta) = p0 integral (pi/2) a(y) sqrt(g/(eps delta)) dy rises with delta (not everywhere: on nearly
// conformal worn gaps it is steep and not monotone, docs/semi-hertz.md); Newton steps with the secant
// slope in (log delta, log F), kept in the bracket, with a bisection after any step that leaves it or
// does not halve the residual, find F(delta) = normal load. F(delta) can jump across the load: where two lobes of contact merge, y0 jumps into the
// neck (docs/stress-suite.md, finding 6b), and where merging lobes widen the contact, eps = eps_y(A,
// B_e(eps delta)) has two fixed points and the warm-started iteration picks one by history. The bracket
// then closes on the jump, and the root find starts again from that bracket by the continuous rule:
//   eps from two passes eps <- eps_y(A, B_e(eps delta)) from eps = 1/2 (exact on constant curvature),
//   y0 the centroid of m_+, m(y) the smallest g on the way from the gap's minimum to y (the lobe
//   centroid where g falls monotonically away from the minimum; across a neck the far side weighs at
//   most g at the neck, nothing when the lobes merge); where other minima are nearly as low, p0 the
//   weighted mean of each such minimum's basin condition (weights continuous in the depths, 1 for the
//   lowest, 0 for one higher by a tenth of its own depth below its neck),
// both continuous in delta, and the second in the depths. The result says which rule ran (SemiHertzResult::rule).
// A caller may ask for the Galerkin rule instead (SemiHertzOptions::galerkin_rule): eps as the continuous
// rule's, p0 from the Boussinesq condition weighted by g_+ over the whole contact, with no reference point:
// on the worn cam's gaps its F(delta) crosses the load once where the single-point rules' crosses it up to
// three times (docs/semi-hertz.md, "The Galerkin rule").
#pragma once

#include <Eigen/Core>

#include "lib/elastic.h"
#include "lib/grid.h"
#include "lib/patch.h"
#include "lib/normal/profile.h"
#include "lib/solve_status.h"
#include "lib/normal/solver_kind.h"

#include <stdexcept>

namespace contact {

// How eps and the reference point y0 were found (see the top of this file).
enum class ApproachRule {
  SelfConsistent,  // eps the fixed point eps = eps_y(A, B_e(eps delta)); y0 the centroid of g_+ over the
                   // patch holding the gap's minimum
  Continuous,      // the remedy where the first one's F(delta) jumps across the load: eps from two passes
                   // from 1/2; y0 the centroid of m_+ (the basin rule)
  Galerkin,        // eps as the continuous rule's; p0 from the Boussinesq condition weighted by g_+ over the
                   // whole contact (no reference point, no basins): SemiHertzOptions::galerkin_rule
};

// A grid none of whose strip centres lies in the contact (a contact split into patches narrower than a
// strip): the caller may solve again with more strips (the wear loop does).
struct NoStripCentreError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct SemiHertzOptions {
  bool heathcote_slip = true;     // fill patch.strip_xi_offset; false leaves it empty (no offset)
  bool pressure_fields = true;    // fill the patch's pressure fields on the grid (fill_strip_pressures);
                                  // false leaves them empty, for a caller that reads only the strips
  int quadrature_cells = 64;      // lateral cells of the Boussinesq integral (docs/semi-hertz.md)
  double load_rtol = 1e-6;        // the root find stops at |F(delta)/F - 1| <= load_rtol
  int max_iterations = 60;        // evaluations of F(delta)
  double initial_approach_m = 0;  // warm start, e.g. the last solve's approach; 0 = estimate
  // with it, d ln F / d ln delta there (the last solve's SemiHertzResult::approach_slope); 0 = Hertz's 3/2.
  // The first step goes to initial_approach_m (F/F(initial))^(1/initial_slope): a caller that solves again
  // on profiles changed by little (the same cam angle one wear step later) passes both and the root find
  // takes 1 or 2 evaluations; a poor guess costs only evaluations, never the result.
  double initial_slope = 0;
  // always the continuous rule (eps from two passes, y0 the basin centroid), never the self-consistent
  // one: the result is then continuous in the profiles as well as in delta. A caller that solves again
  // and again on profiles changing by little (the cam's life, docs/cam-follower.md §12) needs that: by
  // default the rule is chosen per solve, and where the self-consistent F(delta) jumps across the load
  // for one profile and not for the next, the contact jumps between the two rules' solutions.
  bool continuous_rule = false;
  // always the Galerkin rule (ApproachRule::Galerkin): eps from the continuous rule's two passes, and p0 from
  // the Boussinesq condition delta - h(y) = u_z(0, y) weighted by g_+(y) over the whole contact,
  //   p0 = pi E* integral g_+ (delta - h) dy / integral g_+ J dy,  J(y) = integral (p/p0) / r dA at (0, y),
  // the outer integrals by galerkin_points points per piece of the contact (uniform in theta, as the cells).
  // Exact on constant curvature like the others (Hertz's u_z = delta - h holds at every y of the contact);
  // no reference point, no basins, no blend: on nearly conformal worn gaps F(delta) is monotone where the
  // single-point rules' is not, so a warm-started search finds the cold one's root (docs/semi-hertz.md).
  // The Heathcote offsets' reference (reference_y_m) is the centroid of g_+ over the whole contact.
  // Overrides continuous_rule.
  bool galerkin_rule = false;
  int galerkin_points = 2;  // outer points per piece of the contact (>= 1); J is computed at each
  // the strips' lateral extent (profiles' y, lo < hi): the grid laid over [lo, hi] whatever the contact's
  // extent, strips outside the contact empty. Both 0: over the contact's extent (the default), which
  // moves every strip when a lobe of contact enters or leaves; a fixed extent keeps the strips in place
  // as the profiles change, so the strips' sums change continuously (the cam's life, §12 of
  // docs/cam-follower.md). The contact must lie within it.
  double fixed_grid_y_lo_m = 0, fixed_grid_y_hi_m = 0;
  double kp_epsilon = 0;          // 0: eps from the equivalent ellipse (exact on constant curvature);
                                  // in (0, 1): Kik-Piotrowski as published, fixed eps (0.55 in their
                                  // paper) and a = sqrt((eps delta - h)/A), for comparison
};

struct SemiHertzResult {
  // The patch: grid over the contact's bounding box, x in +-max a(y), y over [contact_y_min_m,
  // contact_y_max_m] (so centred on the contact, not on the profiles' y = 0: see grid_y0_m).
  // p_j such that (pi/2) p_j a_j dy is the load of row j exactly (integrated over the row; every row
  // keeps its own load), total = normal load. a_j = a(y_j) at the strip centre, unless that would put
  // p_j above the field's largest peak over the row (g(y_j) small against the row's g: a row cut by
  // a patch's edge, or a neck); then p_j is that peak and a_j = sqrt(gbar^2/gmax / A_mod) carries the
  // row's load (gbar, gmax the row's mean and largest g_+). 0 for rows between disconnected patches.
  // So a_j <= the row's largest a(y) and p_j <= the row's largest p(y) <= p0.
  // a_m, b_m: the equivalent ellipse for Kalker's coefficients, b = half the summed width of the
  // patches, a = contact area / (pi b) (both exact for Hertz). p0_Pa: the continuous field's peak p0
  // above, scaled with the strips to carry the normal load (F/F(delta), within load_rtol of 1).
  // approach_m = delta.
  ContactPatch patch;
  double grid_y0_m = 0;      // profiles' y of the grid's y = 0: strip j lies at grid_y0_m + grid.y_m(j)
  double reference_y_m = 0;  // profiles' y of the reference point y0 (Boussinesq point; where the
                             // Heathcote offset vanishes, so xi is the creepage there)
  double contact_y_min_m = 0, contact_y_max_m = 0;  // lateral extent of the contact (profiles' y)
  double approach_m = 0;      // delta
  double approach_slope = 0;  // d ln F / d ln delta near delta (the root find's last secant; Hertz 3/2), for
                              // SemiHertzOptions::initial_slope
  double epsilon = 0;         // lateral virtual penetration ratio: contact where h < epsilon delta
  double equivalent_B_per_m = 0;  // B_e, lateral curvature of the equivalent ellipse
  bool reaches_edge = false;  // the contact reaches an end of the profiles' overlap (a body's edge)
  int patches = 0;            // separate contact patches along y (disconnected contact)
  ApproachRule rule = ApproachRule::SelfConsistent;
  bool load_jumps = false;    // not converged because F(delta) jumps across the load: the root find's
                              // bracket closed on the jump (the status's message says where and by how much)
  NormalSolverKind solver = NormalSolverKind::SemiHertz;  // Hertz when solve_normal_on_profiles took the closed form
  // Converged: the load is carried within load_rtol. MaxIterations: no approach found (a warning; the
  // result must not be used). Failed when reaches_edge: a body is narrower than the contact, the
  // patch then holds the contact cut at the edge.
  SolveStatus status;
};

// Hertz's ellipse with relative curvatures A (along x) and B (along y): eps_y = B b^2 / delta
// (and A a^2 / delta = 1 - eps_y); 1/2 for a circle. Tabulated once, interpolated in log(A/B).
double hertz_lateral_epsilon(double A_per_m, double B_per_m);

// Heathcote slip: xi(y) - xi at profiles' positions y from the rolling radii Rk - zk(y),
//   offset(y) = (z1(y) - z1(y0))/Rx1 - (z2(y) - z2(y0))/Rx2   (omega_k = V/Rx_k; O(xi z/R) dropped),
// zero at the reference point y0. Positive where the roller's radius is smaller than at y0 (it
// turns slower there: v2 - v1 grows). Throws std::out_of_range outside a profile.
Eigen::ArrayXd heathcote_xi_offset(const Profiles& profiles, double Rx1_m, double Rx2_m, const Eigen::ArrayXd& y_m,
                                   double reference_y_m);

// The normal problem for normal_load_N on the profiles, the grid over the contact's bounding box.
// Throws std::invalid_argument for A <= 0, a zero radius, bad materials, a non-positive load, invalid
// or non-overlapping profiles, bad options; NoStripCentreError for a grid with no strip centre in the contact. A contact reaching the profiles' edge, or a root find that does not
// converge, is a status plus a spdlog::warn.
SemiHertzResult solve_semi_hertz(const Profiles& profiles, double Rx1_m, double Rx2_m, const ElasticPair& pair,
                                 double normal_load_N, const GridSpec& spec, const SemiHertzOptions& options = {});

// The normal problem on profiles, skipping what the case does not need: when both profiles have
// constant curvature (has_constant_curvature with curvature_rtol) and the Hertz ellipse fits inside
// the overlap of their extents, Hertz's solution with the fitted radii, centred on the gap's vertex
// (a spdlog::debug says so; the result's diagnostics filled alike, solver NormalSolverKind::Hertz);
// otherwise solve_semi_hertz. Both agree within 2e-3 on constant curvature (docs/semi-hertz.md).
// F(delta) of the rule the options ask for (Galerkin, continuous, else self-consistent from eps = 1/2) at
// each approach: the load the semi-Hertzian field carries there, for scans of the load equation (tests,
// docs/semi-hertz.md). Throws what solve_semi_hertz throws for its inputs (the load is not used).
Eigen::ArrayXd semi_hertz_load_N(const Profiles& profiles, double Rx1_m, double Rx2_m, const ElasticPair& pair,
                                 const Eigen::ArrayXd& approach_m, const SemiHertzOptions& options = {});

SemiHertzResult solve_normal_on_profiles(const Profiles& profiles, double Rx1_m, double Rx2_m, const ElasticPair& pair,
                                         double normal_load_N, const GridSpec& spec,
                                         const SemiHertzOptions& options = {}, double curvature_rtol = 1e-3);

}  // namespace contact
