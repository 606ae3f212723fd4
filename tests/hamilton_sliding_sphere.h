// Hamilton's explicit equations for the stresses in a half-space under a circular Hertz pressure
// p = p0 sqrt(1 - r^2/a^2) and the sliding traction q = mu p along +x (G. M. Hamilton, "Explicit equations for
// the stresses beneath a sliding spherical contact", Proc. IMechE C 197 (1983) 53-59), as a test oracle
// independent of lib/subsurface/ (which sums Boussinesq's and Cerruti's rectangle solutions over cells).
// Written here from the published equations; tests/subsurface_test.cpp checks the oracle itself
// (equilibrium, compatibility, the surface tractions and Johnson's surface and axis closed forms) before
// comparing the product with it.
//
// Units: lengths in the contact radius a, stresses in p0; z >= 0 the depth into the body; tension positive;
// the pressure pushes into the body (sigma_zz = -p on the loaded surface) and the traction acts on the body
// along +x (sigma_xz = -q there), the product's convention (lib/subsurface/rectangle_stress.h).
// With A = r^2 + z^2 - 1, S = sqrt(A^2 + 4 z^2), M = sqrt((S + A)/2), N = sqrt((S - A)/2), phi = atan(1/M),
// G = M^2 - N^2 + z M - N, H = 2 M N + M + z N. The equations hold off the axis (r > 0): the test points keep
// r >= 0.05 (the 1/r^4 terms cancel towards the axis, losing digits).
#pragma once

#include <cmath>

namespace rollwear_test {

struct HamiltonStress {
  double xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;  // over p0
};

// the normal pressure's part (Q = 0) and the traction's part per unit mu, at (x, y, z)/a, r > 0
struct HamiltonParts {
  HamiltonStress normal, tangential;
};

inline HamiltonParts hamilton_sliding_sphere_parts(double x, double y, double z, double nu) {
  const double x2 = x * x, y2 = y * y, z2 = z * z, r2 = x2 + y2, r4 = r2 * r2;
  const double A = r2 + z2 - 1;
  const double S = std::sqrt(A * A + 4 * z2);
  const double M = std::sqrt((S + A) / 2), N = std::sqrt((S - A) / 2);
  const double phi = std::atan2(1.0, M);
  const double G = M * M - N * N + z * M - N, H = 2 * M * N + M + z * N;
  const double GH = G * G + H * H;
  HamiltonParts out;
  HamiltonStress& n = out.normal;
  // normal load: Hamilton's equations with a = 1 (the factor 3P/(2 pi a^3) = p0/a)
  const double common = (1 - nu) * N * z2 - (1 - 2 * nu) / 3 * (N * S + 2 * A * N + 1) - nu * M * z;
  n.xx = (1 + nu) * z * phi + ((y2 - x2) / r2 * common - N * (x2 + 2 * nu * y2) - M * x2 * z / S) / r2;
  n.yy = (1 + nu) * z * phi + ((x2 - y2) / r2 * common - N * (y2 + 2 * nu * x2) - M * y2 * z / S) / r2;
  n.zz = -N + z * M / S;
  n.xy = x * y * (1 - 2 * nu) / r4 * (-N * r2 + 2.0 / 3 * N * (S + 2 * A) - z * (z * N + M) + 2.0 / 3) +
         x * y * z / r4 * (-M * r2 / S - z * N + M);
  n.xz = -z * (x * N / S - x * z * H / GH);
  n.yz = -z * (y * N / S - y * z * H / GH);
  // tangential load Q = mu P along x: the factor 3Q/(2 pi a^3) = mu p0/a
  HamiltonStress& t = out.tangential;
  const double kx = 1.5 - 2 * x2 / r2, hx = 0.5 - 2 * x2 / r2, hy = 0.5 - 2 * y2 / r2;
  const double c = 1 - 2 * nu;
  t.xx = -x * (nu / 4 + 1) * phi +
         x * M / r4 * (kx * (S * nu - 2 * A * nu + z2) + x2 * z2 / S + 7 * nu * r2 / 4 - 2 * nu * x2 + r2) +
         x * z * N / r4 * (kx * (-S / 6 * c - A / 3 * c - (z2 + 3) / 2) + x2 / S - nu * r2 / 4 - 7 * r2 / 4) +
         4 * x * z / (3 * r4) * kx * c;
  t.yy = -3 * nu * x * phi / 4 +
         x * M / r4 * (hy * (nu * (S - 2 * A + r2) + z2) + y2 * z2 / S + 3 * nu * r2 / 4) +
         z * x * N / r4 * (hy * (-S / 6 * c - A / 3 * c - z2 / 2 - 1.5) + y2 / S - 3 * nu * r2 / 4 - r2 / 4) +
         4 * z * x / (3 * r4) * hy * c;
  t.zz = z * x * N / (2 * r2) * (1 - (r2 + z2 + 1) / S);
  t.xy = y / 2 * (nu / 2 - 1) * phi +
         y * M / r4 * (x2 * z2 / S + nu * ((S - 2 * A) * hx - 2 * x2 + r2 / 4) + r2 / 2 + z2 * hx) +
         y * z * N / r4 * (hx * ((2 * nu - 1) * (S / 6 + A / 3) - z2 / 2 - 1.5 - r2 / 2) + r2 * nu / 4 + x2 / S -
                           y2 / 2 - 1.5 * x2) +
         4 * y * z / (3 * r4) * hx * c;
  t.yz = x * y * z / (2 * r4) * (M * (0.5 + (z2 / 2 - 1.5 - r2 / 2) / S) + z * N / 2 * (-3 + (5 + z2 + r2) / S));
  t.xz = 1.5 * z * phi + z * M / r2 * (1 + x2 / r2 - x2 / S) +
         N / r2 * (-0.75 * (S + 2 * A) + z2 - 0.75 - r2 / 4 + z2 / 2 * hx);
  return out;
}

// the whole stress under p and q = mu p, over p0
inline HamiltonStress hamilton_sliding_sphere(double x, double y, double z, double nu, double mu) {
  const HamiltonParts p = hamilton_sliding_sphere_parts(x, y, z, nu);
  return {p.normal.xx + mu * p.tangential.xx, p.normal.yy + mu * p.tangential.yy,
          p.normal.zz + mu * p.tangential.zz, p.normal.xy + mu * p.tangential.xy,
          p.normal.xz + mu * p.tangential.xz, p.normal.yz + mu * p.tangential.yz};
}

}  // namespace rollwear_test
