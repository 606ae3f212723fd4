// The stress in an elastic half-space under a uniform load on one rectangle of its surface: Boussinesq's
// (normal pressure) and Cerruti's (tangential traction) solutions integrated over the rectangle in closed
// form (docs/subsurface.md §1 derives them). The axes are the grid's x and y and the depth z >= 0 into the
// body; the rectangle is |x| <= c, |y| <= d at z = 0.
//   pressure p >= 0 pushes into the body (sigma_zz = -p on the loaded surface),
//   shear q_x, q_y act on the body's surface in +x, +y (sigma_xz = -q_x, sigma_yz = -q_y there).
// Stresses are positive in tension.
#pragma once

namespace contact {

struct StressTensor {
  double xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;  // Pa (or Pa per Pa of load), tension positive
};

// the stress at (x, y, z) per unit (1 Pa) uniform load of each kind on the rectangle
struct RectangleStress {
  StressTensor pressure;  // normal pressure
  StressTensor shear_x;   // tangential traction along +x
  StressTensor shear_y;   // tangential traction along +y
};

// The fifteen functions of one corner (X, Y, z) of the rectangle, relative to the field point (X = x - xi,
// Y = y - eta for the corner (xi, eta)), whose signed sums over the four corners give the potentials'
// derivatives (docs/subsurface.md §1). Linear: sums of corners add like numbers.
struct CornerTerms {
  double Vx = 0, Vy = 0, Vz = 0;              // first derivatives of the Newtonian potential V = int 1/rho
  double Vxx = 0, Vyy = 0, Vxy = 0, Vxz = 0, Vyz = 0;  // its second derivatives (Vzz = -Vxx - Vyy)
  double Hxx = 0, Hyy = 0, Hxy = 0;           // second derivatives of H = int ln(rho + z)
  double Hxxy = 0, Hxyy = 0;                  // third derivatives of H
  double Ox = 0, Oy = 0;                      // third derivatives d3/dx dy d(x|y) of Omega = int z ln(rho+z) - rho
};
CornerTerms corner_terms(double X_m, double Y_m, double z_m);
// corner sum: +(x+c, y+d) - (x+c, y-d) - (x-c, y+d) + (x-c, y-d)
CornerTerms corner_sum(const CornerTerms& pp, const CornerTerms& pm, const CornerTerms& mp, const CornerTerms& mm);
// the stresses per unit load from the corner sums at depth z, Poisson's ratio nu
RectangleStress stress_from_corners(const CornerTerms& sum, double z_m, double nu);

// the stress at (x, y, z), z >= 0, per unit load on the rectangle |x| <= c, |y| <= d (c, d > 0); finite
// everywhere except on the rectangle's edges at z = 0
RectangleStress rectangle_stress(double x_m, double y_m, double z_m, double c_m, double d_m, double nu);

}  // namespace contact
