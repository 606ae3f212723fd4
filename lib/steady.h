// Steady rolling (du/dt = 0): each strip is marched from its leading edge x = +a_j, where tau = 0,
// to its trailing edge, with the traction bound |tau| <= mu p (PHYSICS.md §3, §4).
#pragma once

#include "lib/tangential.h"

namespace contact {

struct SteadyOptions {
  bool fields = true;  // the fields on the grid; without them only strips and totals are filled
};

TangentialSolution solve_steady(const ContactPatch& patch, const TangentialProblem& problem,
                                TangentialScheme scheme = TangentialScheme::Consistent,
                                const SteadyOptions& options = {});

}  // namespace contact
