// The relaxed model's correction for contacts that are not elliptic (worn crowns: semi-Hertz and half-space
// patches), from the thin-contact limit of the exact theory (docs/accuracy-vs-exact.md, "The worn crown").
//
// As a/b -> 0 each strip of the exact theory tends to plane strain (Carter's theory, which the exact solver
// reproduces in its 2-D mode): its linear creep force per unit width is proportional to its own half-length,
// f_j ~ G a_j c_j. The bed of springs gives f_j = 2 a_j^2 c_j / L with one flexibility L = 8a/(3 C G) taken from
// the patch's equivalent ellipse (a, b), whose Kalker coefficient holds the strip limit for an elliptic
// contact only: sum_j a_j^2 / sum_j a_j is fixed by the ellipse. A flatter contact (a worn band: the half-lengths
// more uniform across y) has a smaller sum of squares for its area, and the springs undercount its force by
//   S = [sum_j a_j^2 / sum_j a_j] / [sum_j e_j^2 / sum_j e_j],
// e_j = a sqrt(1 - ((y_j - y_c)/b)^2) the equivalent ellipse on the same strips, y_c the strips' centroid
// (weights a_j): S = 1 for an elliptic (Hertz) patch, to rounding; the 1e7-revolution worn crown of
// cases/paper-wear.yaml has S = 0.947. The relaxed model scales its flexibilities by S, i.e. each strip's whole
// creepage (the uniform ones and the strip's Heathcote offset, docs/physics.md §2.4) by 1/S: the strips' linear
// forces are then the thin-contact limit's for the patch's own shape. It holds where strip theory holds
// (a/b well below 1, the worn rollers' contacts); no table and no fit.
#pragma once

#include "lib/patch.h"

namespace contact {

// S above: 1 for no strip in contact or a degenerate patch (a_m or b_m not positive). Several patches along y are
// taken as they come (their strips and the equivalent ellipse of the whole): the factor stays continuous in the
// geometry as a patch splits, which a wear life's integrator needs (switching it off there made the fixed-depth
// lives of a spinning roller non-smooth).
double relaxed_shape_factor(const ContactPatch& patch);

}  // namespace contact

namespace contact {

struct TangentialSolution;

// The strips' share of the power. In the same thin-contact limit the exact theory's strip force per unit width is
// proportional to the strip's half-length, the springs' to its square (at the same saturation level of the
// strips: p_j / a_j is the same across a Hertz contact, so Carter's and the springs' levels are), so the exact
// strip's linear power is the springs' times 1 / a_j. Away from that limit the half-space couples the strips and
// the springs' own distribution is the closer one; the model weights each strip's power by
//   w_j = (a / a_j)^p,   p = p0(a/b) f(e) g(s),   p0 = clamp(1 - (a/b) / 2, 0, 1),
//   f(e) = 1 - e^3,      g(s) = 1 - s,
// keeping the total. p0: the strip limit at a/b -> 0, none from a/b = 2 on. f: e = |F| / (mu N) the saturation
// level; at full slip both the exact and the springs' strip powers tend to mu integral of p |s| dx, the weight to 1.
// g: s = |phi Mz| / (|xi Fx| + |eta Fy| + |phi Mz|) spin's share of the creep work; spin's power grows towards the
// outer strips (its slip grows with |y|), which the 1 / a_j law of the uniform creepages does not describe. All
// three continuous (the wear integrator needs it); laws, not fits (the exponent 3 of f chosen on the exact
// per-strip data of tests/data/fast_model/exact_strips.csv, docs/accuracy-vs-exact.md "The shape of a worn contact").
// The forces and the total power do not change; the per-cell power density of strip j is weighted as its strip.
double relaxed_strip_power_exponent(double a_over_b, double level = 0, double spin_share = 0);
// level e and spin share s as above (relaxed.cpp takes them from the solution's forces and creepages)
void redistribute_strip_power(TangentialSolution& s, const ContactPatch& patch, double level = 0,
                              double spin_share = 0);

}  // namespace contact
