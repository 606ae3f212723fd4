#include "lib/tangential/tangential.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "lib/enum_names.h"
#include "lib/numeric.h"

namespace contact {

double mean_flexibility_m_per_Pa(const Flexibilities& f, const Creepages& c, double a_m, double b_m) {
  const double ab = a_m * b_m;
  const double norm = std::sqrt(c.xi * c.xi + c.eta * c.eta + c.phi_per_m * c.phi_per_m * ab);
  if (!(norm > 0)) return f.L1_m_per_Pa;
  return (f.L1_m_per_Pa * std::abs(c.xi) + f.L2_m_per_Pa * std::abs(c.eta) +
          f.L3_m_per_Pa * std::abs(c.phi_per_m) * std::sqrt(ab)) / norm;
}

TangentialProblem make_tangential_problem(const ContactPatch& patch, const ElasticPair& pair,
                                          const Creepages& creepages, double mu, double speed_m_per_s) {
  if (!(mu >= 0) || !std::isfinite(mu))
    throw std::invalid_argument("tangential: friction coefficient must be >= 0 and finite, got " + std::to_string(mu));
  if (!(speed_m_per_s >= 0) || !std::isfinite(speed_m_per_s))
    throw std::invalid_argument("tangential: rolling speed must be >= 0 and finite, got " +
                                std::to_string(speed_m_per_s) + " m/s");
  if (!std::isfinite(creepages.xi) || !std::isfinite(creepages.eta) || !std::isfinite(creepages.phi_per_m))
    throw std::invalid_argument("tangential: creepages must be finite");
  TangentialProblem p;
  p.C = kalker_coefficients(patch.a_m, patch.b_m, combined_poisson(pair));
  p.flex = kalker_flexibilities(p.C, patch.a_m, patch.b_m, combined_shear_modulus_Pa(pair));
  p.L_m_per_Pa = mean_flexibility_m_per_Pa(p.flex, creepages, patch.a_m, patch.b_m);
  p.creepages = creepages;
  p.mu = mu;
  p.speed_m_per_s = speed_m_per_s;
  return p;
}

namespace {

// the grid's nodes x_edge(i) strictly inside |x| < a1 are those strictly inside |x| < a2 (only the
// nodes next to +-a can differ)
bool same_nodes_inside(const Grid& g, double a1, double a2) {
  if (a1 == a2) return true;
  for (const double a : {a1, a2}) {
    const int near = static_cast<int>(std::floor((a + g.half_x_m) / g.dx_m));
    const int far = static_cast<int>(std::floor((-a + g.half_x_m) / g.dx_m));
    for (const int c : {near, far})
      for (int i = std::max(0, c - 1); i <= std::min(g.nx, c + 2); ++i) {
        const double x = g.x_edge(i);
        if ((x > -a1 && x < a1) != (x > -a2 && x < a2)) return false;
      }
  }
  return true;
}

}  // namespace

namespace {

// The last answer of first_mirrored_strip on this thread and what it read: a run that solves many steady
// steps on one patch (the relaxed model's transient) checks its symmetry once (measured: 37 % of the relaxed
// start-stop life's CPU before). Equal inputs give the same answer, so reusing it changes nothing.
struct MirrorMemo {
  bool valid = false;
  int nx = 0, ny = 0, result = 0;
  double dx = 0, half_x = 0, half_y = 0;
  Eigen::ArrayXd y, a, p, o;
};
thread_local MirrorMemo mirror_memo;

bool same_array(const Eigen::ArrayXd& u, const Eigen::ArrayXd& v) {
  return u.size() == v.size() && (u == v).all();
}

bool memo_holds(const MirrorMemo& m, const ContactPatch& patch) {
  const Grid& g = patch.grid;
  return m.valid && m.nx == g.nx && m.ny == g.ny && m.dx == g.dx_m && m.half_x == g.half_x_m &&
         m.half_y == g.half_y_m && same_array(m.y, g.y_m) && same_array(m.a, patch.half_length_m) &&
         same_array(m.p, patch.strip_peak_Pa) && same_array(m.o, patch.strip_xi_offset);
}

int mirrored_from_scratch(const ContactPatch& patch);

}  // namespace

int first_mirrored_strip(const ContactPatch& patch, double phi_per_m, bool skip) {
  const Grid& g = patch.grid;
  const int ny = g.ny;
  if (!skip || phi_per_m != 0 || ny < 2) return ny;
  MirrorMemo& m = mirror_memo;
  if (memo_holds(m, patch)) return m.result;
  m.result = mirrored_from_scratch(patch);
  m.nx = g.nx;
  m.ny = g.ny;
  m.dx = g.dx_m;
  m.half_x = g.half_x_m;
  m.half_y = g.half_y_m;
  m.y = g.y_m;
  m.a = patch.half_length_m;
  m.p = patch.strip_peak_Pa;
  m.o = patch.strip_xi_offset;
  m.valid = true;
  return m.result;
}

namespace {

int mirrored_from_scratch(const ContactPatch& patch) {
  const Grid& g = patch.grid;
  const int ny = g.ny;
  const bool offsets = patch.strip_xi_offset.size() == ny;
  const double a_max = patch.half_length_m.abs().maxCoeff(), p_max = patch.strip_peak_Pa.abs().maxCoeff();
  const double o_max = offsets ? patch.strip_xi_offset.abs().maxCoeff() : 0.0;
  auto same = [](double u, double v, double scale) { return std::abs(u - v) <= kMirrorTol * scale; };
  for (int j = 0; j < ny / 2; ++j) {
    const int m = ny - 1 - j;
    if (!same(g.y_m(j), -g.y_m(m), g.half_y_m) || !same(patch.half_length_m(j), patch.half_length_m(m), a_max) ||
        !same(patch.strip_peak_Pa(j), patch.strip_peak_Pa(m), p_max) ||
        (offsets && !same(patch.strip_xi_offset(j), patch.strip_xi_offset(m), o_max)) ||
        !same_nodes_inside(g, patch.half_length_m(j), patch.half_length_m(m)))
      return ny;
  }
  return ny - ny / 2;
}

// solver.tangential's names (lib/enum_names.h), in the order messages list them
constexpr EnumTable<TangentialScheme, 4> kTangentialSchemeNames = {{{TangentialScheme::Consistent, "consistent"},
                                                                    {TangentialScheme::Classic, "classic"},
                                                                    {TangentialScheme::Exact, "exact"},
                                                                    {TangentialScheme::Relaxed, "relaxed"}}};
}  // namespace

std::string to_string(TangentialScheme scheme) { return enum_name(kTangentialSchemeNames, scheme); }

TangentialScheme parse_tangential_scheme(const std::string& name) {
  if (const std::optional<TangentialScheme> scheme = enum_from_name(kTangentialSchemeNames, name)) return *scheme;
  std::string valid;
  for (const auto& [value, n] : kTangentialSchemeNames) valid += (valid.empty() ? "" : ", ") + std::string(n);
  throw std::invalid_argument("unknown tangential scheme '" + name + "' (valid: " + valid + ")");
}

}  // namespace contact

namespace contact {

std::string strip_invariant_text(const ContactPatch& patch, double mu, int j, const StripTotals& s, bool bounded,
                                 double energy_scale) {
  std::string text = fmt::format("strip {}: Fx {} Fy {} Mz {} dissipated {} (N/m, W/m or J/m)", j, s.Fx, s.Fy, s.Mz,
                                 s.dissipated);
  if (bounded)
    text += fmt::format(", |F| = {} against mu times the strip's load, {}", std::hypot(s.Fx, s.Fy),
                        mu * strip_load_N_per_m(patch, j, s));
  if (energy_scale > 0) text += fmt::format(", dissipation of scale {}", energy_scale);
  return text;
}

}  // namespace contact
