// The worn revolution's dissipation, evaluated again and again over a life (cam/worn_revolution.h).
#include "cam/worn_revolution.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "cam/cam_life.h"
#include "lib/normal/normal.h"
#include "lib/numeric.h"

namespace cam {

namespace {

bool same(double a, double b) {
  if (a == b) return true;
  return std::abs(a - b) <= kSameInputRtol * std::max(std::abs(a), std::abs(b));
}

}  // namespace

WornRevolution::WornRevolution(const CamModel& m, const Revolution& r, const RollerMotion& motion,
                               const contact::Profiles& unworn, const CamWearGrid& g, const CreepLawSettings& law,
                               WornRevolutionOptions options)
    : model_(m), unworn_(unworn), grid_(g), options_(options) {
  if (motion.angles.size() != r.rows.size())
    throw std::invalid_argument("WornRevolution: the roller's motion does not match the revolution");
  check_grid(g);
  duration_s_ = 2 * contact::kPi / m.angle_steps / m.omega_rad_per_s;
  // the strips no wider than the unworn revolution's narrowest contact's (2 b / ny), as
  // worn_revolution_dissipation lays them
  double b_min = std::numeric_limits<double>::infinity();
  for (const RevolutionRow& row : r.rows) b_min = std::min(b_min, row.contact.b_m);
  law_ = worn_contact_settings(unworn, g, law, 2 * b_min / law.grid.ny);

  angles_.resize(r.rows.size());
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    Angle& a = angles_[i];
    a.row = r.rows[i];
    a.roller = motion.angles[i];
    a.cam_radius_m = cam_radius_m(a.row.kin);
    cell_weights(a.row.contact_arc_m, g.arc_cell_m(), g.arc_cells, true, a.a0, a.a1, a.wa);
    if (i > 0) {
      const Angle& p = angles_[i - 1];
      const RollerAngle &x = a.roller, &y = p.roller;
      a.same_inputs_as_previous = same(a.cam_radius_m, p.cam_radius_m) && same(x.normal_N, y.normal_N) &&
                                  same(x.tangential_N, y.tangential_N) && same(x.xi, y.xi) &&
                                  same(x.speed_m_per_s, y.speed_m_per_s) &&
                                  same(x.slip_speed_m_per_s, y.slip_speed_m_per_s) &&
                                  same(a.row.kin.rolling_speed_m_per_s, p.row.kin.rolling_speed_m_per_s) &&
                                  same(mu_at(model_, i), mu_at(model_, i - 1));
      if (a.same_inputs_as_previous) ++stats_.same_input_angles;
    }
  }
  const auto node_weights = [](const Eigen::ArrayXd& y, double width_m, double cell_m, int cells) {
    NodeWeights w;
    w.l0.resize(y.size());
    w.l1.resize(y.size());
    w.wl.resize(y.size());
    for (Eigen::Index i = 0; i < y.size(); ++i)
      cell_weights(y(i) + 0.5 * width_m, cell_m, cells, false, w.l0(i), w.l1(i), w.wl(i));
    return w;
  };
  roller_nodes_ = node_weights(unworn.body1.y_m, g.roller_width_m, g.roller_cell_m(), g.roller_cells);
  track_nodes_ = node_weights(unworn.body2.y_m, g.track_width_m, g.track_cell_m(), g.track_cells);
  track_rows_.resize(static_cast<std::size_t>(g.arc_cells));
  track_row_made_.assign(static_cast<std::size_t>(g.arc_cells), -1);
  solved_track_z_.resize(angles_.size());
  if (options_.skip_stride < 1 || !(options_.skip_power_rtol >= 0))
    throw std::invalid_argument("WornRevolution: skip_stride must be >= 1 and skip_power_rtol >= 0");
}

std::vector<double> WornRevolution::memory() const {
  const WornRevolutionStats& t = stats_;
  std::vector<double> m = {static_cast<double>(t.evaluations),     static_cast<double>(t.same_input_angles),
                           static_cast<double>(t.angles),          static_cast<double>(t.contacts_solved),
                           static_cast<double>(t.approach_evaluations), static_cast<double>(t.creep_evaluations),
                           static_cast<double>(t.cold_retries),    static_cast<double>(t.interpolated_angles)};
  m.reserve(kMemoryHead + kMemoryPerAngle * angles_.size());
  for (const Angle& a : angles_) {
    m.push_back(a.approach_m);
    m.push_back(a.approach_slope);
    m.push_back(a.xi);
    m.push_back(a.xi_known ? 1 : 0);
  }
  return m;
}

void WornRevolution::restore(const std::vector<double>& m) {
  if (m.size() != kMemoryHead + kMemoryPerAngle * angles_.size())
    throw std::invalid_argument("WornRevolution: a memory of " + std::to_string(m.size()) + " numbers is not one of " +
                                std::to_string(angles_.size()) + " angle steps (" +
                                std::to_string(kMemoryHead + kMemoryPerAngle * angles_.size()) + " numbers)");
  const auto count = [&](std::size_t i) { return static_cast<long>(m[i]); };
  stats_ = {count(0), count(1), count(2), count(3), count(4), count(5), count(6), count(7)};
  for (std::size_t i = 0; i < angles_.size(); ++i) {
    Angle& a = angles_[i];
    const double* v = m.data() + kMemoryHead + kMemoryPerAngle * i;
    a.approach_m = v[0];
    a.approach_slope = v[1];
    a.xi = v[2];
    a.xi_known = v[3] != 0;
  }
  // the rows made at an evaluation of the same count are another process's
  std::fill(track_row_made_.begin(), track_row_made_.end(), -1);
}

const Eigen::ArrayXd& WornRevolution::track_row_at_nodes(int arc_cell, const CamWearState& s) {
  const std::size_t c = static_cast<std::size_t>(arc_cell);
  Eigen::ArrayXd& row = track_rows_[c];
  if (track_row_made_[c] == stats_.evaluations) return row;
  const NodeWeights& w = track_nodes_;
  row.resize(w.wl.size());
  for (Eigen::Index i = 0; i < w.wl.size(); ++i)
    row(i) = (1 - w.wl(i)) * s.cam_depth_m(arc_cell, w.l0(i)) + w.wl(i) * s.cam_depth_m(arc_cell, w.l1(i));
  track_row_made_[c] = stats_.evaluations;
  return row;
}

RevolutionDissipation WornRevolution::operator()(const CamWearState& s) {
  if (s.cam_depth_m.rows() != grid_.arc_cells || s.cam_depth_m.cols() != grid_.track_cells ||
      s.roller_depth_m.size() != grid_.roller_cells)
    throw std::invalid_argument("WornRevolution: the state does not match the grid");
  ++stats_.evaluations;
  contact::Profiles worn = unworn_;
  // the roller's worn profile: the same at every angle
  {
    const NodeWeights& w = roller_nodes_;
    for (Eigen::Index i = 0; i < w.wl.size(); ++i)
      worn.body1.z_m(i) += (1 - w.wl(i)) * s.roller_depth_m(w.l0(i)) + w.wl(i) * s.roller_depth_m(w.l1(i));
  }
  const double load_rtol = law_.normal_load_rtol;
  const std::size_t n = angles_.size();
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  RevolutionDissipation out(n);
  // per angle: the angle whose solved contact its record is (itself when solved; kNone: interpolated)
  std::vector<std::size_t> source(n, kNone);
  std::size_t last_solved = kNone;  // the angle solved last, in the order solved
  double previous_approach = 0;     // its approach at the last evaluation

  // angle i solved, or given the contact of ref's source (an angle before i with a solved or shared record)
  // where every step from that source to i has the same inputs and the same track
  const auto compute = [&](std::size_t i, std::size_t ref) {
    Angle& a = angles_[i];
    ++stats_.angles;
    const Eigen::ArrayXd& r0 = track_row_at_nodes(a.a0, s);
    const Eigen::ArrayXd& r1 = track_row_at_nodes(a.a1, s);
    worn.body2.z_m = unworn_.body2.z_m + ((1 - a.wa) * r0 + a.wa * r1);

    const std::size_t src = ref == kNone ? kNone : source[ref];
    bool share = options_.share_contacts && src != kNone && solved_track_z_[src].size() == worn.body2.z_m.size();
    for (std::size_t k = src + 1; share && k <= i; ++k) share = angles_[k].same_inputs_as_previous;
    if (share)
      share = (worn.body2.z_m - solved_track_z_[src]).abs().maxCoeff() <= load_rtol * angles_[src].approach_m;
    if (share) {
      AngleDissipation d = out[src];
      d.theta_rad = a.row.kin.theta_rad;
      d.cam_arc_m = a.row.contact_arc_m;
      out[i] = std::move(d);
      source[i] = src;
      a.approach_m = angles_[src].approach_m;
      a.approach_slope = angles_[src].approach_slope;
      a.xi = angles_[src].xi;
      a.xi_known = angles_[src].xi_known;
      return;
    }

    CreepLawSettings law = law_;
    if (options_.warm_start) {
      // this angle's last approach, scaled as the angle solved before it changed since the last evaluation
      // (what wear did to every angle alike, e.g. the roller's wear)
      law.initial_approach_m = a.approach_m;
      if (a.approach_m > 0 && last_solved != kNone && previous_approach > 0 && angles_[last_solved].approach_m > 0)
        law.initial_approach_m = a.approach_m * (angles_[last_solved].approach_m / previous_approach);
      if (options_.warm_slope) law.initial_slope = a.approach_slope;
    }
    AngleContact c;
    try {
      c = angle_contact(model_.bodies, worn, model_.geometry.roller_radius_m, a.row.kin, a.roller.normal_N, mu_at(model_, i),
                        law);
    } catch (const contact::NormalSolveError&) {
      // a warm-started search that does not converge (F(delta) bends or jumps between the start and the
      // root: semi_hertz.h) is run again from the solver's own first approach, as a cold evaluation would
      if (!(law.initial_approach_m > 0)) throw;
      ++stats_.cold_retries;
      law.initial_approach_m = 0;
      law.initial_slope = 0;
      c = angle_contact(model_.bodies, worn, model_.geometry.roller_radius_m, a.row.kin, a.roller.normal_N, mu_at(model_, i),
                        law);
    }
    ++stats_.contacts_solved;
    stats_.approach_evaluations += c.normal.status.iterations;
    previous_approach = a.approach_m;
    a.approach_m = c.normal.patch.approach_m;
    a.approach_slope = c.normal.on_profiles.approach_slope;
    RollerAngle roller = a.roller;
    const CreepageForForce xi = options_.warm_start && a.xi_known ? creepage_for_force(c, roller.tangential_N, a.xi)
                                                                  : creepage_for_force(c, roller.tangential_N);
    stats_.creep_evaluations += xi.evaluations;
    if (xi.found) {
      roller.xi = xi.xi;
      roller.slip_speed_m_per_s = xi.xi * roller.speed_m_per_s;
      a.xi = xi.xi;
      a.xi_known = true;
    }
    out[i] = angle_dissipation(c, a.row, roller, duration_s_);
    solved_track_z_[i] = worn.body2.z_m;
    source[i] = i;
    last_solved = i;
  };

  // every stride-th angle (all of them without the skip), in order
  const std::size_t stride = static_cast<std::size_t>(options_.skip_stride);
  for (std::size_t i = 0; i < n; i += stride) compute(i, i == 0 ? kNone : i - stride);
  if (stride == 1) return out;

  // The skip: between two computed angles l < r (r == n is angle 0 of the next revolution, the revolution
  // being periodic) whose strip powers differ by at most skip_power_rtol of the largest strip power of the
  // computed angles, the angles are interpolated, linearly in the angle step; otherwise the middle one is
  // computed and both halves looked at again.
  double p_max = 0;
  for (std::size_t i = 0; i < n; i += stride) p_max = std::max(p_max, out[i].power_W_per_m.abs().maxCoeff());
  const double tol = options_.skip_power_rtol * p_max;
  const auto interpolate = [&](std::size_t k, std::size_t l, std::size_t r) {
    const AngleDissipation &A = out[l], &B = out[r % n];
    const Angle &al = angles_[l], &ar = angles_[r % n];
    Angle& a = angles_[k];
    const double w = static_cast<double>(k - l) / static_cast<double>(r - l);
    ++stats_.angles;
    ++stats_.interpolated_angles;
    const double xi = al.xi_known && ar.xi_known ? (1 - w) * al.xi + w * ar.xi : a.roller.xi;
    RollerAngle roller = a.roller;  // at the interpolated creepage, as a solved angle's at its own
    roller.slip_speed_m_per_s = xi * roller.speed_m_per_s;
    AngleDissipation d = angle_step(a.row, roller, duration_s_);
    d.y_m = A.y_m;
    d.power_W_per_m = (1 - w) * A.power_W_per_m + w * B.power_W_per_m;
    d.mean_pressure_Pa = (1 - w) * A.mean_pressure_Pa + w * B.mean_pressure_Pa;
    out[k] = std::move(d);
    // the next evaluation's warm start: between the neighbours'
    a.approach_m = (1 - w) * al.approach_m + w * ar.approach_m;
    a.approach_slope = (1 - w) * al.approach_slope + w * ar.approach_slope;
    if (al.xi_known && ar.xi_known) {
      a.xi = xi;
      a.xi_known = true;
    }
  };
  const std::function<void(std::size_t, std::size_t)> refine = [&](std::size_t l, std::size_t r) {
    if (r - l < 2) return;
    const AngleDissipation &A = out[l], &B = out[r % n];
    const bool close = A.power_W_per_m.size() == B.power_W_per_m.size() && A.y_m.size() == B.y_m.size() &&
                       (A.y_m - B.y_m).abs().maxCoeff() <= kSameInputRtol * A.y_m.abs().maxCoeff() &&
                       (A.power_W_per_m - B.power_W_per_m).abs().maxCoeff() <= tol;
    if (close) {
      for (std::size_t k = l + 1; k < r; ++k) interpolate(k, l, r);
      return;
    }
    const std::size_t m = (l + r) / 2;
    compute(m, l);
    refine(l, m);
    refine(m, r);
  };
  for (std::size_t l = 0; l < n; l += stride) refine(l, std::min(l + stride, n));
  return out;
}

}  // namespace cam
