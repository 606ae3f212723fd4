// Stresses below the surface from the grid's tractions (docs/subsurface.md §1-3).
#include "lib/subsurface/subsurface.h"

#include <fftw3.h>
#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "lib/fftw_planner.h"
#include "lib/numeric.h"
#include "lib/subsurface/stress_measures.h"

namespace contact {

namespace {

constexpr int kLoads = 3;       // pressure, shear x, shear y
constexpr int kComponents = 6;  // xx, yy, zz, xy, xz, yz

std::array<double, kComponents> components(const StressTensor& s) { return {s.xx, s.yy, s.zz, s.xy, s.xz, s.yz}; }

bool has_shear(const SurfaceTractions& t) {
  return t.shear_x_Pa.size() > 0 && (t.shear_x_Pa.abs().maxCoeff() > 0 || t.shear_y_Pa.abs().maxCoeff() > 0);
}

void check_tractions(const SurfaceTractions& t) {
  const Grid& g = t.grid;
  const auto shaped = [&](const Eigen::ArrayXXd& a) { return a.rows() == g.nx && a.cols() == g.ny; };
  if (g.nx < 1 || g.ny < 1 || !shaped(t.pressure_Pa))
    throw std::invalid_argument("subsurface: the pressure is not on the grid");
  if (t.shear_x_Pa.size() > 0 && (!shaped(t.shear_x_Pa) || !shaped(t.shear_y_Pa)))
    throw std::invalid_argument("subsurface: the tangential tractions are not on the grid");
}

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

// one zero-padded mx x my real array and its spectrum, with the two plans between them: the offsets
// -(n-1)..(n-1) of an n-cell grid wrap without overlap onto any length >= 2n - 1, taken as fft_size's
// (prime factors 2, 3, 5, 7 only)
struct PlaneTransform {
  int mx, my, nk;
  std::unique_ptr<double, FftwFree> real;
  std::unique_ptr<fftw_complex, FftwFree> spectrum;
  fftw_plan forward = nullptr, backward = nullptr;

  PlaneTransform(int nx, int ny)
      : mx(fft_size(2 * nx - 1)), my(fft_size(2 * ny - 1)), nk(mx / 2 + 1),
        real(static_cast<double*>(fftw_malloc(sizeof(double) * mx * my))),
        spectrum(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * my * nk))) {
    if (!real || !spectrum) throw std::bad_alloc();
    {
      const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
      forward = fftw_plan_dft_r2c_2d(my, mx, real.get(), spectrum.get(), FFTW_ESTIMATE);
      backward = fftw_plan_dft_c2r_2d(my, mx, spectrum.get(), real.get(), FFTW_ESTIMATE);
    }
    if (!forward || !backward) {
      destroy();
      throw std::runtime_error(fmt::format("subsurface: fftw_plan_dft_r2c_2d failed for {} x {}", mx, my));
    }
  }
  ~PlaneTransform() { destroy(); }
  PlaneTransform(const PlaneTransform&) = delete;
  PlaneTransform& operator=(const PlaneTransform&) = delete;
  void destroy() {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    if (forward) fftw_destroy_plan(forward);
    if (backward) fftw_destroy_plan(backward);
    forward = backward = nullptr;
  }
  std::size_t spectrum_size() const { return static_cast<std::size_t>(my) * nk; }
  // the spectrum of real[] as complex numbers
  std::vector<std::complex<double>> transform() {
    fftw_execute(forward);
    std::vector<std::complex<double>> out(spectrum_size());
    for (std::size_t q = 0; q < out.size(); ++q) out[q] = {spectrum.get()[q][0], spectrum.get()[q][1]};
    return out;
  }
};

}  // namespace

SurfaceTractions surface_tractions(const ContactPatch& patch, const TangentialSolution* solution, int body) {
  if (body != 1 && body != 2)
    throw std::invalid_argument(fmt::format("subsurface: body must be 1 or 2, got {}", body));
  SurfaceTractions t;
  t.grid = patch.grid;
  t.pressure_Pa = patch.pressure_Pa;
  if (solution && solution->tau_x_Pa.size() > 0) {
    const double sign = body == 1 ? 1.0 : -1.0;
    t.shear_x_Pa = sign * solution->tau_x_Pa;
    t.shear_y_Pa = sign * solution->tau_y_Pa;
  }
  check_tractions(t);
  return t;
}

StressTensor stress_at(const SurfaceTractions& t, double nu, double x, double y, double z) {
  check_tractions(t);
  const Grid& g = t.grid;
  const bool shear = has_shear(t);
  StressTensor s;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double p = t.pressure_Pa(i, j);
      const double qx = shear ? t.shear_x_Pa(i, j) : 0.0, qy = shear ? t.shear_y_Pa(i, j) : 0.0;
      if (p == 0 && qx == 0 && qy == 0) continue;
      const RectangleStress r = rectangle_stress(x - g.x_m(i), y - g.y_m(j), z, g.dx_m / 2, g.dy_m / 2, nu);
      const auto add = [&](const StressTensor& k, double load) {
        s.xx += load * k.xx, s.yy += load * k.yy, s.zz += load * k.zz;
        s.xy += load * k.xy, s.xz += load * k.xz, s.yz += load * k.yz;
      };
      add(r.pressure, p);
      if (shear) add(r.shear_x, qx), add(r.shear_y, qy);
    }
  return s;
}

std::vector<StressPlane> stress_planes(const SurfaceTractions& t, double nu, const std::vector<double>& depths_m) {
  check_tractions(t);
  for (const double z : depths_m)
    if (!(z >= 0) || !std::isfinite(z)) throw std::invalid_argument(fmt::format("subsurface: depth {} < 0", z));
  const Grid& g = t.grid;
  const int nx = g.nx, ny = g.ny;
  PlaneTransform ft(nx, ny);
  const int mx = ft.mx, my = ft.my;
  const double scale = 1.0 / (static_cast<double>(mx) * my);
  const int loads = has_shear(t) ? kLoads : 1;

  // the loads' spectra, zero-padded to mx x my
  std::vector<std::vector<std::complex<double>>> load_spectra;
  for (int l = 0; l < loads; ++l) {
    const Eigen::ArrayXXd& a = l == 0 ? t.pressure_Pa : l == 1 ? t.shear_x_Pa : t.shear_y_Pa;
    std::fill(ft.real.get(), ft.real.get() + static_cast<std::size_t>(mx) * my, 0.0);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) ft.real.get()[i + static_cast<std::size_t>(mx) * j] = a(i, j);
    load_spectra.push_back(ft.transform());
  }

  std::vector<StressPlane> planes;
  const int lx = 2 * nx, ly = 2 * ny;  // the corners' lattice: offsets -nx..nx - 1 (+ 1/2) cells
  std::vector<CornerTerms> lattice(static_cast<std::size_t>(lx) * ly);
  std::vector<double> kernels(static_cast<std::size_t>(kComponents) * kLoads * mx * my);
  const auto kernel = [&](int c, int l) { return kernels.data() + static_cast<std::size_t>(c * kLoads + l) * mx * my; };
  for (const double z : depths_m) {
    // the corners of every cell offset: X = (q - nx + 1/2) dx, Y = (r - ny + 1/2) dy
    for (int r = 0; r < ly; ++r)
      for (int q = 0; q < lx; ++q)
        lattice[q + static_cast<std::size_t>(lx) * r] = corner_terms((q - nx + 0.5) * g.dx_m, (r - ny + 0.5) * g.dy_m, z);
    // the rectangle solutions at the offsets (field - source) = (k dx, l dy), wrapped onto the padded grid
    std::fill(kernels.begin(), kernels.end(), 0.0);
    for (int l = -(ny - 1); l <= ny - 1; ++l)
      for (int k = -(nx - 1); k <= nx - 1; ++k) {
        const auto at = [&](int q, int r) -> const CornerTerms& { return lattice[q + static_cast<std::size_t>(lx) * r]; };
        const CornerTerms sum = corner_sum(at(k + nx, l + ny), at(k + nx, l + ny - 1), at(k + nx - 1, l + ny),
                                           at(k + nx - 1, l + ny - 1));
        const RectangleStress rs = stress_from_corners(sum, z, nu);
        const std::size_t w = static_cast<std::size_t>(k < 0 ? k + mx : k) + static_cast<std::size_t>(mx) * (l < 0 ? l + my : l);
        const std::array<const StressTensor*, kLoads> per_load = {&rs.pressure, &rs.shear_x, &rs.shear_y};
        for (int ld = 0; ld < loads; ++ld) {
          const std::array<double, kComponents> v = components(*per_load[ld]);
          for (int c = 0; c < kComponents; ++c) kernel(c, ld)[w] = v[c];
        }
      }
    // each component: the sum over the loads of kernel * load, in the spectrum
    StressPlane plane;
    plane.z_m = z;
    std::array<Eigen::ArrayXXd*, kComponents> out = {&plane.xx, &plane.yy, &plane.zz, &plane.xy, &plane.xz, &plane.yz};
    std::vector<std::complex<double>> acc(ft.spectrum_size());
    for (int c = 0; c < kComponents; ++c) {
      std::fill(acc.begin(), acc.end(), std::complex<double>(0, 0));
      for (int ld = 0; ld < loads; ++ld) {
        std::copy(kernel(c, ld), kernel(c, ld) + static_cast<std::size_t>(mx) * my, ft.real.get());
        const std::vector<std::complex<double>> k = ft.transform();
        for (std::size_t q = 0; q < acc.size(); ++q) acc[q] += k[q] * load_spectra[ld][q];
      }
      for (std::size_t q = 0; q < acc.size(); ++q) ft.spectrum.get()[q][0] = acc[q].real(), ft.spectrum.get()[q][1] = acc[q].imag();
      fftw_execute(ft.backward);
      Eigen::ArrayXXd& o = *out[c];
      o.resize(nx, ny);
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) o(i, j) = ft.real.get()[i + static_cast<std::size_t>(mx) * j] * scale;
    }
    planes.push_back(std::move(plane));
  }
  return planes;
}

namespace {

struct Candidate {
  double value = -std::numeric_limits<double>::infinity();
  int plane = -1, i = 0, j = 0;
};

// the peak's depth and value from the parabola through the plane and its two neighbours (evenly spaced);
// measure is what was maximised (c.value), sign turns it into the peak's value (-1: the compression's -sigma3)
template <class Measure>
StressPeak refine(const std::vector<StressPlane>& planes, const Grid& g, const Candidate& c, Measure measure,
                  double sign) {
  StressPeak peak{sign * c.value, g.x_m(c.i), g.y_m(c.j), planes[c.plane].z_m};
  const int k = c.plane;
  if (k <= 0 || k + 1 >= static_cast<int>(planes.size())) return peak;
  const double f0 = c.value, fm = measure(planes[k - 1].at(c.i, c.j)), fp = measure(planes[k + 1].at(c.i, c.j));
  const double curvature = fm - 2 * f0 + fp;
  if (!(curvature < 0)) return peak;
  const double dz = planes[k + 1].z_m - planes[k].z_m;
  const double shift = std::clamp((fm - fp) / (2 * curvature), -0.5, 0.5);  // in planes
  peak.z_m = planes[k].z_m + shift * dz;
  peak.value_Pa = sign * (f0 - (fm - fp) * (fm - fp) / (8 * curvature));
  return peak;
}

}  // namespace

SubsurfaceMaxima subsurface_maxima(const std::vector<StressPlane>& planes, const Grid& g) {
  if (planes.empty()) throw std::invalid_argument("subsurface: no planes");
  for (std::size_t k = 1; k < planes.size(); ++k) {
    const double dz = planes[k].z_m - planes[k - 1].z_m, dz0 = planes[1].z_m - planes[0].z_m;
    if (!(dz > 0) || std::abs(dz - dz0) > 1e-9 * dz0)
      throw std::invalid_argument("subsurface: the planes are not evenly spaced and increasing");
  }
  // the measures, each to be maximised (compression: the most negative sigma3, maximised as -sigma3)
  const auto vm = [](const StressTensor& s) { return von_mises_Pa(s); };
  const auto tr = [](const StressTensor& s) { return tresca_Pa(s); };
  const auto oz = [](const StressTensor& s) { return std::abs(s.xz); };
  const auto s1 = [](const StressTensor& s) { return principal_stresses(s)[0]; };
  const auto s3 = [](const StressTensor& s) { return -principal_stresses(s)[2]; };
  std::array<Candidate, 5> best;
  for (int k = 0; k < static_cast<int>(planes.size()); ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const StressTensor s = planes[k].at(i, j);
        const std::array<double, 3> p = principal_stresses(s);
        const std::array<double, 5> v = {von_mises_Pa(s), (p[0] - p[2]) / 2, std::abs(s.xz), p[0], -p[2]};
        for (int m = 0; m < 5; ++m)
          if (v[m] > best[m].value) best[m] = {v[m], k, i, j};
      }
  SubsurfaceMaxima out;
  out.von_mises = refine(planes, g, best[0], vm, 1);
  out.tresca = refine(planes, g, best[1], tr, 1);
  out.orthogonal_shear = refine(planes, g, best[2], oz, 1);
  out.tension = refine(planes, g, best[3], s1, 1);
  out.compression = refine(planes, g, best[4], s3, -1);
  return out;
}

Subsurface solve_subsurface(const SurfaceTractions& t, double nu, double smaller_semi_axis_m,
                            const SubsurfaceOptions& options) {
  if (!(options.depth_over_semi_axis > 0 && options.depth_over_semi_axis <= kSubsurfaceDepthMax))
    throw std::invalid_argument(fmt::format("subsurface: depth_over_semi_axis must be in (0, {}], got {}",
                                            kSubsurfaceDepthMax, options.depth_over_semi_axis));
  if (options.planes < 3 || options.planes > kSubsurfacePlanesMax)
    throw std::invalid_argument(
        fmt::format("subsurface: planes must be in [3, {}], got {}", kSubsurfacePlanesMax, options.planes));
  if (!(smaller_semi_axis_m > 0) || !std::isfinite(smaller_semi_axis_m))
    throw std::invalid_argument(fmt::format("subsurface: the semi-axis must be > 0, got {}", smaller_semi_axis_m));
  if (!(nu >= 0 && nu < 0.5)) throw std::invalid_argument(fmt::format("subsurface: nu must be in [0, 0.5), got {}", nu));
  check_tractions(t);
  Subsurface out;
  out.nu = nu;
  const double depth = options.depth_over_semi_axis * smaller_semi_axis_m;
  std::vector<double> depths(options.planes);
  for (int k = 0; k < options.planes; ++k) depths[k] = depth * k / (options.planes - 1);
  out.planes = stress_planes(t, nu, depths);
  out.maxima = subsurface_maxima(out.planes, t.grid);
  Eigen::Index i = 0, j = 0;
  t.pressure_Pa.maxCoeff(&i, &j);
  out.section_strip = static_cast<int>(j);
  return out;
}

}  // namespace contact
