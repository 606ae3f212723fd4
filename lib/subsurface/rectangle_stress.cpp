// Boussinesq's and Cerruti's solutions over a uniformly loaded rectangle (docs/subsurface.md §1).
#include "lib/subsurface/rectangle_stress.h"

#include <cmath>

#include "lib/numeric.h"

namespace contact {

namespace {

// 1/(a + rho) without cancellation when a < 0 (rho^2 - a^2 = b2 > 0)
double inverse_sum(double a, double rho, double b2) { return a >= 0 ? 1 / (a + rho) : (rho - a) / b2; }

// Cerruti's solution for a shear load along the in-plane axis a (x or y), b the other one, from the corner
// sums named by those axes: F = int q ln(rho + z), F1 = int q Omega (dF1/dz = F, dF/dz = V); third derivatives
// of F and F1 not given by a corner function follow from their being harmonic. Writes the components aa, bb,
// zz, ab, az, bz of the stress per unit load.
struct CerrutiTerms {
  double Va, Vb, Vz, Vaa, Vab, Vaz, Habb, Haab, Oa, Ob;
};
void cerruti(const CerrutiTerms& S, double z, double nu, double& aa, double& bb, double& zz, double& ab, double& az,
             double& bz) {
  const double f = 1 / (2 * kPi);
  const double Faaa = -S.Habb - S.Vaz;
  const double F1aaa = -S.Ob - S.Va;
  aa = f * (2 * (1 + nu) * S.Va + 2 * nu * F1aaa - z * Faaa);
  bb = f * (2 * nu * S.Va + 2 * nu * S.Ob - z * S.Habb);
  zz = -f * z * S.Vaz;
  ab = f * (S.Vb + 2 * nu * S.Oa - z * S.Haab);
  az = f * (S.Vz - z * S.Vaa);
  bz = -f * z * S.Vab;
}

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
  // Cerruti along x, and along y: the same with x and y exchanged
  StressTensor &qx = r.shear_x, &qy = r.shear_y;
  cerruti({S.Vx, S.Vy, S.Vz, S.Vxx, S.Vxy, S.Vxz, S.Hxyy, S.Hxxy, S.Ox, S.Oy}, z, nu,  //
          qx.xx, qx.yy, qx.zz, qx.xy, qx.xz, qx.yz);
  cerruti({S.Vy, S.Vx, S.Vz, S.Vyy, S.Vxy, S.Vyz, S.Hxxy, S.Hxyy, S.Oy, S.Ox}, z, nu,  //
          qy.yy, qy.xx, qy.zz, qy.xy, qy.yz, qy.xz);
  return r;
}

RectangleStress rectangle_stress(double x, double y, double z, double c, double d, double nu) {
  const CornerTerms sum = corner_sum(corner_terms(x + c, y + d, z), corner_terms(x + c, y - d, z),
                                     corner_terms(x - c, y + d, z), corner_terms(x - c, y - d, z));
  return stress_from_corners(sum, z, nu);
}

}  // namespace contact
