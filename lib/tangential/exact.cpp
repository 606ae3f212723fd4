// Kalker's exact theory, steady rolling (exact.h; the derivation is in docs/exact-theory.md).
//
// Influence coefficients. Cerruti's surface displacement of one half-space under a tangential
// point force Q_x at the origin is u_x = Q_x/(2 pi G1) [(1-nu)/r + nu X^2/r^3], u_y = Q_x nu X Y /
// (2 pi G1 r^3). Both quasi-identical bodies together (1/G = (1/G1 + 1/G2)/2) give twice that with
// the combined G. Over a rectangle [-c, c] x [-d, d] each term is a mixed second difference of an
// antiderivative F with d2F/dXdY = the kernel:
//   1/r:       X asinh(Y/|X|) + Y asinh(X/|Y|)     (Love's, as for the pressure)
//   X^2/r^3:   Y asinh(X/|Y|)                       (d/dX of it is Y/r, d/dY (Y/r) = X^2/r^3)
//   Y^2/r^3:   X asinh(Y/|X|)
//   X Y/r^3:   -r
// so that with R[F] = F(x+c, y+d) - F(x+c, y-d) - F(x-c, y+d) + F(x-c, y-d), Fa = Y asinh(X/|Y|),
// Fb = X asinh(Y/|X|):
//   A_xx = (R[Fa] + (1-nu) R[Fb]) / (pi G),  A_yy = ((1-nu) R[Fa] + R[Fb]) / (pi G),
//   A_xy = -nu R[r] / (pi G).
//
// Convolution. A depends on the offset of the cells only: u = A tau is a zero-padded cyclic
// convolution on a grid of at least (2 nxe x 2 ny) cells, nxe = nx + 1 (the grid plus one row ahead of the
// leading edge), each length rounded up to one of prime factors 2, 3, 5, 7 (fft_size). A_xx and A_yy are even in both offsets, A_xy odd in both, so all three spectra are real;
// one product is two forward and two backward real 2-D transforms (FFTW, planned once per solve),
// each done as in the normal solver: along x on the ny rows that can be nonzero, along y on all.
//
// The cell's own coefficient. In the slip of cell i, its own traction enters through u_i and
// u_(i+1) only, and diagonally (A_xy vanishes at offsets along x):
//   s_i/V = r_i + B tau_i,  B = diag(bx, by),  bx = (A_xx(0,0) - A_xx(dx,0))/dx,  by likewise.
// The cell's Coulomb problem with everything else frozen (r_i fixed) has a closed form up to one
// scalar root: stick if |B^-1 r| <= g = mu p (tau = -B^-1 r), else slip with
//   s_k = r_k sigma/(sigma + g b_k),  tau_k = -g r_k/(sigma + g b_k),  sum_k (r_k/(sigma + g b_k))^2 = 1,
// whose left side is convex and decreasing in sigma: Newton from sigma = 0 rises monotonically to the
// root. It classifies the cells, gives the slip tractions and measures the residual (exact.h).
//
// The all-stick start. Without the friction bound the problem is linear, D A tau = -w on the contact
// cells. D A has the symbol of d/dx times that of 1/r, i kx/|k|: it is small for tractions that vary
// slowly along x, and GMRES with a diagonal preconditioner needs iterations in proportion to the
// grid (measured: 51, 112, 278 at 10, 20, 40 cells a side, a/b = 1). The right preconditioner M used
// here inverts the local part of D A, b (I - S), S the shift by one cell upstream: a march from
// the leading edge of each run of contact cells, tau_i = z_i/b + tau_(i+1). With it the iterations
// grow like the square root of the grid (26, 36, 48 on the same grids).
// When the result satisfies |tau| <= mu p everywhere it is the solution (full stick).
//
// The friction problem: semi-smooth Newton on the active sets. An iteration classifies every cell by
// its own Coulomb problem with u = A tau fresh (stick, or slip with direction e = s/|s|), then solves
// the linearised problem for all cells at once with the same preconditioned GMRES: stick cells keep
// D A tau = -w; a slip cell's traction is -g e + tau_t t (t the normal to e) and its equation is the
// linearisation of tau = -g s/|s|,
//   (|s|/g) tau_t + t.(w + D A tau) = 0,
// which stays regular as |s| -> 0, where it asks for no slip across e. The march preconditioner
// inverts a slip row's local part with its own term: tau_t = (z + t.(B tau_(i+1)))/(t.B t + |s|/g);
// the rolling step's diagonal one likewise (t.B t + |s|/g). Newton converges in 3 to 5
// iterations on the paper's contact from 20 to 160 cells a side (residual 0.5, 0.3, 0.1, 2e-5, 1e-11
// at 80 x 80). Each linear solve goes to max(stick_tol, min(0.3, max(r, tol/r))): inexact Newton (forcing).
//
// Why not Gauss-Seidel. Kalker's own solvers in CONTACT (ConvexGS, SteadyGS) are Gauss-Seidel
// methods. A pointwise Gauss-Seidel on D A, visiting each strip from leading to trailing edge with
// the strip's displacement kept current and the others refreshed by convolution, diverged here even
// at full stick on 10 x 10 (|Fx| grew by 1e5 in 10 sweeps): the lagged downstream coefficients
// (A(m dx) - A((m+1) dx))/dx add up to A(dx)/dx, and the upstream march through b (I - S)
// accumulates their error along the strip. With the slip tractions updated pointwise (Jacobi) and
// the stick ones by GMRES, the sets settle in a few iterations but the slip directions then
// converge at 0.985 per iteration (residual 2e-3 after 200 at 80 x 80): hence Newton.
#include "lib/fftw_planner.h"
#include "lib/tangential/exact.h"
#include "lib/numeric.h"
#include "lib/history.h"
#include "lib/errors.h"
#include "lib/normal/hertz.h"
#include "lib/tangential/shift_run.h"

#include <fftw3.h>
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <complex>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace contact {

TangentialInfluence line_load_influence(double x_m, double dx_m, double G_Pa, double nu) {
  // integral of ln|t| over [x - c, x + c]: t ln|t| - t between the ends (0 ln 0 = 0)
  const auto f = [](double t) { return t != 0 ? t * std::log(std::abs(t)) - t : 0.0; };
  const double c = dx_m / 2, L = f(x_m + c) - f(x_m - c);
  TangentialInfluence a;
  a.xx = -2 * (1 - nu) / (kPi * G_Pa) * L;
  a.yy = -2 / (kPi * G_Pa) * L;
  a.xy = 0;
  return a;
}

namespace {

// restart length of GMRES
constexpr int kGmresRestart = 60;
// the all-stick start is first solved to this relative residual; when its tractions then exceed the
// bound by more than kLooseStickMargin somewhere, friction decides and the Newton iteration starts
// from it (the tractions' error is of the order of the residual times the condition of D A; a start
// misjudged as exceeding it costs Newton steps, never the answer: the Newton iteration finds full stick
// too). 1e-1: on the paper's contact at 80 x 80 the whole solve then takes 66 GMRES iterations to
// tol 1e-4, 75 from 1e-2.
constexpr double kLooseStickTol = 1e-1;
constexpr double kLooseStickMargin = 0.05;
// a start traction above the bound by no more than this share is the previous solve's clipped one
// (|tau| = g up to rounding): kept as it is, so that the previous step's u = A tau still holds
constexpr double kBoundRounding = 1e-12;
// backtracking steps of the Newton iteration before a step that raised the residual is accepted
constexpr int kMaxHalvings = 4;
// Inexact Newton: the linear solve of a Newton step from the fixed-point residual r goes to the relative
// residual min(kMaxForcing, max(r, tol/r)) (and no lower than stick_tol). Far from the solution the
// active sets are wrong and a tighter solve is wasted (0.3); near it, r keeps the convergence
// quadratic; and a solve more accurate than tol/r (the step lands at about r times its linear
// residual) is not needed to reach tol. On the paper's contact at 80 x 80 (with the start above) this
// takes 66 GMRES iterations to tol 1e-4 and 110 to 1e-9, where r/100 (and the start to 1e-3) took 116
// and 181 (docs/exact-theory.md §3, §5).
constexpr double kMaxForcing = 0.3;
double forcing(double residual, const ExactOptions& opt) {
  return std::max(opt.stick_tol, std::min(kMaxForcing, std::max(residual, opt.tol / residual)));
}

double sq(double v) { return v * v; }

double F_a(double X, double Y) { return Y != 0 ? Y * std::asinh(X / std::abs(Y)) : 0.0; }
double F_b(double X, double Y) { return X != 0 ? X * std::asinh(Y / std::abs(X)) : 0.0; }
double F_r(double X, double Y) { return std::hypot(X, Y); }

template <class F>
double rectangle_difference(F f, double x, double y, double c, double d) {
  return f(x + c, y + d) - f(x + c, y - d) - f(x - c, y + d) + f(x - c, y - d);
}

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

template <class T>
std::unique_ptr<T, FftwFree> fftw_alloc(std::size_t n) {
  std::unique_ptr<T, FftwFree> p(static_cast<T*>(fftw_malloc(sizeof(T) * n)));
  if (!p) throw std::bad_alloc();
  return p;
}

// u = A tau on the extended grid (nxe x ny), by zero-padded convolution
struct TangentialOperator {
  int nxe, ny, mx, my, nk;
  // the rows that can be nonzero (ny x mx, row-major: m + mx n) and the spectra (nk x my, column-major:
  // n + my k, so that the transforms along y run on contiguous columns: 6 to 11 % less per product at 80 x 80
  // than with the rows' spectra in rows, whose columns FFTW copies to and from buffers)
  std::unique_ptr<double, FftwFree> rows_x, rows_y;
  std::unique_ptr<fftw_complex, FftwFree> spec_x, spec_y;
  std::vector<double> kxx, kxy, kyy;  // real spectra / (mx my), n + my k
  // per component: r2c along x on the first ny rows, c2c along y on every column, and back
  fftw_plan rf[2] = {nullptr, nullptr}, cf[2] = {nullptr, nullptr};
  fftw_plan cb[2] = {nullptr, nullptr}, rb[2] = {nullptr, nullptr};

  // the padded lengths: at least twice the grid's (offsets -(n - 1) ... n - 1 without wrapping onto the grid),
  // of small prime factors (fft_size)
  TangentialOperator(int nx_ext, int ny_, double dx, double dy, double G, double nu, bool plane_strain)
      : nxe(nx_ext), ny(ny_), mx(fft_size(2 * nx_ext)), my(fft_size(2 * ny_)), nk(mx / 2 + 1),
        rows_x(fftw_alloc<double>(static_cast<std::size_t>(mx) * ny_)),
        rows_y(fftw_alloc<double>(static_cast<std::size_t>(mx) * ny_)),
        spec_x(fftw_alloc<fftw_complex>(static_cast<std::size_t>(my) * nk)),
        spec_y(fftw_alloc<fftw_complex>(static_cast<std::size_t>(my) * nk)) {
    const std::size_t n_pad = static_cast<std::size_t>(mx) * my;
    std::unique_ptr<double, FftwFree> kernel = fftw_alloc<double>(n_pad);
    fftw_plan kernel_forward = nullptr;
    {
      const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
      double* rows[2] = {rows_x.get(), rows_y.get()};
      fftw_complex* spec[2] = {spec_x.get(), spec_y.get()};
      for (int c = 0; c < 2; ++c) {
        rf[c] = fftw_plan_many_dft_r2c(1, &mx, ny, rows[c], nullptr, 1, mx, spec[c], nullptr, my, 1, FFTW_ESTIMATE);
        cf[c] = fftw_plan_many_dft(1, &my, nk, spec[c], nullptr, 1, my, spec[c], nullptr, 1, my, FFTW_FORWARD,
                                   FFTW_ESTIMATE);
        cb[c] = fftw_plan_many_dft(1, &my, nk, spec[c], nullptr, 1, my, spec[c], nullptr, 1, my, FFTW_BACKWARD,
                                   FFTW_ESTIMATE);
        rb[c] = fftw_plan_many_dft_c2r(1, &mx, ny, spec[c], nullptr, my, 1, rows[c], nullptr, 1, mx, FFTW_ESTIMATE);
      }
      kernel_forward = fftw_plan_dft_r2c_2d(my, mx, kernel.get(), spec_x.get(), FFTW_ESTIMATE);
    }
    bool planned = kernel_forward != nullptr;
    for (int c = 0; c < 2; ++c) planned = planned && rf[c] && cf[c] && cb[c] && rb[c];
    if (!planned) {
      destroy_plans(&kernel_forward);
      throw std::runtime_error(fmt::format("exact: fftw_plan_many_dft failed for {} x {}", mx, my));
    }
    // the three kernels at signed offsets, wrapped onto the padded grid (offsets nxe ... mx - nxe and ny ... my - ny
    // unused)
    std::vector<double> Kxx(n_pad), Kxy(n_pad), Kyy(n_pad);
    // the first quadrant, then by parity: xx, yy even in both offsets, xy odd in both
    for (int l = 0; l < ny; ++l) {
      for (int k = 0; k < nxe; ++k) {
        const TangentialInfluence a = plane_strain ? line_load_influence(k * dx, dx, G, nu)
                                                   : cerruti_rectangle_influence(k * dx, l * dy, dx, dy, G, nu);
        for (const int sl : {1, -1}) {
          if (sl < 0 && l == 0) continue;
          const std::size_t n = static_cast<std::size_t>(sl > 0 ? l : my - l);
          for (const int sk : {1, -1}) {
            if (sk < 0 && k == 0) continue;
            const std::size_t q = static_cast<std::size_t>(sk > 0 ? k : mx - k) + static_cast<std::size_t>(mx) * n;
            Kxx[q] = a.xx;
            Kxy[q] = sk * sl * a.xy;
            Kyy[q] = a.yy;
          }
        }
      }
    }
    const double scale = 1.0 / static_cast<double>(n_pad);
    auto spectrum_of = [&](const std::vector<double>& K, std::vector<double>& out) {
      std::copy(K.begin(), K.end(), kernel.get());
      fftw_execute(kernel_forward);
      out.resize(static_cast<std::size_t>(my) * nk);  // the 2-D plan's (my x nk, row-major) transposed
      for (std::size_t n = 0; n < static_cast<std::size_t>(my); ++n)
        for (std::size_t k = 0; k < static_cast<std::size_t>(nk); ++k)
          out[n + static_cast<std::size_t>(my) * k] = spec_x.get()[k + static_cast<std::size_t>(nk) * n][0] * scale;
    };
    spectrum_of(Kxx, kxx);
    spectrum_of(Kxy, kxy);
    spectrum_of(Kyy, kyy);
    destroy_plans(&kernel_forward, false);
  }
  ~TangentialOperator() { destroy_plans(); }
  TangentialOperator(const TangentialOperator&) = delete;
  TangentialOperator& operator=(const TangentialOperator&) = delete;

  // the apply plans (all = true) and extra, one at a time under the planner's lock
  void destroy_plans(fftw_plan* extra = nullptr, bool all = true) {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    if (extra && *extra) fftw_destroy_plan(*extra);
    if (!all) return;
    for (int c = 0; c < 2; ++c)
      for (fftw_plan* p : {&rf[c], &cf[c], &cb[c], &rb[c]}) {
        if (*p) fftw_destroy_plan(*p);
        *p = nullptr;
      }
  }

  // (ux, uy) = A (tx, ty); all (nxe x ny)
  void apply(const Eigen::ArrayXXd& tx, const Eigen::ArrayXXd& ty, Eigen::ArrayXXd& ux, Eigen::ArrayXXd& uy) {
    Eigen::Map<Eigen::ArrayXXd> px(rows_x.get(), mx, ny), py(rows_y.get(), mx, ny);
    px.topRows(nxe) = tx;
    px.bottomRows(mx - nxe).setZero();
    py.topRows(nxe) = ty;
    py.bottomRows(mx - nxe).setZero();
    fftw_complex* X = spec_x.get();
    fftw_complex* Y = spec_y.get();
    for (int c = 0; c < 2; ++c) {
      fftw_execute(rf[c]);
      double* S = reinterpret_cast<double*>(c == 0 ? X : Y);  // the padded rows' spectrum is zero
      for (std::size_t k = 0; k < static_cast<std::size_t>(nk); ++k)
        std::fill(S + 2 * (static_cast<std::size_t>(my) * k + ny), S + 2 * static_cast<std::size_t>(my) * (k + 1), 0.0);
      fftw_execute(cf[c]);
    }
    const std::size_t n = kxx.size();
    for (std::size_t q = 0; q < n; ++q) {
      const double xr = X[q][0], xi = X[q][1], yr = Y[q][0], yi = Y[q][1];
      X[q][0] = kxx[q] * xr + kxy[q] * yr;
      X[q][1] = kxx[q] * xi + kxy[q] * yi;
      Y[q][0] = kxy[q] * xr + kyy[q] * yr;
      Y[q][1] = kxy[q] * xi + kyy[q] * yi;
    }
    for (int c = 0; c < 2; ++c) {
      fftw_execute(cb[c]);
      fftw_execute(rb[c]);
    }
    ux = px.topRows(nxe);
    uy = py.topRows(nxe);
  }
};

// The operator of the last few grids solved on this thread: the kernel's spectra and FFTW's plans
// depend on the grid, G and nu only, and a transient run or an outer iteration (the shift's force)
// solves on the same grid again and again (building it is about 1 ms at 80 x 80: 6500 rectangles'
// coefficients, three kernel transforms and the plans). Per thread, as apply() works in the
// operator's own buffers.
TangentialOperator& cached_operator(int nxe, int ny, double dx, double dy, double G, double nu, bool plane_strain) {
  struct Entry {
    int nxe, ny;
    double dx, dy, G, nu;
    bool plane_strain;
    std::unique_ptr<TangentialOperator> op;
  };
  constexpr std::size_t kCachedOperators = 4;
  thread_local std::vector<Entry> cache;
  for (std::size_t k = 0; k < cache.size(); ++k) {
    Entry& e = cache[k];
    if (e.nxe == nxe && e.ny == ny && e.dx == dx && e.dy == dy && e.G == G && e.nu == nu &&
        e.plane_strain == plane_strain) {
      std::rotate(cache.begin(), cache.begin() + static_cast<std::ptrdiff_t>(k), cache.begin() + static_cast<std::ptrdiff_t>(k) + 1);
      return *cache.front().op;
    }
  }
  auto op = std::make_unique<TangentialOperator>(nxe, ny, dx, dy, G, nu, plane_strain);
  if (cache.size() == kCachedOperators) cache.pop_back();
  cache.insert(cache.begin(), Entry{nxe, ny, dx, dy, G, nu, plane_strain, std::move(op)});
  return *cache.front().op;
}

// a contact cell's Coulomb problem with everything else frozen: slip s = r + B tau (per unit V),
// |tau| <= g. Returns true for stick.
bool element_solve(double rx, double ry, double bx, double by, double g, double& tx, double& ty) {
  const double sx = -rx / bx, sy = -ry / by;  // the stick traction
  if (sx * sx + sy * sy <= g * g) {
    tx = sx;
    ty = sy;
    return true;
  }
  // slip: sum_k (r_k / (sigma + g b_k))^2 = 1, Newton from sigma = 0 (convex, decreasing)
  double sigma = 0;
  for (int it = 0; it < 100; ++it) {
    const double qx = 1 / (sigma + g * bx), qy = 1 / (sigma + g * by);
    const double h = rx * rx * qx * qx + ry * ry * qy * qy - 1;
    const double dh = -2 * (rx * rx * qx * qx * qx + ry * ry * qy * qy * qy);
    const double step = -h / dh;
    sigma += step;
    if (!(step > 1e-15 * sigma)) break;
  }
  tx = -g * rx / (sigma + g * bx);
  ty = -g * ry / (sigma + g * by);
  return false;
}

}  // namespace

TangentialInfluence cerruti_rectangle_influence(double x_m, double y_m, double dx_m, double dy_m, double G_Pa,
                                                double nu) {
  const double c = dx_m / 2, d = dy_m / 2;
  const double Ra = rectangle_difference(F_a, x_m, y_m, c, d);
  const double Rb = rectangle_difference(F_b, x_m, y_m, c, d);
  const double Rr = rectangle_difference(F_r, x_m, y_m, c, d);
  const double k = 1 / (kPi * G_Pa);
  TangentialInfluence a;
  a.xx = k * (Ra + (1 - nu) * Rb);
  a.yy = k * ((1 - nu) * Ra + Rb);
  a.xy = -k * nu * Rr;
  return a;
}

namespace {

// What a solve carries in besides the patch and the problem; the defaults are the steady solve from
// the all-stick start.
// The transport of a transient step: the previous step's displacement difference ((nx + 1) x ny),
// cell i reading its row i + offset (1: the material rolled by one cell; 0: already carried to where
// it is now, or a shift), and the rigid slip per dx times creep_scale (dq/dx of a partial step).
// Without it (ux == nullptr) the problem is steady: u_(i+1) is A tau too.
struct ExactTransport {
  const Eigen::ArrayXXd* ux = nullptr;
  const Eigen::ArrayXXd* uy = nullptr;
  int offset = 1;
  double creep_scale = 1.0;
};

// A warm start: the tractions (nx x ny) the Newton iteration starts from (tau_x == nullptr: the
// all-stick start), and what else of a previous solve it reuses where given: A of those tractions
// ((nx + 1) x ny, kept when none lies on a cell out of contact now), their stick (1) and slip (2)
// sets (the first Newton step's), their last change ((nx + 1) x ny: the first Newton step's guessed
// direction of the increment).
struct ExactWarmStart {
  const Eigen::ArrayXXd* tau_x = nullptr;
  const Eigen::ArrayXXd* tau_y = nullptr;
  const Eigen::ArrayXXd* u_x = nullptr;
  const Eigen::ArrayXXd* u_y = nullptr;
  const Eigen::ArrayXXi* state = nullptr;
  const Eigen::ArrayXXd* dtau_x = nullptr;
  const Eigen::ArrayXXd* dtau_y = nullptr;
};

// What the trapezoidal power of a transient step pairs with (report): the previous step's tractions
// (nx x ny), displacement ((nx + 1) x ny) and its row behind the trailing edge (ny, empty when not
// computed), and theta, the cells the material moved over the step (1: a rolling step by dx, dq/dx, 0: a
// shift or a standing step). Null tractions: from rest. A steady solve pairs with itself (theta 1).
struct ExactPowerHistory {
  const Eigen::ArrayXXd* tau_x = nullptr;
  const Eigen::ArrayXXd* tau_y = nullptr;
  const Eigen::ArrayXXd* u_x = nullptr;
  const Eigen::ArrayXXd* u_y = nullptr;
  const Eigen::ArrayXd* u_behind_x = nullptr;
  const Eigen::ArrayXd* u_behind_y = nullptr;
  double theta = 1;
};

struct ExactSolveSetup {
  const char* mode_name = nullptr;  // in messages; nullptr: "exact steady", "exact rolling step", "exact shift"
  ExactTransport transport;
  ExactWarmStart start;
  ExactPowerHistory history;     // a transient step's previous state (the power's pairing); unused when steady
  bool warn_unconverged = true;  // spdlog::warn on a solve that did not converge
};

// the previous step's state for the power of a step that moved the material by theta cells (nullptr: at rest)
ExactPowerHistory power_history(const ExactSolution* previous, double theta) {
  ExactPowerHistory h;
  h.theta = theta;
  if (!previous) return h;
  h.tau_x = &previous->fields.tau_x_Pa;
  h.tau_y = &previous->fields.tau_y_Pa;
  h.u_x = &previous->u_x_m;
  h.u_y = &previous->u_y_m;
  h.u_behind_x = &previous->u_behind_x_m;
  h.u_behind_y = &previous->u_behind_y_m;
  return h;
}

// a previous solution as the start: its tractions and their product; with_sets also its stick and
// slip sets and its last change (a rolling step from the previous rolling step)
ExactWarmStart warm_start_from(const ExactSolution& s, bool with_sets) {
  ExactWarmStart w;
  w.tau_x = &s.fields.tau_x_Pa;
  w.tau_y = &s.fields.tau_y_Pa;
  w.u_x = &s.u_x_m;
  w.u_y = &s.u_y_m;
  if (with_sets) {
    w.state = &s.fields.state;
    w.dtau_x = &s.dtau_x_Pa;
    w.dtau_y = &s.dtau_y_Pa;
  }
  return w;
}

// a steady solve's start from given tractions alone (a coarser grid's solution, prolonged)
ExactSolveSetup tractions_start(const Eigen::ArrayXXd& tx, const Eigen::ArrayXXd& ty) {
  ExactSolveSetup setup;
  setup.start.tau_x = &tx;
  setup.start.tau_y = &ty;
  return setup;
}

const char* mode_of(const ExactSolveSetup& setup) {
  const bool transient = setup.transport.ux != nullptr;
  return setup.mode_name               ? setup.mode_name
         : !transient                  ? "exact steady"
         : setup.transport.offset == 1 ? "exact rolling step"
                                       : "exact shift";
}

// the patch, the constants and the options (std::invalid_argument, named by the mode)
void check_exact_inputs(const ContactPatch& patch, double G_Pa, double nu, const Creepages& creepages, double mu,
                        double speed_m_per_s, const ExactOptions& opt, const char* mode) {
  const Grid& grid = patch.grid;
  const int nx = grid.nx, ny = grid.ny;
  if (nx < 1 || ny < 1 || !(grid.dx_m > 0) || !(grid.dy_m > 0) || grid.x_m.size() != nx || grid.y_m.size() != ny)
    throw std::invalid_argument(fmt::format("{}: the patch's grid is empty or inconsistent ({} x {})", mode, nx, ny));
  if (patch.pressure_Pa.rows() != nx || patch.pressure_Pa.cols() != ny)
    throw std::invalid_argument(fmt::format("{}: the patch's pressure is {} x {}, its grid {} x {}", mode,
                                            patch.pressure_Pa.rows(), patch.pressure_Pa.cols(), nx, ny));
  if (!patch.pressure_Pa.allFinite() || (patch.pressure_Pa < 0).any())
    throw std::invalid_argument(std::string(mode) + ": the patch's pressure has a negative or non-finite value");
  if (!(G_Pa > 0) || !std::isfinite(G_Pa))
    throw std::invalid_argument(fmt::format("{}: G must be positive and finite, got {} Pa", mode, G_Pa));
  if (!(nu >= 0 && nu < 0.5)) throw std::invalid_argument(fmt::format("{}: nu must be in [0, 0.5), got {}", mode, nu));
  if (!(mu > 0) || !std::isfinite(mu))
    throw std::invalid_argument(fmt::format("{}: mu must be positive and finite, got {}", mode, mu));
  if (!(speed_m_per_s >= 0) || !std::isfinite(speed_m_per_s))
    throw std::invalid_argument(fmt::format("{}: speed must be >= 0 and finite, got {} m/s", mode, speed_m_per_s));
  if (!std::isfinite(creepages.xi) || !std::isfinite(creepages.eta) || !std::isfinite(creepages.phi_per_m))
    throw std::invalid_argument(std::string(mode) + ": a creepage is not finite");
  if (!(opt.tol > 0) || opt.max_iterations < 1 || !(opt.stick_tol > 0) || opt.max_stick_iterations < 1)
    throw std::invalid_argument(std::string(mode) + ": tol, stick_tol must be positive, max_iterations, max_stick_iterations >= 1");
  if (opt.plane_strain && ny != 1)
    throw std::invalid_argument(fmt::format("{}: plane strain takes one strip (ny = 1), got {}", mode, ny));
}

// the carried fields' shapes: the previous displacement ((nx + 1) x ny), the start's tractions (nx x ny)
void check_carried_inputs(const ExactSolveSetup& setup, int nx, int ny, const char* mode) {
  const Eigen::ArrayXXd* prev_ux = setup.transport.ux;
  const Eigen::ArrayXXd* prev_uy = setup.transport.uy;
  const Eigen::ArrayXXd* start_tx = setup.start.tau_x;
  const Eigen::ArrayXXd* start_ty = setup.start.tau_y;
  if (prev_ux && (prev_ux->rows() != nx + 1 || prev_ux->cols() != ny || prev_uy->rows() != nx + 1 ||
                  prev_uy->cols() != ny || !prev_ux->allFinite() || !prev_uy->allFinite()))
    throw std::invalid_argument(fmt::format("{}: the previous displacement must be finite, {} x {}", mode, nx + 1, ny));
  if (start_tx && (start_tx->rows() != nx || start_tx->cols() != ny || start_ty->rows() != nx ||
                   start_ty->cols() != ny || !start_tx->allFinite() || !start_ty->allFinite()))
    throw std::invalid_argument(fmt::format("{}: the previous tractions must be finite, {} x {}", mode, nx, ny));
}

// The contact cells (column-major index i + nxe j on the grid extended by one row ahead of the
// leading edge), their bound g = mu p and rigid creepage w (per dx, times the transport's scale), and
// w with the previous step's displacement one cell upstream (known) in the equations' we
struct ExactCells {
  std::vector<int> cells;
  Eigen::ArrayXXd g, wx, wy, wex, wey;  // (nxe x ny), zero outside the contact
};

ExactCells contact_cells(const ContactPatch& patch, const Creepages& creepages, double mu, const ExactTransport& tr,
                         int nxe) {
  const Grid& grid = patch.grid;
  const int nx = grid.nx, ny = grid.ny;
  const double dx = grid.dx_m, creep_scale = tr.creep_scale;
  const int prev_offset = tr.offset;
  const bool transient = tr.ux != nullptr;
  ExactCells e;
  std::vector<int>& cells = e.cells;
  e.g = Eigen::ArrayXXd::Zero(nxe, ny);
  e.wx = e.g;
  e.wy = e.g;
  e.wex = e.g;
  e.wey = e.g;
  Eigen::ArrayXXd &g = e.g, &wx = e.wx, &wy = e.wy, &wex = e.wex, &wey = e.wey;
  for (int j = 0; j < ny; ++j) {
    const double xi_j = creepages.xi + (patch.strip_xi_offset.size() == ny ? patch.strip_xi_offset(j) : 0.0);
    for (int i = 0; i < nx; ++i) {
      if (!(patch.pressure_Pa(i, j) > 0)) continue;
      cells.push_back(i + nxe * j);
      g(i, j) = mu * patch.pressure_Pa(i, j);
      wx(i, j) = creep_scale * (xi_j - creepages.phi_per_m * grid.y_m(j));
      wy(i, j) = creep_scale * (creepages.eta + creepages.phi_per_m * grid.x_m(i));
      if (transient) {  // the previous step's displacement one cell upstream, known
        wex(i, j) = wx(i, j) - (*tr.ux)(i + prev_offset, j) / dx;
        wey(i, j) = wy(i, j) - (*tr.uy)(i + prev_offset, j) / dx;
      } else {
        wex(i, j) = wx(i, j);
        wey(i, j) = wy(i, j);
      }
    }
  }
  return e;
}

// One solve of the discrete problem (exact.h): the state of its iteration and its stages, in the
// order solve_exact runs them. The Newton iteration's linear problem: per contact cell c (order of
// `cells`), stick (two unknowns, the traction) or slip (one unknown, the traction's component tau_t
// along t = e^perp, with tau = -g e + tau_t t, e the unit slip direction, |s| the slip of the
// current iterate):
//   stick: (D A tau)_i + w_i = 0
//   slip:  (|s_i|/g_i) tau_t + t.((D A tau)_i + w_i) = 0
// (the Newton linearisation of tau = -g s/|s|; it stays regular as |s| -> 0, where it asks for
// no slip across e).
struct ExactSolve {
  const ContactPatch& patch;
  const ExactOptions& opt;
  const ExactSolveSetup& setup;
  const char* mode;
  int nx, ny, nxe;  // nxe: one row ahead of the leading edge
  double dx, dy;
  bool transient;
  TangentialOperator& A;
  double upstream;  // steady: u_(i+1) is A tau too (1); a rolling step: it is the previous step's, known (0)
  double bx = 0, by = 0;  // the cell's own coefficient B = diag(bx, by)
  ExactCells contact;
  const std::vector<int>& cells;
  int nc;

  // the iterate (tx, ty) and u = A tau of it in (ux, uy) when u_current: kept by linearity through the
  // Newton steps (the product of the right-hand side's tractions plus the Krylov vectors' products
  // combined as the increment is), so that the residual of a Newton iterate costs no product of its own
  Eigen::ArrayXXd tx, ty, ux, uy;
  double* TX = nullptr;
  double* TY = nullptr;
  const double* UX = nullptr;
  const double* UY = nullptr;
  const double* WX = nullptr;  // in the equations: with the previous step's part
  const double* WY = nullptr;
  const double* RX = nullptr;  // the rigid slip alone (creep power)
  const double* RY = nullptr;
  const double* Gb = nullptr;
  bool u_current = false;

  // the Newton step's unknowns: per cell slip or stick, slip direction, |s|, the first unknown's index
  std::vector<char> slip;
  std::vector<double> ex, ey, sabs;
  std::vector<int> offset;
  Eigen::ArrayXXd px, py;  // the traction increment of the unknowns (to_traction)
  int gmres_total = 0;
  int products = 0;  // FFT products A tau
  Eigen::ArrayXXd u0x, u0y, uzx, uzy;
  // allocated per solve: kept per thread instead, the rolling step took 8 % longer (glibc then trims
  // and faults in again the solve's smaller arrays, which the free of these large ones prevents)
  std::vector<Eigen::ArrayXXd> Ukx, Uky;  // the u of each Krylov vector's traction
  Eigen::MatrixXd Vbuf;                   // GMRES's basis, rows for up to 2 nc unknowns

  Eigen::ArrayXXi state;  // per cell of the extended grid: 1 stick, 2 slip, 0 outside
  ExactSolution out;

  ExactSolve(const ContactPatch& patch_, double G_Pa, double nu, const Creepages& creepages, double mu,
             const ExactOptions& opt_, const ExactSolveSetup& setup_, const char* mode_)
      : patch(patch_), opt(opt_), setup(setup_), mode(mode_), nx(patch_.grid.nx), ny(patch_.grid.ny), nxe(nx + 1),
        dx(patch_.grid.dx_m), dy(patch_.grid.dy_m), transient(setup_.transport.ux != nullptr),
        A(cached_operator(nxe, ny, dx, dy, G_Pa, nu, opt_.plane_strain)), upstream(transient ? 0.0 : 1.0),
        cells(contact.cells) {
    const TangentialInfluence A0 = opt.plane_strain ? line_load_influence(0, dx, G_Pa, nu)
                                                    : cerruti_rectangle_influence(0, 0, dx, dy, G_Pa, nu);
    const TangentialInfluence A1 = opt.plane_strain ? line_load_influence(dx, dx, G_Pa, nu)
                                                    : cerruti_rectangle_influence(dx, 0, dx, dy, G_Pa, nu);
    bx = (A0.xx - upstream * A1.xx) / dx;
    by = (A0.yy - upstream * A1.yy) / dx;
    check_carried_inputs(setup, nx, ny, mode);
    ROLLWEAR_ASSERT(bx > 0 && by > 0, fmt::format("own coefficients bx {} by {}", bx, by));

    contact = contact_cells(patch, creepages, mu, setup.transport, nxe);
    nc = static_cast<int>(cells.size());
    if (nc == 0) throw std::invalid_argument(std::string(mode) + ": the patch has no loaded cell");

    tx = Eigen::ArrayXXd::Zero(nxe, ny);
    ty = tx;
    ux = tx;
    uy = tx;
    TX = tx.data();
    TY = ty.data();
    UX = ux.data();
    UY = uy.data();
    WX = contact.wex.data();
    WY = contact.wey.data();
    RX = contact.wx.data();
    RY = contact.wy.data();
    Gb = contact.g.data();
    slip.assign(static_cast<std::size_t>(nc), 0);
    ex.assign(static_cast<std::size_t>(nc), 1.0);
    ey.assign(static_cast<std::size_t>(nc), 0.0);
    sabs.assign(static_cast<std::size_t>(nc), 0.0);
    offset.assign(static_cast<std::size_t>(nc) + 1, 0);
    px = tx;
    py = ty;
    state = Eigen::ArrayXXi::Zero(nxe, ny);
  }
  ExactSolve(const ExactSolve&) = delete;
  ExactSolve& operator=(const ExactSolve&) = delete;

  void index_unknowns() {
    for (int c = 0; c < nc; ++c) offset[c + 1] = offset[c] + (slip[c] ? 1 : 2);
  }

  // x -> traction increments (px, py) on the contact cells
  void to_traction(const Eigen::VectorXd& x) {
    px.setZero();
    py.setZero();
    for (int c = 0; c < nc; ++c) {
      const int q = cells[c], o = offset[c];
      if (slip[c]) {
        px.data()[q] = -ey[c] * x(o);
        py.data()[q] = ex[c] * x(o);
      } else {
        px.data()[q] = x(o);
        py.data()[q] = x(o + 1);
      }
    }
  }

  // right preconditioner x = M z: z as a traction field, marched from the leading edge along each
  // run of contact cells and divided by the own coefficient (the inverse of the local part of D A,
  // b (I - S)), then taken along t on the slip cells
  void precondition(const Eigen::VectorXd& z, Eigen::VectorXd& x) const {
    if (transient) {  // the diagonal of the rows, the slip rows' own term |s|/g included
      for (int c = 0; c < nc; ++c) {
        const int o = offset[c];
        if (slip[c]) {
          x(o) = z(o) / (ey[c] * ey[c] * bx + ex[c] * ex[c] * by + sabs[c] / Gb[cells[c]]);
        } else {
          x(o) = z(o) / bx;
          x(o + 1) = z(o + 1) / by;
        }
      }
      return;
    }
    double ax = 0, ay = 0;
    for (int c = nc - 1; c >= 0; --c) {
      const int q = cells[c], o = offset[c];
      const bool upstream_in = !transient && c + 1 < nc && cells[c + 1] == q + 1;
      if (!upstream_in) ax = ay = 0;
      if (slip[c]) {  // the row t.(B (tau_i - tau_(i+1))) + (|s|/g) tau_t = z, tau_i = tau_t t
        const double tb = ey[c] * ey[c] * bx + ex[c] * ex[c] * by + sabs[c] / Gb[q];
        const double tt = (z(o) + (-ey[c] * bx * ax + ex[c] * by * ay)) / tb;
        x(o) = tt;
        ax = -ey[c] * tt;
        ay = ex[c] * tt;
      } else {
        ax += z(o) / bx;
        ay += z(o + 1) / by;
        x(o) = ax;
        x(o + 1) = ay;
      }
    }
  }

  // rows of the linear operator for traction increments (px, py) and unknowns x; with_w adds w
  void rows(const Eigen::ArrayXXd& fx_, const Eigen::ArrayXXd& fy_, const Eigen::VectorXd* x, bool with_w,
            Eigen::VectorXd& y) {
    A.apply(fx_, fy_, ux, uy);
    for (int c = 0; c < nc; ++c) {
      const int q = cells[c], o = offset[c];
      double rx = (UX[q] - upstream * UX[q + 1]) / dx, ry = (UY[q] - upstream * UY[q + 1]) / dx;
      if (with_w) {
        rx += WX[q];
        ry += WY[q];
      }
      if (slip[c]) {
        y(o) = -ey[c] * rx + ex[c] * ry + (x ? sabs[c] / Gb[q] * (*x)(o) : 0.0);
      } else {
        y(o) = rx;
        y(o + 1) = ry;
      }
    }
  }

  // the Newton step's right-hand side at the current tractions: their unknowns x0 (the fixed part -g e
  // on slip cells aside) and b = -F(x0); u0 = A of them
  void newton_rhs(Eigen::VectorXd& x0, Eigen::VectorXd& b) {
    const int n = offset[nc];
    Eigen::ArrayXXd fx0 = Eigen::ArrayXXd::Zero(nxe, ny), fy0 = fx0;
    x0.resize(n);
    for (int c = 0; c < nc; ++c) {
      const int q = cells[c], o = offset[c];
      if (slip[c]) {
        fx0.data()[q] = -Gb[q] * ex[c];
        fy0.data()[q] = -Gb[q] * ey[c];
        x0(o) = -ey[c] * TX[q] + ex[c] * TY[q];
      } else {
        x0(o) = TX[q];
        x0(o + 1) = TY[q];
      }
    }
    to_traction(x0);
    fx0 += px;
    fy0 += py;
    b.resize(n);
    rows(fx0, fy0, nullptr, true, b);  // F(x0) without the |s|/g term of the slip rows
    ++products;
    u0x = ux;
    u0y = uy;
    uzx.setZero(nxe, ny);
    uzy.setZero(nxe, ny);
    for (int c = 0; c < nc; ++c)
      if (slip[c]) b(offset[c]) += sabs[c] / Gb[cells[c]] * x0(offset[c]);
    b = -b;
  }

  // a guessed direction of the increment (the previous step's change of the tractions, taken along
  // the current unknowns): its multiple that best reduces the residual starts the increment (x_guess,
  // taken off b, its product added to u0)
  void start_from_guess(const Eigen::ArrayXXd& gx, const Eigen::ArrayXXd& gy, Eigen::VectorXd& b,
                        Eigen::VectorXd& x_guess) {
    const int n = offset[nc];
    Eigen::VectorXd xg(n), q(n);
    for (int c = 0; c < nc; ++c) {
      const int qq = cells[c], o = offset[c];
      const double gxq = gx.data()[qq], gyq = gy.data()[qq];
      if (slip[c]) {
        xg(o) = -ey[c] * gxq + ex[c] * gyq;
      } else {
        xg(o) = gxq;
        xg(o + 1) = gyq;
      }
    }
    to_traction(xg);
    rows(px, py, &xg, false, q);
    ++products;
    const double qq = q.squaredNorm(), alpha = qq > 0 ? q.dot(b) / qq : 0.0;
    if (std::isfinite(alpha) && alpha != 0) {
      b -= alpha * q;
      x_guess = alpha * xg;
      u0x += alpha * ux;
      u0y += alpha * uy;
    }
  }

  // GMRES(kGmresRestart) on the right-preconditioned rows: z with |b - rows(M z)| <= rel_tol b_norm (b_norm:
  // the norm of the right-hand side before the guess), within the solve's budget of iterations; the
  // increment's u in (uzx, uzy). Returns the relative residual.
  double gmres(const Eigen::VectorXd& b, double b_norm, double rel_tol, Eigen::VectorXd& z) {
    const int n = offset[nc];
    Eigen::VectorXd w(n), r(n), v(n), xi(n);
    auto matvec = [&](const Eigen::VectorXd& zz, Eigen::VectorXd& y) {
      precondition(zz, xi);
      to_traction(xi);
      rows(px, py, &xi, false, y);
      ++products;
    };
    double rel = 0;
    const int m = kGmresRestart;
    if (Vbuf.rows() < n) Vbuf.resize(2 * nc, m + 1);
    auto Vk = Vbuf.topRows(n);
    if (static_cast<int>(Ukx.size()) < m + 1) {
      Ukx.resize(static_cast<std::size_t>(m) + 1);
      Uky.resize(static_cast<std::size_t>(m) + 1);
    }
    Eigen::MatrixXd Hm = Eigen::MatrixXd::Zero(m + 1, m);
    Eigen::VectorXd cs(m), sn(m), e(m + 1);
    bool zero = true;  // z = 0: the residual is b, no product needed
    for (;;) {
      if (zero) {
        r = b;
      } else {
        matvec(z, w);
        r = b - w;
        uzx = ux;  // the increment's u, measured
        uzy = uy;
      }
      const double beta = r.norm();
      rel = beta / std::max(b_norm, 1e-300);
      if (rel <= rel_tol || gmres_total >= opt.max_stick_iterations) break;
      Vk.col(0) = r / beta;
      e.setZero();
      e(0) = beta;
      Hm.setZero();
      int k = 0;
      while (k < m && gmres_total < opt.max_stick_iterations) {
        v = Vk.col(k);
        matvec(v, w);
        ++gmres_total;
        Ukx[k] = ux;
        Uky[k] = uy;
        for (int i = 0; i <= k; ++i) {  // modified Gram-Schmidt
          Hm(i, k) = Vk.col(i).dot(w);
          w -= Hm(i, k) * Vk.col(i);
        }
        Hm(k + 1, k) = w.norm();
        if (Hm(k + 1, k) > 0) Vk.col(k + 1) = w / Hm(k + 1, k);
        for (int i = 0; i < k; ++i) {  // Givens rotations
          const double t = cs(i) * Hm(i, k) + sn(i) * Hm(i + 1, k);
          Hm(i + 1, k) = -sn(i) * Hm(i, k) + cs(i) * Hm(i + 1, k);
          Hm(i, k) = t;
        }
        const double den = std::hypot(Hm(k, k), Hm(k + 1, k));
        cs(k) = Hm(k, k) / den;
        sn(k) = Hm(k + 1, k) / den;
        Hm(k, k) = den;
        Hm(k + 1, k) = 0;
        e(k + 1) = -sn(k) * e(k);
        e(k) = cs(k) * e(k);
        ++k;
        if (std::abs(e(k)) <= 0.5 * rel_tol * b_norm || !(den > 0)) break;
      }
      const Eigen::VectorXd yk = Hm.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(e.head(k));
      z += Vk.leftCols(k) * yk;
      for (int i = 0; i < k; ++i) {
        uzx += yk(i) * Ukx[i];
        uzy += yk(i) * Uky[i];
      }
      zero = false;
      // the cycle's own residual estimate (exact in exact arithmetic) met the tolerance: done, without
      // the product that would measure it again (the Newton iteration measures its own residual)
      if (std::abs(e(k)) <= 0.5 * rel_tol * b_norm) {
        rel = std::abs(e(k)) / b_norm;
        break;
      }
    }
    return rel;
  }

  // one Newton step from (tx, ty): solves for the increment to rel_tol, starting along the guess
  // (gx, gy) where given; returns the relative residual
  double newton_step(double rel_tol, const Eigen::ArrayXXd* gx = nullptr, const Eigen::ArrayXXd* gy = nullptr) {
    index_unknowns();
    const int n = offset[nc];
    Eigen::VectorXd x0, b;
    newton_rhs(x0, b);
    const double b_norm = b.norm();
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd x_guess;
    if (gx && n > 0 && b_norm > 0) start_from_guess(*gx, *gy, b, x_guess);
    const double rel = n > 0 && b_norm > 0 ? gmres(b, b_norm, rel_tol, z) : 0.0;
    // the new iterate: the increment M z on the start and the guess, its u by linearity
    Eigen::VectorXd xi(n);
    precondition(z, xi);
    xi += x0;
    if (x_guess.size() == n) xi += x_guess;
    to_traction(xi);
    ux = u0x + uzx;
    uy = u0y + uzy;
    u_current = true;
    for (int c = 0; c < nc; ++c) {
      const int q = cells[c];
      TX[q] = px.data()[q] + (slip[c] ? -Gb[q] * ex[c] : 0.0);
      TY[q] = py.data()[q] + (slip[c] ? -Gb[q] * ey[c] : 0.0);
    }
    return rel;
  }

  bool exceeds_bound(double margin) const {
    for (const int q : cells)
      if (TX[q] * TX[q] + TY[q] * TY[q] > sq(Gb[q] * (1 + margin))) return true;
    return false;
  }

  // The start. Warm: the given tractions (clipped later), and their product where it holds. Cold: all
  // stick (the linear theory when mu is large), to kLooseStickTol, and on to stick_tol unless the
  // tractions already exceed the bound by more than that solve's error. Returns GMRES's relative residual
  // (0 for a warm start); admissible: the cold start's tractions are within the bound everywhere.
  double start_iterate(bool& admissible) {
    double rel = 0;
    admissible = false;
    const Eigen::ArrayXXd* start_tx = setup.start.tau_x;
    const Eigen::ArrayXXd* start_ty = setup.start.tau_y;
    if (start_tx) {  // a warm start: the given tractions (clipped below), straight to Newton
      for (const int q : cells) {
        TX[q] = (*start_tx)(q % nxe, q / nxe);
        TY[q] = (*start_ty)(q % nxe, q / nxe);
      }
      // their product given (start_ux: A of the start tractions, the previous step's u) holds when
      // every traction of the start is on a cell in contact now (none dropped)
      const Eigen::ArrayXXd* start_ux = setup.start.u_x;
      const Eigen::ArrayXXd* start_uy = setup.start.u_y;
      if (start_ux && start_uy && start_ux->rows() == nxe && start_ux->cols() == ny && start_uy->rows() == nxe &&
          start_uy->cols() == ny) {
        bool kept = true;
        for (int j = 0; j < ny && kept; ++j)
          for (int i = 0; i < nx; ++i)
            if (((*start_tx)(i, j) != 0 || (*start_ty)(i, j) != 0) && !(patch.pressure_Pa(i, j) > 0)) {
              kept = false;
              break;
            }
        if (kept) {
          ux = *start_ux;
          uy = *start_uy;
          u_current = true;
        }
      }
    } else {
      rel = newton_step(kLooseStickTol);
      if (rel <= kLooseStickTol && !exceeds_bound(kLooseStickMargin)) rel = newton_step(opt.stick_tol);
      admissible = !exceeds_bound(0);
    }
    return rel;
  }

  // the all-stick GMRES did not reach its tolerance: the status says so; returns the residual
  double stick_not_converged(double rel) {
    SolveStatus& status = out.status;
    status.kind = std::isfinite(rel) ? SolveStatus::Kind::MaxIterations : SolveStatus::Kind::Failed;
    status.message = fmt::format("all-stick GMRES: relative residual {:.2g} > tol {:.3g} after {} iterations", rel,
                                 opt.stick_tol, gmres_total);
    return rel;
  }

  // the all-stick tractions are within the bound: the solution (full stick); returns the residual
  double full_stick(double rel) {
    if (!u_current) {
      A.apply(tx, ty, ux, uy);
      ++products;
    }
    for (const int q : cells) state.data()[q] = 1;
    SolveStatus& status = out.status;
    status.kind = SolveStatus::Kind::Converged;
    status.message = fmt::format("full stick: GMRES relative residual {:.2g} <= {:.3g} after {} iterations", rel,
                                 opt.stick_tol, gmres_total);
    return rel;
  }

  // Every cell's own Coulomb problem with u = A tau fresh: the stick and slip sets, the slip directions
  // and |s|, the cells' own tractions in (sol_x, sol_y); returns the fixed-point residual (exact.h). On
  // the first iteration of a start with its sets (first_on_start_sets), the Newton step takes those sets:
  // a slip cell along its previous traction (on the bound), a stick cell stick; the cells' own solutions
  // then only measure the residual.
  double classify_cells(bool first_on_start_sets, Eigen::ArrayXXd& sol_x, Eigen::ArrayXXd& sol_y) {
    double change = 0, scale = 0;
    for (int c = 0; c < nc; ++c) {
      const int q = cells[c];
      const double rx = WX[q] + (UX[q] - upstream * UX[q + 1]) / dx - bx * TX[q];
      const double ry = WY[q] + (UY[q] - upstream * UY[q + 1]) / dx - by * TY[q];
      double sx, sy;
      const bool stick = element_solve(rx, ry, bx, by, Gb[q], sx, sy);
      state.data()[q] = stick ? 1 : 2;
      // squares here, the roots after the loop
      change = std::max(change, sq(sx - TX[q]) + sq(sy - TY[q]));
      scale = std::max({scale, TX[q] * TX[q] + TY[q] * TY[q], sx * sx + sy * sy});  // a zero start: the solution's
      slip[c] = !stick;
      sol_x.data()[q] = sx;
      sol_y.data()[q] = sy;
      if (!stick) {  // the slip of the element solution: s = r + B tau, along -tau
        const double vx = rx + bx * sx, vy = ry + by * sy;
        sabs[c] = std::sqrt(vx * vx + vy * vy);
        const double en = std::sqrt(sx * sx + sy * sy);
        ex[c] = -sx / en;
        ey[c] = -sy / en;
      }
      if (first_on_start_sets) {
        const int i = q % nxe, j = q / nxe;
        const bool was_slip = (*setup.start.state)(i, j) == 2;
        const double t = std::hypot(TX[q], TY[q]);
        if (was_slip && t > 0) {
          if (stick) sabs[c] = 0;  // a cell that sticks by its own solution: no slip across e asked
          slip[c] = 1;
          ex[c] = -TX[q] / t;
          ey[c] = -TY[q] / t;
          sol_x.data()[q] = -Gb[q] * ex[c];
          sol_y.data()[q] = -Gb[q] * ey[c];
        } else {
          slip[c] = 0;
        }
      }
    }
    change = std::sqrt(change);
    scale = std::sqrt(scale);
    return scale > 0 ? change / scale : change;
  }

  // tractions above the bound by more than `rounding` (a share of it) onto it
  void clip_to_bound(double rounding) {
    for (const int q : cells) {
      const double t = std::hypot(TX[q], TY[q]);
      if (t > Gb[q] * (1 + rounding)) {
        TX[q] *= Gb[q] / t;
        TY[q] *= Gb[q] / t;
        u_current = false;
      }
    }
  }

  // Friction: semi-smooth Newton on the active sets. Each iteration: every cell's own Coulomb problem
  // with u = A tau fresh gives the residual, the stick and slip sets, the slip tractions and directions;
  // then one Newton step. Returns the residual; outer: the Newton iterations.
  double friction(int& outer) {
    SolveStatus& status = out.status;
    double residual = 0;
    clip_to_bound(kBoundRounding);  // the stick tractions clipped to the bound start it
    // backtracking: a Newton step that raised the residual is halved towards the last accepted
    // tractions, up to kMaxHalvings times (semi-smooth Newton can cycle between active sets)
    Eigen::ArrayXXd acc_x = tx, acc_y = ty, sol_x = tx, sol_y = ty, acc_ux, acc_uy;
    const Eigen::ArrayXXi* start_state = setup.start.state;
    const bool use_start_state = setup.start.tau_x && start_state && start_state->rows() == nx &&
                                 start_state->cols() == ny;
    const Eigen::ArrayXXd* guess_x = setup.start.dtau_x;
    const Eigen::ArrayXXd* guess_y = setup.start.dtau_y;
    double accepted_residual = std::numeric_limits<double>::infinity();
    int halvings = 0;
    for (;; ++outer) {
      if (!u_current) {
        A.apply(tx, ty, ux, uy);
        ++products;
        u_current = true;
      }
      residual = classify_cells(outer == 0 && use_start_state, sol_x, sol_y);
      if (!std::isfinite(residual)) {
        status.kind = SolveStatus::Kind::Failed;
        status.message = fmt::format("residual is {} after {} Newton iterations", residual, outer);
        break;
      }
      if (residual <= opt.tol) {
        status.kind = SolveStatus::Kind::Converged;
        status.message = fmt::format("residual {:.2g} <= tol {:.3g} after {} Newton iterations ({} GMRES)",
                                     residual, opt.tol, outer, gmres_total);
        break;
      }
      if (outer >= opt.max_iterations || gmres_total >= opt.max_stick_iterations) {
        status.kind = SolveStatus::Kind::MaxIterations;
        status.message = fmt::format("residual {:.2g} > tol {:.3g} after {} Newton iterations ({} GMRES)",
                                     residual, opt.tol, outer, gmres_total);
        break;
      }
      if (residual > accepted_residual && halvings < kMaxHalvings) {
        ++halvings;
        tx = 0.5 * (tx + acc_x);
        ty = 0.5 * (ty + acc_y);
        ux = 0.5 * (ux + acc_ux);  // A is linear: the halved tractions' u
        uy = 0.5 * (uy + acc_uy);
        continue;
      }
      halvings = 0;
      accepted_residual = residual;
      acc_x = tx;
      acc_y = ty;
      acc_ux = ux;
      acc_uy = uy;
      for (int c = 0; c < nc; ++c)
        if (slip[c]) {
          TX[cells[c]] = sol_x.data()[cells[c]];
          TY[cells[c]] = sol_y.data()[cells[c]];
        }
      if (outer == 0 && guess_x && guess_x->rows() == nxe && guess_x->cols() == ny && guess_y->rows() == nxe &&
          guess_y->cols() == ny)
        newton_step(forcing(residual, opt), guess_x, guess_y);
      else
        newton_step(forcing(residual, opt));
    }
    // the iterate obeys the bound to the tolerance only (a slip cell's Newton traction is
    // -g e + tau_t t, |tau| = g sqrt(1 + (tau_t/g)^2)): onto the bound, a change within the tolerance
    clip_to_bound(0);
    if (!u_current) {
      A.apply(tx, ty, ux, uy);
      ++products;
    }
    return residual;
  }

  // The dissipated power (docs/exact-theory.md §4, "Dissipation"): the material now at x_i was at
  // x_i + theta dx at the previous step, with the traction tau_prev there (linear between the cells, as its
  // displacement u_prev); over the step it slipped by S_i = w(x_i + theta dx/2) dq + u_i - u_prev, the rigid
  // slip at its mid position, under the mean traction (tau_prev + tau_i)/2 (the trapezoidal rule). Per cell
  //   D_i = -(tau_prev + tau_i)/2 . S_i/dt,
  // on the contact cells and on the cells behind them that material left (tau_i = 0, tau_prev != 0: the release
  // of its traction), the latter added to the cell upstream that it left when that one is in contact (steady:
  // the strip's trailing cell). Steady rolling pairs the solution with itself (theta 1). The sum over the
  // grid is the work of the rigid slip minus the change of the elastic energy sum tau . A tau dA/2 (A symmetric
  // and commuting with the shift by one cell; steady: the creep work exactly); the first row behind the grid
  // (row -1) needs u there: one product of the tractions shifted by one row, when any lies on row 0.
  void trapezoidal_power(const Creepages& creepages, double V) {
    TangentialSolution& s = out.fields;
    const ExactPowerHistory self{&s.tau_x_Pa, &s.tau_y_Pa, &ux, &uy, &out.u_behind_x_m, &out.u_behind_y_m, 1.0};
    const ExactPowerHistory& h = transient ? setup.history : self;
    const double theta = h.theta, creep_scale = setup.transport.creep_scale;
    const bool prev = h.tau_x != nullptr;
    const bool prev_row0 = prev && theta > 0 && ((h.tau_x->row(0) != 0) || (h.tau_y->row(0) != 0)).any();
    const bool now_row0 = ((tx.row(0) != 0) || (ty.row(0) != 0)).any();
    if (now_row0 || prev_row0) {  // u on row -1: A of the tractions moved one row up, its row 0
      Eigen::ArrayXXd sx = Eigen::ArrayXXd::Zero(nxe, ny), sy = sx, vx, vy;
      sx.bottomRows(nx) = tx.topRows(nx);
      sy.bottomRows(nx) = ty.topRows(nx);
      A.apply(sx, sy, vx, vy);
      ++products;
      out.u_behind_x_m = vx.row(0).transpose();
      out.u_behind_y_m = vy.row(0).transpose();
    } else {
      out.u_behind_x_m.resize(0);
      out.u_behind_y_m.resize(0);
    }
    if (prev_row0 && (h.u_behind_x->size() != ny || h.u_behind_y->size() != ny))
      throw std::logic_error(std::string(mode) + ": the previous step's displacement behind the grid is missing");
    const Grid& grid = patch.grid;
    const bool offsets = patch.strip_xi_offset.size() == ny;
    s.power_W_per_m2.setZero();
    s.strip_power_W_per_m.setZero();
    // the previous step's traction and displacement at row i (-1 ... nx), zero beyond its rows
    auto prev_tau = [&](const Eigen::ArrayXXd* t, int i, int j) { return prev && i >= 0 && i < nx ? (*t)(i, j) : 0.0; };
    auto prev_u = [&](const Eigen::ArrayXXd* u, const Eigen::ArrayXd* ub, int i, int j) {
      if (!prev) return 0.0;
      return i < 0 ? (ub->size() == ny ? (*ub)(j) : 0.0) : (*u)(i, j);
    };
    for (int j = 0; j < ny; ++j) {
      const double xi_j = creepages.xi + (offsets ? patch.strip_xi_offset(j) : 0.0);
      for (int i = -1; i < nx; ++i) {
        const double tpx = (1 - theta) * prev_tau(h.tau_x, i, j) + theta * prev_tau(h.tau_x, i + 1, j);
        const double tpy = (1 - theta) * prev_tau(h.tau_y, i, j) + theta * prev_tau(h.tau_y, i + 1, j);
        const double tnx = i >= 0 ? tx(i, j) : 0.0, tny = i >= 0 ? ty(i, j) : 0.0;
        if (tpx == 0 && tpy == 0 && tnx == 0 && tny == 0) continue;
        const double upx = (1 - theta) * prev_u(h.u_x, h.u_behind_x, i, j) + theta * prev_u(h.u_x, h.u_behind_x, i + 1, j);
        const double upy = (1 - theta) * prev_u(h.u_y, h.u_behind_y, i, j) + theta * prev_u(h.u_y, h.u_behind_y, i + 1, j);
        const double unx = i >= 0 ? ux(i, j) : out.u_behind_x_m(j), uny = i >= 0 ? uy(i, j) : out.u_behind_y_m(j);
        const double x_mid = (i >= 0 ? grid.x_m(i) : grid.x_m(0) - dx) + theta * dx / 2;
        const double Sx = V * (creep_scale * (xi_j - creepages.phi_per_m * grid.y_m(j)) + (unx - upx) / dx);
        const double Sy = V * (creep_scale * (creepages.eta + creepages.phi_per_m * x_mid) + (uny - upy) / dx);
        const double D = -0.5 * ((tpx + tnx) * Sx + (tpy + tny) * Sy);
        auto contact_cell = [&](int k) { return k >= 0 && k < nx && patch.pressure_Pa(k, j) > 0; };
        const int cell = contact_cell(i) ? i : (i + 1 < nx && (i < 0 || contact_cell(i + 1))) ? i + 1 : std::max(i, 0);
        s.power_W_per_m2(cell, j) += D;
        s.strip_power_W_per_m(j) += D * dx;
      }
    }
  }

  // the solution as the fast solvers report it: tractions, slip velocities at speed V, power, forces
  void report(const Creepages& creepages, double V) {
    const Grid& grid = patch.grid;
    const double creep_scale = setup.transport.creep_scale;
    TangentialSolution& s = out.fields;
    s.tau_x_Pa = tx.topRows(nx);
    s.tau_y_Pa = ty.topRows(nx);
    s.slip_x_m_per_s = Eigen::ArrayXXd::Zero(nx, ny);
    s.slip_y_m_per_s = Eigen::ArrayXXd::Zero(nx, ny);
    s.power_W_per_m2 = Eigen::ArrayXXd::Zero(nx, ny);
    s.state = state.topRows(nx);
    s.strip_power_W_per_m = Eigen::ArrayXd::Zero(ny);
    s.strip_creep_power_W_per_m = Eigen::ArrayXd::Zero(ny);
    s.strip_trailing_W_per_m = Eigen::ArrayXd::Zero(ny);
    s.strip_force_x_N_per_m = Eigen::ArrayXd::Zero(ny);
    s.strip_force_y_N_per_m = Eigen::ArrayXd::Zero(ny);
    double stick = 0;
    out.grid_strip_power_W_per_m = Eigen::ArrayXd::Zero(ny);
    for (const int q : cells) {
      const int i = q % nxe, j = q / nxe;
      const double sx = V * (WX[q] + (UX[q] - upstream * UX[q + 1]) / dx);
      const double sy = V * (WY[q] + (UY[q] - upstream * UY[q + 1]) / dx);
      s.slip_x_m_per_s(i, j) = sx;
      s.slip_y_m_per_s(i, j) = sy;
      out.grid_strip_power_W_per_m(j) += -(TX[q] * sx + TY[q] * sy) * dx;
      s.strip_creep_power_W_per_m(j) += -V * (TX[q] * RX[q] + TY[q] * RY[q]) * dx;
      s.strip_force_x_N_per_m(j) += TX[q] * dx;
      s.strip_force_y_N_per_m(j) += TY[q] * dx;
      s.Mz_N_m += (grid.x_m(i) * TY[q] - grid.y_m(j) * TX[q]) * dx * dy;
      if (state.data()[q] == 1) stick += 1;
    }
    s.Fx_N = s.strip_force_x_N_per_m.sum() * dy;
    s.Fy_N = s.strip_force_y_N_per_m.sum() * dy;
    out.grid_power_W = out.grid_strip_power_W_per_m.sum() * dy;
    trapezoidal_power(creepages, V);
    s.power_W = s.strip_power_W_per_m.sum() * dy;
    s.stick_fraction = stick / nc;
    double xi_Fx = creepages.xi * s.Fx_N;
    if (patch.strip_xi_offset.size() == ny) xi_Fx += (patch.strip_xi_offset * s.strip_force_x_N_per_m).sum() * dy;
    s.creep_work_W = creep_scale * V * (xi_Fx + creepages.eta * s.Fy_N + creepages.phi_per_m * s.Mz_N_m);
    out.u_x_m = ux;
    out.u_y_m = uy;
    if (setup.start.tau_x) {
      out.dtau_x_Pa = Eigen::ArrayXXd::Zero(nxe, ny);
      out.dtau_y_Pa = out.dtau_x_Pa;
      out.dtau_x_Pa.topRows(nx) = s.tau_x_Pa - *setup.start.tau_x;
      out.dtau_y_Pa.topRows(nx) = s.tau_y_Pa - *setup.start.tau_y;
    }
  }
};

// Steady rolling or one transient step (setup.transport) of the discrete problem of exact.h, from
// the all-stick start or a warm one (setup.start): the start, then friction where the start's
// tractions exceed the bound, then the solution as the fast solvers report it.
ExactSolution solve_exact(const ContactPatch& patch, double G_Pa, double nu, const Creepages& creepages, double mu,
                          double speed_m_per_s, const ExactOptions& opt, const ExactSolveSetup& setup = {}) {
  const char* const mode = mode_of(setup);
  check_exact_inputs(patch, G_Pa, nu, creepages, mu, speed_m_per_s, opt, mode);
  ExactSolve s(patch, G_Pa, nu, creepages, mu, opt, setup, mode);
  const bool warm = setup.start.tau_x != nullptr;

  bool admissible = false;
  const double rel = s.start_iterate(admissible);
  s.out.stick_iterations = s.gmres_total;
  double residual = 0;
  int outer = 0;
  if (!warm && !(rel <= (admissible ? opt.stick_tol : kLooseStickTol)))
    residual = s.stick_not_converged(rel);
  else if (admissible)
    residual = s.full_stick(rel);
  else
    residual = s.friction(outer);
  ExactSolution& out = s.out;
  SolveStatus& status = out.status;
  out.products = s.products;
  out.active_set_iterations = outer;
  status.iterations = s.gmres_total;
  status.residual = residual;

  s.report(creepages, speed_m_per_s);
  out.products = s.products;  // with the power's product of the row behind the grid, when it took one
  const TangentialSolution& f = out.fields;
  spdlog::debug("{} ({} x {}): {}; Fx {:.6e} N, Fy {:.6e} N, Mz {:.6e} N m, P {:.6e} W, stick {:.3f}", mode,
                s.nx, s.ny, status.message, f.Fx_N, f.Fy_N, f.Mz_N_m, f.power_W, f.stick_fraction);
  if (!status.converged() && setup.warn_unconverged)
    spdlog::warn("{} ({} x {}): not converged: {}", mode, s.nx, s.ny, status.message);
  return std::move(out);
}

}  // namespace

namespace {

// Plane strain from this many cells on: the steady solve starts from the solution on half the cells
// (grid sequencing). From the clipped all-stick tractions the Newton iteration needs ever more
// backtracking steps as the grid is refined near saturation (at xi/xi_c = 0.75: 185 iterations at
// 800 cells, none converging within 200 at 1600 and 3200; docs/exact-theory.md §6): each full step
// flips the traction of the cells near the stick zone's ends and the halvings towards the last
// accepted iterate advance by 1/16 of a step. From the coarse grid's solution the sets are right but
// for a few cells at the zone's ends.
constexpr int kNestedPlaneStrainCells = 400;

// the patch on half the cells along x (pairs of cells merged: the mean pressure of a pair)
ContactPatch coarsened_along_x(const ContactPatch& p) {
  ContactPatch c = p;
  const Grid& g = p.grid;
  c.grid = g;
  c.grid.nx = g.nx / 2;
  c.grid.dx_m = 2 * g.dx_m;
  c.grid.x_m = Eigen::ArrayXd(c.grid.nx);
  c.pressure_Pa = Eigen::ArrayXXd(c.grid.nx, g.ny);
  for (int i = 0; i < c.grid.nx; ++i) {
    c.grid.x_m(i) = 0.5 * (g.x_m(2 * i) + g.x_m(2 * i + 1));
    c.pressure_Pa.row(i) = 0.5 * (p.pressure_Pa.row(2 * i) + p.pressure_Pa.row(2 * i + 1));
  }
  c.pressure_moment_Pa_m.resize(0, 0);
  c.edge_pressure_Pa.resize(0, 0);
  return c;
}

// The 3-D steady solve from this many cells a side on (both even), when it has not converged within
// kColdNewtonBudget Newton iterations from the clipped all-stick tractions, starts again from its
// solution on half the cells each way. From the all-stick start the Newton iteration crawls near
// saturation as in plane strain: pure xi at 90 % of saturation on a/b = 3 took 33, 30, 125 Newton
// iterations at 40, 80, 160 cells a side (12 s at 160; docs/exact-theory.md §3). Where the cold
// start converges quickly (the paper's contact: 3 to 5) it is kept: from the half grid's solution
// the paper's 80 x 80 took 8.
constexpr int kNestedCells = 40;
constexpr int kColdNewtonBudget = 12;
// A steady solve warm-started from a previous solution (solve_exact_steady's start) that has not
// converged within this many Newton iterations starts again cold. On the paper's contact at 80 x 80
// (tol 1e-4) a start from the solution at 0.1 % more load and xi converges in 1 (14 GMRES iterations
// where the cold start takes 84); from 1 % more the semi-smooth Newton iteration stalls near the
// start's residual (0.004: each full step raises it tenfold, the halvings bring it back), so the
// attempt is cut short.
constexpr int kWarmNewtonBudget = 3;

// a coarse field (nx/2 x ny) on the fine cells, linear between the coarse cell centres (constant
// beyond the first and last)
Eigen::ArrayXXd prolonged_along_x(const Eigen::ArrayXXd& c, int nx) {
  Eigen::ArrayXXd f(nx, c.cols());
  const int nc = static_cast<int>(c.rows());
  for (int k = 0; k < nc; ++k) {
    f.row(2 * k) = k > 0 ? (0.75 * c.row(k) + 0.25 * c.row(k - 1)).eval() : c.row(k).eval();
    f.row(2 * k + 1) = k + 1 < nc ? (0.75 * c.row(k) + 0.25 * c.row(k + 1)).eval() : c.row(k).eval();
  }
  return f;
}

}  // namespace

ContactPatch halved_patch(const ContactPatch& p) {
  const Grid& g = p.grid;
  if (g.nx < 4 || g.ny < 4 || g.nx % 2 != 0 || g.ny % 2 != 0)
    throw std::invalid_argument("the patch on half the cells needs an even number of cells each way, at least 4 (" +
                                std::to_string(g.nx) + " x " + std::to_string(g.ny) + ")");
  ContactPatch c = coarsened_along_x(p);
  const int ny = g.ny / 2;
  c.grid.ny = ny;
  c.grid.dy_m = 2 * g.dy_m;
  c.grid.y_m = Eigen::ArrayXd(ny);
  c.pressure_Pa = Eigen::ArrayXXd(c.grid.nx, ny);
  for (int j = 0; j < ny; ++j) {
    c.grid.y_m(j) = 0.5 * (g.y_m(2 * j) + g.y_m(2 * j + 1));
    for (int i = 0; i < c.grid.nx; ++i)  // the mean of the 2 x 2 block (the block's load)
      c.pressure_Pa(i, j) = 0.25 * (p.pressure_Pa(2 * i, 2 * j) + p.pressure_Pa(2 * i + 1, 2 * j) +
                                    p.pressure_Pa(2 * i, 2 * j + 1) + p.pressure_Pa(2 * i + 1, 2 * j + 1));
  }
  if (p.strip_xi_offset.size() == g.ny) {
    c.strip_xi_offset = Eigen::ArrayXd(ny);
    for (int j = 0; j < ny; ++j) c.strip_xi_offset(j) = 0.5 * (p.strip_xi_offset(2 * j) + p.strip_xi_offset(2 * j + 1));
  }
  c.half_length_m.resize(0);
  c.strip_peak_Pa.resize(0);
  return c;
}

ExactSolution solve_exact_steady(const ContactPatch& patch, double G_Pa, double nu, const Creepages& creepages,
                                 double mu, double speed_m_per_s, const ExactOptions& opt, const ExactSolution* start) {
  const int nx = patch.grid.nx, ny = patch.grid.ny;
  if (start && start->fields.tau_x_Pa.rows() == nx && start->fields.tau_x_Pa.cols() == ny &&
      start->fields.tau_y_Pa.rows() == nx && start->fields.tau_y_Pa.cols() == ny && start->fields.state.rows() == nx &&
      start->fields.state.cols() == ny && start->fields.tau_x_Pa.allFinite() && start->fields.tau_y_Pa.allFinite()) {
    // a warm start: the start's tractions and its stick and slip sets (the first Newton step's), not its
    // u (its grid spacing or constants may differ); within kWarmNewtonBudget Newton iterations, else cold
    ExactSolveSetup warm;
    warm.start.tau_x = &start->fields.tau_x_Pa;
    warm.start.tau_y = &start->fields.tau_y_Pa;
    warm.start.state = &start->fields.state;
    warm.warn_unconverged = false;
    ExactOptions budget = opt;
    budget.max_iterations = std::min(opt.max_iterations, kWarmNewtonBudget);
    ExactSolution s = solve_exact(patch, G_Pa, nu, creepages, mu, speed_m_per_s, budget, warm);
    if (s.status.converged()) {
      s.dtau_x_Pa.resize(0, 0);  // a steady solve reports no change
      s.dtau_y_Pa.resize(0, 0);
      return s;
    }
  }
  if (!opt.plane_strain && nx >= kNestedCells && ny >= kNestedCells && nx % 2 == 0 && ny % 2 == 0 &&
      opt.max_iterations > kColdNewtonBudget && patch.pressure_Pa.rows() == nx && patch.pressure_Pa.cols() == ny &&
      patch.grid.x_m.size() == nx && patch.grid.y_m.size() == ny && patch.pressure_Pa.allFinite() &&
      (patch.pressure_Pa >= 0).all() && (patch.strip_xi_offset.size() == 0 || patch.strip_xi_offset.size() == ny)) {
    ExactOptions cold = opt;
    cold.max_iterations = kColdNewtonBudget;
    ExactSolveSetup quiet;
    quiet.warn_unconverged = false;
    ExactSolution first = solve_exact(patch, G_Pa, nu, creepages, mu, speed_m_per_s, cold, quiet);
    // converged, or stopped by the GMRES budget or a failure (which the restart would not mend)
    if (first.status.converged() || first.active_set_iterations < kColdNewtonBudget) {
      if (!first.status.converged())
        spdlog::warn("exact steady ({} x {}): not converged: {}", nx, ny, first.status.message);
      return first;
    }
    const ExactSolution coarse = solve_exact_steady(halved_patch(patch), G_Pa, nu, creepages, mu, speed_m_per_s, opt);
    if (coarse.status.converged()) {
      // prolonged along x, then along y (the transposed field along its rows)
      const Eigen::ArrayXXd tx =
          prolonged_along_x(prolonged_along_x(coarse.fields.tau_x_Pa, nx).transpose().eval(), ny).transpose();
      const Eigen::ArrayXXd ty =
          prolonged_along_x(prolonged_along_x(coarse.fields.tau_y_Pa, nx).transpose().eval(), ny).transpose();
      ExactSolution s = solve_exact(patch, G_Pa, nu, creepages, mu, speed_m_per_s, opt, tractions_start(tx, ty));
      s.status.message += fmt::format(" (from the {} x {} solution after {} Newton iterations from all stick)", nx / 2,
                                      ny / 2, kColdNewtonBudget);
      return s;
    }
  }
  if (opt.plane_strain && nx >= kNestedPlaneStrainCells && nx % 2 == 0 && patch.pressure_Pa.rows() == nx &&
      patch.grid.x_m.size() == nx) {
    const ExactSolution coarse =
        solve_exact_steady(coarsened_along_x(patch), G_Pa, nu, creepages, mu, speed_m_per_s, opt);
    if (coarse.status.converged()) {
      const Eigen::ArrayXXd tx = prolonged_along_x(coarse.fields.tau_x_Pa, nx);
      const Eigen::ArrayXXd ty = prolonged_along_x(coarse.fields.tau_y_Pa, nx);
      ExactSolution s = solve_exact(patch, G_Pa, nu, creepages, mu, speed_m_per_s, opt, tractions_start(tx, ty));
      s.status.message += fmt::format(" (from the {}-cell solution)", nx / 2);
      return s;
    }
  }
  return solve_exact(patch, G_Pa, nu, creepages, mu, speed_m_per_s, opt);
}

ExactSolution solve_exact_rolling_step(const ContactPatch& patch, double G_Pa, double nu, const Creepages& creepages,
                                       double mu, double speed_m_per_s, const ExactSolution* previous,
                                       const ExactOptions& opt) {
  ExactSolveSetup setup;  // rolled by one cell: cell i reads the previous u of cell i + 1
  if (!previous) {
    const Eigen::ArrayXXd rest = Eigen::ArrayXXd::Zero(patch.grid.nx + 1, patch.grid.ny);
    setup.transport = {&rest, &rest, 1, 1.0};
    return solve_exact(patch, G_Pa, nu, creepages, mu, speed_m_per_s, opt, setup);
  }
  setup.transport = {&previous->u_x_m, &previous->u_y_m, 1, 1.0};
  setup.start = warm_start_from(*previous, true);
  setup.history = power_history(previous, 1.0);
  return solve_exact(patch, G_Pa, nu, creepages, mu, speed_m_per_s, opt, setup);
}

ExactSolution solve_exact_shift(const ContactPatch& patch, double G_Pa, double nu, double shift_x_m, double shift_y_m,
                                double mu, double dt_s, const ExactSolution* previous, const ExactOptions& opt) {
  if (!(dt_s > 0) || !std::isfinite(dt_s))
    throw std::invalid_argument(fmt::format("exact shift: dt must be positive and finite, got {} s", dt_s));
  // the rolling step's equations with no transport: w dx = the rigid shift, V = dx/dt
  const double dx = patch.grid.dx_m;
  const Creepages c{shift_x_m / dx, shift_y_m / dx, 0};
  const double V = dx / dt_s;
  ExactSolveSetup setup;  // no transport: cell i reads its own previous u
  if (!previous) {
    const Eigen::ArrayXXd rest = Eigen::ArrayXXd::Zero(patch.grid.nx + 1, patch.grid.ny);
    setup.transport = {&rest, &rest, 0, 1.0};
    return solve_exact(patch, G_Pa, nu, c, mu, V, opt, setup);
  }
  setup.transport = {&previous->u_x_m, &previous->u_y_m, 0, 1.0};
  setup.start = warm_start_from(*previous, false);
  setup.history = power_history(previous, 0.0);
  return solve_exact(patch, G_Pa, nu, c, mu, V, opt, setup);
}


namespace {

// T(F) = (1 - (1 - |F|/(mu Fn))^(2/3)) F/|F| (limit = mu Fn): by Mindlin's relation linear in the shift
// for a circle at nu = 0, T = -shift/scale, and close to linear otherwise, so that the Jacobian
// -I/scale starts Broyden's method well
void mindlin_transform(double fx, double fy, double limit, double& tx, double& ty) {
  const double m = std::hypot(fx, fy);
  if (m == 0) {
    tx = ty = 0;
    return;
  }
  const double h = 1 - std::cbrt(std::pow(std::max(0.0, 1 - m / limit), 2));
  tx = h * fx / m;
  ty = h * fy / m;
}

// the force iteration's status on its best evaluation: a failed shift solve's, converged within tol, or
// MaxIterations (with a spdlog::warn)
void finish_force_status(ExactShiftForce& best, const std::optional<SolveStatus>& failed, double best_error,
                         double tol) {
  SolveStatus& st = best.solution.status;
  if (failed) {
    st = *failed;
    st.message = "a shift solve of the force iteration: " + failed->message;
  } else if (best_error <= tol) {
    st.message = fmt::format("force within {:.2g} N of the target after {} shift solves; last solve: {}", best_error,
                             best.shift_solves, st.message);
  } else {
    st.kind = SolveStatus::Kind::MaxIterations;
    st.message = fmt::format("force {:.3g} N from the target > tol {:.3g} N after {} shift solves", best_error, tol,
                             best.shift_solves);
    spdlog::warn("exact shift: {}", st.message);
  }
}

}  // namespace

ExactShiftForce solve_exact_shift_force(const ContactPatch& patch, double G_Pa, double nu, double Fx_N, double Fy_N,
                                        double mu, double dt_s, const ExactSolution* previous,
                                        const ExactOptions& opt, double force_tol_N) {
  if (!std::isfinite(Fx_N) || !std::isfinite(Fy_N))
    throw std::invalid_argument("exact shift: the prescribed force is not finite");
  if (!(G_Pa > 0) || !(mu > 0) || !std::isfinite(mu))
    throw std::invalid_argument(fmt::format("exact shift: G and mu must be positive, got {} Pa, {}", G_Pa, mu));
  const Grid& grid = patch.grid;
  const double load = patch.pressure_Pa.sum() * grid.dx_m * grid.dy_m;
  const double F_target = std::hypot(Fx_N, Fy_N), limit = mu * load;
  if (!(F_target < limit))
    throw std::invalid_argument(fmt::format("exact shift: the prescribed force {} N is not below mu Fn = {} N (gross "
                                            "sliding: no unique shift)",
                                            F_target, limit));
  const double tol = force_tol_N > 0 ? force_tol_N : 1e-8 * limit;
  // Mindlin's shift at gross sliding for a circle of the patch's mean radius: the scale of the bracket
  const double a_eff = std::sqrt(std::max(patch.a_m * patch.b_m, grid.dx_m * grid.dy_m));
  const double scale = 3 * mu * load * (2 - nu) / (8 * G_Pa * a_eff);

  ExactShiftForce best;
  double best_error = std::numeric_limits<double>::infinity();
  std::optional<ExactSolution> last;  // the last evaluation: the next one's Newton start
  const Eigen::ArrayXXd rest = Eigen::ArrayXXd::Zero(grid.nx + 1, grid.ny);
  const Eigen::ArrayXXd& prev_ux = previous ? previous->u_x_m : rest;
  const Eigen::ArrayXXd& prev_uy = previous ? previous->u_y_m : rest;
  if (previous && (prev_ux.rows() != grid.nx + 1 || prev_ux.cols() != grid.ny))
    throw std::invalid_argument(fmt::format("exact shift: the previous displacement must be {} x {}", grid.nx + 1,
                                            grid.ny));
  const double dx = grid.dx_m;
  std::optional<SolveStatus> failed;
  auto evaluate = [&](double sx, double sy) -> const ExactSolution& {
    const ExactSolution* start = last ? &*last : previous;
    ExactSolveSetup setup;
    setup.mode_name = "exact shift";
    setup.transport = {&prev_ux, &prev_uy, 0, 1.0};
    setup.history = power_history(previous, 0.0);
    if (start) setup.start = warm_start_from(*start, false);
    ExactSolution e = solve_exact(patch, G_Pa, nu, Creepages{sx / dx, sy / dx, 0}, mu, dx / dt_s, opt, setup);
    ++best.shift_solves;
    if (!e.status.converged() && !failed) failed = e.status;
    const double err = std::hypot(e.fields.Fx_N - Fx_N, e.fields.Fy_N - Fy_N);
    if (err < best_error) {
      best_error = err;
      best.solution = e;
      best.shift_x_m = sx;
      best.shift_y_m = sy;
    }
    last = std::move(e);
    return *last;
  };
  // Broyden's method on T(F(shift)) = T(F_target) (mindlin_transform); a step that does not reduce
  // |F - F_target| is halved back towards the best shift.
  auto T = [&](double fx, double fy, double& tx, double& ty) { mindlin_transform(fx, fy, limit, tx, ty); };
  double Tx_t, Ty_t;
  T(Fx_N, Fy_N, Tx_t, Ty_t);
  // J: d T / d shift (2 x 2, row-major)
  double J[4] = {-1 / scale, 0, 0, -1 / scale};
  double sx = 0, sy = 0;  // from rest or from the previous state: no further shift first
  const ExactSolution* e0 = &evaluate(sx, sy);
  double rx, ry;
  T(e0->fields.Fx_N, e0->fields.Fy_N, rx, ry);
  rx -= Tx_t;
  ry -= Ty_t;
  constexpr int kMaxShiftSolves = 40;
  while (!failed && best_error > tol && best.shift_solves < kMaxShiftSolves) {
    const double det = J[0] * J[3] - J[1] * J[2];
    if (!(std::abs(det) > 0) || !std::isfinite(det)) break;
    double px = -(J[3] * rx - J[1] * ry) / det, py = -(-J[2] * rx + J[0] * ry) / det;
    const double err_before = best_error;
    const double bx0 = best.shift_x_m, by0 = best.shift_y_m;
    const ExactSolution* e = &evaluate(sx + px, sy + py);
    for (int h = 0; h < 6 && !failed && best_error >= err_before; ++h) {  // not better: halve the step
      px *= 0.5;
      py *= 0.5;
      e = &evaluate(bx0 + px, by0 + py);
      sx = bx0;
      sy = by0;
    }
    if (failed || best_error >= err_before) break;
    double nrx, nry;
    T(e->fields.Fx_N, e->fields.Fy_N, nrx, nry);
    nrx -= Tx_t;
    nry -= Ty_t;
    // Broyden's update J += (dr - J p) p^T / (p.p)
    const double pp = px * px + py * py;
    if (pp > 0) {
      const double ux = (nrx - rx) - (J[0] * px + J[1] * py), uy = (nry - ry) - (J[2] * px + J[3] * py);
      J[0] += ux * px / pp;
      J[1] += ux * py / pp;
      J[2] += uy * px / pp;
      J[3] += uy * py / pp;
    }
    sx = best.shift_x_m;
    sy = best.shift_y_m;
    rx = nrx;
    ry = nry;
  }
  finish_force_status(best, failed, best_error, tol);
  return best;
}

ExactSolution solve_exact_roll(const ContactPatch& patch, double G_Pa, double nu, const Creepages& creepages,
                               double mu, double dq_m, double dt_s, const ExactSolution* previous,
                               const ExactOptions& opt) {
  const double dx = patch.grid.dx_m;
  if (!(dt_s > 0) || !std::isfinite(dt_s))
    throw std::invalid_argument(fmt::format("exact roll: dt must be positive and finite, got {} s", dt_s));
  if (!(dq_m >= 0) || !(dq_m <= dx * (1 + 1e-12)))
    throw std::invalid_argument(fmt::format("exact roll: the rolled distance must be in [0, dx = {} m], got {} m", dx,
                                            dq_m));
  const int nx = patch.grid.nx, ny = patch.grid.ny;
  // the previous displacement difference where the material now at x_i was: at x_i + dq, linear
  // between the cells i and i + 1 (theta = dq/dx; theta = 1 is the one-cell step, exactly)
  const double theta = std::min(dq_m / dx, 1.0);
  Eigen::ArrayXXd px = Eigen::ArrayXXd::Zero(nx + 1, ny), py = px;
  if (previous) {
    const Eigen::ArrayXXd& ux = previous->u_x_m;
    const Eigen::ArrayXXd& uy = previous->u_y_m;
    if (ux.rows() != nx + 1 || ux.cols() != ny || uy.rows() != nx + 1 || uy.cols() != ny)
      throw std::invalid_argument(fmt::format("exact roll: the previous displacement must be {} x {}", nx + 1, ny));
    px.topRows(nx) = (1 - theta) * ux.topRows(nx) + theta * ux.bottomRows(nx);
    py.topRows(nx) = (1 - theta) * uy.topRows(nx) + theta * uy.bottomRows(nx);
    px.row(nx) = ux.row(nx);
    py.row(nx) = uy.row(nx);
  }
  // the rolling step's equations per dx (V = dx/dt): rigid slip w dq/dx, the previous field not moved
  // again (prev_offset 0), slip velocities S/dt, creep work V_rolling (xi Fx + eta Fy + phi Mz)
  ExactSolveSetup setup;
  setup.mode_name = "exact rolling step";
  setup.transport = {&px, &py, 0, theta};
  setup.history = power_history(previous, theta);
  if (previous) setup.start = warm_start_from(*previous, true);
  return solve_exact(patch, G_Pa, nu, creepages, mu, dx / dt_s, opt, setup);
}

namespace {

// no cell in contact: no traction, no displacement, every output zero on the grid
ExactSolution no_contact(const Grid& g) {
  ExactSolution e;
  e.fields = no_contact_solution(g);
  e.u_x_m = e.u_y_m = Eigen::ArrayXXd::Zero(g.nx + 1, g.ny);
  e.status.kind = SolveStatus::Kind::Converged;
  e.status.message = "no contact";
  return e;
}

}  // namespace

// a transient run's state counts as steady (skip_steady) when the last step's tractions are within this share
// of mu p_max of the steady solution's
constexpr double kSettledTraction = 1e-3;
// or when the last step changed no traction by more than kStoppedChange mu p_max (it met its tolerance from the
// previous step's tractions: the steps have stopped at their fixed point within their tolerance) and they are
// within kStoppedTraction of the steady solution's (measured: a worn start-stop contact stopped at 1.005e-3 with
// the duty cycle's tol 1e-4)
constexpr double kStoppedTraction = 1e-2;
constexpr double kStoppedChange = 1e-9;

ExactOptions exact_run_options() {
  ExactOptions o;
  o.tol = 1e-6;
  o.stick_tol = 1e-8;
  return o;
}

ExactOptions exact_duty_cycle_options() {
  ExactOptions o;
  o.tol = 1e-4;
  o.stick_tol = 1e-4;
  return o;
}

TransientResult run_exact_transient(const TransientCase& c, const StepObserver& observe, const ExactOptions& opt) {
  const TransientSettings& set = c.settings;
  check_transient_inputs(c);
  if (c.inertia) throw SettingError("", "inertia", "the exact solver's run has no roller inertia (Satran's has)");
  if (set.scheme != TransientScheme::Shift)
    throw SettingError("", "scheme", "the exact solver rolls by steps of dq <= dx (the shift scheme's steps); "
                                     "use scheme: shift");
  const double G = combined_shear_modulus_Pa(c.materials), nu = combined_poisson(c.materials);

  std::optional<ExactSolution> prev;  // the previous step's solution (none: at rest)
  // Steady running skipped (settings.skip_steady, docs/exact-theory.md §7): once the creepages, the load and
  // with them the contact have stayed the same over 2a of rolling (the grid's nx steps), the steady solution
  // of those inputs is solved (once per stretch), and the state counts as settled when the last step's
  // tractions are within kSettledTraction mu p_max of it; the rest of the stretch is then that solution's
  // power times its duration, and the state after it that solution (or, once the steps have stopped changing
  // within their tolerance, within kStoppedTraction of it).
  struct Stretch {
    const ContactPatch* patch = nullptr;
    double load_N = 0;
    Creepages creepages;
    int whole_steps = 0;  // whole steps (dq = dx) in a row with these inputs
    std::optional<ExactSolution> steady;  // solved at V = 1 m/s
  } stretch;
  ShiftSkip skip;
  if (set.skip_steady) {
    skip.settled = [&] {
      if (!prev || !stretch.patch || stretch.whole_steps < stretch.patch->grid.nx) return false;
      if (!stretch.steady) {
        ExactSolution ss = solve_exact_steady(*stretch.patch, G, nu, stretch.creepages, c.mu, 1.0, opt);
        if (!ss.status.converged())
          throw std::runtime_error("exact transient: the steady solve of a stretch to skip did not converge: " +
                                   ss.status.message);
        ss.dtau_x_Pa = Eigen::ArrayXXd::Zero(ss.u_x_m.rows(), ss.u_x_m.cols());  // no change to carry on
        ss.dtau_y_Pa = ss.dtau_x_Pa;
        stretch.steady = std::move(ss);
      }
      const double bound = c.mu * stretch.patch->pressure_Pa.maxCoeff();
      const TangentialSolution& a = prev->fields;
      const TangentialSolution& b = stretch.steady->fields;
      const double off = std::max((a.tau_x_Pa - b.tau_x_Pa).abs().maxCoeff(), (a.tau_y_Pa - b.tau_y_Pa).abs().maxCoeff());
      // a step that met its tolerance at its start changes nothing: the steps have stopped within their
      // tolerance of the fixed point, which can leave them a little further from the steady solve's
      const double change = prev->dtau_x_Pa.size() == 0 ? bound
                                                        : std::max(prev->dtau_x_Pa.abs().maxCoeff(), prev->dtau_y_Pa.abs().maxCoeff());
      return off <= kSettledTraction * bound || (off <= kStoppedTraction * bound && change <= kStoppedChange * bound);
    };
    skip.energy = [&](double span_s, double rolled_m, const TangentialSolution&, Eigen::ArrayXd& strip_J, double& J) {
      const double V = rolled_m / span_s;  // the steady powers are at 1 m/s and proportional to the speed
      strip_J = stretch.steady->fields.strip_power_W_per_m * (V * span_s);
      J = stretch.steady->fields.power_W * V * span_s;
    };
    skip.skipped = [&](double) { prev = *stretch.steady; };
  }
  const TransientResult res = run_shift_steps(
      c, observe,
      [&](const ContactPatch& patch, const ShiftStep& s) {
        ExactSolution e = solve_exact_roll(patch, G, nu, s.creepages, c.mu, s.dq_m, s.dt_s, prev ? &*prev : nullptr, opt);
        if (!e.status.converged())
          throw std::runtime_error(fmt::format("exact transient: step {} (t {:.6g} s) not converged: {}", s.step,
                                               s.t_s + s.dt_s, e.status.message));
        prev = std::move(e);
        if (set.skip_steady) {
          const Creepages& k = s.creepages;
          const bool same = stretch.patch == &patch && stretch.load_N == s.normal_load_N && stretch.creepages.xi == k.xi &&
                            stretch.creepages.eta == k.eta && stretch.creepages.phi_per_m == k.phi_per_m;
          if (!same) stretch = Stretch{&patch, s.normal_load_N, k, 0, std::nullopt};
          stretch.whole_steps = s.dq_m == patch.grid.dx_m ? stretch.whole_steps + 1 : 0;
        }
        return prev->fields;
      },
      [&](const Grid& g) {
        prev = no_contact(g);
        stretch = Stretch{};
      },
      skip);
  spdlog::debug("exact transient: {} steps to t {:.6e} s, q {:.6e} m, dissipated {:.6e} J", res.steps, res.t_end_s,
                res.q_end_m, res.dissipated_J);
  return res;
}

}  // namespace contact
