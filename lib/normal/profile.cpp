// Lateral profiles: interpolation, validation, CSV, generators, parabola fit, hash (profile.h).
//
// Generated node spacing: uniform s = width / n with n the smallest even count such that
//   s <= width * kProfileMaxSpacingFraction  and  s^2 kappa / 8 <= kProfileChordTol_m,
// kappa = R^2 / (R^2 - (width/2)^2)^(3/2) the largest curvature of an arc of radius R over the width,
// so the chord error of the linear interpolation stays below 1 nm and y = 0 is a node. Arcs use
//   z = R - sign(R) sqrt(R^2 - y^2) = y^2 / (R + sign(R) sqrt(R^2 - y^2)),
// the second form free of cancellation near the crown.
#include "lib/normal/profile.h"
#include "lib/csv_reader.h"
#include "lib/errors.h"
#include "lib/number.h"

#include <cstring>

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace contact {

namespace {

// numbers as text (lib/number.h): six digits in messages, the shortest round trip in the CSV text
std::string num(double v) { return six_digits(v); }


// the checks shared by validate_profile and the CSV reader; where(i) names point i
void check_points(const Profile& p, const std::function<std::string(int)>& where, const std::string& whole) {
  const Eigen::Index n = p.y_m.size();
  if (p.z_m.size() != n)
    throw std::invalid_argument(whole + ": y_m has " + std::to_string(n) + " points but z_m " +
                                std::to_string(p.z_m.size()));
  // fast path for the common valid profile (comparisons with NaN are false; increasing y is finite
  // when its ends are); the loop below names the first bad point
  const double *y = p.y_m.data(), *z = p.z_m.data();
  bool ok = n == 0 || (std::isfinite(y[0]) && std::isfinite(y[n - 1]));
  double z_max = 0;  // max |z|
  for (Eigen::Index i = 1; i < n; ++i) ok &= y[i] > y[i - 1];
  for (Eigen::Index i = 0; i < n; ++i) {
    ok &= std::abs(z[i]) <= std::numeric_limits<double>::max();
    z_max = std::max(z_max, std::abs(z[i]));
  }
  for (int i = 0; i < n && !ok; ++i) {
    if (!std::isfinite(p.y_m(i))) throw std::invalid_argument(where(i) + ": y_m must be finite, got " + num(p.y_m(i)));
    if (!std::isfinite(p.z_m(i))) throw std::invalid_argument(where(i) + ": z_m must be finite, got " + num(p.z_m(i)));
    if (i > 0 && !(p.y_m(i) > p.y_m(i - 1)))
      throw std::invalid_argument(where(i) + ": y_m must increase, got " + num(p.y_m(i)) + " after " +
                                  num(p.y_m(i - 1)));
  }
  if (n < 5)
    throw std::invalid_argument(whole + ": " + std::to_string(n) + " points, at least 5 needed");
  // units: a body wider than a metre, or a profile deeper than wide, is millimetres read as metres
  const double width = p.y_m(n - 1) - p.y_m(0);
  if (width > kProfileMaxWidth_m)
    throw std::invalid_argument(where(static_cast<int>(n - 1)) + ": width " + num(width) + " m (y_m from " +
                                num(p.y_m(0)) + " to " + num(p.y_m(n - 1)) + ") exceeds " +
                                num(kProfileMaxWidth_m) + " m: looks like millimetres given as metres");
  if (z_max > width) {
    Eigen::Index deepest = 0;
    p.z_m.abs().maxCoeff(&deepest);
    throw std::invalid_argument(where(static_cast<int>(deepest)) + ": |z_m| = " + num(std::abs(p.z_m(deepest))) +
                                " m exceeds the profile's width " + num(width) +
                                " m: looks like millimetres given as metres");
  }
}

void check_size(double v, const char* what, const char* generator) {
  if (!(v > 0) || !std::isfinite(v))
    throw std::invalid_argument(std::string(generator) + ": " + what + " must be positive and finite, got " + num(v));
}

// uniform nodes over [-w/2, w/2], an even number of intervals, spacing as at the top of the file
Eigen::ArrayXd nodes(double width_m, double R_m) {
  double s = width_m * kProfileMaxSpacingFraction;
  if (std::isfinite(R_m)) {  // the arc's curvature is largest at its ends: R^2 / (R^2 - y^2)^(3/2)
    const double c = width_m / 2, r2 = R_m * R_m - c * c;
    s = std::min(s, std::sqrt(8 * kProfileChordTol_m * r2 * std::sqrt(r2) / (R_m * R_m)));
  }
  int n = static_cast<int>(std::ceil(width_m / s - 1e-9));
  n += n % 2;
  Eigen::ArrayXd y(n + 1);  // exactly symmetric, y = 0 and the ends exact
  for (int k = 0; k <= n; ++k) y(k) = width_m * (static_cast<double>(2 * k - n) / (2.0 * n));
  return y;
}

// z of the arc of radius R (nonzero, finite) at y, |y| < |R|
double arc_z(double R_m, double y_m) {
  const double s = R_m > 0 ? 1.0 : -1.0;
  return y_m * y_m / (R_m + s * std::sqrt(R_m * R_m - y_m * y_m));
}

}  // namespace

double profile_z(const Profile& profile, double y_m) {
  const Eigen::ArrayXd& y = profile.y_m;
  const Eigen::Index n = y.size();
  if (n < 2 || !(y_m >= y(0) && y_m <= y(n - 1)))
    throw std::out_of_range(profile.source + ": y = " + num(y_m) + " m is outside the profile's extent [" +
                            (n ? num(y(0)) : "?") + ", " + (n ? num(y(n - 1)) : "?") + "] m");
  const double* begin = y.data();
  const Eigen::Index hi = std::clamp<Eigen::Index>(std::upper_bound(begin, begin + n, y_m) - begin, 1, n - 1);
  const Eigen::Index lo = hi - 1;
  const double t = (y_m - y(lo)) / (y(hi) - y(lo));
  return (1 - t) * profile.z_m(lo) + t * profile.z_m(hi);  // exact at both nodes
}

void validate_profile(const Profile& profile) {
  const std::string& s = profile.source.empty() ? std::string("profile") : profile.source;
  check_points(profile, [&s](int i) { return s + ": point " + std::to_string(i); }, s);
}

Profile read_profile_csv(const std::string& path) {
  CsvTable t;
  try {
    t = read_csv_table(path);  // lib/csv_reader.h
  } catch (const std::runtime_error&) {
    throw std::invalid_argument(path + ": cannot open the profile file");
  }
  Profile p;
  p.source = path;
  std::vector<double> ys, zs;
  std::vector<int> lines;  // file line of each point
  auto where = [&path](int l) { return path + ":" + std::to_string(l); };
  const bool header = !t.header.empty();
  if (header && (t.header.size() != 2 || t.header[0] != "y_m" || t.header[1] != "z_m"))
    throw std::invalid_argument(where(t.header_line) + ": expected the header 'y_m,z_m' (SI units, metres), got '" +
                                clipped(t.header_text) + "'");
  // a size checked before the points are: the memory and time of a wear run grow with them
  if (t.rows.size() > static_cast<std::size_t>(kProfileMaxPoints))
    throw std::invalid_argument(path + ": " + std::to_string(t.rows.size()) + " points, at most " +
                                std::to_string(kProfileMaxPoints) +
                                " are read (kProfileMaxPoints, lib/normal/profile.h); resample the profile to fewer "
                                "points (the generated profiles have about 400 across the width)");
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::vector<std::string>& fields = t.rows[r];
    const int line = t.row_lines[r];
    if (fields.size() != 2)
      throw std::invalid_argument(where(line) + ": expected 2 columns y_m,z_m, got " + std::to_string(fields.size()) +
                                  ": '" + clipped(t.row_texts[r]) + "'");
    double v[2];
    for (int k = 0; k < 2; ++k) {
      const char* name = k == 0 ? "y_m" : "z_m";
      char* end = nullptr;
      v[k] = std::strtod(fields[k].c_str(), &end);
      if (fields[k].empty() || end != fields[k].c_str() + fields[k].size())
        throw std::invalid_argument(where(line) + ": " + name + " is not a number, got '" + clipped(fields[k]) + "'");
      if (!std::isfinite(v[k]))
        throw std::invalid_argument(where(line) + ": " + name + " must be finite, got " + clipped(fields[k]));
    }
    if (!ys.empty() && !(v[0] > ys.back()))
      throw std::invalid_argument(where(line) + ": y_m must increase, got " + num(v[0]) + " after " + num(ys.back()));
    ys.push_back(v[0]);
    zs.push_back(v[1]);
    lines.push_back(line);
  }
  if (!header) throw std::invalid_argument(path + ": no header 'y_m,z_m' and no points");
  p.y_m = Eigen::Map<const Eigen::ArrayXd>(ys.data(), static_cast<Eigen::Index>(ys.size()));
  p.z_m = Eigen::Map<const Eigen::ArrayXd>(zs.data(), static_cast<Eigen::Index>(zs.size()));
  check_points(p, [&](int i) { return where(lines[static_cast<std::size_t>(i)]); }, path);
  return p;
}

std::string profile_csv(const Profile& profile, const std::string& comment) {
  std::string out;
  std::stringstream ss(comment);
  std::string l;
  while (!comment.empty() && std::getline(ss, l)) out += "# " + l + "\n";
  out += "y_m,z_m\n";
  for (Eigen::Index i = 0; i < profile.y_m.size(); ++i) {
    append_round_trip(out, profile.y_m(i));
    out += ',';
    append_round_trip(out, profile.z_m(i));
    out += '\n';
  }
  return out;
}

Profile crowned_profile(double Ry_m, double width_m) {
  check_size(Ry_m, "Ry", "crowned_profile");
  Profile p = arc_profile(Ry_m, width_m);
  p.source = "crowned_profile(Ry " + num(Ry_m) + " m, width " + num(width_m) + " m)";
  return p;
}

Profile flat_profile(double width_m) {
  check_size(width_m, "width", "flat_profile");
  Profile p;
  p.y_m = nodes(width_m, std::numeric_limits<double>::infinity());
  p.z_m = Eigen::ArrayXd::Zero(p.y_m.size());
  p.source = "flat_profile(width " + num(width_m) + " m)";
  validate_profile(p);
  return p;
}

Profile arc_profile(double R_m, double width_m) {
  check_size(width_m, "width", "arc_profile");
  if (R_m == 0 || !std::isfinite(R_m) || !(width_m < 2 * std::abs(R_m)))
    throw std::invalid_argument("arc_profile: radius must be finite, nonzero and larger than half the width " +
                                num(width_m / 2) + " m, got " + num(R_m) + " m");
  Profile p;
  p.y_m = nodes(width_m, R_m);
  p.z_m = p.y_m.unaryExpr([R_m](double y) { return arc_z(R_m, y); });
  p.source = "arc_profile(R " + num(R_m) + " m, width " + num(width_m) + " m)";
  validate_profile(p);
  return p;
}

Profile flat_worn_crown_profile(double Ry_m, double width_m, double band_half_width_m) {
  check_size(Ry_m, "Ry", "flat_worn_crown_profile");
  check_size(width_m, "width", "flat_worn_crown_profile");
  if (!(width_m < 2 * Ry_m))
    throw std::invalid_argument("flat_worn_crown_profile: Ry " + num(Ry_m) + " m must exceed half the width " +
                                num(width_m / 2) + " m");
  if (!(band_half_width_m >= 0) || !(band_half_width_m < width_m / 2))
    throw std::invalid_argument("flat_worn_crown_profile: band half-width must be in [0, width/2 = " +
                                num(width_m / 2) + " m), got " + num(band_half_width_m) + " m");
  // the band's edges are nodes: move the nearest uniform node there, or insert one
  std::vector<double> y;
  {
    const Eigen::ArrayXd u = nodes(width_m, Ry_m);
    y.assign(u.data(), u.data() + u.size());
    const double s = u(1) - u(0);
    for (double edge : {-band_half_width_m, band_half_width_m}) {
      if (band_half_width_m == 0) break;
      auto it = std::lower_bound(y.begin(), y.end(), edge);
      if (it != y.end() && *it - edge < 0.25 * s) *it = edge;
      else if (it != y.begin() && edge - *(it - 1) < 0.25 * s) *(it - 1) = edge;
      else y.insert(it, edge);
    }
  }
  Profile p;
  p.y_m = Eigen::Map<const Eigen::ArrayXd>(y.data(), static_cast<Eigen::Index>(y.size()));
  const double z_band = arc_z(Ry_m, band_half_width_m);
  p.z_m = p.y_m.unaryExpr([&](double v) { return std::max(arc_z(Ry_m, v) - z_band, 0.0); });
  p.source = "flat_worn_crown_profile(Ry " + num(Ry_m) + " m, width " + num(width_m) + " m, band half-width " +
             num(band_half_width_m) + " m)";
  validate_profile(p);
  return p;
}

ParabolaFit fit_parabola(const Profile& profile) {
  validate_profile(profile);
  const Eigen::Index n = profile.y_m.size();
  // centred and scaled abscissa t in [-1, 1] keeps the normal equations well conditioned
  const double ym = (profile.y_m(0) + profile.y_m(n - 1)) / 2, hw = (profile.y_m(n - 1) - profile.y_m(0)) / 2;
  const Eigen::ArrayXd t = (profile.y_m - ym) / hw;
  Eigen::MatrixXd V(n, 3);
  V.col(0).setOnes();
  V.col(1) = t.matrix();
  V.col(2) = (t * t).matrix();
  const Eigen::Vector3d d = V.colPivHouseholderQr().solve(profile.z_m.matrix());
  ParabolaFit f;
  f.curvature_per_m = 2 * d(2) / (hw * hw);
  f.vertex_y_m = d(2) != 0 ? ym - hw * d(1) / (2 * d(2)) : 0.0;
  f.max_residual_m = (V * d - profile.z_m.matrix()).cwiseAbs().maxCoeff();
  f.depth_range_m = profile.z_m.maxCoeff() - profile.z_m.minCoeff();
  return f;
}

bool has_constant_curvature(const ParabolaFit& f, double rel_tol) {
  if (!(rel_tol > 0)) throw std::invalid_argument("has_constant_curvature: rel_tol must be positive, got " + num(rel_tol));
  return f.max_residual_m <= rel_tol * f.depth_range_m;
}

bool has_constant_curvature(const Profile& profile, double rel_tol) {
  return has_constant_curvature(fit_parabola(profile), rel_tol);
}

std::uint64_t hash_words(const void* data, std::size_t size, std::uint64_t h) {
  // FNV-1a over 64-bit words (the arrays are doubles): a word at a time is 8 times fewer rounds
  const auto* b = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; i += sizeof(std::uint64_t)) {
    std::uint64_t w = 0;
    std::memcpy(&w, b + i, std::min(sizeof w, size - i));
    h = (h ^ w) * 1099511628211ull;
  }
  return h;
}

std::uint64_t profile_hash(const Profile& profile) {
  const std::int64_t n = profile.y_m.size(), m = profile.z_m.size();
  std::uint64_t h = hash_words(&n, sizeof n);
  h = hash_words(profile.y_m.data(), static_cast<std::size_t>(n) * sizeof(double), h);
  h = hash_words(&m, sizeof m, h);
  return hash_words(profile.z_m.data(), static_cast<std::size_t>(m) * sizeof(double), h);
}

std::uint64_t profile_hash(const Profiles& profiles) {
  const std::uint64_t h1 = profile_hash(profiles.body1), h2 = profile_hash(profiles.body2);
  return h1 ^ (h2 + 0x9e3779b97f4a7c15ull + (h1 << 6) + (h1 >> 2));
}

}  // namespace contact
