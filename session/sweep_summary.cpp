#include "session/sweep_summary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <spdlog/fmt/fmt.h>

#include "lib/number.h"
#include "session/sweep.h"
#include "session/sweep_random.h"
#include "wear/wear_loop.h"

namespace session {

using namespace wear;  // the wear case, its model and its life

using contact::round_trip;

// ---- summaries ----

namespace {

struct TableRow {
  long index = 0;
  std::vector<double> inputs;
  double life = 0;
  bool censored = false;
  bool ok = false;
};

std::vector<std::string> split_fields(const std::string& line, std::size_t count) {
  std::vector<std::string> f;
  std::size_t at = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t comma = line.find(',', at);
    f.push_back(line.substr(at, comma == std::string::npos ? std::string::npos : comma - at));
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  return f;
}

double to_double(const std::string& t) {
  try {
    return std::stod(t);
  } catch (const std::exception&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

// Kaplan-Meier: the smallest life at which the estimated fraction failed reaches p; +inf when it never does
double km_quantile(std::vector<std::pair<double, bool>> lives, double p) {  // (life, censored)
  for (const KaplanMeierStep& s : kaplan_meier(std::move(lives)))
    if (s.failed_fraction >= p - 1e-12) return s.life;
  return std::numeric_limits<double>::infinity();
}

std::string life_text(double v) { return std::isinf(v) ? "beyond the budget (censored)" : fmt::format("{:.4g}", v); }

}  // namespace

std::vector<KaplanMeierStep> kaplan_meier(std::vector<std::pair<double, bool>> lives) {
  std::sort(lives.begin(), lives.end(), [](const auto& a, const auto& b) {
    return a.first < b.first || (a.first == b.first && !a.second && b.second);  // failures before censoring at a tie
  });
  std::vector<KaplanMeierStep> steps;
  double survival = 1;
  std::size_t at_risk = lives.size();
  for (const auto& [t, censored] : lives) {
    if (!censored) {
      survival *= 1 - 1.0 / static_cast<double>(at_risk);
      steps.push_back({t, 1 - survival});
    }
    --at_risk;
  }
  return steps;
}

namespace {

// a contact sweep's summary: the cases, those not ok, and each output's range over the ok ones
std::string contact_summary(const std::string& results_csv) {
  std::istringstream table(results_csv);
  std::string header;
  std::getline(table, header);
  const std::vector<std::string> head = split_fields(header, 1000);
  constexpr std::size_t kOutputs = 9;  // a_m ... stick_fraction (session/sweep.h ContactOutputs)
  if (head.size() < kOutputs + 3) throw std::invalid_argument("sweep_summary: not a contact sweep's results table");
  const std::size_t first = head.size() - kOutputs - 2;
  std::vector<double> lo(kOutputs, std::numeric_limits<double>::infinity()), hi(kOutputs, -std::numeric_limits<double>::infinity());
  long cases = 0, not_ok = 0;
  for (std::string line; std::getline(table, line);) {
    if (line.empty()) continue;
    ++cases;
    const std::vector<std::string> f = split_fields(line, first + kOutputs + 1);
    if (f.size() < first + kOutputs + 1 || f[first + kOutputs] != "ok") {
      ++not_ok;
      continue;
    }
    for (std::size_t k = 0; k < kOutputs; ++k) {
      const double v = to_double(f[first + k]);
      lo[k] = std::min(lo[k], v);
      hi[k] = std::max(hi[k], v);
    }
  }
  std::string out = fmt::format("contact sweep: {} cases, {} not ok (left out below)\n", cases, not_ok);
  if (cases > not_ok)
    for (std::size_t k = 0; k < kOutputs; ++k) out += fmt::format("  {:<16} {:.6g} to {:.6g}\n", head[first + k], lo[k], hi[k]);
  return out;
}

}  // namespace

std::string sweep_summary(const std::string& results_csv, const std::string& sweep_txt) {
  if (sweep_txt.find("\nkind contact\n") != std::string::npos) return contact_summary(results_csv);
  // sweep.txt
  std::istringstream info(sweep_txt);
  std::string sampling = "product", word;
  std::uint64_t seed = 0;
  struct AxisInfo {
    std::string key;
    long size = 0;
    double base = 0;
  };
  std::vector<AxisInfo> axes;
  for (std::string line; std::getline(info, line);) {
    std::istringstream l(line);
    l >> word;
    if (word == "sampling") l >> sampling;
    else if (word == "seed") l >> seed;
    else if (word == "axis") {
      AxisInfo a;
      std::string base;
      l >> a.key >> a.size >> base;
      a.base = to_double(base);
      axes.push_back(a);
    }
  }
  // results.csv
  std::istringstream table(results_csv);
  std::string header;
  std::getline(table, header);
  const std::vector<std::string> head = split_fields(header, 1000);
  if (head.size() < 7) throw std::invalid_argument("sweep_summary: not a results table");
  // the inputs run from after the index to life_revolutions; the margin columns (with the failure margins) follow
  // worn_volume_m3
  const auto life_column = std::find(head.begin(), head.end(), "life_revolutions");
  if (life_column == head.end()) throw std::invalid_argument("sweep_summary: not a results table (no life_revolutions)");
  const std::size_t k = static_cast<std::size_t>(life_column - head.begin()) - 1;
  const std::size_t status_column = head.size() - 2;  // status, message last
  const std::vector<std::string> keys(head.begin() + 1, head.begin() + 1 + static_cast<long>(k));
  std::vector<TableRow> rows;
  for (std::string line; std::getline(table, line);) {
    if (line.empty()) continue;
    const std::vector<std::string> f = split_fields(line, head.size());
    TableRow r;
    r.index = row_index(line);
    for (std::size_t a = 0; a < k; ++a) r.inputs.push_back(to_double(f[1 + a]));
    r.life = to_double(f[1 + k]);
    const LifeEnd end = parse_life_end(f[2 + k]);
    r.censored = end == LifeEnd::Revolutions || end == LifeEnd::MaxSteps;
    r.ok = parse_case_status(f[status_column]) == CaseStatus::Ok;
    rows.push_back(r);
  }
  std::vector<const TableRow*> ok;
  for (const TableRow& r : rows)
    if (r.ok) ok.push_back(&r);
  std::string out = fmt::format("# summary of {} cases: {} ok, {} not ok (left out of every number below)\n", rows.size(),
                                ok.size(), rows.size() - ok.size());
  out += "# sampling: " + sampling + "\n";
  if (ok.empty()) return out + "no case ended ok: no summary\n";

  if (sampling == "monte-carlo" || sampling == "latin-hypercube") {
    std::vector<std::pair<double, bool>> lives;
    long censored = 0;
    for (const TableRow* r : ok) {
      lives.emplace_back(r->life, r->censored);
      censored += r->censored;
    }
    out += fmt::format("censored lives (reached wear.revolutions or max_steps; Kaplan-Meier): {}\n", censored);
    for (const double p : {0.1, 0.5}) {
      const double estimate = km_quantile(lives, p);
      std::vector<double> resampled;
      for (int b = 0; b < kBootstrapResamples; ++b) {
        std::vector<std::pair<double, bool>> draw;
        for (std::size_t j = 0; j < lives.size(); ++j)
          draw.push_back(lives[std::min(lives.size() - 1, static_cast<std::size_t>(
                                                              unit_uniform(seed, static_cast<std::uint64_t>(b), 1000 + j) *
                                                              static_cast<double>(lives.size())))]);
        resampled.push_back(km_quantile(draw, p));
      }
      std::sort(resampled.begin(), resampled.end());
      const auto at = [&](double q) { return resampled[static_cast<std::size_t>(q * (kBootstrapResamples - 1) + 0.5)]; };
      out += fmt::format("B{:.0f} life: {} revolutions (95 % bootstrap interval {} .. {}, {} resamples)\n", p * 100,
                         life_text(estimate), life_text(at(0.025)), life_text(at(0.975)), kBootstrapResamples);
    }
    std::vector<double> life;
    for (const TableRow* r : ok) life.push_back(r->life);
    for (std::size_t a = 0; a < k && ok.size() >= 2; ++a) {
      std::vector<double> x;
      for (const TableRow* r : ok) x.push_back(r->inputs[a]);
      out += fmt::format("spearman {} vs life: {:.3f}\n", keys[a], spearman(x, life));
    }
    return out;
  }
  if (sampling != "product" || axes.size() != k) return out + "(elasticities: for a product grid only)\n";

  // the grid: the multi-index of each row (the last axis fastest), the base point nearest the base case
  std::map<long, const TableRow*> by_index;
  for (const TableRow& r : rows) by_index[r.index] = &r;
  const auto value_at = [&](std::size_t a, long j) -> double {  // axis a's j-th value, read from a row that has it
    long stride = 1;
    for (std::size_t b = a + 1; b < k; ++b) stride *= axes[b].size;
    const auto it = by_index.find(j * stride);
    return it == by_index.end() ? std::numeric_limits<double>::quiet_NaN() : it->second->inputs[a];
  };
  std::vector<long> centre(k);
  for (std::size_t a = 0; a < k; ++a) {
    centre[a] = (axes[a].size - 1) / 2;  // the middle, when the base case does not give the key
    if (!std::isnan(axes[a].base)) {
      double best = std::numeric_limits<double>::infinity();
      for (long j = 0; j < axes[a].size; ++j) {
        const double d = std::abs(value_at(a, j) - axes[a].base);
        if (d < best) best = d, centre[a] = j;
      }
    }
  }
  const auto row_at = [&](const std::vector<long>& idx) -> const TableRow* {
    long i = 0;
    for (std::size_t a = 0; a < k; ++a) i = i * axes[a].size + idx[a];
    const auto it = by_index.find(i);
    return it == by_index.end() || !it->second->ok ? nullptr : it->second;
  };
  const TableRow* c = row_at(centre);
  std::string point;
  for (std::size_t a = 0; a < k; ++a) point += (a ? ", " : "") + keys[a] + " = " + round_trip(value_at(a, centre[a]));
  out += "elasticities d ln(life) / d ln(x) about the grid point nearest the base case (" + point + ")" +
         (c ? fmt::format(", life {:.4g} revolutions", c->life) : std::string(", which did not end ok")) + ":\n";
  for (std::size_t a = 0; a < k; ++a) {
    if (axes[a].size < 2) continue;
    std::vector<long> lo = centre, hi = centre;
    lo[a] = std::max(0L, centre[a] - 1);
    hi[a] = std::min(axes[a].size - 1, centre[a] + 1);
    const TableRow *rl = row_at(lo), *rh = row_at(hi);
    const char* kind = lo[a] < centre[a] && hi[a] > centre[a] ? "central" : "one-sided";
    if (!rl || !rh || !(rl->inputs[a] > 0) || !(rh->inputs[a] > 0) || !(rl->life > 0) || !(rh->life > 0)) {
      out += fmt::format("  {}: n/a (a neighbour did not end ok, or a value is not positive)\n", keys[a]);
      continue;
    }
    const double e = (std::log(rh->life) - std::log(rl->life)) / (std::log(rh->inputs[a]) - std::log(rl->inputs[a]));
    out += fmt::format("  {}: {:.4f} ({}, between {} and {})\n", keys[a], e, kind, round_trip(rl->inputs[a]), round_trip(rh->inputs[a]));
  }
  return out;
}

}  // namespace session
