// The half-space normal problem (halfspace.h).
//
// Influence coefficients. A point load P on the surface displaces both surfaces together by
// P / (pi E* r) (Boussinesq; 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2). A rectangle [-c, c] x [-d, d]
// (c = dx/2, d = dy/2) under unit pressure therefore displaces the point (x, y) by
//   u(x, y) = (1/(pi E*)) integral of dA / sqrt(X^2 + Y^2),   X = x - x', Y = y - y',
// and with G(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|) (each term 0 when its divisor is 0), whose mixed
// derivative d2G/dXdY = Y^2/r^3 + X^2/r^3 = 1/r for every sign of X and Y,
//   u(x, y) = (1/(pi E*)) [G(x+c, y+d) - G(x+c, y-d) - G(x-c, y+d) + G(x-c, y-d)].
// This is Love's (1929) closed form, written with asinh instead of logarithms of ratios so that it
// keeps its digits on either side of the rectangle. K_ij = u(x_i - x_j, y_i - y_j).
//
// Convolution. K_ij depends on the offset of the cells only, so u = K p is a discrete convolution;
// on a zero-padded (mx x my) grid with the kernel stored at offsets -(n-1)..(n-1) (wrapped: they do not
// overlap on any length >= 2n - 1; mx, my are fft_size's, the smallest with prime factors 2, 3, 5, 7
// only) the cyclic convolution equals the linear one on the nx x ny block:
//   u = IFFT( FFT(K) . FFT(p) ) / (mx my).
// The kernel is even in both offsets, so FFT(K) is real. The padded rows ny..my-1 of p are zero and
// those of u are not wanted: r2c along x on the first ny rows, c2c along y on every column, and back
// the same way (a quarter less work than the full 2-D transform). FFTW, planned once per process and
// grid size (FFTW_ESTIMATE; a plan costs about 0.5 ms, so a solve of its own would pay a third of a
// warm 80 x 80 solve for them) and executed on each solve's arrays.
//
// Polonsky & Keer (1999), "A numerical method for solving rough contact problems based on the
// multi-level multi-summation and conjugate gradient techniques", Wear 231, 206-219, section 3.
// The pressure minimises the complementary energy p.K p / 2 + p.h over p >= 0, sum p dx dy = F. Each
// iteration, with Ic the loaded cells (p > 0):
//   g = h + K p,  g -= mean_Ic g               (separation; the mean is the approach delta)
//   z = M^-1 g on Ic, z -= mean_Ic z           (preconditioned; z = g in Polonsky & Keer's method)
//   G = sum_Ic g z,  t = z + (G/G_old) t on Ic (t = z after a restart), t = 0 elsewhere
//   r = K t,  r -= mean_Ic r,  tau = sum_Ic g t / sum_Ic r t
//   p -= tau t on Ic,  p = max(p, 0)
//   Iol = {p = 0, g < 0} (overlap outside the contact): p = -tau g there, and restart the direction
//   (a conjugate t with tau < 0, uphill, is replaced by the steepest descent t = g, whose tau >= 0)
//   p *= F / (sum p dx dy)                     (prescribed load)
// The residual of halfspace.h is measured on g at the start of each iteration. p_new = scale (p - tau t
// + dp), dp nonzero on the cells clipped or loaded in the step, so K p_new = scale (K p - tau K t + K dp):
// with few such cells K dp is summed from the kernel in real space and the next iteration needs no
// convolution for g. The final residual is always judged on a fresh K p.
// M^-1 (SpectralPreconditioner) is the inverse of the half-space's symbol, E* |k| / 2, on the periodic
// grid: SPD on the vectors that vanish off Ic and sum to zero over it, where t lives, so this is a
// preconditioned CG on the active set. K's condition number grows with the grid; with M the worn
// 80 x 80 contact of tests/bench/halfspace_life_bench takes 21 iterations instead of 100.
#include "lib/fftw_planner.h"
#include "lib/normal/halfspace.h"
#include "lib/numeric.h"

#include <fftw3.h>
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <utility>
#include <cmath>
#include <memory>
#include <optional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace contact {

namespace {

// antiderivative of 1/r in X and Y (top of file)
double love_antiderivative(double X, double Y) {
  double G = 0;
  if (X != 0) G += X * std::asinh(Y / std::abs(X));
  if (Y != 0) G += Y * std::asinh(X / std::abs(Y));
  return G;
}

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

template <class T>
std::unique_ptr<T, FftwFree> fftw_array(std::size_t n) {
  std::unique_ptr<T, FftwFree> p(static_cast<T*>(fftw_malloc(sizeof(T) * n)));
  if (!p) throw std::bad_alloc();
  return p;
}

// The plans of one grid size nx x ny: made once per process (FFTW_ESTIMATE, on scratch arrays of the
// workspace's sizes and alignment) and kept, executed on each workspace's own arrays by FFTW's
// new-array functions (thread-safe). A life solves on two or three sizes, thousands of times.
struct HalfspacePlans {
  fftw_plan rows_forward, columns_forward, columns_backward, rows_backward;  // the padded product
  fftw_plan kernel_forward;                                                  // the padded kernel, 2-d r2c
  fftw_plan periodic_forward, periodic_backward;                             // the preconditioner's nx x ny
};

// the process's plans by grid size, destroyed at exit (no thread plans then, so without the planner's lock)
struct HalfspacePlanCache {
  std::map<std::pair<int, int>, HalfspacePlans> plans;
  ~HalfspacePlanCache() {
    for (const auto& [size, p] : plans)
      for (fftw_plan q : {p.rows_forward, p.columns_forward, p.columns_backward, p.rows_backward, p.kernel_forward,
                          p.periodic_forward, p.periodic_backward})
        fftw_destroy_plan(q);
  }
};

const HalfspacePlans& plans_for(int nx, int ny) {
  static HalfspacePlanCache plan_cache;
  std::map<std::pair<int, int>, HalfspacePlans>& cache = plan_cache.plans;
  const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  const auto found = cache.find({nx, ny});
  if (found != cache.end()) return found->second;
  int mx = fft_size(2 * nx - 1), my = fft_size(2 * ny - 1);
  const int nk = mx / 2 + 1;
  auto rows = fftw_array<double>(static_cast<std::size_t>(mx) * ny);
  auto spectrum = fftw_array<fftw_complex>(static_cast<std::size_t>(my) * nk);
  auto columns = fftw_array<fftw_complex>(static_cast<std::size_t>(my) * nk);
  auto kernel = fftw_array<double>(static_cast<std::size_t>(mx) * my);
  auto periodic = fftw_array<double>(static_cast<std::size_t>(nx) * ny);
  auto periodic_spectrum = fftw_array<fftw_complex>(static_cast<std::size_t>(ny) * (nx / 2 + 1));
  // the padded rows ny..my-1 of p are zero: transform only the first ny along x, all columns along y;
  // back, all columns along y and only the first ny rows along x. The columns go out of place into
  // (and back from) an array that holds each column contiguously: FFTW_ESTIMATE's plans for the
  // strided columns in place copy through buffers and take about half as long again.
  HalfspacePlans p;
  p.rows_forward = fftw_plan_many_dft_r2c(1, &mx, ny, rows.get(), nullptr, 1, mx, spectrum.get(), nullptr, 1, nk,
                                          FFTW_ESTIMATE);
  p.columns_forward = fftw_plan_many_dft(1, &my, nk, spectrum.get(), nullptr, nk, 1, columns.get(), nullptr, 1, my,
                                         FFTW_FORWARD, FFTW_ESTIMATE);
  p.columns_backward = fftw_plan_many_dft(1, &my, nk, columns.get(), nullptr, 1, my, spectrum.get(), nullptr, nk, 1,
                                          FFTW_BACKWARD, FFTW_ESTIMATE);
  p.rows_backward = fftw_plan_many_dft_c2r(1, &mx, ny, spectrum.get(), nullptr, 1, nk, rows.get(), nullptr, 1, mx,
                                           FFTW_ESTIMATE);
  p.kernel_forward = fftw_plan_dft_r2c_2d(my, mx, kernel.get(), spectrum.get(), FFTW_ESTIMATE);
  p.periodic_forward = fftw_plan_dft_r2c_2d(ny, nx, periodic.get(), periodic_spectrum.get(), FFTW_ESTIMATE);
  p.periodic_backward = fftw_plan_dft_c2r_2d(ny, nx, periodic_spectrum.get(), periodic.get(), FFTW_ESTIMATE);
  const fftw_plan all[] = {p.rows_forward,   p.columns_forward,  p.columns_backward, p.rows_backward,
                           p.kernel_forward, p.periodic_forward, p.periodic_backward};
  if (std::any_of(std::begin(all), std::end(all), [](fftw_plan q) { return q == nullptr; })) {
    for (fftw_plan q : all)
      if (q) fftw_destroy_plan(q);
    throw std::runtime_error("halfspace: FFTW could not plan the transforms of " + std::to_string(nx) + " x " +
                             std::to_string(ny));
  }
  return cache.emplace(std::make_pair(nx, ny), p).first->second;
}

// the influence operator u = K p on one grid: padded buffers and the kernel's spectrum
struct HalfspaceWorkspace {
  int nx, ny;      // grid
  int mx, my;      // padded grid (>= 2n - 1: fft_size), row-major for FFTW: row n (along y) holds mx values along x
  int nk;          // mx/2 + 1 complex values per row of the spectrum
  const HalfspacePlans& plans;
  // the product's input and output sides in buffers of their own, so that the input's zero padding (the
  // columns nx..mx-1 of rows, the rows ny..my-1 of spectrum) is written once, not on every product
  std::unique_ptr<double, FftwFree> rows;               // (ny x mx): the rows of p that can be nonzero, padded
  std::unique_ptr<fftw_complex, FftwFree> spectrum;     // (my x nk): their r2c along x, rows ny.. zero
  std::unique_ptr<fftw_complex, FftwFree> columns;      // (nk x my): the spectrum's columns, each contiguous
  std::unique_ptr<fftw_complex, FftwFree> spectrum_out;  // (my x nk): the product's columns transformed back
  std::unique_ptr<double, FftwFree> rows_out;           // (ny x mx): u on the first nx of each row
  std::vector<double> kernel_spectrum;              // (nk x my) FFT of the even kernel (real) / (mx my)
  Eigen::ArrayXXd quadrant;                         // (nx x ny) K at the offsets (k dx, l dy), k, l >= 0
  int products = 0;                                 // convolutions u = K p so far

  HalfspaceWorkspace(const Grid& g, double Estar_Pa)
      : nx(g.nx), ny(g.ny), mx(fft_size(2 * g.nx - 1)), my(fft_size(2 * g.ny - 1)), nk(mx / 2 + 1),
        plans(plans_for(g.nx, g.ny)),
        rows(fftw_array<double>(static_cast<std::size_t>(mx) * ny)),
        spectrum(fftw_array<fftw_complex>(static_cast<std::size_t>(my) * nk)),
        columns(fftw_array<fftw_complex>(static_cast<std::size_t>(my) * nk)),
        spectrum_out(fftw_array<fftw_complex>(static_cast<std::size_t>(my) * nk)),
        rows_out(fftw_array<double>(static_cast<std::size_t>(mx) * ny)),
        kernel_spectrum(static_cast<std::size_t>(my) * nk), quadrant(g.nx, g.ny) {
    // kernel at the offsets of the first quadrant (Love's form, top of file), from Love's antiderivative
    // on the lattice of the cells' corners, G_ij = G((i + 1/2) dx, (j + 1/2) dy), each corner's value
    // computed once (G is odd in X and in Y: G_-1,j = -G_0,j); even in both, wrapped onto the padded grid
    Eigen::ArrayXXd corner(nx + 1, ny + 1);  // corner(i + 1, j + 1) = G_ij, i, j >= -1
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        corner(i + 1, j + 1) = love_antiderivative((i + 0.5) * g.dx_m, (j + 0.5) * g.dy_m);
    corner.row(0).tail(ny) = -corner.row(1).tail(ny);
    corner.col(0) = -corner.col(1);
    const double to_m_per_Pa = 1 / (kPi * Estar_Pa);
    for (int l = 0; l < ny; ++l)
      for (int k = 0; k < nx; ++k)
        quadrant(k, l) = (corner(k + 1, l + 1) - corner(k + 1, l) - corner(k, l + 1) + corner(k, l)) * to_m_per_Pa;
    auto kernel = fftw_array<double>(static_cast<std::size_t>(mx) * my);
    double* K = kernel.get();
    for (int n = 0; n < my; ++n) {
      const int l = n < ny ? n : my - n;  // |offset| along y; ny..my - ny are no offset (l >= ny)
      for (int m = 0; m < mx; ++m) {
        const int k = m < nx ? m : mx - m;
        K[m + mx * n] = (k < nx && l < ny) ? quadrant(k, l) : 0.0;
      }
    }
    fftw_execute_dft_r2c(plans.kernel_forward, K, spectrum_out.get());
    const double scale = 1.0 / (static_cast<double>(mx) * my);
    for (int n = 0; n < my; ++n)
      for (int m = 0; m < nk; ++m)
        kernel_spectrum[static_cast<std::size_t>(m) * my + n] = spectrum_out.get()[static_cast<std::size_t>(n) * nk + m][0] * scale;
    // the padding, once: the out-of-place r2c and c2c transforms of apply() do not write their inputs
    std::fill_n(rows.get(), static_cast<std::size_t>(mx) * ny, 0.0);
    std::fill_n(reinterpret_cast<double*>(spectrum.get()), 2 * static_cast<std::size_t>(my) * nk, 0.0);
  }

  // u = K p: zero-padded cyclic convolution
  void apply(const Eigen::ArrayXXd& p, Eigen::ArrayXXd& u) {
    ++products;
    Eigen::Map<Eigen::ArrayXXd>(rows.get(), mx, ny).topRows(nx) = p;  // the rest stays zero
    fftw_complex* const S = spectrum.get();
    fftw_execute_dft_r2c(plans.rows_forward, rows.get(), S);  // its rows 0..ny-1; the rest stay zero
    fftw_complex* const Tc = columns.get();
    fftw_execute_dft(plans.columns_forward, S, Tc);
    for (std::size_t q = 0; q < kernel_spectrum.size(); ++q) {
      Tc[q][0] *= kernel_spectrum[q];
      Tc[q][1] *= kernel_spectrum[q];
    }
    fftw_execute_dft(plans.columns_backward, Tc, spectrum_out.get());
    fftw_execute_dft_c2r(plans.rows_backward, spectrum_out.get(), rows_out.get());  // destroys spectrum_out
    u = Eigen::Map<const Eigen::ArrayXXd>(rows_out.get(), mx, ny).topRows(nx);
  }

  // u += w K e_(i, j): the displacement of one cell's pressure w, from the kernel in real space
  void add_cell(double w, int i, int j, Eigen::ArrayXXd& u) const {
    for (int l = 0; l < ny; ++l) {
      const auto Kl = quadrant.col(std::abs(l - j));
      u.col(l).head(i) += w * Kl.segment(1, i).reverse();
      u.col(l).tail(nx - i) += w * Kl.head(nx - i);
    }
  }
};

// The preconditioner of the conjugate gradient: the inverse of the half-space's operator on the
// periodic nx x ny grid, whose symbol is E* |k| / 2 (Boussinesq: u^ = 2 p^ / (E* |k|)), with |k| the
// central-difference wavenumber (the scale does not matter). z = M^-1 g for g on the loaded cells
// (zero elsewhere); symmetric and positive definite on the vectors that vanish off the loaded cells
// and sum to zero over them, where the iteration's directions live.
struct SpectralPreconditioner {
  int nx, ny, nk;
  const HalfspacePlans& plans;
  std::unique_ptr<double, FftwFree> values;          // (ny x nx), x fastest
  std::unique_ptr<fftw_complex, FftwFree> spectrum;  // (ny x nk)
  std::vector<double> symbol;                        // (ny x nk) / (nx ny)

  explicit SpectralPreconditioner(const Grid& g)
      : nx(g.nx), ny(g.ny), nk(g.nx / 2 + 1), plans(plans_for(g.nx, g.ny)),
        values(fftw_array<double>(static_cast<std::size_t>(nx) * ny)),
        spectrum(fftw_array<fftw_complex>(static_cast<std::size_t>(ny) * nk)), symbol(static_cast<std::size_t>(ny) * nk) {
    const double scale = 1.0 / (static_cast<double>(nx) * ny);
    for (int n = 0; n < ny; ++n) {
      const double sy = 2 * std::sin(kPi * n / ny) / g.dy_m;
      for (int m = 0; m < nk; ++m) {
        const double sx = 2 * std::sin(kPi * m / nx) / g.dx_m;
        symbol[static_cast<std::size_t>(n) * nk + m] = std::sqrt(sx * sx + sy * sy) * scale;
      }
    }
  }

  // z = M^-1 g on the loaded cells (mask 1; g taken as 0 elsewhere), z = 0 elsewhere
  void apply(const Eigen::ArrayXXd& loaded, const Eigen::ArrayXXd& g, Eigen::ArrayXXd& z) {
    Eigen::Map<Eigen::ArrayXXd> V(values.get(), nx, ny);
    V = loaded * g;
    fftw_complex* const C = spectrum.get();
    fftw_execute_dft_r2c(plans.periodic_forward, V.data(), C);
    for (std::size_t q = 0; q < symbol.size(); ++q) {
      C[q][0] *= symbol[q];
      C[q][1] *= symbol[q];
    }
    fftw_execute_dft_c2r(plans.periodic_backward, C, V.data());
    z = loaded * V;
  }
};

void check_grid(const Grid& grid, const char* who) {
  if (grid.nx < 1 || grid.ny < 1 || !(grid.dx_m > 0) || !(grid.dy_m > 0) || !std::isfinite(grid.dx_m) ||
      !std::isfinite(grid.dy_m) || grid.x_m.size() != grid.nx || grid.y_m.size() != grid.ny)
    throw std::invalid_argument(std::string(who) + ": the grid is empty or inconsistent (" +
                                std::to_string(grid.nx) + " x " + std::to_string(grid.ny) + " cells)");
}

std::string size_text(Eigen::Index rows, Eigen::Index cols) {
  return std::to_string(rows) + " x " + std::to_string(cols);
}

// the pressure carries the load to rounding over the cells (it is rescaled to F at every iteration)
constexpr double kLoadBalanceRtol = 1e-9;

// where the loaded region ends beyond the centre of its outermost loaded cell, in cell widths, from
// the values q at that cell and at its inner neighbour: q linear in the distance to the edge,
// clamped to [0, 1] (the edge lies before the first unloaded cell's centre)
double edge_beyond_centre(double q_out, double q_in) {
  if (!(q_in > q_out)) return 1.0;
  return std::clamp(q_out / (q_in - q_out), 0.0, 1.0);
}

}  // namespace

double rectangle_influence_m_per_Pa(double x_m, double y_m, double dx_m, double dy_m, double Estar_Pa) {
  const double c = dx_m / 2, d = dy_m / 2;
  const double G = love_antiderivative(x_m + c, y_m + d) - love_antiderivative(x_m + c, y_m - d) -
                   love_antiderivative(x_m - c, y_m + d) + love_antiderivative(x_m - c, y_m - d);
  return G / (kPi * Estar_Pa);
}

namespace {

void check_halfspace_inputs(const Grid& grid, const Eigen::ArrayXXd& gap_m, double Estar_Pa, double normal_load_N,
                            const HalfspaceOptions& opt) {
  check_grid(grid, "halfspace");
  if (gap_m.rows() != grid.nx || gap_m.cols() != grid.ny)
    throw std::invalid_argument("halfspace: gap is " + size_text(gap_m.rows(), gap_m.cols()) + ", grid is " +
                                size_text(grid.nx, grid.ny));
  if (!gap_m.allFinite()) throw std::invalid_argument("halfspace: gap has a non-finite value");
  if (!(Estar_Pa > 0) || !std::isfinite(Estar_Pa))
    throw std::invalid_argument("halfspace: E* must be positive and finite, got " + std::to_string(Estar_Pa) + " Pa");
  if (!(normal_load_N > 0) || !std::isfinite(normal_load_N))
    throw std::invalid_argument("halfspace: normal load must be positive and finite, got " +
                                std::to_string(normal_load_N) + " N");
  if (!(opt.tol > 0)) throw std::invalid_argument("halfspace: tol must be positive, got " + std::to_string(opt.tol));
  if (opt.max_iterations < 1)
    throw std::invalid_argument("halfspace: max_iterations must be at least 1, got " +
                                std::to_string(opt.max_iterations));
  if (opt.initial_pressure_Pa && (opt.initial_pressure_Pa->rows() != grid.nx || opt.initial_pressure_Pa->cols() != grid.ny))
    throw std::invalid_argument("halfspace: initial pressure is " +
                                size_text(opt.initial_pressure_Pa->rows(), opt.initial_pressure_Pa->cols()) +
                                ", grid is " + size_text(grid.nx, grid.ny));
  if (opt.initial_pressure_Pa && !opt.initial_pressure_Pa->allFinite())
    throw std::invalid_argument("halfspace: initial pressure has a non-finite value");
}

// Polonsky & Keer's iteration (top of file), one stage per method: the state is the pressure p, the
// displacement u = K p, the separation g and the conjugate direction t.
class PolonskyKeer {
 public:
  PolonskyKeer(const Grid& grid, const Eigen::ArrayXXd& h, double Estar_Pa, double F, const Eigen::ArrayXXd* start,
               bool precondition)
      : K_(grid, Estar_Pa), M_(precondition ? std::make_unique<SpectralPreconditioner>(grid) : nullptr), h_(h), cell_m2_(grid.dx_m * grid.dy_m), F_(F), h_min_(h.minCoeff()),
        // start: the load spread evenly over the grid
        p_(Eigen::ArrayXXd::Constant(grid.nx, grid.ny, F / (grid.nx * grid.ny * cell_m2_))),
        u_(grid.nx, grid.ny), g_(grid.nx, grid.ny), t_(Eigen::ArrayXXd::Zero(grid.nx, grid.ny)), Kt_(grid.nx, grid.ny),
        z_(M_ ? grid.nx : 0, M_ ? grid.ny : 0), changed_(static_cast<std::size_t>(grid.nx) * grid.ny) {
    // or the caller's start, non-negative and carrying the load
    if (start) {
      const Eigen::ArrayXXd q = start->max(0.0);
      const double carried = q.sum() * cell_m2_;
      if (carried > 0 && std::isfinite(carried)) p_ = q * (F / carried);
    }
    K_.apply(p_, u_);
  }

  // separation s = h + u - delta for the current pressure; delta = its mean over the loaded cells;
  // the complementarity residual (no gap under load, no overlap outside it). The loops over the cells
  // are Eigen's array expressions with the loaded cells as a 0/1 mask: vectorised, reductions included.
  void measure_separation() {
    loaded_ = (p_ > 0).cast<double>();
    n_loaded_ = loaded_.sum();
    g_ = h_ + u_;
    delta_ = (g_ * loaded_).sum() / n_loaded_;
    g_ -= delta_;
    // |s| on the loaded cells, -s elsewhere
    const double violation = std::max(0.0, (loaded_ * g_.abs() - (1 - loaded_) * g_).maxCoeff());
    residual_ = violation / (delta_ - h_min_);
  }

  // the residual is judged on a fresh convolution, not on u updated along the step
  void refresh_displacement() {
    if (u_by_fft_) return;
    K_.apply(p_, u_);
    u_by_fft_ = true;
    measure_separation();
  }

  // conjugate direction on the loaded cells, from the separation g or, preconditioned, from z = M^-1 g
  // with its mean over the loaded cells removed (the direction keeps the load, as g does)
  void conjugate_direction() {
    const Eigen::ArrayXXd* Z = &g_;
    if (M_) {
      M_->apply(loaded_, g_, z_);
      z_ -= loaded_ * (z_.sum() / n_loaded_);
      Z = &z_;
    }
    const double G = (g_ * *Z * loaded_).sum();
    const double beta = conjugate_ ? G / G_old_ : 0.0;
    t_ = loaded_ * (*Z + beta * t_);
    G_old_ = G;
  }

  // step length along t, for the part of K t that keeps the load (mean over the loaded cells removed);
  // r.t <= 0 (the direction lost) returns false
  bool step_length(double& tau, double& rt) {
    K_.apply(t_, Kt_);
    const double Kt_sum = (Kt_ * loaded_).sum(), Kt_t = (Kt_ * t_).sum(), s_t = (g_ * t_).sum();
    rt = Kt_t - Kt_sum / n_loaded_ * t_.sum();  // t = 0 off the loaded cells
    if (!(rt > 0)) return false;
    tau = s_t / rt;
    return true;
  }

  // the step, kept non-negative; overlap outside the loaded cells is loaded and restarts the direction;
  // then the prescribed load, and the displacement along the step, K p = scale (u - tau K t), with the
  // cells clipped or added (p other than p - tau t) added from the kernel in real space when they are
  // few, else by a fresh convolution
  void step(double tau) {
    const Eigen::Index n_cells = p_.size();
    double* const P = p_.data();
    const double* const S = g_.data();
    const double* const T = t_.data();
    bool overlap = false;
    Change* const C = changed_.data();  // n_cells long: no call in the loop
    std::size_t n_changed = 0;
    for (Eigen::Index i = 0; i < n_cells; ++i) {
      const double along = P[i] > 0 ? P[i] - tau * T[i] : 0.0;  // p - tau t (t = 0 off the loaded cells)
      double now = along;
      if (P[i] > 0 && now <= 0) now = 0;
      if (now == 0 && S[i] < 0) {
        now = -tau * S[i];
        overlap = true;
      }
      if (now != along) C[n_changed++] = {i, now - along};
      P[i] = now;
    }
    const double sum_p = p_.sum();
    conjugate_ = !overlap;
    const double scale = F_ / (sum_p * cell_m2_);
    p_ *= scale;
    if (n_changed > kSparseCells) {
      K_.apply(p_, u_);
      u_by_fft_ = true;
      return;
    }
    u_ -= tau * Kt_;
    const int nx = static_cast<int>(p_.rows());
    for (std::size_t c = 0; c < n_changed; ++c)
      K_.add_cell(C[c].dp, static_cast<int>(C[c].i % nx), static_cast<int>(C[c].i / nx), u_);
    u_ *= scale;
    u_by_fft_ = false;
  }

  // drop the conjugate direction (the next one is the steepest descent); false if it was that already
  bool restart_direction() {
    const bool was = conjugate_;
    conjugate_ = false;
    return was;
  }

  double residual() const { return residual_; }
  double approach() const { return delta_; }
  int products() const { return K_.products; }
  Eigen::ArrayXXd& pressure() { return p_; }

 private:
  // at most this many cells changed off the step are added from the kernel in real space (nx ny
  // multiply-adds each), more take a convolution
  static constexpr std::size_t kSparseCells = 24;
  struct Change {
    Eigen::Index i;
    double dp;
  };
  HalfspaceWorkspace K_;
  std::unique_ptr<SpectralPreconditioner> M_;
  const Eigen::ArrayXXd& h_;
  double cell_m2_, F_, h_min_;
  Eigen::ArrayXXd p_, u_, g_, t_, Kt_, z_, loaded_;  // loaded_: 1 on the loaded cells (p > 0), else 0
  std::vector<Change> changed_;
  bool u_by_fft_ = true;  // u = K p from a convolution, not updated along the step
  bool conjugate_ = false;
  double G_old_ = 1, delta_ = 0, residual_ = 0, n_loaded_ = 0;
};

}  // namespace

HalfspaceSolution solve_halfspace(const Grid& grid, const Eigen::ArrayXXd& gap_m, double Estar_Pa,
                                  double normal_load_N, const HalfspaceOptions& opt) {
  check_halfspace_inputs(grid, gap_m, Estar_Pa, normal_load_N, opt);
  const int nx = grid.nx, ny = grid.ny;
  std::optional<PolonskyKeer> solver;
  solver.emplace(grid, gap_m, Estar_Pa, normal_load_N, opt.initial_pressure_Pa, opt.precondition);
  PolonskyKeer* pk_now = &*solver;
  bool warm = opt.initial_pressure_Pa != nullptr;
  int earlier_products = 0;  // of a warm start given up

  int it = 0;
  HalfspaceSolution s;
  for (;; ++it) {
    PolonskyKeer& pk = *pk_now;
    pk.measure_separation();
    if (pk.residual() <= opt.tol || it >= opt.max_iterations) pk.refresh_displacement();
    const double residual = pk.residual();
    if (!std::isfinite(residual)) {
      s.status.kind = SolveStatus::Kind::Failed;
      s.status.message = fmt::format("residual is {} after {} iterations", residual, it);
      break;
    }
    if (residual <= opt.tol) {
      s.status.kind = SolveStatus::Kind::Converged;
      s.status.message = fmt::format("residual {:.2g} <= tol {:.3g} after {} iterations", residual, opt.tol, it);
      break;
    }
    if (it >= opt.max_iterations) {
      s.status.kind = SolveStatus::Kind::MaxIterations;
      s.status.message = fmt::format("residual {:.2g} > tol {:.3g} after {} iterations", residual, opt.tol, it);
      break;
    }
    pk.conjugate_direction();
    double tau = 0, rt = 0;
    bool descends = pk.step_length(tau, rt);
    // a conjugate direction along which the step would go uphill (tau < 0: it would put negative
    // pressure on the overlapping cells; seen from a warm start): start again from the steepest descent
    if (descends && tau < 0 && pk.restart_direction()) {
      pk.conjugate_direction();
      descends = pk.step_length(tau, rt);
    }
    // A caller's start can leave a loaded set on which every direction that keeps the load is null (one loaded
    // cell, or a separation constant over them: r.t = 0) while cells outside it overlap. The problem is convex,
    // so its answer does not depend on the start: begin again from the even spread (seen on a worn roller under
    // spin, whose fine solve started from the coarse one's single loaded cell).
    if (!descends && warm) {
      spdlog::debug("halfspace ({} x {}): the warm start's direction is lost (r.t = {:.3g}) after {} iterations; "
                    "starting again from an even pressure", nx, ny, rt, it);
      earlier_products += pk.products();
      warm = false;
      solver.emplace(grid, gap_m, Estar_Pa, normal_load_N, nullptr, opt.precondition);
      pk_now = &*solver;
      continue;
    }
    if (!descends) {
      s.status.kind = SolveStatus::Kind::Failed;
      s.status.message = fmt::format("search direction lost (r.t = {:.3g}) with residual {:.2g} after {} iterations",
                                     rt, residual, it);
      break;
    }
    pk.step(tau);
  }

  PolonskyKeer& pk = *pk_now;
  s.pressure_Pa = std::move(pk.pressure());
  s.approach_m = pk.approach();
  const double cell_m2 = grid.dx_m * grid.dy_m;
  s.contact_area_m2 = static_cast<double>((s.pressure_Pa > 0).count()) * cell_m2;
  s.status.iterations = it;
  s.status.residual = pk.residual();
  s.products = earlier_products + pk.products();
  // per solve: the pressure is non-negative and carries the load (it is rescaled to F every iteration)
  if (s.status.kind != SolveStatus::Kind::Failed) {
    ROLLWEAR_ASSERT(s.pressure_Pa.minCoeff() >= 0, fmt::format("pressure down to {} Pa", s.pressure_Pa.minCoeff()));
    ROLLWEAR_ASSERT(std::abs(s.pressure_Pa.sum() * cell_m2 - normal_load_N) <= kLoadBalanceRtol * normal_load_N,
                    fmt::format("the pressure carries {} N of {} N", s.pressure_Pa.sum() * cell_m2, normal_load_N));
  }

  spdlog::debug("halfspace ({} x {}): {}; approach {:.6e} m, area {:.6e} m^2, p max {:.6e} Pa", nx, ny,
                s.status.message, s.approach_m, s.contact_area_m2, s.pressure_Pa.maxCoeff());
  if (!s.status.converged())
    spdlog::warn("halfspace ({} x {}): not converged: {}", nx, ny, s.status.message);

  // a contact cut by the grid's border misses the pressure outside it
  const Eigen::ArrayXXd& ps = s.pressure_Pa;
  s.reaches_border =
      (ps.row(0) > 0).any() || (ps.row(nx - 1) > 0).any() || (ps.col(0) > 0).any() || (ps.col(ny - 1) > 0).any();
  // (said of a converged solve only: an unconverged iterate's pressure near the border says nothing of the grid)
  if (s.reaches_border && opt.warn_at_border && s.status.converged())
    spdlog::warn("halfspace ({} x {}): the contact reaches the grid's border (half-sizes {:.3e} m x {:.3e} m): "
                 "enlarge the grid",
                 nx, ny, grid.half_x_m, grid.half_y_m);
  return s;
}

Eigen::ArrayXXd interpolate_pressure(const Eigen::ArrayXXd& p, const Grid& from, double from_y0_m, const Grid& to,
                                     double to_y0_m) {
  check_grid(from, "interpolate_pressure");
  check_grid(to, "interpolate_pressure");
  if (p.rows() != from.nx || p.cols() != from.ny)
    throw std::invalid_argument("interpolate_pressure: pressure is " + size_text(p.rows(), p.cols()) + ", grid is " +
                                size_text(from.nx, from.ny));
  // position in `from`'s cells: u = (x - x_0)/dx, cell centres at integers 0..n-1; outside [0, n-1]: 0
  const auto weights = [](double u, int n, int& k, double& t) {
    if (u > -1e-9 && u < 0) u = 0;
    if (u > n - 1 && u < n - 1 + 1e-9) u = n - 1;
    if (!(u >= 0) || !(u <= n - 1)) return false;
    k = std::min(static_cast<int>(std::floor(u)), std::max(n - 2, 0));
    t = n > 1 ? u - k : 0.0;
    // a centre within rounding of a centre of `from` takes its value alone: no trace of the neighbour,
    // which may be an unloaded cell (a trace there is a loaded cell with an open gap, for the solver to clip)
    constexpr double kSnap = 1e-9;
    if (t < kSnap) t = 0;
    if (t > 1 - kSnap) t = 1;
    return true;
  };
  Eigen::ArrayXXd q = Eigen::ArrayXXd::Zero(to.nx, to.ny);
  for (int j = 0; j < to.ny; ++j) {
    int l = 0;
    double ty = 0;
    if (!weights((to_y0_m + to.y_m(j) - from_y0_m - from.y_m(0)) / from.dy_m, from.ny, l, ty)) continue;
    const int l1 = std::min(l + 1, from.ny - 1);
    for (int i = 0; i < to.nx; ++i) {
      int k = 0;
      double tx = 0;
      if (!weights((to.x_m(i) - from.x_m(0)) / from.dx_m, from.nx, k, tx)) continue;
      const int k1 = std::min(k + 1, from.nx - 1);
      q(i, j) = (1 - ty) * ((1 - tx) * p(k, l) + tx * p(k1, l)) + ty * ((1 - tx) * p(k, l1) + tx * p(k1, l1));
    }
  }
  return q;
}

LoadedCells loaded_cells(const Eigen::ArrayXXd& P, double threshold_rel) {
  const double peak = P.size() > 0 ? P.maxCoeff() : 0.0;
  if (!(peak > 0)) throw std::invalid_argument("loaded_cells: no cell is loaded");
  const double threshold = threshold_rel * peak;
  LoadedCells c{static_cast<int>(P.rows()), -1, static_cast<int>(P.cols()), -1};
  for (int j = 0; j < P.cols(); ++j)
    for (int i = 0; i < P.rows(); ++i)
      if (P(i, j) > threshold) {
        c.i0 = std::min(c.i0, i);
        c.i1 = std::max(c.i1, i);
        c.j0 = std::min(c.j0, j);
        c.j1 = std::max(c.j1, j);
      }
  return c;
}

void loaded_lateral_extent(const HalfspaceSolution& s, const Grid& grid, double& y_lo_m, double& y_hi_m) {
  check_grid(grid, "loaded_lateral_extent");
  const Eigen::ArrayXXd& P = s.pressure_Pa;
  if (P.rows() != grid.nx || P.cols() != grid.ny)
    throw std::invalid_argument("loaded_lateral_extent: pressure is " + size_text(P.rows(), P.cols()) + ", grid is " +
                                size_text(grid.nx, grid.ny));
  const Eigen::ArrayXd q = P.colwise().sum().transpose();  // strip loads (per dx)
  if (!(q.maxCoeff() > 0)) throw std::invalid_argument("loaded_lateral_extent: no cell is loaded");
  int j0 = 0, j1 = grid.ny - 1;
  while (!(q(j0) > 0)) ++j0;
  while (!(q(j1) > 0)) --j1;
  const double dy = grid.dy_m;
  y_lo_m = grid.y_m(j0) - dy / 2;
  y_hi_m = grid.y_m(j1) + dy / 2;
  if (j1 > j0) {
    y_lo_m = grid.y_m(j0) - dy * edge_beyond_centre(q(j0), q(j0 + 1));
    y_hi_m = grid.y_m(j1) + dy * edge_beyond_centre(q(j1), q(j1 - 1));
  }
}

double displacement_at_m(const HalfspaceSolution& s, const Grid& grid, double x_m, double y_m, double Estar_Pa) {
  const Eigen::ArrayXXd& P = s.pressure_Pa;
  if (P.rows() != grid.nx || P.cols() != grid.ny)
    throw std::invalid_argument("displacement_at_m: pressure is " + size_text(P.rows(), P.cols()) + ", grid is " +
                                size_text(grid.nx, grid.ny));
  // Love's closed form near the point; farther than kFar cell sizes, its expansion in the cell's size
  //   dx dy/(pi E* r) [1 + (dx^2 (3 X^2/r^2 - 1) + dy^2 (3 Y^2/r^2 - 1)) / (24 r^2)],
  // whose next term is O((d/r)^4): below 1e-4 of the cell's displacement there
  constexpr double kFar = 4;
  const double dx = grid.dx_m, dy = grid.dy_m, far2 = kFar * kFar * std::max(dx * dx, dy * dy);
  const double point = dx * dy / (kPi * Estar_Pa);
  double u = 0;
  for (int j = 0; j < grid.ny; ++j) {
    const double Y = y_m - grid.y_m(j);
    for (int i = 0; i < grid.nx; ++i) {
      if (!(P(i, j) > 0)) continue;
      const double X = x_m - grid.x_m(i);
      const double r2 = X * X + Y * Y;
      if (r2 > far2)
        u += P(i, j) * point / std::sqrt(r2) * (1 + (dx * dx * (3 * X * X / r2 - 1) + dy * dy * (3 * Y * Y / r2 - 1)) / (24 * r2));
      else
        u += P(i, j) * rectangle_influence_m_per_Pa(X, Y, dx, dy, Estar_Pa);
    }
  }
  return u;
}

ContactPatch halfspace_patch(const HalfspaceSolution& s, const Grid& grid, double normal_load_N) {
  check_grid(grid, "halfspace_patch");
  const Eigen::ArrayXXd& P = s.pressure_Pa;
  if (P.rows() != grid.nx || P.cols() != grid.ny)
    throw std::invalid_argument("halfspace_patch: pressure is " + size_text(P.rows(), P.cols()) + ", grid is " +
                                size_text(grid.nx, grid.ny));
  if (!(normal_load_N > 0) || !std::isfinite(normal_load_N))
    throw std::invalid_argument("halfspace_patch: normal load must be positive and finite, got " +
                                std::to_string(normal_load_N) + " N");
  const double dx = grid.dx_m, dy = grid.dy_m;
  const double carried_N = P.sum() * dx * dy;
  if (!(carried_N > 0) || !P.allFinite())
    throw std::invalid_argument("halfspace_patch: the solution carries no load");
  if (std::abs(carried_N - normal_load_N) > 1e-6 * carried_N)
    throw std::invalid_argument(fmt::format("halfspace_patch: the solution carries {:.9g} N, not the {:.9g} N given",
                                            carried_N, normal_load_N));
  const double scale = normal_load_N / carried_N;

  ContactPatch patch;
  patch.grid = grid;
  patch.normal_load_N = normal_load_N;
  patch.approach_m = s.approach_m;
  patch.half_length_m = Eigen::ArrayXd::Zero(grid.ny);
  patch.strip_peak_Pa = Eigen::ArrayXd::Zero(grid.ny);
  Eigen::ArrayXd strip_load_N_per_m = Eigen::ArrayXd::Zero(grid.ny);

  for (int j = 0; j < grid.ny; ++j) {
    // the strip's loaded cells, i0..i1
    int i0 = 0, i1 = grid.nx - 1;
    while (i0 < grid.nx && !(P(i0, j) > 0)) ++i0;
    if (i0 == grid.nx) continue;
    while (!(P(i1, j) > 0)) --i1;

    // contact extent: square-root edges, p^2 linear in the distance to the edge
    double x_lo = grid.x_m(i0) - dx / 2, x_hi = grid.x_m(i1) + dx / 2;  // single loaded cell
    if (i1 > i0) {
      x_lo = grid.x_m(i0) - dx * edge_beyond_centre(P(i0, j) * P(i0, j), P(i0 + 1, j) * P(i0 + 1, j));
      x_hi = grid.x_m(i1) + dx * edge_beyond_centre(P(i1, j) * P(i1, j), P(i1 - 1, j) * P(i1 - 1, j));
    }
    const double a_j = std::min((x_hi - x_lo) / 2, grid.half_x_m);

    // semi-ellipse carrying the strip's load
    strip_load_N_per_m(j) = P.col(j).sum() * dx * scale;
    patch.half_length_m(j) = a_j;
    patch.strip_peak_Pa(j) = strip_load_N_per_m(j) / (kPi / 2 * a_j);
  }

  // equivalent ellipse: the longest strip, and the lateral extent with strip loads linear at its ends
  int j0 = 0, j1 = grid.ny - 1;
  while (!(strip_load_N_per_m(j0) > 0)) ++j0;
  while (!(strip_load_N_per_m(j1) > 0)) --j1;
  double y_lo = grid.y_m(j0) - dy / 2, y_hi = grid.y_m(j1) + dy / 2;
  if (j1 > j0) {
    y_lo = grid.y_m(j0) - dy * edge_beyond_centre(strip_load_N_per_m(j0), strip_load_N_per_m(j0 + 1));
    y_hi = grid.y_m(j1) + dy * edge_beyond_centre(strip_load_N_per_m(j1), strip_load_N_per_m(j1 - 1));
  }
  patch.a_m = patch.half_length_m.maxCoeff();
  patch.b_m = std::min((y_hi - y_lo) / 2, grid.half_y_m);
  patch.p0_Pa = patch.strip_peak_Pa.maxCoeff();
  fill_strip_pressures(patch);
  return patch;
}

}  // namespace contact
