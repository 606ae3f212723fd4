// Steady rolling (du/dt = 0): each strip is marched from its leading edge x = +a_j, where tau = 0,
// to its trailing edge, with the traction bound |tau| <= mu p (docs/physics.md §3, §4).
#pragma once

#include "lib/tangential/tangential.h"

namespace contact {

struct SteadyOptions {
  bool fields = true;  // the fields on the grid; without them only strips and totals are filled
  // the skips of a case that does not need the whole march (docs/accuracy-and-speed.md), each exact
  // to rounding: consistent scheme without fields and eta = phi = 0: each strip is the closed form of
  // pure xi, no march; no spin on a mirror-symmetric patch: half the strips, mirrored
  // (first_mirrored_strip). Off: every strip is marched (for the tests and benchmarks of the skips).
  bool skips = true;
};

// scheme Exact is not a scheme of the simplified theory (solve_exact_steady, lib/tangential/exact.h,
// solves it): std::invalid_argument.
TangentialSolution solve_steady(const ContactPatch& patch, const TangentialProblem& problem,
                                TangentialScheme scheme = TangentialScheme::Consistent,
                                const SteadyOptions& options = {});

}  // namespace contact
