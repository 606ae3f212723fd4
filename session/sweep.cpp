#include "session/sweep.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <condition_variable>
#include <exception>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <spdlog/spdlog.h>

#include "lib/io/case_run.h"
#include "lib/io/case_node.h"
#include "lib/io/csv.h"
#include "lib/errors.h"
#include "lib/number.h"
#include "lib/io/yaml_reader.h"
#include "lib/normal/profile.h"
#include "lib/tangential/satran.h"
#include "wear/wear_case.h"
#include "wear/wear_loop.h"
#include "wear/wear_output.h"
#include "session/output_folder.h"
#include "session/sweep_random.h"
#include "session/sweep_summary.h"
#include "session/wear_life_run.h"

namespace session {

using namespace wear;  // the wear case, its model and its life

using contact::CaseError;
using contact::YamlMap;
using contact::YamlValue;
using contact::round_trip;

namespace {
// a separate stream for the Latin hypercube's permutations (a key no input index reaches)
constexpr std::uint64_t kPermutationStream = 0x5157a11e00000000ull;
}  // namespace

// ---- the sweep file ----

namespace {

const std::set<std::string>& distribution_names() {
  static const std::set<std::string> k = {"uniform", "normal", "lognormal", "truncated-normal"};
  return k;
}

std::string finite(double v) { return std::isfinite(v) ? "" : "must be finite"; }

std::string key_path_check(const std::string& key) {
  if (key.empty() || key.front() == '.' || key.back() == '.' || key.find("..") != std::string::npos)
    return "must be a key path of the case, e.g. friction.mu";
  return "";
}

// values of one grid axis: values, linear or log
void read_axis_values(YamlMap& a, SweepAxis& axis) {
  int forms = 0;
  a.optional_value("values", [&](const YamlValue& v) {
    ++forms;
    const std::vector<YamlValue> e = v.elements("a list of numbers, e.g. [0.2, 0.3]");
    if (e.empty()) v.fail("needs at least one value");
    for (std::size_t k = 0; k < e.size(); ++k)
      axis.values.push_back(e[k].as<double>(finite, "element " + std::to_string(k + 1)));
  });
  for (const bool logarithmic : {false, true}) {
    a.optional_section(logarithmic ? "log" : "linear", [&](YamlMap& r) {
      ++forms;
      double from = 0, to = 0;
      int count = 0;
      const auto check = logarithmic ? contact::positive_finite : finite;
      r.required("from", from, check);
      r.required("to", to, check);
      r.required("count", count, [](int n) { return n >= 1 ? "" : "must be >= 1"; });
      for (int k = 0; k < count; ++k) {
        const double t = count == 1 ? 0.0 : static_cast<double>(k) / (count - 1);
        double v = logarithmic ? std::exp(std::log(from) + (std::log(to) - std::log(from)) * t) : from + (to - from) * t;
        if (k == 0) v = from;
        if (k == count - 1 && count > 1) v = to;  // the ends as written
        axis.values.push_back(v);
      }
    });
  }
  if (forms != 1) a.fail_here("give exactly one of values: [...], linear: {from, to, count} or log: {from, to, count}");
}

std::filesystem::path resolve_base(const std::string& sweep_path, const std::string& base) {
  const std::filesystem::path p = std::filesystem::path(base).is_absolute() ? std::filesystem::path(base)
                                                                            : std::filesystem::path(sweep_path).parent_path() / base;
  return p.lexically_normal();
}

void read_input(YamlMap& m, RandomInput& in) {
  std::string name;
  m.required("distribution", name, [](const std::string& d) {
    return distribution_names().count(d) ? "" : "must be one of uniform, normal, lognormal, truncated-normal";
  });
  if (name == "uniform" || name == "truncated-normal") {
    m.required("min", in.min, finite);
    m.required("max", in.max, finite);
    if (!(in.max > in.min)) m.fail("max", "must be > min (" + round_trip(in.min) + "), got " + round_trip(in.max));
  }
  if (name == "normal" || name == "truncated-normal") {
    m.required("mean", in.mean, finite);
    m.required("sd", in.sd, contact::positive_finite);
  }
  if (name == "lognormal") {
    m.required("median", in.median, contact::positive_finite);
    m.required("sigma_ln", in.sigma_ln, contact::positive_finite);
  }
  in.distribution = name == "uniform"  ? Distribution::Uniform
                    : name == "normal" ? Distribution::Normal
                    : name == "lognormal" ? Distribution::LogNormal
                                          : Distribution::TruncatedNormal;
  if (in.distribution == Distribution::TruncatedNormal &&
      !(normal_cdf((in.max - in.mean) / in.sd) - normal_cdf((in.min - in.mean) / in.sd) > 1e-12))
    m.fail_here("[min, max] holds no probability of the normal (mean, sd): move the bounds nearer the mean");
}

// the case's report.txt has the failure margins (wear::failure_margins: wear.fatigue, wear.limits.shakedown or
// wear.limits.scuffing true, or a thermal: section), read from its text so that a case refused as bad input has
// the columns too
bool has_failure_margins(const YAML::Node& doc) {
  if (!doc.IsMap()) return false;
  if (doc["thermal"]) return true;
  const YAML::Node w = doc["wear"];
  if (!w || !w.IsMap()) return false;
  if (w["fatigue"]) return true;
  const YAML::Node limits = w["limits"];
  if (!limits || !limits.IsMap()) return false;
  for (const char* key : {"shakedown", "scuffing"}) {
    try {
      if (limits[key] && limits[key].as<bool>()) return true;
    } catch (const std::exception&) {
      return true;  // not a boolean: the case is refused, its row has the columns all the same
    }
  }
  return false;
}

}  // namespace

Sweep read_sweep(const std::string& path) {
  Sweep s;
  s.path = path;
  std::string base;
  bool has_axes = false, has_random = false;
  std::set<std::string> keys;
  const auto add_key = [&](const YamlMap& m, const std::string& key) {
    if (!keys.insert(key).second) m.fail("key", "'" + key + "' is varied twice");
  };
  contact::read_yaml_file(path, nullptr, [&](YamlMap& m) {
    m.required("base", base);
    // the kind of the cases: a contact sweep when the base case has no wear: section (a base that cannot be
    // read is refused by validate_cases, naming it)
    try {
      const YAML::Node b = contact::load_yaml_file(resolve_base(path, base).string());
      if (b.IsMap() && !b["wear"]) s.kind = SweepKind::Contact;
      if (b.IsMap() && b["wear"]) s.margins = has_failure_margins(b);
    } catch (const std::exception&) {
    }
    m.optional_section("output", [&](YamlMap& o) {
      o.optional("directory", s.output_directory);
      o.optional("case_files", s.case_files);
      if (!s.case_files && s.kind != SweepKind::Contact)
        o.fail("case_files", "false applies to a contact sweep (a base case without wear:); a wear sweep writes each case's folder");
    });
    std::string combine = "product";
    m.optional("combine", combine, [](const std::string& c) { return c == "product" || c == "zip" ? "" : "must be product or zip"; });
    s.combine = combine == "zip" ? Combine::Zip : Combine::Product;
    has_axes = m.optional_value("axes", [&](const YamlValue& v) {
      const std::vector<YamlValue> e = v.elements("a list of axes, e.g. - { key: friction.mu, values: [0.2, 0.3] }");
      if (e.empty()) v.fail("needs at least one axis");
      for (const YamlValue& a : e)
        a.mapping([&](YamlMap& am) {
          SweepAxis axis;
          axis.location = a.location();
          am.required("key", axis.key, key_path_check);
          add_key(am, axis.key);
          read_axis_values(am, axis);
          s.axes.push_back(std::move(axis));
        });
      if (s.combine == Combine::Zip)
        for (const SweepAxis& axis : s.axes)
          if (axis.values.size() != s.axes.front().values.size())
            throw CaseError(axis.location + ": axes: " + axis.key + ": zip needs axes of one length; it has " +
                            std::to_string(axis.values.size()) + " values, " + s.axes.front().key + " " +
                            std::to_string(s.axes.front().values.size()));
    });
    m.optional_section("random", [&](YamlMap& r) {
      has_random = true;
      std::string method;
      r.required("method", method, [](const std::string& x) {
        return x == "monte-carlo" || x == "latin-hypercube" ? "" : "must be monte-carlo or latin-hypercube";
      });
      s.sampling = method == "monte-carlo" ? Sampling::MonteCarlo : Sampling::LatinHypercube;
      int count = 0;
      r.required("count", count, [](int n) { return n >= 1 ? "" : "must be >= 1"; });
      s.count = count;
      double seed = 0;  // read as a number: an integer in [0, 2^53]
      r.required("seed", seed, [](double x) {
        return x >= 0 && x <= kTwoPow53 && std::floor(x) == x ? "" : "must be an integer in [0, 2^53]";
      });
      s.seed = static_cast<std::uint64_t>(seed);
      r.required_value("inputs", [&](const YamlValue& v) {
        const std::vector<YamlValue> e = v.elements("a list of inputs, e.g. - { key: friction.mu, distribution: uniform, min: 0.2, max: 0.4 }");
        if (e.empty()) v.fail("needs at least one input");
        for (const YamlValue& x : e)
          x.mapping([&](YamlMap& xm) {
            RandomInput in;
            in.location = x.location();
            xm.required("key", in.key, key_path_check);
            add_key(xm, in.key);
            read_input(xm, in);
            s.inputs.push_back(std::move(in));
          });
      });
      r.optional_value("correlation", [&](const YamlValue& v) {
        const std::size_t k = s.inputs.size();
        const std::vector<YamlValue> rows = v.elements("a matrix of rank correlations, one row per input, e.g. [[1, 0.5], [0.5, 1]]");
        if (rows.size() != k) v.fail("needs " + std::to_string(k) + " rows (one per input), got " + std::to_string(rows.size()));
        for (std::size_t a = 0; a < k; ++a) {
          const std::vector<YamlValue> e = rows[a].elements("a row of numbers");
          if (e.size() != k) rows[a].fail("row " + std::to_string(a + 1) + " needs " + std::to_string(k) + " numbers, got " + std::to_string(e.size()));
          std::vector<double> row;
          for (std::size_t b = 0; b < k; ++b)
            row.push_back(e[b].as<double>(contact::in_closed(-1, 1), "row " + std::to_string(a + 1) + " element " + std::to_string(b + 1)));
          if (row[a] != 1) rows[a].fail("row " + std::to_string(a + 1) + ": the diagonal must be 1, got " + round_trip(row[a]));
          s.correlation.push_back(row);
        }
        for (std::size_t a = 0; a < k; ++a)
          for (std::size_t b = 0; b < a; ++b)
            if (s.correlation[a][b] != s.correlation[b][a])
              rows[a].fail("must be symmetric: row " + std::to_string(a + 1) + " element " + std::to_string(b + 1) + " is " +
                           round_trip(s.correlation[a][b]) + ", row " + std::to_string(b + 1) + " element " + std::to_string(a + 1) +
                           " " + round_trip(s.correlation[b][a]));
        Eigen::MatrixXd C(k, k);
        for (std::size_t a = 0; a < k; ++a)
          for (std::size_t b = 0; b < k; ++b) C(a, b) = s.correlation[a][b];
        if (Eigen::LLT<Eigen::MatrixXd>(C).info() != Eigen::Success) v.fail("must be positive definite (a possible correlation matrix)");
        if (s.count <= static_cast<long>(k)) v.fail("needs count > the number of inputs (" + std::to_string(k) + ")");
      });
    });
    if (has_axes == has_random)
      m.fail_here("give either axes: (a grid) or random: (sampling), " + std::string(has_axes ? "not both" : "none given"));
  });
  if (has_random && s.combine == Combine::Zip)
    throw CaseError(path + ": combine: applies to axes:, not to random:");
  s.base_path = resolve_base(path, base);
  if (s.sampling != Sampling::Grid) {
    const std::size_t n = static_cast<std::size_t>(s.count), k = s.inputs.size();
    s.samples.assign(n, std::vector<double>(k));
    for (std::size_t a = 0; a < k; ++a) {
      std::vector<long> perm;  // a Latin hypercube's stratum of each case: a permutation drawn by Fisher-Yates
      if (s.sampling == Sampling::LatinHypercube) {
        perm.resize(n);
        std::iota(perm.begin(), perm.end(), 0L);
        for (long j = s.count - 1; j > 0; --j) {
          const double w = unit_uniform(s.seed, static_cast<std::uint64_t>(j), kPermutationStream + a);
          std::swap(perm[static_cast<std::size_t>(j)], perm[static_cast<std::size_t>(std::min<long>(j, static_cast<long>(w * (j + 1))))]);
        }
      }
      for (std::size_t i = 0; i < n; ++i) {
        double u = unit_uniform(s.seed, i, a);
        if (!perm.empty()) u = std::clamp((static_cast<double>(perm[i]) + u) / static_cast<double>(n), 0x1p-53, 1 - 0x1p-53);
        s.samples[i][a] = quantile(s.inputs[a], u);
      }
    }
    if (!s.correlation.empty()) iman_conover(s.samples, s.correlation);
  }
  return s;
}

std::vector<std::string> varied_keys(const Sweep& s) {
  std::vector<std::string> k;
  for (const SweepAxis& a : s.axes) k.push_back(a.key);
  for (const RandomInput& in : s.inputs) k.push_back(in.key);
  return k;
}

long case_count(const Sweep& s) {
  if (s.sampling != Sampling::Grid) return s.count;
  if (s.combine == Combine::Zip) return static_cast<long>(s.axes.front().values.size());
  long n = 1;
  for (const SweepAxis& a : s.axes) n *= static_cast<long>(a.values.size());
  return n;
}

std::vector<double> case_inputs(const Sweep& s, long i) {
  if (i < 0 || i >= case_count(s)) throw std::out_of_range("case_inputs: no case " + std::to_string(i));
  std::vector<double> v;
  if (s.sampling == Sampling::Grid) {
    v.resize(s.axes.size());
    long rest = i;
    for (std::size_t a = s.axes.size(); a-- > 0;) {
      const long n = static_cast<long>(s.axes[a].values.size());
      v[a] = s.axes[a].values[static_cast<std::size_t>(s.combine == Combine::Zip ? i : rest % n)];
      rest /= n;
    }
    return v;
  }
  return s.samples[static_cast<std::size_t>(i)];
}

// ---- the cases ----

namespace {

std::string key_location(const Sweep& s, const std::string& key) {
  for (const SweepAxis& a : s.axes)
    if (a.key == key) return a.location;
  for (const RandomInput& in : s.inputs)
    if (in.key == key) return in.location;
  return s.path;
}

std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts;
  std::stringstream ss(key);
  for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
  return parts;
}

// doc's value at the key path set to the number (the parents must be mappings of the base case)
void set_key(const Sweep& s, YAML::Node doc, const std::string& key, double value) {
  const std::vector<std::string> parts = split_key(key);
  YAML::Node cur = doc;
  std::string walked;
  for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
    walked += (walked.empty() ? "" : ".") + parts[k];
    const YAML::Node& const_cur = cur;
    const YAML::Node next = const_cur[parts[k]];
    if (!next || !next.IsMap())
      throw CaseError(key_location(s, key) + ": " + key + ": the base case " + s.base_path.string() + " has no mapping " +
                      walked + (next ? " (it holds " + contact::yaml_describe(next) + ")" : ""));
    cur.reset(next);
  }
  const YAML::Node& const_cur = cur;
  const YAML::Node old = const_cur[parts.back()];
  if (old && !old.IsScalar() && !old.IsNull())
    throw CaseError(key_location(s, key) + ": " + key + ": the base case holds " + contact::yaml_describe(old) +
                    " there (a time history or a list); a sweep replaces a number");
  cur[parts.back()] = round_trip(value);
}

YAML::Node with_inputs(const Sweep& s, const YAML::Node& base, long i, const std::vector<double>& inputs,
                       const std::vector<bool>& use) {
  YAML::Node doc = YAML::Clone(base);
  const std::vector<std::string> keys = varied_keys(s);
  for (std::size_t k = 0; k < keys.size(); ++k)
    if (use[k]) set_key(s, doc, keys[k], inputs[k]);
  const std::string stem = base["name"] && base["name"].IsScalar() ? base["name"].Scalar() : s.base_path.stem().string();
  doc["name"] = stem + "-" + fmt::format("{:04d}", i);
  return doc;
}

std::string emit(const Sweep& s, const YAML::Node& doc, long i, const std::vector<double>& inputs) {
  YAML::Emitter out;
  out << doc;
  std::string head = fmt::format("# case {} of the sweep {} (base {}):", i, std::filesystem::path(s.path).filename().string(),
                                 s.base_path.filename().string());
  const std::vector<std::string> keys = varied_keys(s);
  for (std::size_t k = 0; k < keys.size(); ++k) head += " " + keys[k] + " = " + round_trip(inputs[k]);
  return head + "\n" + out.c_str() + "\n";
}

}  // namespace

YAML::Node load_base_case(const Sweep& s) {
  YAML::Node doc = contact::load_yaml_file(s.base_path.string());
  if (!doc.IsMap()) throw CaseError(s.base_path.string() + ": expected a mapping of sections");
  const YAML::Node& cdoc = doc;
  // profile files are relative to the case file: made absolute, the generated case reads them from anywhere
  if (cdoc["profiles"] && cdoc["profiles"].IsMap())
    for (const char* body : {"body1", "body2"}) {
      const YAML::Node p = cdoc["profiles"][body];
      if (!p || !p.IsMap() || !p["file"] || !p["file"].IsScalar()) continue;
      const std::filesystem::path f = p["file"].Scalar();
      if (f.is_relative()) doc["profiles"][body]["file"] = std::filesystem::absolute(s.base_path.parent_path() / f).lexically_normal().string();
    }
  // each case writes into its own folder: the base's output folder is not theirs
  if (cdoc["output"] && cdoc["output"].IsMap() && cdoc["output"]["directory"]) {
    doc["output"].remove("directory");
    if (doc["output"].size() == 0) doc.remove("output");
  }
  return doc;
}

std::string case_yaml(const Sweep& s, const YAML::Node& base, long i, const std::vector<double>& inputs) {
  return emit(s, with_inputs(s, base, i, inputs, std::vector<bool>(inputs.size(), true)), i, inputs);
}

std::string case_folder_name(long i) { return fmt::format("case_{:04d}", i); }

namespace {

// "" when the case reader (and, for a wear case, its model) takes the text, else the reader's message.
// `shown_as` names the text in the messages.
std::string refusal(const Sweep& s, const std::string& text, const std::string& shown_as) {
  try {
    if (s.kind == SweepKind::Contact) {
      contact::validate_steady(contact::read_contact_case_text(text, shown_as, s.base_path.parent_path()));
    } else {
      (void)make_wear_model(read_wear_case_text(text, shown_as, s.base_path.parent_path()));
    }
    return "";
  } catch (const CaseError& e) {
    return e.what();
  }
}

}  // namespace

std::vector<SweepCase> validate_cases(const Sweep& s, const std::vector<long>& indices) {
  const YAML::Node base = load_base_case(s);
  const std::vector<std::string> keys = varied_keys(s);
  const std::vector<bool> none(keys.size(), false), all(keys.size(), true);
  const std::string base_refused = refusal(s, emit(s, with_inputs(s, base, 0, case_inputs(s, 0), none), 0, case_inputs(s, 0)),
                                           s.base_path.string() + " (as the base of the sweep)");
  if (!base_refused.empty()) throw CaseError(s.path + ": base: the base case is refused: " + base_refused);
  std::vector<SweepCase> cases;
  cases.reserve(indices.size());
  // progress of the reading itself, every kCheckReport_s (a forced sweep of 1e6 cases reads for minutes)
  constexpr double kCheckReport_s = 5;
  const auto t0 = std::chrono::steady_clock::now();
  double last_report_s = 0;
  for (const long i : indices) {
    if ((cases.size() & 255) == 255) {
      const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (elapsed_s - last_report_s >= kCheckReport_s) {
        spdlog::info("sweep: read and checked {} of {} cases before running them", cases.size(), indices.size());
        last_report_s = elapsed_s;
      }
    }
    SweepCase c;
    c.index = i;
    c.inputs = case_inputs(s, i);
    const std::vector<double>& in = c.inputs;
    const std::string shown = case_folder_name(i) + "/case.yaml";
    std::string why;
    if (s.kind == SweepKind::Contact) {
      // read from the document itself (no text written and parsed again); a refusal is read again from the
      // text, whose lines the message names
      const YAML::Node doc = with_inputs(s, base, i, in, all);
      if (s.case_files) c.text = emit(s, doc, i, in);
      try {
        auto read = std::make_shared<contact::ContactCase>(contact::read_contact_case_node(doc, shown, s.base_path.parent_path()));
        contact::validate_steady(*read);
        c.contact = std::move(read);
      } catch (const CaseError&) {
        const std::string text = c.text.empty() ? emit(s, doc, i, in) : c.text;
        why = refusal(s, text, shown);
        if (why.empty())  // the text passes where the document did not: run the text's case
          c.contact = std::make_shared<contact::ContactCase>(contact::read_contact_case_text(text, shown, s.base_path.parent_path()));
      }
    } else {
      c.text = case_yaml(s, base, i, in);
      why = refusal(s, c.text, shown);
    }
    if (why.empty()) {
      cases.push_back(std::move(c));
      continue;
    }
    // the culprit: the value the reader refuses alone
    for (std::size_t k = 0; k < keys.size(); ++k) {
      std::vector<bool> only(keys.size(), false);
      only[k] = true;
      const std::string alone = refusal(s, emit(s, with_inputs(s, base, i, in, only), i, in), shown);
      if (!alone.empty())
        throw CaseError(key_location(s, keys[k]) + ": " + keys[k] + ": case " + std::to_string(i) + "'s value " +
                        round_trip(in[k]) + " is refused: " + alone);
    }
    std::string values;
    for (std::size_t k = 0; k < keys.size(); ++k) values += (k ? ", " : "") + keys[k] + " = " + round_trip(in[k]);
    throw CaseError(s.path + ": case " + std::to_string(i) + " (" + values +
                    "): each value passes alone, the combination is refused: " + why);
  }
  return cases;
}

// ---- the results table ----

namespace {
std::string csv_field(const std::string& text) {
  std::string t = text;
  for (char& ch : t)
    if (ch == '\n' || ch == '\r') ch = ' ';
  if (t.find_first_of(",\"") == std::string::npos) return t;
  std::string q = "\"";
  for (const char ch : t) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}
}  // namespace

std::string to_string(CaseStatus s) {
  switch (s) {
    case CaseStatus::Ok: return "ok";
    case CaseStatus::Failed: return "failed";
    case CaseStatus::BadInput: return "bad_input";
    case CaseStatus::Error: return "error";
  }
  return "error";
}

CaseStatus parse_case_status(const std::string& word) {
  for (const CaseStatus s : {CaseStatus::Ok, CaseStatus::Failed, CaseStatus::BadInput, CaseStatus::Error})
    if (to_string(s) == word) return s;
  throw std::invalid_argument("not a case status: '" + contact::clipped(word) + "' (ok, failed, bad_input, error)");
}

namespace {
// the columns of a case's outputs, between the inputs and the status
std::string output_columns(SweepKind kind, bool margins) {
  if (kind == SweepKind::Contact) return "a_m,b_m,p0_Pa,approach_m,Fx_N,Fy_N,Mz_N_m,power_W,stick_fraction";
  return std::string("life_revolutions,ended_by,max_depth_m,worn_volume_m3") + (margins ? std::string(",") + kMarginColumns : "") +
         "," + kErrorColumns;
}
std::size_t output_column_count(SweepKind kind, bool margins) {
  return kind == SweepKind::Contact ? 9 : (margins ? 8 : 4) + 4;
}
}  // namespace

std::string results_header(const std::vector<std::string>& keys, SweepKind kind, bool margins) {
  std::string h = "index";
  for (const std::string& k : keys) h += "," + csv_field(k);
  return h + "," + output_columns(kind, margins) + ",status,message\n";
}

std::string results_row(const CaseOutcome& o) {
  std::string r = std::to_string(o.index);
  for (const double v : o.inputs) r += "," + round_trip(v);
  if (o.kind == SweepKind::Contact) {
    const ContactOutputs& c = o.contact;
    for (const double v : {c.a_m, c.b_m, c.p0_Pa, c.approach_m, c.Fx_N, c.Fy_N, c.Mz_N_m, c.power_W, c.stick_fraction})
      r += "," + round_trip(v);
  } else {
    r += "," + round_trip(o.life_revolutions) + "," + to_string(o.ended_by) + "," + round_trip(o.max_depth_m) + "," +
         round_trip(o.worn_volume_m3);
    if (o.margins)
      for (const double v : {o.max_damage, o.depth_fraction, o.shakedown_margin, o.scuffing_margin_K}) r += "," + round_trip(v);
    r += "," + csv_field(o.fidelity) + "," + std::to_string(o.exact_solves) + "," + round_trip(o.error_power_rel) + "," +
         round_trip(o.error_power_l1);
  }
  r += "," + to_string(o.status) + "," + csv_field(o.message);
  return r + "\n";
}

CaseStatus row_status(const std::string& row, std::size_t keys, SweepKind kind, bool margins) {
  std::size_t at = 0;
  for (std::size_t k = 0; k < keys + 1 + output_column_count(kind, margins); ++k) {  // index, the inputs, the outputs
    at = row.find(',', at);
    if (at == std::string::npos) throw std::invalid_argument("not a results row: " + contact::clipped(row));
    ++at;
  }
  return parse_case_status(row.substr(at, row.find(',', at) - at));
}

long row_index(const std::string& row) {
  const std::size_t comma = row.find(',');
  const std::string head = row.substr(0, comma);
  if (head.empty() || head.find_first_not_of("0123456789") != std::string::npos)
    throw std::invalid_argument("not a results row: " + contact::clipped(row));
  return std::stol(head);
}

// ---- running ----

CaseOutcome run_case(const std::string& yaml_text, long index, const std::vector<double>& inputs,
                     const std::filesystem::path& dir) {
  CaseOutcome o;
  o.index = index;
  o.inputs = inputs;
  // the row's margin columns: from the text, so that a case refused as bad input has them too
  try {
    o.margins = has_failure_margins(YAML::Load(yaml_text));
  } catch (const std::exception&) {
  }
  std::filesystem::create_directories(dir);
  remove_stale_temporaries(dir);
  const std::filesystem::path case_path = dir / "case.yaml";
  contact::write_file_atomic(case_path, yaml_text);
  try {
    const WearCase c = read_wear_case(case_path.string());
    WearModel model = make_wear_model(c);
    model.collective_threads = 1;  // the sweep's threads run cases: a collective's conditions run on the case's
    const WearModel& m = model;
    const double hours_per_rev = hours_per_revolution(m);
    WearCache cache;
    std::string summary = wear_summary_header(m);
    std::vector<contact::OutputFile> files;
    int snapshots = 0;
    const auto snapshot = [&](double N, const Eigen::VectorXd& state) {
      for (int body : {1, 2})
        if ((body == 1 ? m.n1 : m.n2) > 0)
          files.push_back({dir / wear_snapshot_path(snapshots, body), wear_snapshot_csv(m, body, N, N * hours_per_rev, state)});
      ++snapshots;
    };
    // the life as rollwear run drives it (session/wear_life_run.h), its files written at the end
    WearLifeObserver observer;
    observer.on_row = [&](const LifeStep& s) { summary += wear_summary_row(m, s, hours_per_rev); };
    observer.on_snapshot = snapshot;
    const LifeStart start = fresh_wear_start(m, cache, observer);
    snapshot(0, start.state);
    const auto t0 = std::chrono::steady_clock::now();
    const LifeResult life = drive_wear_life(m, c, start, cache, observer);
    snapshot(life.N, life.state);
    WearReport report;
    report.case_name = m.name;
    report.life = life;
    report.hours_per_revolution = hours_per_rev;
    report.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    files.push_back({dir / "summary.csv", summary});
    files.push_back({dir / "report.txt", wear_report_text(m, report)});
    contact::write_files_atomic(files);
    o.life_revolutions = life.N;
    o.ended_by = life.ended_by;
    o.max_depth_m = max_depth_m(m, life.state);
    o.worn_volume_m3 = (m.n1 > 0 ? worn_volume_m3(m, life.state, 1) : 0.0) + (m.n2 > 0 ? worn_volume_m3(m, life.state, 2) : 0.0);
    // the margins as report.txt has them (the same text read back: the same doubles), NaN where it has none
    if (o.margins)
      for (const auto& [key, value] : failure_margins(m, life)) {
        double* column = key == "max_damage" ? &o.max_damage : key == "depth_fraction" ? &o.depth_fraction
                       : key == "shakedown_margin" ? &o.shakedown_margin : key == "scuffing_margin_K" ? &o.scuffing_margin_K : nullptr;
        if (column) *column = std::stod(value);
      }
    // the fidelity and the error estimate, as report.txt has them
    o.fidelity = contact::to_string(m.fidelity);
    o.exact_solves = life.exact_solves;
    o.error_power_rel = life.error.power_rel;
    o.error_power_l1 = life.error.power_l1;
    const bool failed = life.ended_by == LifeEnd::Failed || life.ended_by == LifeEnd::NotRun;
    o.status = failed ? CaseStatus::Failed : CaseStatus::Ok;
    o.message = life.message;
  } catch (const CaseError& e) {
    o.status = CaseStatus::BadInput;
    o.message = e.what();
  } catch (const std::exception& e) {
    o.status = CaseStatus::Error;
    o.message = e.what();
  }
  contact::write_file_atomic(dir / "row.csv", results_row(o));
  return o;
}

CaseOutcome run_contact_case(const contact::ContactCase& c, const std::string& text, long index,
                             const std::vector<double>& inputs, const std::filesystem::path& dir) {
  CaseOutcome o;
  o.index = index;
  o.inputs = inputs;
  o.kind = SweepKind::Contact;
  const bool files = !dir.empty();
  std::vector<contact::OutputFile> out;
  if (files) {
    std::filesystem::create_directories(dir);
    remove_stale_temporaries(dir);
    out.push_back({dir / "case.yaml", text});
  }
  const bool fields = files && c.output.fields;
  try {
    const contact::ContactRun r = contact::solve_contact_case(c, fields);  // as rollwear contact
    const contact::ContactPatch& p = r.normal.patch;
    const contact::TangentialSolution& t = r.solution;
    o.contact = {p.a_m, p.b_m, p.p0_Pa, p.approach_m, t.Fx_N, t.Fy_N, t.Mz_N_m, t.power_W, t.stick_fraction};
    o.status = CaseStatus::Ok;
    if (files) {  // rollwear contact's files
      out.push_back({dir / "summary.csv", contact::contact_summary_csv(c.name, r)});
      out.push_back({dir / "strips.csv", contact::strips_csv(contact::in_profile_coordinates(r.normal), t)});
      if (fields) out.push_back({dir / "fields.csv", contact::fields_csv(p, t)});
    }
  } catch (const CaseError& e) {
    o.status = CaseStatus::BadInput;
    o.message = e.what();
  } catch (const contact::SolverError& e) {  // a solver's failure on good input
    o.status = CaseStatus::Failed;
    o.message = e.what();
  } catch (const contact::NormalSolveError& e) {
    o.status = CaseStatus::Failed;
    o.message = e.what();
  } catch (const std::exception& e) {
    o.status = CaseStatus::Error;
    o.message = e.what();
  }
  if (files) {
    out.push_back({dir / "row.csv", results_row(o)});  // renamed last: the mark that the case finished
    contact::write_files_atomic(out);
    std::error_code ec;
    if (!fields) std::filesystem::remove(dir / "fields.csv", ec);  // a killed earlier run's: not this case's fields
  }
  return o;
}

CaseOutcome run_sweep_case(const Sweep& s, const YAML::Node& base, long i, const std::filesystem::path& out) {
  const std::vector<double> inputs = case_inputs(s, i);
  const std::string text = case_yaml(s, base, i, inputs);
  const std::filesystem::path dir = out / case_folder_name(i);
  if (s.kind == SweepKind::Wear) return run_case(text, i, inputs, dir);
  try {
    const contact::ContactCase c = contact::read_contact_case_text(text, case_folder_name(i) + "/case.yaml", s.base_path.parent_path());
    return run_contact_case(c, text, i, inputs, s.case_files ? dir : std::filesystem::path());
  } catch (const CaseError& e) {  // validated before: not expected
    CaseOutcome o;
    o.index = i;
    o.inputs = inputs;
    o.kind = SweepKind::Contact;
    o.status = CaseStatus::BadInput;
    o.message = e.what();
    return o;
  }
}

std::vector<long> shard_indices(long count, int k, int n) {
  if (n < 1 || k < 1 || k > n) throw CaseError("--shard: K/N needs 1 <= K <= N, got " + std::to_string(k) + "/" + std::to_string(n));
  std::vector<long> v;
  for (long i = k - 1; i < count; i += n) v.push_back(i);
  return v;
}

namespace {

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error(p.string() + ": cannot read");
  std::ostringstream t;
  t << in.rdbuf();
  return t.str();
}

std::string sampling_name(const Sweep& s) {
  switch (s.sampling) {
    case Sampling::Grid: return s.combine == Combine::Zip ? "zip" : "product";
    case Sampling::MonteCarlo: return "monte-carlo";
    case Sampling::LatinHypercube: return "latin-hypercube";
  }
  return "product";
}

// the base case's number at the key path, NaN when it has none there
double base_value(const YAML::Node& base, const std::string& key) {
  YAML::Node cur = YAML::Clone(base);
  for (const std::string& part : split_key(key)) {
    const YAML::Node& c = cur;
    if (!c.IsMap() || !c[part]) return std::numeric_limits<double>::quiet_NaN();
    cur.reset(c[part]);
  }
  double v = 0;
  return cur.IsScalar() && YAML::convert<double>::decode(cur, v) ? v : std::numeric_limits<double>::quiet_NaN();
}

std::uint64_t sweep_fingerprint(const Sweep& s) {
  const std::string text = read_text(s.path) + '\0' + read_text(s.base_path);
  return contact::hash_words(text.data(), text.size());
}

// The finished rows of a sweep without case folders (output.case_files: false): OUT/finished.csv, its first
// line naming the sweep (fingerprint) and the shard, then a row per finished case as it finishes (one
// append each). A resumed run reads it: another sweep's is a CaseError; a last line cut short by a kill is
// dropped.
class Journal {
 public:
  Journal(const std::filesystem::path& path, const std::string& head, const std::string& sweep_path) {
    std::error_code ec;
    std::string text;
    if (std::filesystem::exists(path, ec)) {
      text = read_text(path);
      if (text.compare(0, head.size(), head) != 0)
        throw CaseError(sweep_path + ": " + path.string() + " holds the rows of another sweep or shard (the sweep or its base " +
                        "changed): give another output folder");
      text.resize(text.rfind('\n') + 1);  // a row cut short by a kill: dropped (run again)
      std::filesystem::resize_file(path, text.size());
    }
    fd_ = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw std::runtime_error(path.string() + ": cannot open: " + std::strerror(errno));
    if (text.empty()) {
      append(head);
      return;
    }
    std::istringstream lines(text.substr(head.size()));
    for (std::string line; std::getline(lines, line);)
      if (!line.empty()) rows[row_index(line)] = line + "\n";
  }
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;
  ~Journal() { ::close(fd_); }
  void append(const std::string& line) {
    if (::write(fd_, line.data(), line.size()) != static_cast<ssize_t>(line.size()))
      throw std::runtime_error("sweep: cannot append to finished.csv: " + std::string(std::strerror(errno)));
  }
  std::map<long, std::string> rows;  // the rows found, by index

 private:
  int fd_ = -1;
};

// OUT/shard.txt: which shard of how many the folder holds ("shard K/N"), written before its first case
// runs (a finished folder's sweep.txt says it too). Another shard's folder is refused, as is a whole
// sweep's (shard 1/1) for a shard: its finished cases are not this shard's, and a merge would find them
// twice.
void claim_shard_folder(const std::filesystem::path& out, int k, int n, const std::string& sweep_path) {
  const std::string asked = fmt::format("{}/{}", k, n);
  for (const char* name : {"shard.txt", "sweep.txt"}) {
    const std::filesystem::path p = out / name;
    std::error_code ec;
    if (!std::filesystem::exists(p, ec)) continue;
    std::istringstream in(read_text(p));
    std::string word, held;
    while (in >> word)
      if (word == "shard" && in >> held) break;
    if (held.empty()) continue;
    if (held != asked)
      throw CaseError(sweep_path + ": " + out.string() + " holds shard " + held + " of a sweep (" + p.string() +
                      "), asked for shard " + asked + ": run shard " + held + " there, or give shard " + asked +
                      " a folder of its own");
    return;
  }
  contact::write_files_atomic({{out / "shard.txt", "shard " + asked + "\n"}});
}

}  // namespace

SweepPlan plan_sweep(const Sweep& s, int shard_k, int shard_n) {
  SweepPlan p;
  p.cases = case_count(s);
  p.shard_cases = shard_k >= 1 && shard_n >= shard_k ? (p.cases - shard_k + shard_n) / shard_n : 0;  // i mod n = k-1
  const double columns = static_cast<double>(varied_keys(s).size()) + 9;  // the results table's
  p.bytes_per_case = columns * contact::kCsvBytesPerNumber;
  if (s.case_files && p.cases > 0) {
    const std::string text = case_yaml(s, load_base_case(s), 0, case_inputs(s, 0));
    p.bytes_per_case += 2 * static_cast<double>(text.size());  // case.yaml; report.txt or the contact's tables
    if (s.kind == SweepKind::Wear) {
      try {  // the worn profiles' snapshots and the summary table
        const wear::WearCase c = wear::read_wear_case_text(text, s.base_path.string(), s.base_path.parent_path());
        double nodes = 0;
        if (c.wear.body1) nodes += static_cast<double>(c.contact.profiles->profiles.body1.y_m.size());
        if (c.wear.body2) nodes += static_cast<double>(c.contact.profiles->profiles.body2.y_m.size());
        const double snapshots = static_cast<double>(c.wear.snapshots_revolutions.size()) + 2;
        p.bytes_per_case += (snapshots * nodes * 4 + kPlannedSummaryRows * 12) * contact::kCsvBytesPerNumber;
      } catch (const CaseError&) {  // validate_cases names the refusal
      }
    }
  }
  p.bytes = p.bytes_per_case * static_cast<double>(p.shard_cases);
  return p;
}

std::string to_string(const SweepPlan& p, int shard_k, int shard_n) {
  return fmt::format("{} cases{}, about {:.3g} MB of output ({:.3g} kB a case)", p.cases,
                     shard_n > 1 ? fmt::format(" (shard {}/{}: {})", shard_k, shard_n, p.shard_cases) : std::string(),
                     p.bytes / 1e6, p.bytes_per_case / 1e3);
}

SweepRunSummary run_sweep(const Sweep& s, const SweepRunOptions& o) {
  const long total = case_count(s);
  // the plan, said at once, and refused above the limit before any case is read
  const SweepPlan plan = plan_sweep(s, o.shard_k, o.shard_n);
  spdlog::info("sweep {}: plans {}", s.path, to_string(plan, o.shard_k, o.shard_n));
  if (plan.shard_cases > o.max_cases && !o.force)
    throw CaseError(fmt::format("{}: the sweep plans {}: more than {} cases are refused (kSweepMaxCases, "
                                "session/sweep.h); split it with --shard K/N, or run with --force (Python: force=True)",
                                s.path, to_string(plan, o.shard_k, o.shard_n), o.max_cases));
  const std::vector<long> indices = shard_indices(total, o.shard_k, o.shard_n);
  const std::filesystem::path& out = o.output_directory;
  std::filesystem::create_directories(out);
  remove_stale_temporaries(out);
  const std::vector<SweepCase> cases = validate_cases(s, indices);
  claim_shard_folder(out, o.shard_k, o.shard_n, s.path);

  // what is finished (row.csv next to the same case.yaml, or its row in finished.csv) and what is to run
  const YAML::Node base = load_base_case(s);
  const std::uint64_t fingerprint = sweep_fingerprint(s);
  std::unique_ptr<Journal> journal;
  if (!s.case_files)
    journal = std::make_unique<Journal>(out / "finished.csv", fmt::format("# sweep {:016x} shard {}/{}\n", fingerprint, o.shard_k, o.shard_n), s.path);
  std::map<long, std::string> rows;
  std::vector<const SweepCase*> pending;
  SweepRunSummary summary;
  summary.cases = static_cast<long>(indices.size());
  for (const SweepCase& c : cases) {
    const long i = c.index;
    const std::string& text = c.text;
    const std::filesystem::path dir = out / case_folder_name(i);
    if (journal) {
      const auto found = journal->rows.find(i);
      if (found == journal->rows.end()) {
        pending.push_back(&c);
      } else {
        rows[i] = found->second;
        ++summary.resumed;
      }
    } else if (std::filesystem::exists(dir / "row.csv")) {
      if (read_text(dir / "case.yaml") != text)
        throw CaseError(s.path + ": " + (dir / "case.yaml").string() + " finished with other inputs than case " +
                        std::to_string(i) + " has now (the sweep or its base changed): give another output folder");
      rows[i] = read_text(dir / "row.csv");
      ++summary.resumed;
    } else {
      pending.push_back(&c);
    }
  }
  if (summary.resumed > 0)
    spdlog::info("sweep: {} of {} cases finished before, {} to run", summary.resumed, summary.cases, pending.size());

  // one case per thread, the next pending one taken when a thread is free
  std::mutex mutex;
  std::condition_variable changed;
  std::atomic<std::size_t> next{0};
  long done = summary.resumed, failed = 0;
  const std::size_t nkeys = varied_keys(s).size();
  for (const auto& [i, row] : rows)
    if (row_status(row, nkeys, s.kind, s.margins) != CaseStatus::Ok) ++failed;
  std::size_t running = 0;
  std::exception_ptr error;  // a failure outside a case's own (the disk): the first one ends the sweep, exit 1
  const auto work = [&] {
    // one thread per case while the sweep runs several at once; a case alone on a free core shares
    // Satran's strips among the cores (lib/tangential/satran.h)
    contact::set_satran_threads(pending.size() < static_cast<std::size_t>(o.threads) ? 0 : 1);
    try {
      for (std::size_t k = next++; k < pending.size(); k = next++) {
        const SweepCase& sc = *pending[k];
        const long i = sc.index;
        const CaseOutcome c = s.kind == SweepKind::Contact
                                  ? run_contact_case(*sc.contact, sc.text, i, sc.inputs, s.case_files ? out / case_folder_name(i) : std::filesystem::path())
                                  : run_case(sc.text, i, sc.inputs, out / case_folder_name(i));
        std::string row = results_row(c);
        const std::lock_guard<std::mutex> lock(mutex);
        if (journal) journal->append(row);
        rows[i] = std::move(row);
        ++done;
        if (c.status != CaseStatus::Ok) ++failed;
        changed.notify_all();
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
      next = pending.size();  // no new case starts; the running ones finish (and are kept for a resume)
    }
    const std::lock_guard<std::mutex> lock(mutex);
    --running;
    changed.notify_all();
  };
  const auto t0 = std::chrono::steady_clock::now();
  if (o.dispatch && !pending.empty()) {  // elsewhere (MPI ranks): each row as it comes
    double last_report_s = 0;
    std::vector<std::pair<long, std::string>> dealt;  // index, case text
    for (const SweepCase* c : pending) dealt.emplace_back(c->index, c->text);
    o.dispatch(dealt, [&](const std::string& row) {
      if (journal) journal->append(row);
      rows[row_index(row)] = row;
      ++done;
      if (row_status(row, nkeys, s.kind, s.margins) != CaseStatus::Ok) ++failed;
      const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (o.progress && (elapsed_s - last_report_s >= o.progress_interval_s || done == summary.cases)) {
        o.progress(done, failed, summary.cases, elapsed_s);
        last_report_s = elapsed_s;
      }
    });
    pending.clear();
    if (static_cast<long>(rows.size()) != summary.cases)
      throw std::runtime_error(fmt::format("sweep: {} of {} cases came back from the ranks", rows.size(), summary.cases));
  }
  const int threads = std::max(1, std::min<int>(o.threads, static_cast<int>(pending.size())));
  std::vector<std::thread> pool;
  running = pending.empty() ? 0 : static_cast<std::size_t>(threads);
  for (int t = 0; t < threads && !pending.empty(); ++t) pool.emplace_back(work);
  bool cancelled = false;
  {
    std::unique_lock<std::mutex> lock(mutex);
    double last_report_s = 0;
    while (running > 0) {
      changed.wait_for(lock, std::chrono::duration<double>(o.progress_interval_s));
      const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (o.progress && (elapsed_s - last_report_s >= o.progress_interval_s || running == 0)) {
        o.progress(done, failed, summary.cases, elapsed_s);
        last_report_s = elapsed_s;
      }
      if (!cancelled && o.cancelled && o.cancelled()) {
        cancelled = true;
        next = pending.size();  // no new case starts; the running ones finish (and are kept for a resume)
      }
    }
  }
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  if (cancelled) throw SweepCancelled(fmt::format("sweep {}: cancelled after {} of {} cases", s.path, done, summary.cases));
  summary.failed = 0;
  std::string table = results_header(varied_keys(s), s.kind, s.margins);
  for (const auto& [i, row] : rows) {
    table += row;
    if (row_status(row, nkeys, s.kind, s.margins) != CaseStatus::Ok) ++summary.failed;
  }
  std::string info = fmt::format("fingerprint {:016x}\ncases {}\nshard {}/{}\nsampling {}\nseed {}\n", fingerprint,
                                 total, o.shard_k, o.shard_n, sampling_name(s), s.seed);
  if (s.kind == SweepKind::Contact) info += "kind contact\n";
  for (const SweepAxis& a : s.axes) info += fmt::format("axis {} {} {}\n", a.key, a.values.size(), round_trip(base_value(base, a.key)));
  std::vector<contact::OutputFile> files = {{out / "results.csv", table}, {out / "sweep.txt", info}};
  if (o.shard_n == 1) files.push_back({out / "summary.txt", sweep_summary(table, info)});
  contact::write_files_atomic(files);
  return summary;
}

std::string merge_results(const std::vector<std::filesystem::path>& dirs, std::string* sweep_txt) {
  if (dirs.empty()) throw CaseError("--merge: give the shards' output folders");
  std::string header, fingerprint;
  long total = -1;
  std::map<long, std::pair<std::string, std::string>> rows;  // index -> row, folder
  for (const std::filesystem::path& d : dirs) {
    if (!std::filesystem::exists(d / "sweep.txt") || !std::filesystem::exists(d / "results.csv"))
      throw CaseError(d.string() + ": not the output folder of a finished sweep shard (no sweep.txt and results.csv)");
    std::istringstream info(read_text(d / "sweep.txt"));
    std::string word, fp;
    long cases = -1;
    while (info >> word) {
      if (word == "fingerprint") info >> fp;
      else if (word == "cases") info >> cases;
      else info >> word;
    }
    if (fingerprint.empty()) {
      fingerprint = fp, total = cases;
      if (sweep_txt) *sweep_txt = read_text(d / "sweep.txt");
    }
    if (fp != fingerprint || cases != total)
      throw CaseError(d.string() + ": a shard of another sweep than " + dirs.front().string() + " (sweep.txt differs)");
    std::istringstream table(read_text(d / "results.csv"));
    std::string line;
    std::getline(table, line);
    if (header.empty()) header = line;
    if (line != header) throw CaseError((d / "results.csv").string() + ": its columns differ from " + dirs.front().string() + "'s");
    while (std::getline(table, line)) {
      if (line.empty()) continue;
      const long i = row_index(line);
      const auto [it, inserted] = rows.emplace(i, std::make_pair(line + "\n", d.string()));
      if (!inserted)
        throw CaseError(d.string() + ": case " + std::to_string(i) + " is also in " + it->second.second + " (shards overlap)");
    }
  }
  std::vector<long> missing;
  for (long i = 0; i < total; ++i)
    if (!rows.count(i)) missing.push_back(i);
  if (!missing.empty()) {
    std::string list;
    for (std::size_t k = 0; k < std::min<std::size_t>(missing.size(), 10); ++k) list += (k ? ", " : "") + std::to_string(missing[k]);
    throw CaseError("--merge: " + std::to_string(missing.size()) + " of " + std::to_string(total) + " cases missing (" + list +
                    (missing.size() > 10 ? ", ..." : "") + "): a shard not given, or not finished");
  }
  std::string out = header + "\n";
  for (const auto& [i, r] : rows) out += r.first;
  return out;
}

}  // namespace session
