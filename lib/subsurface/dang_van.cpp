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

std::array<double, 6> as_components(const StressTensor& s) { return {s.xx, s.yy, s.zz, s.xy, s.xz, s.yz}; }

}  // namespace

DangVanPoint dang_van_of_history(const std::vector<StressTensor>& history, const DangVanConstants& k) {
  check_constants(k);
  if (history.empty()) throw std::invalid_argument("dang_van: an empty stress history");
  // the shift: the mid-range of each deviatoric component over the path, made traceless
  std::array<double, 6> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (const StressTensor& s : history) {
    const std::array<double, 6> d = as_components(deviator(s));
    for (int c = 0; c < 6; ++c) lo[c] = std::min(lo[c], d[c]), hi[c] = std::max(hi[c], d[c]);
  }
  std::array<double, 6> mid;
  for (int c = 0; c < 6; ++c) mid[c] = (lo[c] + hi[c]) / 2;
  DangVanPoint out;
  out.shift = deviator({mid[0], mid[1], mid[2], mid[3], mid[4], mid[5]});
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
