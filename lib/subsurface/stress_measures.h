// What a stress tensor says about yield and fatigue (docs/subsurface.md §2): its principal stresses, the
// von Mises equivalent stress, Tresca's (the largest principal shear stress). Stresses tension positive.
#pragma once

#include <array>

#include "lib/subsurface/rectangle_stress.h"

namespace contact {

// the eigenvalues sigma1 >= sigma2 >= sigma3 (closed form for a symmetric 3 x 3)
std::array<double, 3> principal_stresses(const StressTensor& s);

// sqrt(((s1 - s2)^2 + (s2 - s3)^2 + (s3 - s1)^2) / 2), from the components
double von_mises_Pa(const StressTensor& s);

// the largest principal shear stress (sigma1 - sigma3)/2 (Johnson's tau_1; yield by Tresca when it reaches k)
double tresca_Pa(const StressTensor& s);

}  // namespace contact
