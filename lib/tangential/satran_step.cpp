// Satran, the transient tangential solver (equations and schemes at the top of satran.h).
//
// Shift step. Node i of a strip receives the material that sat at node i+1 (or entered at the
// leading edge) one step earlier; the interval between them is updated with the steady kernel
// (lib/tangential/strip_march.h), whose integrals are those of the material's path through the interval. With
// rates per rolled distance (w/V = creepages) and dq = dx the interval's dissipated energy is
//   L dq [ -alpha Ix - (eta/L2) Iy - (phi/L3) Ixy + (|tau_hi|^2 - |tau_lo|^2)/2 ],
// and summed over a strip the last term telescopes to E_start - E_end - (L dx/2)|tau(-a)|^2, with
// E = (L dx/2) sum over interior nodes of |tau|^2: the balance of docs/physics.md §4 to rounding.
//
// The shift step, arranged for speed (the same scheme; shift_strip): the intervals of a step form no
// chain, and most of them stick, so a strip's interior intervals take the stick step in SIMD blocks,
// and only those whose stick test fails, and the strip's two end intervals, go through the whole kernel.
//
// Upwind and Lax-Friedrichs steps update the interior nodes from the old values of their neighbours
// (0 outside the contact) and clip to mu p at the node; see explicit_strip for their energy.
#include "lib/tangential/satran.h"
#include "lib/tangential/satran_workspace.h"
#include "lib/errors.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/enum_names.h"
#include "lib/tangential/kalker.h"
#include "lib/tangential/strip_march.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace contact {

namespace {
constexpr EnumTable<TransientScheme, 3> kTransientSchemes = {{{TransientScheme::Shift, "shift"},
                                                             {TransientScheme::Upwind, "upwind"},
                                                             {TransientScheme::LaxFriedrichs, "lax-friedrichs"}}};
constexpr EnumTable<StepScheme, 4> kStepSchemes = {{{StepScheme::Shift, "shift"},
                                                    {StepScheme::Standstill, "standstill"},
                                                    {StepScheme::Upwind, "upwind"},
                                                    {StepScheme::LaxFriedrichs, "lax-friedrichs"}}};
}  // namespace

std::string to_string(TransientScheme scheme) { return enum_name(kTransientSchemes, scheme); }

TransientScheme parse_transient_scheme(const std::string& name) {
  if (const std::optional<TransientScheme> scheme = enum_from_name(kTransientSchemes, name)) return *scheme;
  throw std::invalid_argument("unknown transient scheme '" + name + "' (valid: " + enum_names_list(kTransientSchemes) +
                              ")");
}

std::string to_string(StepScheme scheme) { return enum_name(kStepSchemes, scheme); }

StepScheme step_scheme(TransientScheme scheme, double dq_m, double dx_m) {
  if (scheme == TransientScheme::LaxFriedrichs) return StepScheme::LaxFriedrichs;
  if (scheme == TransientScheme::Upwind) return StepScheme::Upwind;
  return dq_m == dx_m ? StepScheme::Shift : dq_m == 0 ? StepScheme::Standstill : StepScheme::Upwind;
}

TransientState rest_state(const Grid& grid) {
  TransientState s;
  s.nx = grid.nx;
  s.ny = grid.ny;
  s.nodes.assign(static_cast<size_t>(grid.nx + 1) * grid.ny, StripNode{});
  s.mirror_images = true;
  s.lateral_free = true;
  return s;
}

void fill_mirrored_strips(TransientState& s) {
  if (!s.mirror_deferred) return;
  const int n = s.nx + 1;
  for (int j = s.ny - s.ny / 2; j < s.ny; ++j)
    s.nodes.copy(static_cast<size_t>(s.ny - 1 - j) * n, static_cast<size_t>(j) * n, n);
  s.mirror_deferred = false;
}

namespace {
thread_local int t_satran_threads = 0;  // 0: every core

// Helper threads that take chunks of a loop beside the calling thread. The caller takes chunks too and waits
// only for those a helper has claimed, so a helper the scheduler has not woken (a shared machine) costs the
// loop nothing: at worst it runs on the caller alone. A claim names the loop's generation, so a helper that
// wakes late cannot take a chunk of the next loop. Which thread takes which chunk varies; what a chunk
// computes does not.
class StripPool {
  static void pause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }
  // how long a helper spins for the next loop before it sleeps: the serial part between two loops of a
  // run (the sums, the run's bookkeeping, the next step's set-up) takes about 4 us at 320 x 320; the
  // helper may also finish its last chunk a chunk (2 to 7 us) before the caller
  static constexpr std::chrono::microseconds kSpin{10};
  static constexpr unsigned kProbe = 8;

 public:
  explicit StripPool(int helpers) {
    for (int h = 1; h <= helpers; ++h) threads_.emplace_back([this, h] { serve(h); });
  }
  ~StripPool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
  }
  StripPool(const StripPool&) = delete;
  StripPool& operator=(const StripPool&) = delete;

  // body(chunk, worker) for every chunk in [0, chunks); worker 0 is the caller, 1.. the helpers
  template <class Body>
  void run(int chunks, Body&& body) {
    auto call = [](void* b, int chunk, int worker) { (*static_cast<Body*>(b))(chunk, worker); };
    uint32_t gen;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      gen = ++generation_;
      body_ = &body;
      call_ = call;
      chunks_ = chunks;
      finished_.store(0, std::memory_order_relaxed);
      claim_.store(static_cast<uint64_t>(gen) << 32, std::memory_order_release);
      published_.store(gen, std::memory_order_release);
    }
    // a helper still spinning sees published_ change: no system call (sleepers_ counts under mutex_, so a
    // helper that went to sleep before the lock above is counted here)
    if (sleepers_.load(std::memory_order_acquire) > 0) wake_.notify_all();
    work(gen, chunks, &body, call, 0);
    while (finished_.load(std::memory_order_acquire) < chunks) std::this_thread::yield();
  }

 private:
  using Call = void (*)(void*, int, int);
  // claims and runs chunks of generation gen while there are any
  void work(uint32_t gen, int chunks, void* body, Call call, int worker) {
    uint64_t c = claim_.load(std::memory_order_acquire);
    for (;;) {
      if (static_cast<uint32_t>(c >> 32) != gen || static_cast<int>(c & 0xffffffffu) >= chunks) return;
      if (!claim_.compare_exchange_weak(c, c + 1, std::memory_order_acq_rel)) continue;
      call(body, static_cast<int>(c & 0xffffffffu), worker);
      finished_.fetch_add(1, std::memory_order_acq_rel);
      c = claim_.load(std::memory_order_acquire);
    }
  }
  void serve(int worker) {
    uint32_t seen = 0;
    bool spin = true;
    unsigned loops = 0;
    for (;;) {
      // the next loop, first spinning for kSpin (the serial part between two loops is shorter: waking a
      // sleeping helper costs the caller a system call and the helper tens of microseconds), then asleep.
      // A pause, not a yield, and only while the loops came within kSpin (tried again every kProbe loops):
      // on a loaded machine (the caller off its core between loops) a spinning or yielding helper is off its
      // core in turn when the loop comes, and not woken; measured, the loops then ran slower than with a
      // helper that sleeps at once.
      const auto wait_start = std::chrono::steady_clock::now();
      const auto spin_end = wait_start + kSpin;
      for (int n = 0; spin && published_.load(std::memory_order_acquire) == seen; ++n) {
        if ((n & 15) == 15 && std::chrono::steady_clock::now() > spin_end) break;
        pause();
      }
      uint32_t gen;
      int chunks;
      void* body;
      Call call;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        sleepers_.fetch_add(1, std::memory_order_acq_rel);
        wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
        sleepers_.fetch_sub(1, std::memory_order_acq_rel);
        if (stop_) return;
        spin = std::chrono::steady_clock::now() - wait_start < kSpin || ++loops % kProbe == 0;
        gen = seen = generation_;
        chunks = chunks_;
        body = body_;
        call = call_;
      }
      work(gen, chunks, body, call, worker);
    }
  }

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  uint32_t generation_ = 0;  // under mutex_
  int chunks_ = 0;
  void* body_ = nullptr;
  Call call_ = nullptr;
  std::atomic<uint32_t> published_{0};  // generation_, read without the lock by a spinning helper
  std::atomic<int> sleepers_{0};        // helpers waiting on wake_ (changed under mutex_)
  std::atomic<uint64_t> claim_{0};  // generation << 32 | next chunk
  std::atomic<int> finished_{0};
};
}  // namespace

void set_satran_threads(int threads) { t_satran_threads = std::max(0, threads); }

int satran_threads() {
  return t_satran_threads > 0 ? t_satran_threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

namespace {

bool inside(const ContactPatch& p, int i, int j) {
  const double x = p.grid.x_edge(i), a = p.half_length_m(j);
  return x > -a && x < a;
}

double node_energy_sum(const TransientState& s) {  // sum of |tau|^2 over all nodes
  double e = 0;
  for (size_t k = 0; k < s.nodes.size(); ++k) e += s.nodes.tx[k] * s.nodes.tx[k] + s.nodes.ty[k] * s.nodes.ty[k];
  return e;
}

// strip `to` takes the nodes of strip `from`
void mirror_strip(TransientState& s, int from, int to) {
  const size_t n = s.nx + 1;
  s.nodes.copy(from * n, to * n, n);
}

void allocate_fields(StepResult& r, const Grid& g) {
  r.tau_x_Pa = Eigen::ArrayXXd::Zero(g.nx, g.ny);
  r.tau_y_Pa = Eigen::ArrayXXd::Zero(g.nx, g.ny);
  r.slip_x_m_per_s = Eigen::ArrayXXd::Zero(g.nx, g.ny);
  r.slip_y_m_per_s = Eigen::ArrayXXd::Zero(g.nx, g.ny);
}

// one strip over a step, per unit width: its totals (dissipated: energy; counted_length: upwind and
// lax-friedrichs count dx per node in contact, shift the exact 2 a_j) and the other energies
struct StripEnergy : StripTotals {
  double creep = 0, trailing = 0, transport = 0;
  double E_start = 0, E_end = 0;  // sums of |tau|^2 over the interior nodes before and after the step
};

// the whole kernel for one interval, kept out of the loops over the strip
template <bool kSpin>
[[gnu::noinline]] StripNode whole_kernel(const StripRates& r, const StripNode& hi, const IntervalGeometry& geo,
                                         IntervalSums& s) {
  return march_interval<kSpin>(r, hi, geo, s);
}

// The stick pass takes a strip's interior intervals in blocks; an Eigen array of a block is a run of
// SIMD packets.
constexpr int kBlock = 4;
using Block = Eigen::Array<double, kBlock, 1>;
using BlockMap = Eigen::Map<const Block>;  // a block of an array: the per-step geometry, the pressures

// The stick pass without spin (plain_stick_pass) in the compiler's vectors of two lanes (an SSE2 packet: wider
// ones, split on the project's x86-64 baseline, had their comparisons taken lane by lane), the arithmetic lane
// by lane as in scalar code (no reordering within a lane)
constexpr int kLanes = 2;
typedef double Lanes __attribute__((vector_size(kLanes * sizeof(double))));
typedef std::int64_t LaneMask __attribute__((vector_size(kLanes * sizeof(double))));
[[gnu::always_inline]] inline void load_lanes(Lanes& v, const double* p) { std::memcpy(&v, p, sizeof v); }
[[gnu::always_inline]] inline void store_lanes(double* p, const Lanes& v) { std::memcpy(p, &v, sizeof v); }
// a lane of m is set (all ones): the sign bits gathered at once where the target has it
[[gnu::always_inline]] inline bool any_lane(const LaneMask& m) {
#if defined(__SSE2__)
  return _mm_movemask_pd(reinterpret_cast<__m128d>(m)) != 0;
#else
  return (m[0] | m[1]) != 0;
#endif
}

// what the shift step of every strip shares, and room for one strip's, set up once per step from the
// rates r of any strip (only eta/L2 and phi/L3, the same on every strip, are used)
struct ShiftScratch {
  // what it was built from: the grid's nodes, and the lateral rates
  int nx = 0;
  double half_x_m = 0, dx_m = 0, eta_L2 = 0, phi_L3 = 0;
  bool built_for(const Grid& g, const StripRates& r) const {
    return nx == g.nx && half_x_m == g.half_x_m && dx_m == g.dx_m && eta_L2 == r.eta_L2_Pa_per_m &&
           phi_L3 == r.phi_L3_Pa_per_m2;
  }
  Eigen::ArrayXd x;  // the nodes x_edge(i), i = 0 .. nx
  // cell i whole, from x_edge(i+1) down to x_edge(i): its length t and the terms of its stick solution
  // that involve neither tau nor alpha, so that they are the same on every strip
  Eigen::ArrayXd t, beta_t, gamma_t2;                                // the prediction's
  Eigen::ArrayXd t2_2, beta_t2_2, gamma_t3_3, beta_t3_3, gamma_t4_4;  // the integrals'
  Eigen::ArrayXd bulge;  // |gamma| t^2 / 4: how far the stick parabola can rise over its chord
  std::vector<int> failed;             // a strip's interior intervals whose stick test failed
  std::vector<StripNode> failed_hi;    // their old upstream nodes
  std::vector<char> failed_between;    // spin: the interior test failed, or a slip node sticks again
  std::vector<detail::SlipTurn> turn;  // their slip turns, from a slip node
  ShiftScratch(const Grid& g, const StripRates& r)
      : nx(g.nx), half_x_m(g.half_x_m), dx_m(g.dx_m), eta_L2(r.eta_L2_Pa_per_m), phi_L3(r.phi_L3_Pa_per_m2),
        x(g.nx + 1), t(g.nx), beta_t(g.nx), gamma_t2(g.nx), t2_2(g.nx), beta_t2_2(g.nx), gamma_t3_3(g.nx),
        beta_t3_3(g.nx), gamma_t4_4(g.nx), bulge(g.nx), failed(g.nx), failed_hi(g.nx), failed_between(g.nx),
        turn(g.nx) {
    for (int i = 0; i <= g.nx; ++i) x(i) = g.x_edge(i);
    for (int i = 0; i < g.nx; ++i) {
      t(i) = x(i + 1) - x(i);
      const double beta = detail::stick_beta(r, x(i + 1));
      const detail::StickGeometry<double> sg = detail::stick_geometry(r, beta, t(i));
      const detail::StickMoments<double> sm = detail::stick_moments(beta, r.phi_L3_Pa_per_m2 / 2, t(i));
      beta_t(i) = sg.beta_t;
      gamma_t2(i) = sg.gamma_t2;
      t2_2(i) = sm.t2_2;
      beta_t2_2(i) = sm.beta_t2_2;
      gamma_t3_3(i) = sm.gamma_t3_3;
      beta_t3_3(i) = sm.beta_t3_3;
      gamma_t4_4(i) = sm.gamma_t4_4;
      bulge(i) = std::abs(sg.gamma_t2) / 4;
    }
  }
};

// two doubles hold the same bits (compared as integers: a call to memcmp per node cost more than the node)
inline bool same_bits(double a, double b) {
  std::uint64_t ua, ub;
  std::memcpy(&ua, &a, sizeof a);
  std::memcpy(&ub, &b, sizeof b);
  return ua == ub;
}

// A strip's two end intervals, and the interval where stick turns to slip, go through the whole kernel at
// every step, and their inputs seldom change: the leading one takes tau = 0 in, the trailing one a node that
// slips on the bound (mu p e) once the material slips there, and in a steady stretch the turn to slip stays
// in one interval with the same stick node upstream. Where the rates, the geometry and the upstream node are
// the same to the bit, so are the new node and the integrals: kept here from the step that computed them. The
// rates and the geometry are the same while the interval and the workspace's generation of the strips' rates
// and spans are (SatranWorkspace::Impl::generation: bumped whenever either is computed anew); where the
// generation changed (a new patch, or an inertia run's trial steps), their bytes are compared as well.
struct EdgeInterval {
  bool valid = false;
  unsigned long generation = 0;
  int i = -1;
  StripRates r;
  IntervalGeometry geo;
  StripNode hi, lo;
  IntervalSums cell;
  // the same node for the kernel: tau and stick, and the direction where it slips (a stick node's is not read)
  static bool same(const StripNode& a, const StripNode& b) {
    return same_bits(a.tx, b.tx) && same_bits(a.ty, b.ty) && a.stick == b.stick &&
           (a.stick || (same_bits(a.ex, b.ex) && same_bits(a.ey, b.ey)));
  }
  bool holds(unsigned long gen, int ii, const StripNode& h) const {
    return valid && generation == gen && i == ii && same(hi, h);
  }
  bool holds_bytes(const StripRates& rr, const IntervalGeometry& g, const StripNode& h) const {
    return valid && std::memcmp(&r, &rr, sizeof r) == 0 && std::memcmp(&geo, &g, sizeof geo) == 0 && same(hi, h);
  }
};
// a node holds the bits (tx, ty, stick) given, and (ex, ey) where it slips: what the steady strips' skip asks of
// every node written (a stick node's direction is not read)
inline bool same_bits(const StripNode& n, double tx, double ty, double ex, double ey, bool stick) {
  return EdgeInterval::same(n, {tx, ty, ex, ey, stick});
}
// the same for a node that sticks: its bits (tx, ty) and stick
inline bool same_stick_bits(double tx_old, double ty_old, unsigned char stick_old, double tx, double ty) {
  return same_bits(tx_old, tx) && same_bits(ty_old, ty) && stick_old == 1;
}

// A strip whose step left every node as it was (to the bit) is steady: while its rates, the patch, L and the
// rolled distance stay the same (to the bit), every later step leaves it as it is too, with the same totals
struct SteadyStrip {
  bool unchanged = false;  // the last step on this strip left its nodes as they were
  unsigned long serial = 0;
  int variant = -1;  // the shift step compiled: 0 pure xi without lateral work, 1 lateral, 2 spin
  StripRates r;
  double L = 0, dq = 0;
  StripEnergy e;
  bool holds(unsigned long s, int v, const StripRates& rr, double LL, double q) const {
    return unchanged && serial == s && variant == v && std::memcmp(&r, &rr, sizeof r) == 0 &&
           std::memcmp(&L, &LL, sizeof L) == 0 && std::memcmp(&dq, &q, sizeof dq) == 0;
  }
};

// per strip: the leading interval, the trailing one, and the last interval where stick turned to slip
constexpr int kKeptIntervals = 3;

// A strip's intervals on the grid: i_bot .. i_top in contact, first .. last of them strictly inside it (both
// ends); they depend on the patch alone, and a run keeps them while the patch is the same
struct StripSpan {
  int i_bot = 0, first = 0, last = -1, i_top = -1;
};
inline StripSpan strip_span(const Grid& g, const double* x, double a) {
  StripSpan s;
  s.i_top = std::min(g.nx - 1, static_cast<int>(std::floor((a + g.half_x_m) / g.dx_m)));
  s.i_bot = std::max(0, static_cast<int>(std::floor((-a + g.half_x_m) / g.dx_m)));
  s.first = s.i_bot;
  s.last = s.i_top;
  while (s.first <= s.last && !(x[s.first] > -a)) ++s.first;
  while (s.last >= s.first && !(x[s.last + 1] < a)) --s.last;
  return s;
}
static_assert(sizeof(StripRates) == 8 * sizeof(double) && sizeof(IntervalGeometry) == 5 * sizeof(double),
              "EdgeInterval compares them as bytes: no padding");

// One strip, shift. In a shift step node i's new value depends on the old node i+1 alone: the intervals
// form no chain, and most of them stick. So the interior intervals (both ends strictly inside the strip)
// first take the stick step in blocks: the prediction at x_lo, Kalker's test, the stick integrals (the
// arithmetic of stick_step, lane by lane). The intervals whose test fails follow, together: from a slip
// node the slip direction turns by the midpoint rule, and their turns (an exponential each) are taken
// all at once so that they overlap, as in the steady march; from a stick node the whole kernel finds the
// crossing into slip. The strip's two end intervals go through the whole kernel. The fields need each
// interval's integrals: when they are written, every interval goes through the whole kernel.
template <bool kFields, bool kSpin, bool kLateral>
class ShiftStrip {
 public:
  ShiftStrip(const ContactPatch& patch, const StripRates& r, int j, double L, const StepKinematics& k,
             ShiftScratch& scratch, TransientState& state, StepResult* fields, EdgeInterval* edge, bool track,
             const StripSpan& span, unsigned long generation)
      : patch_(patch), r_(r), j_(j), L_(L), k_(k), scratch_(scratch), fields_(fields), edge_(edge), span_(span),
        generation_(generation),
        track_(track), a_(r.a_m),
        dx_(patch.grid.dx_m),
        x_(scratch.x.data()), edge_p_(&patch.edge_pressure_Pa(0, j)) {
    const size_t o = state.index(0, j);
    tx_ = state.nodes.tx.data() + o;
    ty_ = state.nodes.ty.data() + o;
    ex_ = state.nodes.ex.data() + o;
    ey_ = state.nodes.ey.data() + o;
    st_ = state.nodes.stick.data() + o;
  }

  // the step of the strip: the trailing edge's intervals, the interior ones (the stick pass in blocks, then
  // those whose stick test failed), the leading edge's; every interval through the whole kernel where the
  // fields are written or the interior is shorter than a block
  StripEnergy step() {
    const int i_bot = span_.i_bot, first = span_.first, last = span_.last, i_top = span_.i_top;
    if (kFields || last - first + 1 < kBlock) {
      for (int i = i_bot; i <= i_top; ++i) whole_interval(i);
    } else {
      for (int i = i_bot; i < first; ++i) whole_interval(i);
      if constexpr (kSpin) {
        failed_intervals(stick_pass(first, last));
      } else {
        failed_intervals(plain_stick_pass(first, last));
      }
      for (int i = last + 1; i <= i_top; ++i) whole_interval(i);
    }
    return energies();
  }

 private:
  // interval i: its part of the strip and the bound at x_lo (0 at the trailing edge)
  IntervalGeometry geometry(int i) const {
    IntervalGeometry geo;
    geo.x_hi = std::min(x_[i + 1], a_);
    geo.x_lo = std::max(x_[i], -a_);
    geo.bound_lo_Pa = geo.x_lo > -a_ ? r_.mu * edge_p_[i] : 0.0;
    geo.load_N_per_m = patch_.pressure_Pa(i, j_) * dx_;
    geo.moment_N = patch_.pressure_moment_Pa_m(i, j_) * dx_;
    return geo;
  }

  // the totals of interval i from its old upstream node hi, and the new node lo (the trailing edge's
  // carries its energy out of the contact)
  void record(int i, const IntervalGeometry& geo, const StripNode& hi, const StripNode& lo, const IntervalSums& cell) {
    add_interval_sums(strip_, cell);
    hi2_ += hi.tx * hi.tx + hi.ty * hi.ty;
    lo2_ += lo.tx * lo.tx + lo.ty * lo.ty;
    if (geo.x_lo > -a_) {
      if (track_) same_ &= same_bits(load(i), lo.tx, lo.ty, lo.ex, lo.ey, lo.stick);
      store(i, lo);
    } else {
      trail2_ = lo.tx * lo.tx + lo.ty * lo.ty;
    }
    if constexpr (kFields) {
      const double h = geo.x_hi - geo.x_lo;
      fields_->tau_x_Pa(i, j_) = cell.Ix / dx_;
      fields_->tau_y_Pa(i, j_) = cell.Iy / dx_;
      fields_->slip_x_m_per_s(i, j_) = L_ * k_.dq_m / k_.dt_s * cell.slip_x / h;
      fields_->slip_y_m_per_s(i, j_) = L_ * k_.dq_m / k_.dt_s * cell.slip_y / h;
    }
  }

  // interval i through the whole kernel, from the old node i+1 (tau = 0 enters at the leading edge)
  void whole_interval(int i) {
    // an end interval: the last result, if its inputs are the same (its geometry too, then)
    const bool leading = !(x_[i + 1] < a_), trailing = !(x_[i] > -a_);
    if (edge_ && (leading || trailing)) {
      const StripNode hi = leading ? StripNode{} : load(i + 1);
      EdgeInterval& e = edge_[leading ? 0 : 1];
      if (e.holds(generation_, i, hi)) {
        record(i, e.geo, hi, e.lo, e.cell);
        return;
      }
      const IntervalGeometry geo = geometry(i);
      if (!(geo.x_hi > geo.x_lo)) return;
      kept_kernel(e, i, geo, hi);
      return;
    }
    const IntervalGeometry geo = geometry(i);
    if (!(geo.x_hi > geo.x_lo)) return;
    const StripNode hi = leading ? StripNode{} : load(i + 1);
    IntervalSums cell;
    const StripNode lo = whole_kernel<kSpin>(r_, hi, geo, cell);
    record(i, geo, hi, lo, cell);
  }

  // interval i through the whole kernel, or the result kept in e where its inputs are the same to the bit
  void kept_kernel(EdgeInterval& e, int i, const IntervalGeometry& geo, const StripNode& hi) {
    if (!e.holds(generation_, i, hi)) {
      if (!e.holds_bytes(r_, geo, hi)) {
        e.cell = IntervalSums{};
        e.lo = whole_kernel<kSpin>(r_, hi, geo, e.cell);
        e.r = r_;
        e.geo = geo;
        e.hi = hi;
        e.valid = true;
      }
      e.generation = generation_;
      e.i = i;
    }
    record(i, geo, hi, e.lo, e.cell);
  }

  // The stick pass without spin over the interior intervals first .. last: what stick_pass does for them, the
  // same numbers to the bit (the sums too: a block's lanes added as stick_pass adds them), in the compiler's
  // vectors, a block of kBlock intervals as two packets of kLanes. Without spin gamma = 0 and its terms are
  // left out (adding +0 changes no value but the sign of a zero). A block whose intervals all stick is written
  // a packet per quantity; one where an interval fails is taken lane by lane, its failed intervals kept in the
  // scratch with their old upstream node for failed_intervals.
  int plain_stick_pass(int first, int last) {
    static_assert(kBlock == 2 * kLanes, "a block is two packets");
    const double alpha = r_.alpha_Pa_per_m, mu = r_.mu;
    const double* const x = x_;
    const double* const edge_p = edge_p_;
    double* const TX = tx_;
    double* const TY = ty_;
    unsigned char* const ST = st_;
    ShiftScratch& scratch = scratch_;
    const double* const t = scratch.t.data();
    const double* const t2_2 = scratch.t2_2.data();
    const double* const beta_t = scratch.beta_t.data();
    const double* const beta_t2_2 = scratch.beta_t2_2.data();
    const double* const beta_t3_3 = scratch.beta_t3_3.data();
    const bool track = track_;
    bool same = true;
    int n_failed = 0;
    IntervalSums strip = strip_;  // in registers through the pass
    double hi2s = hi2_, lo2s = lo2_;
    // interval i from the old node i + 1 (not written yet), lane by lane: the prediction, the integrals, and
    // Kalker's test at x_lo (true: it fails)
    auto one = [&](int i, double& px, double& py, double& Ix, double& Iy, double& Ixy, double& lo2, double& hi2) {
      const double tx = TX[i + 1], h = t[i];
      px = tx - alpha * h;
      Ix = tx * h - alpha * t2_2[i];
      if constexpr (kLateral) {
        const double ty = TY[i + 1];
        py = ty - beta_t[i];
        Iy = ty * h - beta_t2_2[i];
        Ixy = x[i + 1] * Iy - (ty * t2_2[i] - beta_t3_3[i]);
        lo2 = px * px + py * py;
        hi2 = tx * tx + ty * ty;
      } else {
        py = Iy = Ixy = 0;
        lo2 = px * px;
        hi2 = tx * tx;
      }
      const double bound = mu * edge_p[i];
      return lo2 - bound * bound > 0;
    };
    // the same for the intervals i, i + 1 in a packet; fails: the lanes where the test fails
    struct Pair {
      Lanes h, px, py, Ix, Iy, Ixy, lo2, hi2;
    };
    auto pair = [&](int i, Pair& o) {
      Lanes tx, t22, bound;
      load_lanes(tx, TX + i + 1);
      load_lanes(o.h, t + i);
      load_lanes(t22, t2_2 + i);
      load_lanes(bound, edge_p + i);
      bound *= mu;
      o.px = tx - alpha * o.h;
      o.Ix = tx * o.h - alpha * t22;
      if constexpr (kLateral) {
        Lanes ty, bt, bt22, bt33, xh;
        load_lanes(ty, TY + i + 1);
        load_lanes(bt, beta_t + i);
        load_lanes(bt22, beta_t2_2 + i);
        load_lanes(bt33, beta_t3_3 + i);
        load_lanes(xh, x + i + 1);
        o.py = ty - bt;
        o.Iy = ty * o.h - bt22;
        o.Ixy = xh * o.Iy - (ty * t22 - bt33);
        o.lo2 = o.px * o.px + o.py * o.py;
        o.hi2 = tx * tx + ty * ty;
      } else {
        o.py = o.Iy = o.Ixy = Lanes{};
        o.lo2 = o.px * o.px;
        o.hi2 = tx * tx;
      }
      return o.lo2 - bound * bound > 0;
    };
    // a block's sum, in the order of stick_pass's (Eigen's: lanes 0 + 2, 1 + 3, then the two)
    auto block_sum = [](const Lanes& a, const Lanes& b) {
      const Lanes s = a + b;
      return s[0] + s[1];
    };
    // the new nodes i, i + 1 of a pair that sticks, with a packet per quantity
    auto store_pair = [&](int i, const Pair& o) {
      if (track) {
        LaneMask ox, oy;
        std::memcpy(&ox, TX + i, sizeof ox);
        std::memcpy(&oy, TY + i, sizeof oy);
        const LaneMask sx = ox == reinterpret_cast<LaneMask>(o.px), sy = oy == reinterpret_cast<LaneMask>(o.py);
        same &= !any_lane(~(sx & sy)) && (ST[i] & ST[i + 1]) == 1;
      }
      store_lanes(TX + i, o.px);
      store_lanes(TY + i, o.py);
      ST[i] = 1;
      ST[i + 1] = 1;
    };
    for (int from = first; from <= last; from += kBlock) {
      const int b = std::min(from, last - kBlock + 1);  // the block's intervals are b .. b + kBlock - 1
      if (b == from) {
        Pair A, B;
        const LaneMask fa = pair(b, A), fb = pair(b + kLanes, B);
        if (!any_lane(fa | fb)) {  // the whole block sticks
          store_pair(b, A);
          store_pair(b + kLanes, B);
          strip.Ix += block_sum(A.Ix, B.Ix);
          if constexpr (kLateral) {
            strip.Iy += block_sum(A.Iy, B.Iy);
            strip.Ixy += block_sum(A.Ixy, B.Ixy);
          }
          strip.stick_length_m += block_sum(A.h, B.h);
          hi2s += block_sum(A.hi2, B.hi2);
          lo2s += block_sum(A.lo2, B.lo2);
          continue;
        }
      }
      // lane by lane from the trailing side up (node i + 1 is not written yet); below `from` the block before
      // did them
      for (int i = from; i < b + kBlock; ++i) {
        double px, py, Ix, Iy, Ixy, lo2, hi2;
        if (one(i, px, py, Ix, Iy, Ixy, lo2, hi2)) {
          scratch.failed[n_failed] = i;
          scratch.failed_hi[n_failed++] = load(i + 1);
          continue;
        }
        if (track) same &= same_stick_bits(TX[i], TY[i], ST[i], px, py);
        TX[i] = px;
        TY[i] = py;
        ST[i] = 1;
        strip.Ix += Ix;
        if constexpr (kLateral) {
          strip.Iy += Iy;
          strip.Ixy += Ixy;
        }
        strip.stick_length_m += t[i];
        hi2s += hi2;
        lo2s += lo2;
      }
    }
    strip_ = strip;
    hi2_ = hi2s;
    lo2_ = lo2s;
    same_ &= same;
    return n_failed;
  }

  // The stick pass over the interior intervals first .. last, in blocks from the trailing side up; the last
  // block is moved back to end at `last`, and its intervals below `from` were done by the block before. The
  // intervals whose test fails are kept in the scratch (with their old upstream node) for failed_intervals;
  // returns how many. With spin Kalker's test also asks whether the stick solution stays inside the bound
  // between the nodes, and a slip node whose slip stops dissipating sticks again (stick_step, spin_sticks):
  // those intervals fail too. (kSpin: compiled apart, so that without spin it does nothing more)
  int stick_pass(int first, int last) {
    const StripRates& r = r_;
    const double* x = x_;
    const double* edge_p = edge_p_;
    double* const TX = tx_;
    double* const TY = ty_;
    unsigned char* const ST = st_;
    ShiftScratch& scratch = scratch_;
    // the sums in registers through the pass (a node written may alias a member)
    IntervalSums strip = strip_;
    double hi2 = hi2_, lo2 = lo2_;
    const bool track = track_;
    bool same = true;
    const detail::BoundQuadratic bound_q = detail::bound_quadratic(r);
    int n_failed = 0;
    for (int from = first; from <= last; from += kBlock) {
      const int b = std::min(from, last - kBlock + 1);  // the block's intervals are b .. b + kBlock - 1
      // the old tau at x_hi: nodes b + 1 and up are not written yet
      const Block tx = BlockMap(TX + b + 1);
      Block ty = Block::Zero();
      if constexpr (kLateral) ty = BlockMap(TY + b + 1);
      bool slip_node = false;  // one of them slips (asked with spin only)
      if constexpr (kSpin) {
        unsigned char all = 1;
        for (int q = 0; q < kBlock; ++q) all &= ST[b + 1 + q];
        slip_node = all == 0;
      }
      auto at = [b](const Eigen::ArrayXd& v) { return BlockMap(v.data() + b); };
      const BlockMap x_hi(x + b + 1), h = at(scratch.t);
      const Block bound = r.mu * BlockMap(edge_p + b);
      // without lateral work tau_y = 0 stays 0 (beta = gamma = 0): the x parts alone, the same numbers
      detail::StickPrediction<Block> p;
      detail::StickIntegrals<Block> I;
      Block lo2_lane, hi2_lane;
      if constexpr (kLateral) {
        p = detail::stick_prediction<Block, BlockMap>(r.alpha_Pa_per_m, tx, ty, h,
                                                      {at(scratch.beta_t), at(scratch.gamma_t2)});
        I = detail::stick_integrals<Block, BlockMap>(r.alpha_Pa_per_m, tx, ty, x_hi, h,
                                                     {at(scratch.t2_2), at(scratch.beta_t2_2), at(scratch.gamma_t3_3),
                                                      at(scratch.beta_t3_3), at(scratch.gamma_t4_4)});
        lo2_lane = p.px * p.px + p.py * p.py;
        hi2_lane = tx * tx + ty * ty;
      } else {
        p.px = tx - r.alpha_Pa_per_m * h;
        I.Ix = tx * h - r.alpha_Pa_per_m * at(scratch.t2_2);
        lo2_lane = p.px * p.px;
        hi2_lane = tx * tx;
      }
      const Block excess = lo2_lane - bound * bound;  // > 0 exactly where stick_step's node test fails
      // With spin, from a stick node: first a sufficient pass, rigorous with a margin far above rounding,
      // |tau| <= max(|tau_hi|, |p|) + |gamma| h^2 / 4 (the parabola is its chord, convex in |.|, plus
      // gamma t (t - h) e_y) below min(g_hi, g_lo) (g is concave in x), where clear < 0; where it does
      // not settle it, the hull of spin_sticks' excess F, > 0 where the interior test needs
      // first_crossing. The intervals from slip nodes are decided one by one below.
      Block clear, inner;
      bool hull = false;
      if constexpr (kSpin) {
        constexpr double kMargin = 1e-12;
        const Block bound_hi = r.mu * BlockMap(edge_p + b + 1);
        const Block room = (bound_hi.min(bound) * (1 - kMargin) - at(scratch.bulge)).max(0.0);
        clear = hi2_lane.max(lo2_lane) - room * room;
        if (clear.maxCoeff() >= 0) {  // the hull, if a stick node's interval that passes at x_lo needs it
          for (int q = 0; q < kBlock && !hull; ++q)
            hull = ST[b + 1 + q] && excess(q) <= 0 && clear(q) >= 0;
        }
        if (hull) {
          inner = detail::hull_excess(detail::stick_excess<Block, BlockMap>(
              r.alpha_Pa_per_m, bound_q, tx, ty, x_hi, h, {at(scratch.beta_t), at(scratch.gamma_t2)}));
        }
      }
      // the new nodes from the trailing side up, so that node i+1 still holds the old tau when node i is
      // written; an interval whose test fails keeps its old upstream node for later. A stick node's direction
      // is not read (StripNode): it is left as it was.
      auto stick = [&](int q) {
        const int i = b + q;
        const double py = kLateral ? p.py(q) : 0.0;
        if (track) same &= same_stick_bits(TX[i], TY[i], ST[i], p.px(q), py);
        TX[i] = p.px(q);
        TY[i] = py;
        ST[i] = 1;
      };
      if (b == from && excess.maxCoeff() <= 0 &&
          (!kSpin || (!slip_node && (!hull || ((clear < 0) || (inner <= 0)).all())))) {  // the whole block sticks
        if (track) {
          for (int q = 0; q < kBlock; ++q) stick(q);
        } else {
          Eigen::Map<Block>(TX + b) = p.px;
          if constexpr (kLateral) {
            Eigen::Map<Block>(TY + b) = p.py;
          } else {
            Eigen::Map<Block>(TY + b).setZero();
          }
          for (int q = 0; q < kBlock; ++q) ST[b + q] = 1;
        }
        strip.Ix += I.Ix.sum();
        if constexpr (kLateral) {
          strip.Iy += I.Iy.sum();
          strip.Ixy += I.Ixy.sum();
        }
        strip.stick_length_m += h.sum();
        hi2 += hi2_lane.sum();
        lo2 += lo2_lane.sum();
        continue;
      }
      for (int q = from - b; q < kBlock; ++q) {
        // with spin: from a stick node the whole kernel also where the interior test may fail; from a slip
        // node what spin_sticks decides (stick, slip on, or the whole kernel where it sticks again)
        bool fails = excess(q) > 0, between = false;
        if constexpr (kSpin) {
          const StripNode hi = load(b + q + 1);
          if (hi.stick) {
            between = !fails && hull && clear(q) >= 0 && inner(q) > 0;
          } else {
            const int i = b + q;
            const detail::SlipNodeStep step = detail::slip_node_step(
                r, bound_q, hi, x[i + 1], scratch.t(i), {scratch.beta_t(i), scratch.gamma_t2(i)}, !fails);
            fails = step != detail::SlipNodeStep::kSticks;
            between = step == detail::SlipNodeStep::kKernel;
          }
        }
        if (fails || between) {
          scratch.failed[n_failed] = b + q;
          if constexpr (kSpin) scratch.failed_between[n_failed] = between;
          scratch.failed_hi[n_failed++] = load(b + q + 1);
          continue;
        }
        strip.Ix += I.Ix(q);
        if constexpr (kLateral) {
          strip.Iy += I.Iy(q);
          strip.Ixy += I.Ixy(q);
        }
        strip.stick_length_m += h(q);
        hi2 += hi2_lane(q);
        lo2 += lo2_lane(q);
        stick(q);
      }
    }

    strip_ = strip;
    hi2_ = hi2;
    lo2_ = lo2;
    same_ &= same;
    return n_failed;
  }

  // The intervals whose stick test failed: from a slip node the interval slips throughout (with spin until
  // its slip stops dissipating, then it sticks again inside the interval, as in the kernel), from a stick
  // node the whole kernel finds the crossing into slip, and so it does for the intervals of spin marked by
  // the stick pass. With a lateral creep rate the slip direction turns, and the turns from slip nodes are
  // taken first, all at once (with xi alone they are asked for only where tau is not along x)
  void failed_intervals(int n_failed) {
    const StripRates& r = r_;
    const double* x = x_;
    ShiftScratch& scratch = scratch_;
    const bool turns = r.eta_L2_Pa_per_m != 0 || r.phi_L3_Pa_per_m2 != 0;
    for (int f = 0; turns && f < n_failed; ++f) {
      const int i = scratch.failed[f];
      if (!scratch.failed_hi[f].stick && !(kSpin && scratch.failed_between[f]))
        scratch.turn[f] = detail::interior_slip_turn(r, x[i + 1], x[i]);
    }
    for (int f = 0; f < n_failed; ++f) {
      const int i = scratch.failed[f];
      const StripNode& hi = scratch.failed_hi[f];
      const IntervalGeometry geo = geometry(i);
      auto turn = [&] { return turns ? scratch.turn[f] : detail::interior_slip_turn(r, x[i + 1], x[i]); };
      if (edge_ && (hi.stick || (kSpin && scratch.failed_between[f]))) {
        kept_kernel(edge_[2], i, geo, hi);  // where stick turns to slip: the same in a steady stretch
        continue;
      }
      IntervalSums cell;
      const StripNode lo = hi.stick || (kSpin && scratch.failed_between[f]) ? whole_kernel<kSpin>(r, hi, geo, cell)
                                                                            : slip_throughout<kSpin>(r, hi, geo, turn, cell);
      record(i, geo, hi, lo, cell);
    }
  }

  // the strip's energies: the per-interval formula summed (its last term telescopes)
  StripEnergy energies() const {
    const double dq = k_.dq_m;
    StripEnergy e;
    e.creep = L_ * dq * creep_power_per_VL(r_, strip_);
    e.dissipated = e.creep + L_ * dq * (hi2_ - lo2_) / 2;
    e.E_start = hi2_;  // the old interior nodes are the intervals' upstream nodes (the leading one is 0)
    e.E_end = lo2_ - trail2_;  // the new ones their downstream nodes, but for the trailing edge's
    e.trailing = L_ * dq * trail2_ / 2;
    e.Fx = strip_.Ix;
    e.Fy = strip_.Iy;
    e.Mz = strip_.Ixy - r_.y_m * strip_.Ix;
    e.stick_length = strip_.stick_length_m;
    return e;
  }

  const ContactPatch& patch_;
  const StripRates& r_;
  const int j_;
  const double L_;
  const StepKinematics& k_;
  ShiftScratch& scratch_;
  StepResult* fields_;
  EdgeInterval* edge_;  // the strip's kept intervals (kKeptIntervals; null: none kept)
  const StripSpan& span_;
  const unsigned long generation_;  // of the strips' rates and spans (EdgeInterval)
 public:
  const bool track_;   // same_ is asked for
  bool same_ = true;   // every node written so far holds the bits it held before the step
 private:
  const double a_, dx_;
  const double* x_;      // the nodes x_edge(i)
  // the strip's nodes, one array per quantity: node i sits at x_edge(i)
  double *tx_, *ty_, *ex_, *ey_;
  unsigned char* st_;
  StripNode load(int i) const { return {tx_[i], ty_[i], ex_[i], ey_[i], st_[i] != 0}; }
  void store(int i, const StripNode& n) {
    tx_[i] = n.tx;
    ty_[i] = n.ty;
    ex_[i] = n.ex;
    ey_[i] = n.ey;
    st_[i] = n.stick ? 1 : 0;
  }
  const double* edge_p_;
  // the integrals add up over the strip (per interval only for the fields)
  IntervalSums strip_;
  double hi2_ = 0, lo2_ = 0, trail2_ = 0;  // sums of |tau|^2 at the upstream, downstream, trailing nodes
};

// the strip's step; *same (where given): every node holds the bits it held before the step
template <bool kFields, bool kSpin, bool kLateral>
StripEnergy shift_strip(const ContactPatch& patch, const StripRates& r, int j, double L, const StepKinematics& k,
                        ShiftScratch& scratch, TransientState& state, StepResult* fields, EdgeInterval* edge,
                        bool* same, const StripSpan& span, unsigned long generation) {
  ShiftStrip<kFields, kSpin, kLateral> strip(patch, r, j, L, k, scratch, state, fields, edge, same != nullptr, span,
                                             generation);
  const StripEnergy e = strip.step();
  if (same) *same = strip.same_;
  return e;
}

// one strip, upwind (lf = false) or Lax-Friedrichs (lf = true) at CFL = dq/dx, split in two:
// transport tau^T = (1 - C) tau_i + C tau_{i+1} (upwind) or the Lax-Friedrichs average, which loses
// energy by numerical diffusion and outflow (reported, not dissipated by slip), then creep and clip
// tau* = tau^T - incr, tau = clip(tau*), delta = tau - tau*, with
//   dissipated = -L dx sum (tau^T + tau)/2 . delta,   creep = -L dx sum (tau^T + tau)/2 . incr,
// so that dissipated = creep - (E_end - E^T) exactly. At C = 0 (no rolling) there is no transport.
StripEnergy explicit_strip(const ContactPatch& patch, const TangentialProblem& pb, int j, const StepKinematics& k,
                           bool lf, TransientState& state, std::vector<StripNode>& old, StepResult* fields) {
  const Grid& g = patch.grid;
  const double L = pb.L_m_per_Pa, dx = g.dx_m, cfl = k.dq_m / dx;
  const double y = g.y_m(j), mu = pb.mu;
  const double offset = patch.strip_xi_offset.size() > j ? patch.strip_xi_offset(j) : 0.0;
  // creep increments of tau over the step: c dt / L
  const double inc_x = (k.slip_x_m + offset * k.dq_m) / pb.flex.L1_m_per_Pa - k.spin_rad * y / pb.flex.L3_m_per_Pa;
  const double inc_y0 = k.slip_y_m / pb.flex.L2_m_per_Pa, inc_yx = k.spin_rad / pb.flex.L3_m_per_Pa;
  StripEnergy e;
  for (int i = 0; i <= g.nx; ++i) old[i] = state.node(i, j);
  const StripNode zero{};
  auto at = [&](int i) -> const StripNode& {
    return (i >= 0 && i <= g.nx && inside(patch, i, j)) ? old[i] : zero;
  };
  double E_old = 0, E_transported = 0;
  for (int i = 0; i <= g.nx; ++i) {
    if (!inside(patch, i, j)) continue;
    const double x = g.x_edge(i);
    const StripNode& o = old[i];
    E_old += o.tx * o.tx + o.ty * o.ty;

    // transport
    const StripNode& up = at(i + 1);
    double Tx = o.tx + cfl * (up.tx - o.tx), Ty = o.ty + cfl * (up.ty - o.ty);
    if (lf) {
      const StripNode& dn = at(i - 1);
      Tx = (up.tx + dn.tx) / 2 + cfl * (up.tx - dn.tx) / 2;
      Ty = (up.ty + dn.ty) / 2 + cfl * (up.ty - dn.ty) / 2;
    }
    E_transported += Tx * Tx + Ty * Ty;

    // creep, then the Coulomb bound
    const double incx = inc_x, incy = inc_y0 + inc_yx * x;
    const double px = Tx - incx, py = Ty - incy;
    const double bound = mu * patch.edge_pressure_Pa(i, j);
    const double n = std::sqrt(px * px + py * py);
    const bool slip = n > bound;
    StripNode nw{px, py, o.ex, o.ey, !slip};
    if (slip) {
      nw.ex = px / n;
      nw.ey = py / n;
      nw.tx = bound * nw.ex;
      nw.ty = bound * nw.ey;
    }
    state.set_node(i, j, nw);
    const double mx = (Tx + nw.tx) / 2, my = (Ty + nw.ty) / 2;
    e.dissipated += -L * dx * (mx * (nw.tx - px) + my * (nw.ty - py));
    e.creep += -L * dx * (mx * incx + my * incy);
    e.Fx += nw.tx * dx;
    e.Fy += nw.ty * dx;
    e.Mz += (x * nw.ty - y * nw.tx) * dx;
    if (!slip) e.stick_length += dx;
    e.counted_length += dx;
    if (fields && k.dt_s > 0) {
      // node -> the two cells it borders, half to each
      for (int c : {i - 1, i}) {
        if (c < 0 || c >= g.nx) continue;
        fields->tau_x_Pa(c, j) += nw.tx / 2;
        fields->tau_y_Pa(c, j) += nw.ty / 2;
        fields->slip_x_m_per_s(c, j) += L * (nw.tx - px) / k.dt_s / 2;
        fields->slip_y_m_per_s(c, j) += L * (nw.ty - py) / k.dt_s / 2;
      }
    }
  }
  e.transport = L * dx / 2 * (E_old - E_transported);
  e.E_start = E_old;
  for (int i = 0; i <= g.nx; ++i) {
    const size_t n = state.index(i, j);
    e.E_end += state.nodes.tx[n] * state.nodes.tx[n] + state.nodes.ty[n] * state.nodes.ty[n];
  }
  return e;
}

}  // namespace

struct SatranWorkspace::Impl {
  std::vector<ShiftScratch> scratch;             // one per thread, built for scratch[0].built_for
  std::vector<std::vector<StripNode>> old;       // the explicit schemes' copy of a strip, one per thread
  std::vector<StripEnergy> energies;             // the strips' totals of a step
  std::vector<SteadyStrip> steady;  // each strip's last shift step: did it change the strip
  std::vector<EdgeInterval> edges;  // each strip's leading and trailing intervals of the last shift step
  // each strip's intervals on the patch (serial), and its rates for the problem `rates_of` (the fields that
  // strip_rates reads, compared to the bit)
  std::vector<StripSpan> spans;
  std::vector<StripRates> rates;
  unsigned long generation = 0;  // bumped whenever the spans or the rates are computed anew (EdgeInterval)
  bool spans_valid = false;
  unsigned long spans_serial = 0;  // the patch they were computed on
  int rates_count = 0;  // strips 0 .. rates_count - 1 hold their rates
  Creepages rates_creepages;
  Flexibilities rates_flex;
  double rates_L3x = 0, rates_mu = 0;
  bool rates_hold(const TangentialProblem& pb) const {
    return std::memcmp(&rates_creepages, &pb.creepages, sizeof(Creepages)) == 0 &&
           std::memcmp(&rates_flex, &pb.flex, sizeof(Flexibilities)) == 0 &&
           std::memcmp(&rates_L3x, &pb.L3x_m_per_Pa, sizeof(double)) == 0 &&
           std::memcmp(&rates_mu, &pb.mu, sizeof(double)) == 0;
  }
  // the patch of the last step (its serial): its first mirrored strip, and that the nodes outside its contact
  // hold no traction in the states stepped on it
  bool seen = false;
  unsigned long serial = 0;
  int first_mirrored = 0;
  std::unique_ptr<StripPool> pool;  // threads - 1 helpers, made on the first step that shares its strips
};

SatranWorkspace::SatranWorkspace() : impl(std::make_unique<Impl>()) {}
SatranWorkspace::~SatranWorkspace() = default;
SatranWorkspace::SatranWorkspace(SatranWorkspace&&) noexcept = default;
SatranWorkspace& SatranWorkspace::operator=(SatranWorkspace&&) noexcept = default;

bool workspace_stepped_on(const SatranWorkspace& ws, unsigned long patch_serial) {
  return ws.impl->seen && ws.impl->serial == patch_serial;
}

void workspace_forget_patch(SatranWorkspace& ws) { ws.impl->seen = false; }

namespace {

// the state's grid is the contact's, and the step's CFL number dq/dx within [0, 1]
void check_step(const Grid& g, const TransientState& state, const StepKinematics& k, double cfl) {
  if (state.nx != g.nx || state.ny != g.ny)
    throw std::invalid_argument("satran: the state's grid (" + std::to_string(state.nx) + " x " +
                                std::to_string(state.ny) + ") is not the contact's (" + std::to_string(g.nx) +
                                " x " + std::to_string(g.ny) + ")");
  if (!(cfl >= 0) || cfl > 1 + 1e-12)
    throw std::invalid_argument("satran: CFL number " + std::to_string(cfl) + " outside [0, 1] (dq " +
                                std::to_string(k.dq_m) + " m, dx " + std::to_string(g.dx_m) + " m)");
}

// A new flexibility rescales tau = u/L with u carried; where that lifts tau above the bound mu p of the
// step's contact (L smaller), the node slips back onto the bound at once. Returns the change of the
// springs' energy (StepResult::flexibility_J).
double rescale_flexibility(const ContactPatch& patch, const TangentialProblem& problem, TransientState& state) {
  const Grid& g = patch.grid;
  const double dx = g.dx_m, L = problem.L_m_per_Pa;
  const double before = state.L_m_per_Pa * dx / 2 * node_energy_sum(state) * g.dy_m;
  const double scale = state.L_m_per_Pa / L;
  for (double& t : state.nodes.tx) t *= scale;
  for (double& t : state.nodes.ty) t *= scale;
  if (scale > 1) {
    for (int j = 0; j < g.ny; ++j) {
      const double a = patch.half_length_m(j);
      for (int i = 0; i <= g.nx; ++i) {
        const double x = g.x_edge(i);
        if (!(x > -a && x < a)) continue;  // released below
        StripNode n = state.node(i, j);
        const double bound = problem.mu * patch.edge_pressure_Pa(i, j), norm = std::hypot(n.tx, n.ty);
        if (!(norm > bound)) continue;
        n.ex = n.tx / norm;
        n.ey = n.ty / norm;
        n.tx = bound * n.ex;
        n.ty = bound * n.ey;
        n.stick = false;
        state.set_node(i, j, n);
      }
    }
  }
  return L * dx / 2 * node_energy_sum(state) * g.dy_m - before;
}

// Nodes outside the contact carry no traction: each one that holds some gives its springs' energy up
// (added to released_J)
void release_outside_contact(const ContactPatch& patch, double L, TransientState& state, double& released_J) {
  const Grid& g = patch.grid;
  const double dx = g.dx_m;
  for (int j = 0; j < g.ny; ++j) {
    const double a = patch.half_length_m(j);
    for (int i = 0; i <= g.nx; ++i) {
      const double x = g.x_edge(i);
      if (x > -a && x < a) {
        i = std::max(i, static_cast<int>(std::ceil((a + g.half_x_m) / dx)) - 1);  // skip the interior
        continue;
      }
      const StripNode n = state.node(i, j);
      const double n2 = n.tx * n.tx + n.ty * n.ty;
      if (n2 == 0) continue;
      released_J += L * dx / 2 * n2 * g.dy_m;
      state.set_node(i, j, StripNode{});
    }
  }
}

// each thread's scratch: the shift kernel's, built for the grid and the rates r0, or the explicit schemes'
// copy of a strip
void prepare_scratch(SatranWorkspace::Impl& w, const Grid& g, bool exact_shift, const StripRates& r0, int threads) {
  if (exact_shift) {
    if (w.scratch.empty() || !w.scratch[0].built_for(g, r0)) w.scratch.clear();
    while (static_cast<int>(w.scratch.size()) < threads) w.scratch.emplace_back(g, r0);
  } else {
    w.old.resize(std::max<size_t>(w.old.size(), threads));
    for (std::vector<StripNode>& o : w.old) o.resize(g.nx + 1);
  }
}

// The shift kernel's strip spans (where the patch changed) and rates of the strips below `strips` (where the
// rates' problem changed): the same numbers as computed afresh (strip_rates of the same inputs)
void refresh_spans_and_rates(SatranWorkspace::Impl& w, const ContactPatch& patch, const TangentialProblem& rates_problem,
                             int strips, bool same_patch, unsigned long patch_serial) {
  const Grid& g = patch.grid;
  if (!same_patch || !w.spans_valid || w.spans_serial != patch_serial) {
    w.spans.resize(g.ny);
    for (int j = 0; j < g.ny; ++j) w.spans[j] = strip_span(g, w.scratch[0].x.data(), patch.half_length_m(j));
    w.spans_valid = true;
    w.spans_serial = patch_serial;
    w.rates_count = 0;
  }
  if (w.rates_count < strips || !w.rates_hold(rates_problem)) {
    w.rates.resize(g.ny);
    for (int j = 0; j < strips; ++j) w.rates[j] = strip_rates(patch, rates_problem, j);
    w.rates_count = strips;
    w.rates_creepages = rates_problem.creepages;
    w.rates_flex = rates_problem.flex;
    w.rates_L3x = rates_problem.L3x_m_per_Pa;
    w.rates_mu = rates_problem.mu;
    ++w.generation;
  }
}

// step_strip(j, thread) for the strips 0 .. strips - 1, shared among `threads` threads (the pool's helpers
// and the caller) in chunks; the first exception a strip throws is thrown again here
template <class StepStrip>
void for_each_strip(SatranWorkspace::Impl& w, int strips, int threads, const StepStrip& step_strip) {
  if (threads > 1) {
    if (!w.pool) w.pool = std::make_unique<StripPool>(threads - 1);
    constexpr int kChunk = 2;  // strips per claim
    std::mutex failure_mutex;
    std::exception_ptr failure;
    w.pool->run((strips + kChunk - 1) / kChunk, [&](int chunk, int worker) {
      try {
        for (int j = chunk * kChunk; j < std::min(strips, (chunk + 1) * kChunk); ++j) step_strip(j, worker);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
      }
    });
    if (failure) std::rethrow_exception(failure);
  } else {
    for (int j = 0; j < strips; ++j) step_strip(j, 0);
  }
}

// The strips from `strips` up as mirror images of those below, then every strip's totals summed in a fixed
// order (the same numbers for any thread count) into r's forces, powers and energies
void sum_strips(const ContactPatch& patch, const TangentialProblem& problem, SatranWorkspace& ws, int strips,
                bool load_held, bool fields, TransientState& state, StepResult& r) {
  const Grid& g = patch.grid;
  SatranWorkspace::Impl& w = *ws.impl;
  std::vector<StripEnergy>& energies = w.energies;
  const double dx = g.dx_m, L = problem.L_m_per_Pa;
  const bool defer = ws.defer_mirror && strips < g.ny;
  double E_start = 0, E_end = 0;  // sums of |tau|^2 over interior nodes
  bool hold = true;               // every strip's invariants (strip_totals_hold)
  for (int j = 0; j < g.ny; ++j) {
    if (!(patch.half_length_m(j) > 0)) continue;
    StripEnergy& e = energies[j];
    if (j >= strips) {  // tau(x, -y) = tau(x, y); Mz = integral(x tau_y) - y Fx
      const int m = g.ny - 1 - j;
      w.steady[j].unchanged = false;  // not stepped: its nodes are m's
      e = energies[m];
      e.Mz += (g.y_m(m) - g.y_m(j)) * e.Fx;
      if (!defer) mirror_strip(state, m, j);
      if (fields) {
        r.tau_x_Pa.col(j) = r.tau_x_Pa.col(m);
        r.tau_y_Pa.col(j) = r.tau_y_Pa.col(m);
        r.slip_x_m_per_s.col(j) = r.slip_x_m_per_s.col(m);
        r.slip_y_m_per_s.col(j) = r.slip_y_m_per_s.col(m);
      }
    }
    // finite, and within mu times the strip's load unless the load fell in this step (a falling load
    // leaves nodes above the new bound, which the step's path means carry before they slip back onto it).
    // Not asserted: an exact shift step's strip dissipation >= 0, which random histories break beyond
    // rounding (docs/satran.md, "Invariants")
    hold &= strip_totals_hold(patch, problem.mu, j, e, load_held, 0);
    r.strip_energy_J_per_m(j) = e.dissipated;
    r.creep_work_J += e.creep * g.dy_m;
    r.trailing_J += e.trailing * g.dy_m;
    r.transport_J += e.transport * g.dy_m;
    E_start += e.E_start;
    E_end += e.E_end;
  }
  state.mirror_deferred = defer;
  const PatchTotals totals =
      checked_patch_totals(patch, problem.mu, energies, hold, load_held, [](int) { return 0.0; });
  r.Fx_N = totals.Fx_N;
  r.Fy_N = totals.Fy_N;
  r.Mz_N_m = totals.Mz_N_m;
  r.dissipated_J = totals.dissipated;
  r.stick_fraction = totals.stick_fraction;
  r.elastic_change_J = L * dx / 2 * (E_end - E_start) * g.dy_m;
  r.balance_residual_J = r.dissipated_J - (r.creep_work_J - r.elastic_change_J - r.trailing_J - r.transport_J);
}

}  // namespace

StepResult satran_step(const ContactPatch& patch, const TangentialProblem& problem, const StepKinematics& k,
                       TransientScheme scheme, TransientState& state, bool fields, TransientSkips skips) {
  SatranWorkspace ws;
  return satran_step(patch, problem, k, scheme, state, fields, skips, ws);
}

StepResult satran_step(const ContactPatch& patch, const TangentialProblem& problem, const StepKinematics& k,
                       TransientScheme scheme, TransientState& state, bool fields, TransientSkips skips,
                       SatranWorkspace& ws) {
  const Grid& g = patch.grid;
  const double dx = g.dx_m, L = problem.L_m_per_Pa;
  const double cfl = k.dq_m / dx;
  check_step(g, state, k, cfl);
  SatranWorkspace::Impl& w = *ws.impl;
  StepResult r;
  r.strip_energy_J_per_m = Eigen::ArrayXd::Zero(g.ny);
  if (fields) allocate_fields(r, g);

  // the patch as the last step left it (the same serial): its symmetry is known, and the nodes outside its
  // contact hold nothing (the release below cleared them, and no step writes them)
  const bool same_patch = w.seen && w.serial == ws.patch_serial;
  if (!same_patch) w.first_mirrored = first_mirrored_strip(patch, 0.0);
  // without spin, on a mirror-symmetric patch and state, strips from `strips` up are mirror images
  const int strips = skips.mirrored && k.spin_rad == 0 && state.mirror_images ? w.first_mirrored : g.ny;
  const bool rescale = state.L_m_per_Pa > 0 && state.L_m_per_Pa != L;
  // the stale mirror images are read by the rescale, the release and a step that does not mirror
  if (rescale || !same_patch || strips == g.ny) fill_mirrored_strips(state);

  // a new flexibility rescales tau = u/L with u carried; where that lifts tau above the bound mu p of the
  // step's contact (L smaller), the node slips back onto the bound at once, and the step starts within it
  // (stress finding "rescale": the path means of the step exceeded mu F). The energy the springs lose
  // counts with the rescale's.
  if (rescale) r.flexibility_J = rescale_flexibility(patch, problem, state);
  state.L_m_per_Pa = L;
  // the bound mu p(x) is nowhere lower than at the last step's end where the load has not fallen
  const bool load_held = !(patch.normal_load_N < state.normal_load_N);
  state.normal_load_N = patch.normal_load_N;
  // nodes outside the current contact carry no traction
  if (!same_patch) release_outside_contact(patch, L, state, r.released_J);
  w.seen = true;
  w.serial = ws.patch_serial;

  const bool exact_shift = scheme == TransientScheme::Shift && cfl == 1.0;
  TangentialProblem rates_problem = problem;  // creepages per rolled distance for the shift kernel
  if (exact_shift) rates_problem.creepages = {k.slip_x_m / k.dq_m, k.slip_y_m / k.dq_m, k.spin_rad / k.dq_m};
  // the strips on `threads` threads where the grid is large enough, each with its scratch
  const int threads = g.nx * g.ny >= kSatranParallelCells ? std::max(1, ws.threads) : 1;
  // any strip's rates: eta/L2 and phi/L3 are the same on every strip
  const StripRates r0 = exact_shift ? strip_rates(patch, rates_problem, 0) : StripRates{};
  prepare_scratch(w, g, exact_shift, r0, threads);
  // the shift step compiled with or without spin (phi/L3 is the same on every strip), and without the
  // lateral work where tau_y = 0 stays 0: no lateral creepage or spin from a state without tau_y
  const bool spin = exact_shift && has_spin(r0);
  const bool lateral_free = state.lateral_free && k.slip_y_m == 0 && k.spin_rad == 0;
  if (exact_shift) w.edges.resize(kKeptIntervals * static_cast<size_t>(g.ny));
  auto shift_kinds = [&](int j, const StripRates& rj, ShiftScratch& scratch, bool* same) {
    StepResult* out = fields ? &r : nullptr;
    EdgeInterval* edge = &w.edges[kKeptIntervals * static_cast<size_t>(j)];
    const StripSpan& span = w.spans[j];
    const unsigned long gen = w.generation;
    if (spin) {
      return fields ? shift_strip<true, true, true>(patch, rj, j, L, k, scratch, state, out, edge, same, span, gen)
                    : shift_strip<false, true, true>(patch, rj, j, L, k, scratch, state, out, edge, same, span, gen);
    }
    if (lateral_free && skips.lateral) {
      return fields ? shift_strip<true, false, false>(patch, rj, j, L, k, scratch, state, out, edge, same, span, gen)
                    : shift_strip<false, false, false>(patch, rj, j, L, k, scratch, state, out, edge, same, span, gen);
    }
    return fields ? shift_strip<true, false, true>(patch, rj, j, L, k, scratch, state, out, edge, same, span, gen)
                  : shift_strip<false, false, true>(patch, rj, j, L, k, scratch, state, out, edge, same, span, gen);
  };
  const bool steady_skip = skips.steady_strips && !fields;
  w.steady.resize(g.ny);
  if (!exact_shift)  // an explicit step changes the nodes without asking
    for (SteadyStrip& st : w.steady) st.unchanged = false;
  const int variant = spin ? 2 : lateral_free && skips.lateral ? 0 : 1;
  // the strips' spans and rates where the patch or the rates' problem changed (the same numbers as computed
  // afresh: strip_rates of the same inputs)
  if (exact_shift) refresh_spans_and_rates(w, patch, rates_problem, strips, same_patch, ws.patch_serial);
  auto shift = [&](int j, ShiftScratch& scratch) {
    const StripRates& rj = w.rates[j];
    SteadyStrip& st = w.steady[j];
    if (steady_skip && st.holds(ws.patch_serial, variant, rj, L, k.dq_m)) return st.e;  // nodes as they are
    bool unchanged = false;
    bool* same = steady_skip ? &unchanged : nullptr;
    const StripEnergy e = shift_kinds(j, rj, scratch, same);
    st.unchanged = unchanged;
    if (!steady_skip) return e;  // nothing else is asked for
    st.serial = ws.patch_serial;
    st.variant = variant;
    st.r = rj;
    st.L = L;
    st.dq = k.dq_m;
    st.e = e;
    return e;
  };
  state.lateral_free = lateral_free;  // after this step (every scheme keeps tau_y = 0 then)
  state.mirror_images = strips < g.ny;  // after this step
  std::vector<StripEnergy>& energies = w.energies;
  energies.assign(g.ny, StripEnergy{});
  // the strips below `strips`, each on its own (on any thread: each writes its own nodes, fields and totals)
  auto step_strip = [&](int j, int thread) {
    if (!(patch.half_length_m(j) > 0)) return;
    energies[j] = exact_shift ? shift(j, w.scratch[thread])
                              : explicit_strip(patch, problem, j, k, scheme == TransientScheme::LaxFriedrichs, state,
                                               w.old[thread], fields ? &r : nullptr);
  };
  for_each_strip(w, strips, threads, step_strip);
  // the mirror images and the sums, strip by strip in a fixed order (the same numbers for any thread count)
  sum_strips(patch, problem, ws, strips, load_held, fields, state, r);
  return r;
}

}  // namespace contact
