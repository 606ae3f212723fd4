// Dang Van's criterion over one rolling pass (docs/subsurface.md §5).
#include "lib/subsurface/dang_van.h"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "lib/subsurface/stress_measures.h"

namespace contact {

namespace {

void check_constants(const DangVanConstants& k) {
  if (!(k.a >= kDangVanAMin && k.a <= kDangVanAMax))
    throw std::invalid_argument(
        fmt::format("dang_van: a must be in [{}, {}], got {}", kDangVanAMin, kDangVanAMax, k.a));
  if (!(k.b_Pa >= kDangVanBMin_Pa && k.b_Pa <= kDangVanBMax_Pa))
    throw std::invalid_argument(
        fmt::format("dang_van: b_Pa must be in [{}, {}], got {}", kDangVanBMin_Pa, kDangVanBMax_Pa, k.b_Pa));
}

double hydrostatic(const StressTensor& s) { return (s.xx + s.yy + s.zz) / 3; }

StressTensor deviator(const StressTensor& s) {
  const double h = hydrostatic(s);
  return {s.xx - h, s.yy - h, s.zz - h, s.xy, s.xz, s.yz};
}

}  // namespace

std::array<double, 6> smallest_enclosing_centre(const std::vector<std::array<double, 6>>& p, double tolerance,
                                                int* iterations) {
  if (p.empty()) throw std::invalid_argument("smallest_enclosing_centre: no points");
  const auto dist2 = [](const std::array<double, 6>& a, const std::array<double, 6>& b) {
    double d = 0;
    for (int c = 0; c < 6; ++c) d += (a[c] - b[c]) * (a[c] - b[c]);
    return d;
  };
  const std::size_t n = p.size();
  // start on the two ends of a long chord: the point farthest from p[0], and the one farthest from it
  std::size_t alpha = 0, beta = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (dist2(p[i], p[0]) > dist2(p[alpha], p[0])) alpha = i;
  for (std::size_t i = 0; i < n; ++i)
    if (dist2(p[i], p[alpha]) > dist2(p[beta], p[alpha])) beta = i;
  std::vector<double> u(n, 0.0), d2(n);
  u[alpha] += 0.5, u[beta] += 0.5;
  std::array<double, 6> c;
  for (int k = 0; k < 6; ++k) c[k] = (p[alpha][k] + p[beta][k]) / 2;
  int it = 0;
  for (; it < kSmallestBallIterations; ++it) {
    double gamma = 0;  // the dual objective sum u |p - c|^2, at most the smallest radius squared
    std::size_t far = 0, near = n;
    for (std::size_t i = 0; i < n; ++i) {
      d2[i] = dist2(p[i], c);
      gamma += u[i] * d2[i];
      if (d2[i] > d2[far]) far = i;
      if (u[i] > 0 && (near == n || d2[i] < d2[near])) near = i;
    }
    if (!(gamma > 0)) break;  // one point (or all equal): its centre
    const double up = d2[far] / gamma - 1, down = 1 - d2[near] / gamma;
    if (std::max(up, down) <= tolerance) break;
    if (up >= down) {  // towards the farthest point
      const double lambda = up / (2 * (1 + up));
      for (double& v : u) v *= 1 - lambda;
      u[far] += lambda;
      for (int k = 0; k < 6; ++k) c[k] = (1 - lambda) * c[k] + lambda * p[far][k];
    } else {  // away from the nearest supporting point
      const double lambda = std::min(down / (2 * (1 - down)), u[near] / (1 - u[near]));
      for (double& v : u) v *= 1 + lambda;
      u[near] -= lambda;
      if (u[near] < 1e-15) u[near] = 0;
      for (int k = 0; k < 6; ++k) c[k] = (1 + lambda) * c[k] - lambda * p[near][k];
    }
  }
  if (iterations) *iterations = it;
  if (it >= kSmallestBallIterations)
    throw std::runtime_error(fmt::format("smallest_enclosing_centre: not within {} after {} iterations", tolerance,
                                         kSmallestBallIterations));
  return c;
}

DangVanPoint dang_van_of_history(const std::vector<StressTensor>& history, const DangVanConstants& k) {
  check_constants(k);
  if (history.empty()) throw std::invalid_argument("dang_van: an empty stress history");
  // the shift: the centre of the smallest ball around the deviatoric path in the norm sqrt(s:s) (shear
  // components weighted sqrt(2) as they count twice)
  const double w = std::sqrt(2.0);
  std::vector<std::array<double, 6>> points;
  points.reserve(history.size());
  for (const StressTensor& s : history) {
    const StressTensor d = deviator(s);
    points.push_back({d.xx, d.yy, d.zz, w * d.xy, w * d.xz, w * d.yz});
  }
  const std::array<double, 6> mid = smallest_enclosing_centre(points, kSmallestBallTolerance);
  DangVanPoint out;
  out.shift = deviator({mid[0], mid[1], mid[2], mid[3] / w, mid[4] / w, mid[5] / w});
  out.index = -std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < history.size(); ++t) {
    const StressTensor d = deviator(history[t]);
    const StressTensor m = {d.xx - out.shift.xx, d.yy - out.shift.yy, d.zz - out.shift.zz,
                            d.xy - out.shift.xy, d.xz - out.shift.xz, d.yz - out.shift.yz};
    const double tau = tresca_Pa(m), ph = hydrostatic(history[t]);
    const double index = (tau + k.a * ph) / k.b_Pa;
    if (index > out.index) out.index = index, out.step = static_cast<int>(t), out.tau_Pa = tau, out.hydrostatic_Pa = ph;
  }
  return out;
}

DangVanField dang_van_field(const Subsurface& s, const Grid& g, const DangVanConstants& k) {
  check_constants(k);
  if (s.planes.empty()) throw std::invalid_argument("dang_van: no planes");
  for (const StressPlane& p : s.planes)
    if (p.xx.rows() != g.nx || p.xx.cols() != g.ny) throw std::invalid_argument("dang_van: a plane is not on the grid");
  const int planes = static_cast<int>(s.planes.size());
  DangVanField out;
  out.constants = k;
  out.index.resize(g.ny, planes);
  out.index_max = -std::numeric_limits<double>::infinity();
  std::vector<StressTensor> history(static_cast<std::size_t>(g.nx) + 1);  // [0]: unloaded, then the pass
  for (int z = 0; z < planes; ++z)
    for (int j = 0; j < g.ny; ++j) {
      history[0] = StressTensor{};
      for (int i = 0; i < g.nx; ++i) history[static_cast<std::size_t>(i) + 1] = s.planes[z].at(i, j);
      const DangVanPoint p = dang_van_of_history(history, k);
      out.index(j, z) = p.index;
      if (p.index > out.index_max) {
        out.index_max = p.index;
        out.x_m = p.step > 0 ? g.x_m(p.step - 1) : std::numeric_limits<double>::quiet_NaN();
        out.y_m = g.y_m(j);
        out.z_m = s.planes[z].z_m;
        out.tau_Pa = p.tau_Pa;
        out.hydrostatic_Pa = p.hydrostatic_Pa;
      }
    }
  return out;
}

}  // namespace contact
