// The tangential tests' contact: a Hertz ellipse of a/b with b = 1 mm and p0 = 1 GPa on n x n cells.
#pragma once

#include "lib/grid.h"
#include "lib/normal/hertz.h"
#include "lib/numeric.h"
#include "lib/patch.h"

namespace rollwear_test {

inline contact::ContactPatch ellipse_patch(double ab, int n) {
  contact::HertzContact h;
  h.b_m = 1e-3;
  h.a_m = ab * h.b_m;
  h.p0_Pa = 1e9;
  h.normal_load_N = 2 * contact::kPi * h.a_m * h.b_m * h.p0_Pa / 3;
  return contact::hertz_patch(h, contact::make_grid(h.a_m, h.b_m, {n, n}));
}

}  // namespace rollwear_test
