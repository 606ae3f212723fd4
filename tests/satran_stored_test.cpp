// Satran's numbers kept while its step is made faster: short runs that go through every path of the step
// (the shift step with and without the mirror and lateral skips, spin, a load that changes the contact and
// the flexibility, fallback and standstill steps, the roller's inertia, the explicit schemes, the fields of
// a snapshot, one and two threads) against values stored from the code before the work on its speed
// (tests/data/satran_stored/*.txt). Every record's forces, moment, power and stick fraction, the run's strip
// energies, the snapshot's fields and the final state's tractions must equal the stored ones to 1e-12
// relative (of the largest of their kind): only the order of sums may change.
//
// To write the files again (only from code whose numbers are the reference): ROLLWEAR_WRITE_STORED=1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "lib/normal/hertz.h"
#include "lib/tangential/satran.h"

namespace contact {
namespace {

// the same arithmetic in another order of sums: far below any error the solver is asked for
constexpr double kStoredRel = 1e-12;

struct Column {
  std::string name;
  std::vector<double> v;
};

TransientCase base_case(int n, double xi, double eta, double phi) {
  TransientCase tc;
  tc.bodies = {{0.020, 0.500}, {0.025, kFlat}};
  tc.materials = {{210e9, 0.28}, {210e9, 0.28}};
  tc.mu = 0.3;
  tc.inputs.speed_m_per_s = constant_history(1.8);
  tc.inputs.xi = constant_history(xi);
  tc.inputs.eta = constant_history(eta);
  tc.inputs.phi_per_m = constant_history(phi);
  tc.inputs.normal_load_N = constant_history(1500);
  tc.settings.grid = {n, n};
  return tc;
}

History table(std::vector<double> t, std::vector<double> v) { return History{std::move(t), std::move(v)}; }

// the columns of a run: its records, strip energies, the last snapshot's fields and the final state
std::vector<Column> columns_of(const TransientCase& tc, bool with_state = true) {
  std::vector<Column> c = {{"Fx", {}}, {"Fy", {}}, {"Mz", {}}, {"power", {}}, {"stick", {}}, {"dt", {}}};
  const TransientResult res = run_transient(tc, [&](const TransientRecord& r, const Eigen::ArrayXd&) {
    c[0].v.push_back(r.Fx_N);
    c[1].v.push_back(r.Fy_N);
    c[2].v.push_back(r.Mz_N_m);
    c[3].v.push_back(r.power_W);
    c[4].v.push_back(r.stick_fraction);
    c[5].v.push_back(r.dt_s);
  });
  c.push_back({"strip_energy", {res.strip_energy_J_per_m.begin(), res.strip_energy_J_per_m.end()}});
  c.push_back({"dissipated", {res.dissipated_J}});
  if (!with_state) return c;
  if (!res.snapshots.empty()) {
    const Snapshot& s = res.snapshots.back();
    for (const auto& [name, f] : {std::pair<const char*, const Eigen::ArrayXXd*>{"tau_x", &s.tau_x_Pa},
                                  {"tau_y", &s.tau_y_Pa},
                                  {"slip_x", &s.slip_x_m_per_s},
                                  {"slip_y", &s.slip_y_m_per_s}})
      c.push_back({name, {f->data(), f->data() + f->size()}});
  }
  Column tx{"state_tx", {}}, ty{"state_ty", {}}, stick{"state_stick", {}};
  for (const StripNode& n : res.final_state.nodes) {
    tx.v.push_back(n.tx);
    ty.v.push_back(n.ty);
    stick.v.push_back(n.stick ? 1 : 0);
  }
  c.push_back(tx);
  c.push_back(ty);
  c.push_back(stick);
  return c;
}

std::string stored_path(const std::string& name) {
  return std::string(ROLLWEAR_SOURCE_DIR) + "/tests/data/satran_stored/" + name + ".txt";
}

void write_stored(const std::string& name, const std::vector<Column>& cols) {
  std::ofstream out(stored_path(name));
  char buf[64];
  for (const Column& c : cols) {
    out << c.name << ' ' << c.v.size();
    for (double v : c.v) {
      std::snprintf(buf, sizeof buf, " %.17g", v);
      out << buf;
    }
    out << '\n';
  }
}

std::vector<Column> read_stored(const std::string& name) {
  std::ifstream in(stored_path(name));
  std::vector<Column> cols;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    Column c;
    size_t n = 0;
    s >> c.name >> n;
    c.v.resize(n);
    for (double& v : c.v) s >> v;
    cols.push_back(std::move(c));
  }
  return cols;
}

// every column equal to the stored one to kStoredRel of its largest magnitude
void expect_stored(const std::string& name, const TransientCase& tc, bool with_state = true) {
  const std::vector<Column> got = columns_of(tc, with_state);
  if (std::getenv("ROLLWEAR_WRITE_STORED")) {
    write_stored(name, got);
    GTEST_SKIP() << "wrote " << stored_path(name);
  }
  const std::vector<Column> want = read_stored(name);
  ASSERT_EQ(got.size(), want.size()) << name << ": missing " << stored_path(name) << "?";
  for (size_t k = 0; k < got.size(); ++k) {
    const Column &g = got[k], &w = want[k];
    ASSERT_EQ(g.name, w.name);
    ASSERT_EQ(g.v.size(), w.v.size()) << name << " " << g.name;
    double scale = 0;
    for (double v : w.v) scale = std::max(scale, std::abs(v));
    int bad = 0;
    for (size_t i = 0; i < g.v.size() && bad < 5; ++i)
      if (!(std::abs(g.v[i] - w.v[i]) <= kStoredRel * scale)) {
        ++bad;
        ADD_FAILURE() << name << " " << g.name << "[" << i << "]: " << g.v[i] << " stored " << w.v[i];
      }
  }
}

// the paper's start from rest (pure xi: the mirror and lateral skips), a speed that ramps, runs and stops
// (fallback and standstill steps), snapshot fields on the way
TEST(SatranStored, PureXiStartAndStop) {
  TransientCase tc = base_case(24, 1e-3, 0, 0);
  tc.inputs.speed_m_per_s = table({0, 1e-4, 5e-4, 6e-4}, {0, 1.8, 1.8, 0});
  tc.settings.t_end_s = 7e-4;
  tc.settings.dt_s = 2e-5;
  tc.settings.snapshot_times_s = {3e-4};
  expect_stored("pure_xi_start_stop", tc);
}

// the same with every skip off
TEST(SatranStored, PureXiEverySkipOff) {
  TransientCase tc = base_case(24, 1e-3, 0, 0);
  tc.settings.t_end_s = 3e-4;
  tc.settings.skips = {false, false};
  tc.settings.snapshot_times_s = {2e-4};
  expect_stored("pure_xi_skips_off", tc);
}

// xi, eta, phi with the speed and the creepages varying (spin: the whole kernel, re-sticking)
TEST(SatranStored, SpinVaryingSpeed) {
  TransientCase tc = base_case(24, 1e-3, 5e-4, 0.5);
  tc.inputs.speed_m_per_s = ramp_history(0, 0.9, 4e-4, 1.8);
  tc.inputs.phi_per_m = table({0, 2e-4, 4e-4}, {0.5, -2.0, 3.0});
  tc.inputs.xi = table({0, 3e-4}, {1e-3, 2e-3});
  tc.settings.t_end_s = 4e-4;
  tc.settings.snapshot_times_s = {3e-4};
  expect_stored("spin_varying_speed", tc);
}

// a load that rises and falls (new contacts: released nodes, rescaled tractions clipped to the bound), pure
// xi then a lateral creepage (the mirror and lateral skips end)
TEST(SatranStored, VaryingLoadThenLateral) {
  TransientCase tc = base_case(20, 1e-3, 0, 0);
  tc.inputs.normal_load_N = table({0, 1e-4, 2e-4}, {1500, 900, 1800});
  tc.inputs.eta = table({0, 2.5e-4, 2.6e-4}, {0, 0, 4e-4});
  tc.settings.t_end_s = 3.5e-4;
  tc.settings.snapshot_times_s = {3e-4};
  expect_stored("varying_load_then_lateral", tc);
}

// the roller spun up by its creep force (implicit steps, the state copied for each trial)
TEST(SatranStored, Inertia) {
  TransientCase tc = base_case(16, 0, 0, 0);
  RollerInertia in;
  in.R1_m = 0.02;
  in.J1_kg_m2 = 2e-5;
  in.path_speed_m_per_s = constant_history(1.0);
  tc.inertia = in;
  tc.settings.t_end_s = 1e-4;
  tc.settings.dt_s = 4e-6;
  expect_stored("inertia", tc);
}

// the explicit schemes
TEST(SatranStored, UpwindAndLaxFriedrichs) {
  TransientCase tc = base_case(16, 1e-3, 3e-4, 0.4);
  tc.settings.t_end_s = 1e-4;
  tc.settings.dt_s = 5e-6;
  tc.settings.scheme = TransientScheme::Upwind;
  tc.settings.substep = true;
  tc.settings.snapshot_times_s = {5e-5};
  expect_stored("upwind", tc);
  tc.settings.scheme = TransientScheme::LaxFriedrichs;
  expect_stored("lax_friedrichs", tc);
}

// a grid large enough for the strips to be shared between threads: the records and strip energies (the
// state and fields of 160 x 160 would make a large file; their bit-identity across thread counts is
// SatranThreads' test)
TEST(SatranStored, LargeGridSpin) {
  TransientCase tc = base_case(160, 1e-3, 5e-4, 0.5);
  tc.settings.t_end_s = 2.5e-5;
  expect_stored("large_grid_spin", tc, false);
  tc.inputs.eta = tc.inputs.phi_per_m = constant_history(0.0);
  expect_stored("large_grid_xi", tc, false);
}

// The steady strips' skip (TransientSkips::steady_strips) changes nothing, to the bit, where the strips settle
// and then every input the skip compares changes in turn: xi (the rates), the load (the patch and L), eta (the
// lateral work), the speed (none: rates per rolled distance), spin; with the fallback and standstill steps
// of a stop in between. Checked to fail when the skip ignores what it compares.
TEST(SatranSkip, SteadyStripsChangeNothing) {
  TransientCase tc = base_case(24, 1e-3, 0, 0);
  tc.inputs.xi = table({0, 8e-4, 8.01e-4}, {1e-3, 1e-3, 2e-3});
  tc.inputs.normal_load_N = table({0, 1.3e-3, 1.31e-3}, {1500, 1500, 1200});
  tc.inputs.eta = table({0, 1.8e-3, 1.81e-3}, {0, 0, 3e-4});
  tc.inputs.phi_per_m = table({0, 2.6e-3, 2.61e-3}, {0, 0, 0.4});
  tc.inputs.speed_m_per_s = table({0, 2.2e-3, 2.3e-3, 2.4e-3, 3.1e-3}, {1.8, 1.8, 0, 0, 1.0});
  tc.settings.t_end_s = 3.4e-3;
  tc.settings.dt_s = 2e-5;
  tc.settings.snapshot_times_s = {7e-4};
  const std::vector<Column> with = columns_of(tc);
  tc.settings.skips.steady_strips = false;
  const std::vector<Column> without = columns_of(tc);
  ASSERT_EQ(with.size(), without.size());
  for (size_t k = 0; k < with.size(); ++k) {
    ASSERT_EQ(with[k].v.size(), without[k].v.size()) << with[k].name;
    size_t differ = 0;
    for (size_t i = 0; i < with[k].v.size(); ++i)
      differ += std::memcmp(&with[k].v[i], &without[k].v[i], sizeof(double)) != 0;
    EXPECT_EQ(differ, 0u) << with[k].name;
  }
}

// The strips of a large grid shared between threads give the same numbers to the bit as one thread: every
// strip computes alone, and the sums run strip by strip in one order (docs/benchmarks.md)
TEST(SatranThreads, SameBitsForAnyThreadCount) {
  for (const bool spin : {true, false}) {
    TransientCase tc = base_case(160, 1e-3, spin ? 5e-4 : 0.0, spin ? 0.5 : 0.0);
    tc.settings.t_end_s = 2.5e-5;
    tc.settings.snapshot_times_s = {2e-5};
    tc.settings.threads = 1;
    const std::vector<Column> one = columns_of(tc);
    for (const int threads : {2, 3}) {
      tc.settings.threads = threads;
      const std::vector<Column> more = columns_of(tc);
      ASSERT_EQ(one.size(), more.size());
      for (size_t k = 0; k < one.size(); ++k) {
        ASSERT_EQ(one[k].v.size(), more[k].v.size());
        size_t differ = 0;
        for (size_t i = 0; i < one[k].v.size(); ++i) differ += one[k].v[i] != more[k].v[i];
        EXPECT_EQ(differ, 0u) << one[k].name << " with " << threads << " threads" << (spin ? " (spin)" : "");
      }
    }
  }
}

// a sweep's thread runs its cases on itself alone: set_satran_threads is the thread's, and 0 restores every core
TEST(SatranThreads, ThreadCountIsTheCallingThreads) {
  const int all = satran_threads();
  EXPECT_GE(all, 1);
  set_satran_threads(1);
  EXPECT_EQ(satran_threads(), 1);
  int other = 0;
  std::thread([&] { other = satran_threads(); }).join();
  EXPECT_EQ(other, all);
  set_satran_threads(0);
  EXPECT_EQ(satran_threads(), all);
}

}  // namespace
}  // namespace contact
