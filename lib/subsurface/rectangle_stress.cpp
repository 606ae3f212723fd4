// Boussinesq's and Cerruti's solutions over a uniformly loaded rectangle (docs/subsurface.md §1).
#include "lib/subsurface/rectangle_stress.h"

#include <cmath>

#include "lib/numeric.h"

namespace contact {

namespace {

// 1/(a + rho) without cancellation when a < 0 (rho^2 - a^2 = b2 > 0)
double inverse_sum(double a, double rho, double b2) { return a >= 0 ? 1 / (a + rho) : (rho - a) / b2; }

}  // namespace

CornerTerms corner_terms(double X, double Y, double z) {
  const double X2 = X * X, Y2 = Y * Y, z2 = z * z;
  const double rho = std::sqrt(X2 + Y2 + z2);
  const double rz = rho + z;
  const double iY = inverse_sum(Y, rho, X2 + z2);  // 1/(Y + rho)
  const double iX = inverse_sum(X, rho, Y2 + z2);  // 1/(X + rho)
  CornerTerms t;
  // ln(Y + rho) less ln sqrt(X^2 + z^2), a function of X alone that cancels between the corners of one X
  t.Vx = X2 + z2 > 0 ? std::asinh(Y / std::sqrt(X2 + z2)) : 0.0;
  t.Vy = Y2 + z2 > 0 ? std::asinh(X / std::sqrt(Y2 + z2)) : 0.0;
  // minus the solid angle's corner term; atan2 keeps its limit z -> 0+
  t.Vz = -std::atan2(X * Y, z * rho);
  t.Vxx = X / rho * iY;
  t.Vyy = Y / rho * iX;
  t.Vxy = 1 / rho;
  t.Vxz = z / rho * iY;
  t.Vyz = z / rho * iX;
  // atan(Y/X) - atan(z Y/(X rho)) in one continuous arctangent (rho - z = (X^2 + Y^2)/(rho + z))
  t.Hxx = std::atan2(X * Y * (X2 + Y2), rz * (X2 * rho + z * Y2));
  t.Hyy = std::atan2(X * Y * (X2 + Y2), rz * (Y2 * rho + z * X2));
  t.Hxy = std::log(rz);
  t.Hxxy = X / (rho * rz);
  t.Hxyy = Y / (rho * rz);
  t.Ox = -X / rz;
  t.Oy = -Y / rz;
  return t;
}

CornerTerms corner_sum(const CornerTerms& pp, const CornerTerms& pm, const CornerTerms& mp, const CornerTerms& mm) {
  const auto s = [](double a, double b, double c, double d) { return a - b - c + d; };
  CornerTerms t;
  t.Vx = s(pp.Vx, pm.Vx, mp.Vx, mm.Vx);
  t.Vy = s(pp.Vy, pm.Vy, mp.Vy, mm.Vy);
  t.Vz = s(pp.Vz, pm.Vz, mp.Vz, mm.Vz);
  t.Vxx = s(pp.Vxx, pm.Vxx, mp.Vxx, mm.Vxx);
  t.Vyy = s(pp.Vyy, pm.Vyy, mp.Vyy, mm.Vyy);
  t.Vxy = s(pp.Vxy, pm.Vxy, mp.Vxy, mm.Vxy);
  t.Vxz = s(pp.Vxz, pm.Vxz, mp.Vxz, mm.Vxz);
  t.Vyz = s(pp.Vyz, pm.Vyz, mp.Vyz, mm.Vyz);
  t.Hxx = s(pp.Hxx, pm.Hxx, mp.Hxx, mm.Hxx);
  t.Hyy = s(pp.Hyy, pm.Hyy, mp.Hyy, mm.Hyy);
  t.Hxy = s(pp.Hxy, pm.Hxy, mp.Hxy, mm.Hxy);
  t.Hxxy = s(pp.Hxxy, pm.Hxxy, mp.Hxxy, mm.Hxxy);
  t.Hxyy = s(pp.Hxyy, pm.Hxyy, mp.Hxyy, mm.Hxyy);
  t.Ox = s(pp.Ox, pm.Ox, mp.Ox, mm.Ox);
  t.Oy = s(pp.Oy, pm.Oy, mp.Oy, mm.Oy);
  return t;
}

RectangleStress stress_from_corners(const CornerTerms& S, double z, double nu) {
  const double f = 1 / (2 * kPi);
  const double Vzz = -S.Vxx - S.Vyy;  // V is harmonic
  RectangleStress r;
  // Boussinesq: potentials H = int p ln(rho + z) and V = dH/dz
  StressTensor& p = r.pressure;
  p.xx = f * (2 * nu * S.Vz - (1 - 2 * nu) * S.Hxx - z * S.Vxx);
  p.yy = f * (2 * nu * S.Vz - (1 - 2 * nu) * S.Hyy - z * S.Vyy);
  p.zz = f * (S.Vz - z * Vzz);
  p.xy = -f * ((1 - 2 * nu) * S.Hxy + z * S.Vxy);
  p.xz = -f * z * S.Vxz;
  p.yz = -f * z * S.Vyz;
  // Cerruti along x: F = int q ln(rho + z), F1 = int q Omega (dF1/dz = F, dF/dz = V); third derivatives of
  // F and F1 not given by a corner function follow from their being harmonic
  const double Fxxx = -S.Hxyy - S.Vxz;
  const double F1xxx = -S.Oy - S.Vx;
  StressTensor& qx = r.shear_x;
  qx.xx = f * (2 * (1 + nu) * S.Vx + 2 * nu * F1xxx - z * Fxxx);
  qx.yy = f * (2 * nu * S.Vx + 2 * nu * S.Oy - z * S.Hxyy);
  qx.zz = -f * z * S.Vxz;
  qx.xy = f * (S.Vy + 2 * nu * S.Ox - z * S.Hxxy);
  qx.xz = f * (S.Vz - z * S.Vxx);
  qx.yz = -f * z * S.Vxy;
  // Cerruti along y: the same with x and y exchanged
  const double Gyyy = -S.Hxxy - S.Vyz;
  const double G1yyy = -S.Ox - S.Vy;
  StressTensor& qy = r.shear_y;
  qy.yy = f * (2 * (1 + nu) * S.Vy + 2 * nu * G1yyy - z * Gyyy);
  qy.xx = f * (2 * nu * S.Vy + 2 * nu * S.Ox - z * S.Hxxy);
  qy.zz = -f * z * S.Vyz;
  qy.xy = f * (S.Vx + 2 * nu * S.Oy - z * S.Hxyy);
  qy.yz = f * (S.Vz - z * S.Vyy);
  qy.xz = -f * z * S.Vxy;
  return r;
}

RectangleStress rectangle_stress(double x, double y, double z, double c, double d, double nu) {
  const CornerTerms sum = corner_sum(corner_terms(x + c, y + d, z), corner_terms(x + c, y - d, z),
                                     corner_terms(x - c, y + d, z), corner_terms(x - c, y - d, z));
  return stress_from_corners(sum, z, nu);
}

}  // namespace contact
