// Lateral profiles of the two bodies (docs/physics.md §1-2): the curve z(y) of a body's surface across
// the rolling direction. y is lateral; z points into the body's material and is measured from the
// body's rolling radius Rx at y = 0, so a crowned roller of radius Ry has z = Ry - sqrt(Ry^2 - y^2)
// ~ y^2/(2 Ry) >= 0, and the body's rolling radius at y is Rx - z(y). Both bodies use the same
// lateral coordinate y. The profile's extent [y_m(0), y_m(n-1)] is the body's width: a contact that
// reaches it is reported by the normal solver, never cut silently.
//
// Between nodes z is interpolated linearly. The gap of two profiles is then piecewise linear on the
// union of their nodes, so the semi-Hertzian solver (semi_hertz.h) works on it without resampling.
// The generators space their nodes uniformly, at most kProfileMaxSpacingFraction of the width, and
// close enough that the chord error of an arc, s^2 kappa/8 with kappa its largest curvature over
// the width (~1/|R|), stays below kProfileChordTol_m (1 nm, against approaches of micrometres).
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <string>

namespace contact {

struct Profile {
  Eigen::ArrayXd y_m;  // (n >= 5) lateral node positions, strictly increasing; extent = body's width
  Eigen::ArrayXd z_m;  // (n) surface position into the material from the rolling radius at y = 0
  std::string source;  // where it came from (file path or generator call), for messages
};

// the two bodies' lateral profiles: body 1 the roller (upper), body 2 the path (lower)
struct Profiles {
  Profile body1;
  Profile body2;
};

constexpr double kProfileChordTol_m = 1e-9;         // chord error of generated arcs
constexpr double kProfileMaxSpacingFraction = 1.0 / 400;  // generated node spacing <= width/400
constexpr double kProfileMaxWidth_m = 1.0;          // wider bodies look like millimetres given as m
// a profile file holds at most this many points (read_profile_csv refuses more, naming the count): 50 times
// the generated 400 across the width; the memory a wear run needs grows with the worn profile's nodes
// (wear/wear_loop.h estimate_memory_bytes), and is checked against solver.max_memory_bytes before it runs
constexpr int kProfileMaxPoints = 20000;

// z at y by linear interpolation; throws std::out_of_range (naming the source) outside the extent
double profile_z(const Profile& profile, double y_m);

// throws std::invalid_argument naming the source: sizes differ, fewer than 5 points, NaN/inf,
// y not strictly increasing, width > 1 m or |z| > width ("looks like millimetres given as metres")
void validate_profile(const Profile& profile);

// CSV: a header line "y_m,z_m", then one point "y,z" per line; lines starting with '#' are
// comments, blank lines are ignored. Throws std::invalid_argument "path:line: what, got ..." (the
// line of the offending value) for unreadable files and every check of validate_profile, and for a file of
// more than kProfileMaxPoints points ("path: N points, at most 20000 are read; resample ...").
Profile read_profile_csv(const std::string& path);

// the CSV text read_profile_csv reads: comment lines (each prefixed "# "), header, the shortest text that
// reads back as the same double (lib/number.h)
std::string profile_csv(const Profile& profile, const std::string& comment = "");

// Generated profiles, centred on y = 0 over [-width/2, width/2]; node spacing as at the top.
// All throw std::invalid_argument for non-positive or non-finite sizes.
// crowned roller: the arc of radius Ry_m > 0, z = Ry - sqrt(Ry^2 - y^2); needs width < 2 Ry
Profile crowned_profile(double Ry_m, double width_m);
// flat: z = 0
Profile flat_profile(double width_m);
// circular arc of any nonzero radius: convex (R > 0, z >= 0) or concave (R < 0, z <= 0),
// z = R - sign(R) sqrt(R^2 - y^2); needs width < 2 |R|
Profile arc_profile(double R_m, double width_m);
// a crown worn flat: the arc of radius Ry cut by the plane through its points at y = +-band, and
// measured from that plane (the worn body's rolling radius): z = max(z_arc(y) - z_arc(band), 0).
// z = 0 over |y| <= band, the original crown outside; continuous, with a slope step band/Ry at the
// band's edges, which are nodes (the nearest uniform node moved there when within a quarter spacing,
// else one inserted). Needs 0 <= band_half_width < width/2.
Profile flat_worn_crown_profile(double Ry_m, double width_m, double band_half_width_m);

// Least-squares parabola z ~ c0 + c1 y + c2 y^2 through all nodes.
struct ParabolaFit {
  double curvature_per_m = 0;  // z'' = 2 c2 (1/Ry; 0 = flat, negative = concave)
  double vertex_y_m = 0;       // -c1/(2 c2); 0 when c2 = 0
  double max_residual_m = 0;   // max |z - fit| over the nodes
  double depth_range_m = 0;    // max z - min z over the nodes
};
ParabolaFit fit_parabola(const Profile& profile);

// True when the profile is a parabola (so an arc, to the order Hertz's theory keeps) within
// rel_tol: max residual <= rel_tol * depth range (a flat profile has constant curvature 0). The
// caller may then use Hertz with Ry = 1/curvature instead of the semi-Hertzian solver.
bool has_constant_curvature(const Profile& profile, double rel_tol);
// the same test on a fit already made
bool has_constant_curvature(const ParabolaFit& fit, double rel_tol);

// A 64-bit hash (FNV-1a) of the node arrays' bytes: equal profiles give equal hashes, so a caller
// that stored the hash of the profiles of its last solve can reuse that solution.
std::uint64_t profile_hash(const Profile& profile);
// the hash it is made of: FNV-1a over the bytes taken 8 at a time, continuing from h
std::uint64_t hash_words(const void* data, std::size_t size, std::uint64_t h = 1469598103934665603ull);
std::uint64_t profile_hash(const Profiles& profiles);

}  // namespace contact
