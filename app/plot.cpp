// rollwear plot: reads a wear run's output folder (summary.csv, snapshots/, report.txt), writes one
// gnuplot script with the data inline (converted to mm, µm, MPa), runs gnuplot on it once, and
// renames the PNGs into place only when gnuplot has succeeded.
#include "app/plot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "lib/io/csv.h"
#include "lib/csv_reader.h"
#include "lib/errors.h"
#include "session/sweep.h"
#include "session/sweep_summary.h"
#include "wear/wear_loop.h"
#include "lib/numeric.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;

using contact::kExitBadInput;  // the exit statuses: lib/errors.h
using contact::kExitFailure;
constexpr const char* kGnuplotPackage = "gnuplot-nox";

// a failure the command reports as one line: bad input is a contact::CaseError (exit 2), any other
// failure a std::runtime_error (exit 1); lib/errors.h maps them
contact::CaseError bad_input(const std::string& message) { return contact::CaseError(message); }

// ---- reading the run's tables ------------------------------------------------------------------------

using contact::csv_trim;
using Table = contact::CsvTable;  // the one CSV reader, lib/csv_reader.h

std::string trim(const std::string& s) { return csv_trim(s); }

std::string where(const fs::path& path, int line) { return fmt::format("{} line {}", path.string(), line); }

// reads path; a missing file, a row not as wide as the header or a table without rows is bad input
Table read_table(const fs::path& path) {
  Table t;
  try {
    t = contact::read_csv_table(path.string());
  } catch (const std::runtime_error& e) {
    throw bad_input(e.what());
  }
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    if (t.rows[r].size() != t.header.size())
      throw bad_input(fmt::format("{}: malformed row: {} cells, the header (line {}) has {}", where(path, t.row_lines[r]),
                                  t.rows[r].size(), t.header_line, t.header.size()));
  if (t.header.empty()) throw bad_input(fmt::format("{}: no header row (only comments or nothing)", path.string()));
  if (t.rows.empty()) throw bad_input(fmt::format("{}: no data row after the header", where(path, t.header_line)));
  return t;
}

// a finite number, the whole cell
bool parse_number(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(value) && errno != ERANGE;
}

bool has_column(const Table& t, const std::string& name) {
  return std::find(t.header.begin(), t.header.end(), name) != t.header.end();
}

// the column of that name, each cell a finite number
std::vector<double> column(const Table& t, const std::string& name) {
  const auto it = std::find(t.header.begin(), t.header.end(), name);
  if (it == t.header.end())
    throw bad_input(fmt::format("{}: no column '{}' in the header", where(t.path, t.header_line), name));
  const std::size_t k = static_cast<std::size_t>(it - t.header.begin());
  std::vector<double> values(t.rows.size());
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    if (!parse_number(t.rows[r][k], values[r]))
      throw bad_input(fmt::format("{}: malformed row: column {} is '{}', not a finite number",
                                  where(t.path, t.row_lines[r]), name, contact::clipped(t.rows[r][k])));
  return values;
}

// ---- the run's output folder -------------------------------------------------------------------------

struct Snapshot {
  int index = 0;                                                  // KKKK of the file name
  double revolutions = std::numeric_limits<double>::quiet_NaN();  // "# revolutions:", nan if absent
  std::vector<double> y_m, z_original_m, z_m, depth_m;            // one per profile node
  std::vector<double> damage;  // the Miner damage per node (a fatigue run's reference body, docs/fatigue.md), else empty
};

struct BodySnapshots {
  std::string body;                 // body1, body2
  std::vector<Snapshot> snapshots;  // increasing index
};

struct RunOutput {
  std::string case_name;
  std::vector<double> revolutions, max_depth_m, p0_Pa;  // one per accepted step
  std::vector<BodySnapshots> bodies;                    // the worn bodies with snapshots, by name
};

// the case's name: summary.csv's "# case:", else report.txt's "case:", else the folder's name
std::string case_name_of(const Table& summary, const fs::path& dir) {
  const auto it = summary.comments.find("case");
  if (it != summary.comments.end() && !it->second.first.empty()) return it->second.first;
  std::ifstream report(dir / "report.txt");
  for (std::string line; std::getline(report, line);) {
    const std::size_t colon = line.find(':');
    if (colon != std::string::npos && trim(line.substr(0, colon)) == "case") {
      const std::string name = trim(line.substr(colon + 1));
      if (!name.empty()) return name;
    }
  }
  fs::path folder = fs::absolute(dir).lexically_normal();
  if (folder.filename().empty()) folder = folder.parent_path();  // "out/paper/"
  return folder.filename().string();
}

Snapshot read_snapshot(const fs::path& path, int index) {
  const Table t = read_table(path);
  Snapshot s;
  s.index = index;
  const auto rev = t.comments.find("revolutions");
  if (rev != t.comments.end() && !parse_number(rev->second.first, s.revolutions))
    throw bad_input(fmt::format("{}: malformed comment: revolutions is '{}', not a finite number",
                                where(path, rev->second.second), rev->second.first));
  s.y_m = column(t, "y_m");
  s.z_original_m = column(t, "z_original_m");
  s.z_m = column(t, "z_m");
  s.depth_m = column(t, "depth_m");
  if (has_column(t, "damage")) s.damage = column(t, "damage");
  return s;
}

// "snapshot_KKKK_BODY.csv": KKKK (1 to 9 digits) and BODY; false for any other name
bool parse_snapshot_name(const std::string& leaf, int& index, std::string& body) {
  const std::string prefix = "snapshot_", suffix = ".csv";
  if (leaf.size() <= prefix.size() + suffix.size() || leaf.compare(0, prefix.size(), prefix) != 0 ||
      leaf.compare(leaf.size() - suffix.size(), suffix.size(), suffix) != 0)
    return false;
  const std::string middle = leaf.substr(prefix.size(), leaf.size() - prefix.size() - suffix.size());
  const std::size_t underscore = middle.find('_');
  if (underscore == 0 || underscore > 9 || underscore + 1 >= middle.size()) return false;
  const std::string digits = middle.substr(0, underscore);
  if (digits.find_first_not_of("0123456789") != std::string::npos) return false;
  index = std::stoi(digits);
  body = middle.substr(underscore + 1);
  return true;
}

// snapshots/snapshot_KKKK_BODY.csv, grouped by body, each body's in increasing KKKK; other files
// (a running wear loop's temporaries among them) are not snapshots
std::vector<BodySnapshots> read_snapshots(const fs::path& dir) {
  std::map<std::string, std::map<int, fs::path>> files;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return {};
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    int index = 0;
    std::string body;
    if (parse_snapshot_name(e.path().filename().string(), index, body) && e.is_regular_file(ec))
      files[body][index] = e.path();
  }
  if (ec) throw bad_input(fmt::format("cannot list {}: {}", dir.string(), ec.message()));
  std::vector<BodySnapshots> bodies;
  for (const auto& [body, by_index] : files) {
    BodySnapshots b{body, {}};
    for (const auto& [index, path] : by_index) b.snapshots.push_back(read_snapshot(path, index));
    bodies.push_back(std::move(b));
  }
  return bodies;
}

RunOutput read_run_output(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) throw bad_input(fmt::format("no such folder: {}", dir.string()));
  if (!fs::is_directory(dir, ec)) throw bad_input(fmt::format("not a folder: {}", dir.string()));
  const fs::path summary_path = dir / "summary.csv";
  if (!fs::exists(summary_path, ec))
    throw bad_input(
        fmt::format("no {} (is {} the output folder of a rollwear run?)", summary_path.string(), dir.string()));
  const Table summary = read_table(summary_path);
  RunOutput run;
  run.case_name = case_name_of(summary, dir);
  run.revolutions = column(summary, "revolutions");
  run.max_depth_m = column(summary, "max_depth_m");
  run.p0_Pa = column(summary, "p0_Pa");
  run.bodies = read_snapshots(dir / "snapshots");
  return run;
}

// ---- the gnuplot script ------------------------------------------------------------------------------

// text in a gnuplot single-quoted string (no escapes there but '' for ')
std::string quote(const std::string& text) {
  std::string q = "'";
  for (const char ch : text) {
    if (ch == '\'') q += '\'';
    q += ch == '\n' || ch == '\r' ? ' ' : ch;
  }
  return q + "'";
}

// a count of revolutions as a legend shows it: 0, 750, 1.5e7
std::string revolutions_label(double revolutions) {
  if (std::isnan(revolutions)) return "";
  if (revolutions == 0) return "0 rev";
  if (std::fabs(revolutions) >= 1e-2 && std::fabs(revolutions) < 1e4) return fmt::format("{:.4g} rev", revolutions);
  std::string s = fmt::format("{:.3g}", revolutions);  // 1.5e+07
  const std::size_t e = s.find('e');
  if (e != std::string::npos) {
    std::string exponent = s.substr(e + 1);
    const bool negative = !exponent.empty() && exponent[0] == '-';
    exponent.erase(0, exponent.find_first_not_of("+-0"));
    s = s.substr(0, e) + "e" + (negative ? "-" : "") + (exponent.empty() ? "0" : exponent);
  }
  return s + " rev";
}

// the revolutions axis in thousands, millions or billions (words, not superscripts, which libgd's
// png terminal may lack): the divisor and the axis label
std::pair<double, std::string> revolutions_axis(const std::vector<double>& revolutions) {
  double largest = 0;
  for (const double r : revolutions) largest = std::max(largest, std::fabs(r));
  if (largest >= 1e9) return {1e9, "revolutions (billions, 10^9)"};
  if (largest >= 1e6) return {1e6, "revolutions (millions)"};
  if (largest >= 1e4) return {1e3, "revolutions (thousands)"};
  return {1.0, "revolutions"};
}

// the colour of snapshot k of n: blue (early) through teal and amber to red (late)
std::string snapshot_colour(std::size_t k, std::size_t n) {
  static const int kStops[][3] = {{0x1f, 0x4e, 0x9c}, {0x2a, 0x9d, 0x8f}, {0xe9, 0xa0, 0x3b}, {0xc0, 0x39, 0x2b}};
  constexpr int kLast = 3;
  const double t = n > 1 ? static_cast<double>(k) / static_cast<double>(n - 1) : 1.0;
  const int i = std::min(static_cast<int>(t * kLast), kLast - 1);
  const double f = t * kLast - i;
  int rgb[3];
  for (int c = 0; c < 3; ++c)
    rgb[c] = static_cast<int>(std::lround(kStops[i][c] + f * (kStops[i + 1][c] - kStops[i][c])));
  return fmt::format("#{:02x}{:02x}{:02x}", rgb[0], rgb[1], rgb[2]);
}

// the legend entry of snapshot k of n: every snapshot's while they are few, else about ten spread
// evenly, the last among them (the colours tell the order of the others)
std::string snapshot_title(const Snapshot& s, std::size_t k, std::size_t n) {
  constexpr std::size_t kMaxEntries = 12;
  const std::size_t stride = n <= kMaxEntries ? 1 : (n - 1 + 9) / 10;
  if (k % stride != 0 && k + 1 != n) return "notitle";
  return "title " +
         quote(std::isnan(s.revolutions) ? fmt::format("snapshot {}", s.index) : revolutions_label(s.revolutions));
}

// the terminal: pngcairo when this gnuplot has it (Debian's gnuplot-nox does), else libgd's png
std::string terminal_script() {
  return "if (strstrt(GPVAL_TERMINALS, ' pngcairo ') > 0) {\n"
         "  set terminal pngcairo size 1000,650 noenhanced font 'Sans,12' linewidth 1.2\n"
         "} else {\n"
         "  if (strstrt(GPVAL_TERMINALS, ' png ') > 0) {\n"
         "    set terminal png size 1000,650 noenhanced\n"
         "  } else {\n"
         "    exit error 'this gnuplot has neither the pngcairo nor the png terminal'\n"
         "  }\n"
         "}\n";
}

// what every picture starts with: its temporary output, the title, the grid
std::string figure_start(const fs::path& output, const std::string& title) {
  return fmt::format(
      "\nreset\n"
      "set encoding utf8\n"
      "set output {}\n"
      "set title {} font ',14'\n"
      "set grid xtics ytics lt 1 lc rgb '#d4d4d4' lw 1\n"
      "set border lw 1.2\n"
      "set key box opaque samplen 3 spacing 1.2 width 1\n"
      "set xlabel offset 0,0.3\n",
      quote(output.string()), quote(title));
}

const char* const kFigureEnd = "unset output\n";

void put(std::string& out, double v) { fmt::format_to(std::back_inserter(out), "{:.10g}", v); }

// the summary as columns: revolutions (scaled), max depth (µm), p0 (MPa)
std::string summary_block(const RunOutput& run, double revolutions_divisor) {
  std::string out = "$summary << EOD\n";
  for (std::size_t r = 0; r < run.revolutions.size(); ++r) {
    put(out, run.revolutions[r] / revolutions_divisor);
    out += ' ';
    put(out, run.max_depth_m[r] * 1e6);
    out += ' ';
    put(out, run.p0_Pa[r] * 1e-6);
    out += '\n';
  }
  return out + "EOD\n";
}

// a snapshot as columns: y (mm), z original (mm), z (mm), depth (µm)[, damage]
std::string snapshot_block(const std::string& name, const Snapshot& s) {
  std::string out = name + " << EOD\n";
  for (std::size_t r = 0; r < s.y_m.size(); ++r) {
    for (const double v : {s.y_m[r] * 1e3, s.z_original_m[r] * 1e3, s.z_m[r] * 1e3}) {
      put(out, v);
      out += ' ';
    }
    put(out, s.depth_m[r] * 1e6);
    if (!s.damage.empty()) {
      out += ' ';
      put(out, s.damage[r]);
    }
    out += '\n';
  }
  return out + "EOD\n";
}

// a quantity of the summary against revolutions
std::string history_figure(const RunOutput& run, const fs::path& output, const std::string& title,
                           const std::string& revolutions_label_text, const std::string& ylabel, int column_index,
                           const std::string& curve, const std::string& colour) {
  const bool points = run.revolutions.size() <= 200;  // one marker per accepted step, when few
  return figure_start(output, title) +
         fmt::format(
             "set xlabel {}\n"
             "set ylabel {}\n"
             "set key outside right top\n"
             "set autoscale yfix\n"
             "set offsets 0, 0, graph 0.05, graph 0.05\n"
             "plot $summary using 1:{} with {} lw 2 lc rgb '{}'{} title {}\n",
             quote(revolutions_label_text), quote(ylabel), column_index, points ? "linespoints" : "lines", colour,
             points ? " pt 7 ps 0.7" : "", quote(curve)) +
         kFigureEnd;
}

// the worn profile at every snapshot over the original (z down into the material)
std::string profile_figure(const std::string& case_name, const BodySnapshots& b, const std::vector<std::string>& blocks,
                           const fs::path& output) {
  std::string plot;
  for (std::size_t k = 0; k < b.snapshots.size(); ++k)
    plot += fmt::format("{} using 1:3 with lines lw 2 lc rgb '{}' {}, \\\n     ", blocks[k],
                        snapshot_colour(k, b.snapshots.size()), snapshot_title(b.snapshots[k], k, b.snapshots.size()));
  plot += blocks.front() + " using 1:2 with lines lw 2.5 dt (8,6) lc rgb 'black' title 'original'\n";
  return figure_start(output,
                      fmt::format("{}: {} profile, worn at each snapshot over the original", case_name, b.body)) +
         "set xlabel 'lateral position y (mm)'\n"
         "set ylabel 'z (mm), into the material (axis points down)'\n"
         "set yrange [*:*] reverse\n"
         "set autoscale yfix\n"
         "set offsets 0, 0, graph 0.05, graph 0.05\n"
         "set key outside right top title 'revolutions'\n"
         "plot " +
         plot + kFigureEnd;
}

// the wear depth across the profile at every snapshot (depth down into the material)
std::string depth_profile_figure(const std::string& case_name, const BodySnapshots& b,
                                 const std::vector<std::string>& blocks, const fs::path& output) {
  std::string plot;
  for (std::size_t k = 0; k < b.snapshots.size(); ++k) {
    if (k > 0) plot += ", \\\n     ";
    plot += fmt::format("{} using 1:4 with lines lw 2 lc rgb '{}' {}", blocks[k],
                        snapshot_colour(k, b.snapshots.size()), snapshot_title(b.snapshots[k], k, b.snapshots.size()));
  }
  return figure_start(output, fmt::format("{}: {} wear depth across the profile", case_name, b.body)) +
         "set xlabel 'lateral position y (mm)'\n"
         "set ylabel 'wear depth (µm), into the material (axis points down)'\n"
         "set yrange [*:*] reverse\n"
         "set autoscale yfix\n"
         "set offsets 0, 0, graph 0.05, graph 0.05\n"
         "set xzeroaxis lt -1 lw 1\n"
         "set key outside right top title 'revolutions'\n"
         "plot " +
         plot + "\n" + kFigureEnd;
}

// every snapshot of the body has the damage column (a fatigue run's reference body)
bool has_damage(const BodySnapshots& b) {
  return !b.snapshots.empty() &&
         std::all_of(b.snapshots.begin(), b.snapshots.end(), [](const Snapshot& s) { return !s.damage.empty(); });
}

// the fatigue damage along the track (Miner's sum per profile node, docs/fatigue.md) at every snapshot, with the
// crack-initiation line at damage 1
std::string damage_profile_figure(const std::string& case_name, const BodySnapshots& b,
                                  const std::vector<std::string>& blocks, const fs::path& output) {
  std::string plot;
  for (std::size_t k = 0; k < b.snapshots.size(); ++k)
    plot += fmt::format("{} using 1:5 with lines lw 2 lc rgb '{}' {}, \\\n     ", blocks[k],
                        snapshot_colour(k, b.snapshots.size()), snapshot_title(b.snapshots[k], k, b.snapshots.size()));
  plot += "1 with lines lw 1.5 dt (8,6) lc rgb 'black' title 'damage 1: crack initiation'\n";
  return figure_start(output, fmt::format("{}: {} fatigue damage along the track", case_name, b.body)) +
         "set xlabel 'lateral position y (mm)'\n"
         "set ylabel 'fatigue damage (Miner sum)'\n"
         "set yrange [0:*]\n"
         "set offsets 0, 0, graph 0.05, 0\n"
         "set key outside right top title 'revolutions'\n"
         "plot " +
         plot + kFigureEnd;
}

// ---- files -------------------------------------------------------------------------------------------

fs::path temporary_for(const fs::path& path) {
  fs::path tmp = path;
  tmp += ".tmp." + std::to_string(::getpid());
  return tmp;
}

// removes its files when it goes (the script, and any PNG not renamed into place)
class Temporaries {
 public:
  Temporaries() = default;
  Temporaries(const Temporaries&) = delete;
  Temporaries& operator=(const Temporaries&) = delete;
  ~Temporaries() {
    for (const fs::path& p : paths_) {
      std::error_code ignored;
      fs::remove(p, ignored);
    }
  }
  void add(const fs::path& p) { paths_.push_back(p); }

 private:
  std::vector<fs::path> paths_;
};

bool has_png_signature(const fs::path& p) {
  static const char kSignature[] = "\x89PNG\r\n\x1a\n";
  char head[8] = {};
  std::ifstream in(p, std::ios::binary);
  return in.read(head, sizeof head) && std::memcmp(head, kSignature, sizeof head) == 0;
}

// gnuplot's messages on one line: lines joined by " | ", its caret lines left out
std::string one_line(const std::string& text) {
  std::string joined;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = trim(text.substr(start, end - start));
    start = end + 1;
    if (line.empty() || line.find_first_not_of("^ \t") == std::string::npos) continue;
    if (!joined.empty()) joined += " | ";
    joined += line;
  }
  return joined;
}

// runs "gnuplot SCRIPT" (found on PATH), stdin from /dev/null; returns its stdout and stderr
// together. Throws std::runtime_error when gnuplot is not installed, cannot start or fails.
std::string run_gnuplot(const fs::path& script) {
  int fd[2];
  if (::pipe2(fd, O_CLOEXEC) != 0)
    throw std::runtime_error(fmt::format("cannot run gnuplot: pipe: {}", std::strerror(errno)));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, fd[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fd[1], STDERR_FILENO);
  std::string program = "gnuplot", script_path = script.string();
  char* argv[] = {program.data(), script_path.data(), nullptr};
  pid_t pid = 0;
  const int spawned = ::posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fd[1]);
  if (spawned != 0) {
    ::close(fd[0]);
    if (spawned == ENOENT)
      throw std::runtime_error(fmt::format("gnuplot is not installed (not found on PATH); it is Debian's package {}: "
                                  "sudo apt-get install -y {}",
                                  kGnuplotPackage, kGnuplotPackage));
    throw std::runtime_error(fmt::format("cannot run gnuplot: {}", std::strerror(spawned)));
  }

  std::string messages;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd[0], buffer, sizeof buffer);
    if (n > 0)
      messages.append(buffer, static_cast<std::size_t>(n));
    else if (n == 0 || errno != EINTR)
      break;
  }
  ::close(fd[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return messages;
  const std::string how = WIFEXITED(status)     ? fmt::format("exit status {}", WEXITSTATUS(status))
                          : WIFSIGNALED(status) ? fmt::format("signal {}", WTERMSIG(status))
                                                : std::string("unknown status");
  const std::string said = one_line(messages);
  throw std::runtime_error(fmt::format("gnuplot failed ({}): {}", how, said.empty() ? "no message" : said));
}

struct Picture {
  fs::path path, temporary;
};

// the pictures a script draws: each one's temporary name, for the script to draw to
struct Pictures {
  fs::path plots;
  std::vector<Picture> list;
  fs::path operator()(const std::string& leaf) {
    const fs::path path = plots / leaf;
    list.push_back({path, temporary_for(path)});
    return list.back().temporary;
  }
};

std::vector<fs::path> render(const std::string& script, const std::vector<Picture>& pictures, const fs::path& plots,
                             std::ostream& err);

// the pictures: the script, gnuplot, then every PNG into place; returns the PNGs written
std::vector<fs::path> draw(const RunOutput& run, const fs::path& plots, std::ostream& err) {
  Pictures picture{plots, {}};

  // the data, then one figure after another
  const auto [divisor, revolutions_text] = revolutions_axis(run.revolutions);
  std::string script = "# rollwear plot: " + run.case_name + "\n" + terminal_script() + summary_block(run, divisor);
  script += history_figure(run, picture("depth.png"), run.case_name + ": maximum wear depth", revolutions_text,
                           "maximum wear depth (µm)", 2, "max depth", "#c0392b");
  script += history_figure(run, picture("pressure.png"), run.case_name + ": peak contact pressure", revolutions_text,
                           "peak pressure p0 (MPa)", 3, "peak pressure p0", "#1f4e9c");
  for (std::size_t b = 0; b < run.bodies.size(); ++b) {
    const BodySnapshots& body = run.bodies[b];
    std::vector<std::string> blocks;
    for (std::size_t k = 0; k < body.snapshots.size(); ++k) {
      blocks.push_back(fmt::format("$body{}_snapshot{}", b, k));
      script += snapshot_block(blocks.back(), body.snapshots[k]);
    }
    script += profile_figure(run.case_name, body, blocks, picture("profile_" + body.body + ".png"));
    script += depth_profile_figure(run.case_name, body, blocks, picture("depth_profile_" + body.body + ".png"));
    if (has_damage(body))
      script += damage_profile_figure(run.case_name, body, blocks, picture("damage_profile_" + body.body + ".png"));
  }
  return render(script, picture.list, plots, err);
}

// gnuplot draws every picture to its temporary name (any failure removes them all), then each goes into
// place; returns the PNGs written
std::vector<fs::path> render(const std::string& script, const std::vector<Picture>& pictures, const fs::path& plots,
                             std::ostream& err) {
  Temporaries temporaries;
  for (const Picture& p : pictures) temporaries.add(p.temporary);
  const fs::path script_path = temporary_for(plots / "plot.gp");
  temporaries.add(script_path);
  try {
    contact::write_file_atomic(script_path, script);
  } catch (const std::exception& e) {
    throw std::runtime_error(e.what());
  }
  const std::string messages = one_line(run_gnuplot(script_path));
  if (!messages.empty()) err << "rollwear plot: gnuplot said: " << messages << '\n';
  for (const Picture& p : pictures)
    if (!has_png_signature(p.temporary))
      throw std::runtime_error(fmt::format("gnuplot did not draw {}", p.path.string()));

  // then each into place
  std::vector<fs::path> written;
  for (const Picture& p : pictures) {
    std::error_code ec;
    fs::rename(p.temporary, p.path, ec);
    if (ec) throw std::runtime_error(fmt::format("cannot write {}: {}", p.path.string(), ec.message()));
    written.push_back(p.path);
  }
  return written;
}

// ---- a sweep's output folder (rollwear sweep, docs/sweeps.md) -----------------------------------------

struct SweepCase {
  std::vector<double> inputs;
  std::vector<double> outputs;  // a contact sweep's: a_m ... stick_fraction (SweepOutput::output_names)
  double life = 0;
  bool censored = false;  // the life reached the budget (wear.revolutions, max_steps): it lasts at least that
};

struct SweepOutput {
  std::string name;                 // the folder's name
  std::string sampling = "product"; // product | zip | monte-carlo | latin-hypercube (sweep.txt)
  std::vector<std::string> keys;    // the varied keys, in the table's order
  std::vector<double> base;         // each key's value in the base case (sweep.txt's axis lines), NaN if none
  std::vector<SweepCase> cases;     // the cases with status ok
  long left_out = 0;                // cases whose status is not ok
  bool contact = false;             // a contact sweep: no life, the contact's columns (output_names)
  std::vector<std::string> output_names;
};

bool is_sweep_folder(const fs::path& dir) { return fs::exists(dir / "results.csv") && fs::exists(dir / "sweep.txt"); }

bool is_random(const SweepOutput& s) { return s.sampling == "monte-carlo" || s.sampling == "latin-hypercube"; }

SweepOutput read_sweep_output(const fs::path& dir) {
  SweepOutput o;
  const fs::path normal = fs::absolute(dir).lexically_normal();
  o.name = (normal.has_filename() ? normal.filename() : normal.parent_path().filename()).string();
  std::map<std::string, double> base;
  std::ifstream info(dir / "sweep.txt");
  for (std::string line; std::getline(info, line);) {
    std::istringstream l(line);
    std::string word, key, size, value;
    l >> word;
    if (word == "sampling") l >> o.sampling;
    if (word == "axis" && l >> key >> size >> value) {
      double v = std::numeric_limits<double>::quiet_NaN();
      parse_number(value, v);
      base[key] = v;
    }
  }
  const Table t = read_table(dir / "results.csv");
  // a wear sweep's outputs: life_revolutions .. worn_volume_m3, with the failure margins (docs/fatigue.md,
  // session/sweep.h kMarginColumns) after worn_volume_m3, then the fidelity and error estimate (kErrorColumns;
  // a table written before they were has none), status and message
  const auto wear_tail = [](bool margins, bool error) {
    std::vector<std::string> tail = {"life_revolutions", "ended_by", "max_depth_m", "worn_volume_m3"};
    for (const char* columns : {margins ? session::kMarginColumns : "", error ? session::kErrorColumns : ""}) {
      std::istringstream list(columns);
      for (std::string column; std::getline(list, column, ',');) tail.push_back(column);
    }
    tail.insert(tail.end(), {"status", "message"});
    return tail;
  };
  // a contact sweep's outputs, as session/sweep.h writes them: "index,<outputs>,status,message" with no keys
  static const std::vector<std::string> kContactTail = [] {
    std::vector<std::string> tail;
    std::string line = session::results_header({}, session::SweepKind::Contact);
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    std::istringstream header(line);
    for (std::string column; std::getline(header, column, ',');)
      if (column != "index") tail.push_back(column);
    return tail;
  }();
  const std::size_t n = t.header.size();
  const auto ends_with = [&](const std::vector<std::string>& tail) {
    return n >= tail.size() + 2 && t.header.front() == "index" && std::equal(tail.begin(), tail.end(), t.header.end() - static_cast<long>(tail.size()));
  };
  o.contact = ends_with(kContactTail);
  std::vector<std::string> plain_tail, margins_tail;
  for (const bool error : {true, false})
    if (plain_tail.empty() && (ends_with(wear_tail(false, error)) || ends_with(wear_tail(true, error)))) {
      plain_tail = wear_tail(false, error);
      margins_tail = wear_tail(true, error);
    }
  if (plain_tail.empty()) plain_tail = margins_tail = wear_tail(false, true);
  const bool fatigue = !o.contact && ends_with(margins_tail);
  std::string contact_columns;
  for (const std::string& c : kContactTail) contact_columns += (contact_columns.empty() ? "" : ", ") + c;
  if (!o.contact && !fatigue && !ends_with(plain_tail))
    throw bad_input(fmt::format("{}: not a sweep's results table (index, the varied keys, then life_revolutions, ended_by, "
                                "max_depth_m, worn_volume_m3, [the margins,] [fidelity, exact_solves, error_power_rel, error_power_l1,] status, message; or a contact sweep's {})",
                                where(t.path, t.header_line), contact_columns));
  const std::size_t tail = o.contact ? kContactTail.size() : fatigue ? margins_tail.size() : plain_tail.size();
  o.keys.assign(t.header.begin() + 1, t.header.end() - static_cast<long>(tail));
  if (o.contact) o.output_names.assign(kContactTail.begin(), kContactTail.end() - 2);
  for (const std::string& k : o.keys) o.base.push_back(base.count(k) ? base[k] : std::numeric_limits<double>::quiet_NaN());
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::vector<std::string>& row = t.rows[r];
    if (row[n - 2] != "ok") {
      ++o.left_out;
      continue;
    }
    SweepCase c;
    const auto number = [&](std::size_t col) {
      double v = 0;
      if (!parse_number(row[col], v))
        throw bad_input(fmt::format("{}: malformed row: column {} is '{}', not a finite number",
                                    where(t.path, t.row_lines[r]), t.header[col], contact::clipped(row[col])));
      return v;
    };
    for (std::size_t k = 0; k < o.keys.size(); ++k) c.inputs.push_back(number(1 + k));
    if (o.contact) {
      for (std::size_t k = 0; k < o.output_names.size(); ++k) c.outputs.push_back(number(1 + o.keys.size() + k));
      o.cases.push_back(std::move(c));
      continue;
    }
    c.life = number(1 + o.keys.size());  // life_revolutions, ended_by right after the inputs
    try {
      const wear::LifeEnd end = wear::parse_life_end(row[2 + o.keys.size()]);
      c.censored = end == wear::LifeEnd::Revolutions || end == wear::LifeEnd::MaxSteps;
    } catch (const std::invalid_argument& e) {
      throw bad_input(fmt::format("{}: malformed row: ended_by: {}", where(t.path, t.row_lines[r]), e.what()));
    }
    o.cases.push_back(std::move(c));
  }
  if (o.cases.empty())
    throw bad_input(fmt::format("{}: no case with status ok to plot ({} left out)", (dir / "results.csv").string(),
                                o.left_out));
  return o;
}

// "friction.mu" -> "friction_mu": a file name
std::string file_stem(const std::string& key) {
  std::string f;
  for (const char ch : key) f += std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' ? ch : '_';
  return f;
}

bool all_positive(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return x > 0; });
}

// a log axis where every value is positive and they span a decade or more
bool log_axis(const std::vector<double>& v) {
  if (v.empty() || !all_positive(v)) return false;
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi >= 10 * *lo;
}

std::string count_note(const SweepOutput& s) {
  return fmt::format("{} cases{}", s.cases.size(),
                     s.left_out > 0 ? fmt::format(", {} not ok left out", s.left_out) : std::string());
}

// every ok case as a row: the inputs, the life (scaled), 1 if censored
std::string sweep_block(const SweepOutput& s, double divisor) {
  std::string out = "$sweep << EOD\n";
  for (const SweepCase& c : s.cases) {
    for (const double v : c.inputs) {
      put(out, v);
      out += ' ';
    }
    put(out, c.life / divisor);
    out += c.censored ? " 1\n" : " 0\n";
  }
  return out + "EOD\n";
}

// the cases of a product grid through the base point along axis a: the other axes at the grid value
// nearest the base case's (the axis' middle value when the base case does not give the key), as
// summary.txt's elasticities take them; sorted by the axis' value
std::vector<const SweepCase*> base_slice(const SweepOutput& s, std::size_t a) {
  std::vector<double> held(s.keys.size());
  for (std::size_t k = 0; k < s.keys.size(); ++k) {
    std::vector<double> values;
    for (const SweepCase& c : s.cases) values.push_back(c.inputs[k]);
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    held[k] = values[values.size() / 2];
    if (!std::isnan(s.base[k]))
      for (const double v : values)
        if (std::fabs(v - s.base[k]) < std::fabs(held[k] - s.base[k])) held[k] = v;
  }
  std::vector<const SweepCase*> slice;
  for (const SweepCase& c : s.cases) {
    bool on = true;
    for (std::size_t k = 0; k < s.keys.size(); ++k)
      if (k != a && c.inputs[k] != held[k]) on = false;
    if (on) slice.push_back(&c);
  }
  std::sort(slice.begin(), slice.end(), [a](const SweepCase* x, const SweepCase* y) { return x->inputs[a] < y->inputs[a]; });
  return slice;
}

// the life against axis (or input) a: every case, the censored marked, and on a product grid of more
// than one axis the line through the base point
std::string life_figure(const SweepOutput& s, std::size_t a, double divisor, const std::string& life_label,
                        const fs::path& output) {
  std::vector<double> x, lives;
  for (const SweepCase& c : s.cases) x.push_back(c.inputs[a]), lives.push_back(c.life);
  const std::size_t column = a + 1, life_column = s.keys.size() + 1, censored_column = s.keys.size() + 2;
  const bool any_censored = std::any_of(s.cases.begin(), s.cases.end(), [](const SweepCase& c) { return c.censored; });
  std::string plot = fmt::format("$sweep using {0}:(${2} == 0 ? ${1} : NaN) with points pt 7 ps 1.1 lc rgb '#7f8c9a' "
                                 "title 'every case'",
                                 column, life_column, censored_column);
  if (any_censored)
    plot += fmt::format(", \\\n     $sweep using {0}:(${2} == 1 ? ${1} : NaN) with points pt 9 ps 1.6 lc rgb '#e9a03b' "
                        "title 'reached the budget (a lower bound)'",
                        column, life_column, censored_column);
  std::string slice_block;
  if (s.sampling == "product" && s.keys.size() > 1) {
    slice_block = fmt::format("$slice{} << EOD\n", a);
    for (const SweepCase* c : base_slice(s, a)) {
      put(slice_block, c->inputs[a]);
      slice_block += ' ';
      put(slice_block, c->life / divisor);
      slice_block += '\n';
    }
    slice_block += "EOD\n";
    plot += fmt::format(", \\\n     $slice{} using 1:2 with linespoints lw 2 pt 7 ps 1.2 lc rgb '#c0392b' title "
                        "'the other keys at the base case'",
                        a);
  }
  return slice_block + figure_start(output, fmt::format("{}: life against {} ({})", s.name, s.keys[a], count_note(s))) +
         fmt::format("set xlabel {}\nset ylabel {}\n", quote(s.keys[a]), quote(life_label)) +
         (log_axis(x) ? "set logscale x\nset format x '%g'\n" : "") + (all_positive(lives) ? "set logscale y\n" : "") +
         "set offsets graph 0.03, graph 0.03, 0, 0\n"
         "set key inside left top box opaque\n"
         "plot " + plot + "\n" + kFigureEnd;
}

// the life's empirical distribution (every ok life as if it had ended, i/n) and the Kaplan-Meier estimate
// (a life at the budget right-censored), the censored lives marked on it, B10 and B50 as dashed lines
std::string distribution_figure(const SweepOutput& s, double divisor, const std::string& life_label,
                                const fs::path& output) {
  std::vector<std::pair<double, bool>> lives;
  std::vector<double> sorted;
  for (const SweepCase& c : s.cases) lives.emplace_back(c.life, c.censored), sorted.push_back(c.life);
  std::sort(sorted.begin(), sorted.end());
  const std::vector<session::KaplanMeierStep> km = session::kaplan_meier(lives);
  std::string out = "$empirical << EOD\n";
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    put(out, sorted[i] / divisor);
    out += ' ';
    put(out, static_cast<double>(i + 1) / static_cast<double>(sorted.size()));
    out += '\n';
  }
  out += "EOD\n$km << EOD\n";
  for (const session::KaplanMeierStep& k : km) {  // a vertical jump at each failure
    const double before = &k == &km.front() ? 0.0 : (&k - 1)->failed_fraction;
    for (const double f : {before, k.failed_fraction}) {
      put(out, k.life / divisor);
      out += ' ';
      put(out, f);
      out += '\n';
    }
  }
  if (!km.empty() && sorted.back() > km.back().life) {  // held to the longest life
    put(out, sorted.back() / divisor);
    out += ' ';
    put(out, km.back().failed_fraction);
    out += '\n';
  }
  out += "EOD\n$censored << EOD\n";
  long censored = 0;
  for (const auto& [life, is_censored] : lives) {
    if (!is_censored) continue;
    ++censored;
    double f = 0;
    for (const session::KaplanMeierStep& k : km)
      if (k.life <= life) f = k.failed_fraction;
    put(out, life / divisor);
    out += ' ';
    put(out, f);
    out += '\n';
  }
  out += "EOD\n";
  std::string plot = "$empirical using 1:2 with steps lw 1.5 lc rgb '#7f8c9a' title 'empirical, every life as if ended (i/n)', \\\n"
                     "     $empirical using 1:2 with points pt 7 ps 0.8 lc rgb '#7f8c9a' notitle";
  if (!km.empty()) plot += ", \\\n     $km using 1:2 with lines lw 2.5 lc rgb '#c0392b' title 'Kaplan-Meier (budget lives censored)'";
  if (censored > 0)
    plot += fmt::format(", \\\n     $censored using 1:2 with points pt 2 ps 1.8 lw 2 lc rgb '#e9a03b' title 'censored ({})'",
                        censored);
  return out + figure_start(output, fmt::format("{}: distribution of the life ({})", s.name, count_note(s))) +
         fmt::format("set xlabel {}\n", quote(life_label)) +
         "set ylabel 'fraction of lives ended by N'\n"
         "set yrange [0:1]\n" +
         (all_positive(sorted) ? "set logscale x\n" : "") +
         "set offsets graph 0.03, graph 0.03, 0, 0\n"
         "set arrow from graph 0, first 0.1 to graph 1, first 0.1 nohead dt 2 lc rgb '#1f4e9c'\n"
         "set arrow from graph 0, first 0.5 to graph 1, first 0.5 nohead dt 2 lc rgb '#1f4e9c'\n"
         "set label 'B10' at graph 0.01, first 0.125 tc rgb '#1f4e9c'\n"
         "set label 'B50' at graph 0.01, first 0.525 tc rgb '#1f4e9c'\n"
         "set key inside left top\n"
         "plot " + plot + "\n" + kFigureEnd;
}

// a contact sweep: the contact against varied key a, four panels (the semi-axes, the peak pressure, the creep
// forces, the dissipated power): every case as a dot, and on a product grid of more than one axis the line
// through the base point
std::string contact_figure(const SweepOutput& s, std::size_t a, const fs::path& output) {
  const auto column = [&](const std::string& name) {
    const auto it = std::find(s.output_names.begin(), s.output_names.end(), name);
    if (it == s.output_names.end()) throw std::logic_error("plot: a contact sweep without " + name);
    return static_cast<std::size_t>(it - s.output_names.begin());
  };
  // x, a (mm), b (mm), p0 (MPa), Fx (N), Fy (N), power (W)
  const std::vector<std::pair<std::size_t, double>> shown = {{column("a_m"), 1e3},  {column("b_m"), 1e3},
                                                             {column("p0_Pa"), 1e-6}, {column("Fx_N"), 1},
                                                             {column("Fy_N"), 1},   {column("power_W"), 1}};
  const auto rows = [&](const std::vector<const SweepCase*>& cases, const std::string& name) {
    std::string out = "$" + name + " << EOD\n";
    for (const SweepCase* c : cases) {
      put(out, c->inputs[a]);
      for (const auto& [k, scale] : shown) {
        out += ' ';
        put(out, c->outputs[k] * scale);
      }
      out += '\n';
    }
    return out + "EOD\n";
  };
  std::vector<const SweepCase*> every;
  for (const SweepCase& c : s.cases) every.push_back(&c);
  const bool slice = s.sampling == "product" && s.keys.size() > 1;
  std::string out = rows(every, fmt::format("contact{}", a));
  if (slice) out += rows(base_slice(s, a), fmt::format("contact_slice{}", a));
  std::vector<double> x;
  for (const SweepCase& c : s.cases) x.push_back(c.inputs[a]);
  const auto panel = [&](const std::string& title, const std::vector<std::pair<int, std::string>>& curves) {
    std::string plot;
    for (const auto& [col, label] : curves) {
      if (!plot.empty()) plot += ", \\\n     ";
      plot += fmt::format("$contact{} using 1:{} with points pt 7 ps 0.9 lc rgb '#7f8c9a' notitle", a, col);
      if (slice)
        plot += fmt::format(", \\\n     $contact_slice{} using 1:{} with linespoints lw 2 pt 7 ps 1.1 title {}", a, col,
                            quote(label));
    }
    return "set title " + quote(title) + "\nplot " + plot + "\n";
  };
  return out + figure_start(output, fmt::format("{}: the contact against {} ({})", s.name, s.keys[a], count_note(s))) +
         "set multiplot layout 2,2\n" + fmt::format("set xlabel {}\n", quote(s.keys[a])) +
         (log_axis(x) ? "set logscale x\nset format x '%g'\n" : "") +
         "set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05\nset key inside left top box opaque\n" +
         panel("semi-axes a, b (mm)", {{2, "a"}, {3, "b"}}) + panel("peak pressure p0 (MPa)", {{4, "p0"}}) +
         panel("creep forces Fx, Fy (N)", {{5, "Fx"}, {6, "Fy"}}) + panel("dissipated power (W)", {{7, "power"}}) +
         "unset multiplot\n" + kFigureEnd;
}

// a sweep's pictures: the life against each varied key, and for random sampling the life's distribution; a
// contact sweep's: the contact against each varied key
std::vector<fs::path> draw_sweep(const SweepOutput& s, const fs::path& plots, std::ostream& err) {
  std::vector<Picture> pictures;
  const auto picture = [&](const std::string& leaf) {
    const fs::path path = plots / leaf;
    pictures.push_back({path, temporary_for(path)});
    return pictures.back().temporary;
  };
  if (s.contact) {
    std::string script = "# rollwear plot: the contact sweep " + s.name + "\n" + terminal_script();
    for (std::size_t a = 0; a < s.keys.size(); ++a)
      script += contact_figure(s, a, picture("contact_vs_" + file_stem(s.keys[a]) + ".png"));
    return render(script, pictures, plots, err);
  }
  std::vector<double> lives;
  for (const SweepCase& c : s.cases) lives.push_back(c.life);
  const auto [divisor, revolutions_text] = revolutions_axis(lives);
  const std::string life_label = "life, " + revolutions_text;
  std::string script = "# rollwear plot: the sweep " + s.name + "\n" + terminal_script() + sweep_block(s, divisor);
  for (std::size_t a = 0; a < s.keys.size(); ++a)
    script += life_figure(s, a, divisor, life_label, picture("life_vs_" + file_stem(s.keys[a]) + ".png"));
  if (is_random(s)) script += distribution_figure(s, divisor, life_label, picture("life_distribution.png"));
  return render(script, pictures, plots, err);
}

// ---- a cam's life (rollwear run on a cam case, session/cam_life_run.h) --------------------------------------------

// the folder of a cam's life: life.csv and dissipation.csv, which a wear loop's run does not write
bool is_cam_output(const fs::path& dir) {
  std::error_code ec;
  return fs::exists(dir / "life.csv", ec) && fs::exists(dir / "dissipation.csv", ec) && !fs::exists(dir / "summary.csv", ec);
}

// the last snapshots/wear_map_KKKK.csv (highest KKKK)
fs::path last_wear_map(const fs::path& dir) {
  fs::path best;
  int best_k = -1;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir / "snapshots", ec)) {
    const std::string leaf = e.path().filename().string();
    if (leaf.size() != std::string("wear_map_0000.csv").size() || leaf.compare(0, 9, "wear_map_") != 0 ||
        leaf.compare(13, 4, ".csv") != 0 || leaf.substr(9, 4).find_first_not_of("0123456789") != std::string::npos)
      continue;
    const int k = std::stoi(leaf.substr(9, 4));
    if (k > best_k) best_k = k, best = e.path();
  }
  if (best_k < 0) throw bad_input(fmt::format("no wear map in {} (snapshots/wear_map_KKKK.csv)", (dir / "snapshots").string()));
  return best;
}

// 1, 2 or 5 times a power of ten, the largest not above x (x > 0)
double round_down_125(double x) {
  const double decade = std::pow(10.0, std::floor(std::log10(x)));
  for (const double m : {5.0, 2.0, 1.0})
    if (m * decade <= x) return m * decade;
  return decade;
}

// ---- a cam's film and flash temperature over the revolution (cam.lubricant, cam.thermal: docs/cam-follower.md §17) ----

// the table of a lubricated cam revolution (revolution.csv of rollwear cam, dissipation.csv of a cam life) has them
bool has_cam_film(const Table& t) { return has_column(t, "h_min_m") || has_column(t, "flash_max_K"); }

// cam_film.png: the film (h_min, h_c in um) and lambda over the cam angle, and the flash temperature (K); each panel
// only when its columns are there
std::string cam_film_script(const Table& t, const std::string& name, Pictures& picture) {
  const bool film = has_column(t, "h_min_m"), flash = has_column(t, "flash_max_K");
  const std::vector<double> theta = column(t, "cam_angle_deg");
  std::vector<double> h_min, h_c, lambda, temperature;
  if (film) h_min = column(t, "h_min_m"), h_c = column(t, "h_central_m"), lambda = column(t, "lambda");
  if (flash) temperature = column(t, "flash_max_K");
  std::string script = "$film << EOD\n";
  for (std::size_t k = 0; k < theta.size(); ++k)
    script += fmt::format("{:.8g} {:.8g} {:.8g} {:.8g} {:.8g}\n", theta[k], film ? h_min[k] * 1e6 : 0.0,
                          film ? h_c[k] * 1e6 : 0.0, film ? lambda[k] : 0.0, flash ? temperature[k] : 0.0);
  script += "EOD\n";
  script += figure_start(picture("cam_film.png"), name + ": film and flash temperature over the revolution") +
            fmt::format("set multiplot layout {},1\n", film && flash ? 2 : 1) +
            "set xlabel 'cam angle (deg)'\nset xrange [0:360]\nset xtics 60\n";
  if (film)
    script += "set title 'film thickness (µm) and film parameter λ'\nset ylabel 'µm'\nset y2label 'λ'\n"
              "set ytics nomirror\nset y2tics\nset yrange [0:*]\nset y2range [0:*]\nset key outside right top\n"
              "plot $film using 1:2 with lines lw 2 lc rgb '#1f4e9c' title 'h_min', "
              "$film using 1:3 with lines lw 2 dt (6,4) lc rgb '#2a9d8f' title 'h_c', "
              "$film using 1:4 axes x1y2 with lines lw 2 lc rgb '#c0392b' title 'λ'\n"
              "unset y2tics\nunset y2label\nset ytics mirror\n";
  if (flash)
    script += "set title 'flash temperature (K above the bulk)'\nset ylabel 'K'\nset yrange [0:*]\nunset key\n"
              "plot $film using 1:5 with lines lw 2 lc rgb '#e9a03b'\n";
  script += std::string("unset multiplot\n") + kFigureEnd;
  return script;
}

// the folder of `rollwear cam`: revolution.csv alone (no life, no wear run)
bool is_cam_revolution_output(const fs::path& dir) {
  std::error_code ec;
  return fs::exists(dir / "revolution.csv", ec) && !fs::exists(dir / "life.csv", ec) && !fs::exists(dir / "summary.csv", ec);
}

std::vector<fs::path> draw_cam_revolution(const fs::path& dir, const fs::path& plots, std::ostream& err) {
  const Table rev = read_table(dir / "revolution.csv");
  if (!has_cam_film(rev))
    throw bad_input(fmt::format("{}: a cam revolution without the film's or the flash temperature's columns (the case "
                                "has no cam.lubricant or cam.thermal): nothing to draw; rollwear plot draws a cam life's "
                                "folder (rollwear run) or a lubricated revolution's film and temperature",
                                where(rev.path, rev.header_line)));
  const fs::path normal = fs::absolute(dir).lexically_normal();
  const std::string name = (normal.has_filename() ? normal.filename() : normal.parent_path().filename()).string();
  Pictures picture{plots, {}};
  const std::string script = "# rollwear plot: " + name + "\n" + terminal_script() + cam_film_script(rev, name, picture);
  return render(script, picture.list, plots, err);
}

std::vector<fs::path> draw_cam(const fs::path& dir, const fs::path& plots, std::ostream& err) {
  const Table life = read_table(dir / "life.csv");
  const Table rev = read_table(dir / "revolution.csv");
  const Table dis = read_table(dir / "dissipation.csv");
  const fs::path map_path = last_wear_map(dir);
  const Table map = read_table(map_path);
  const std::string name = case_name_of(life, dir);
  double map_revolutions = std::numeric_limits<double>::quiet_NaN();
  if (const auto it = map.comments.find("revolutions"); it != map.comments.end()) parse_number(it->second.first, map_revolutions);

  const std::vector<double> N = column(life, "revolutions"), depth = column(life, "max_depth_m"),
                            loss = column(life, "lift_loss_m");
  const std::vector<double> theta = column(rev, "cam_angle_deg"), lift = column(rev, "lift_m"),
                            phi = column(rev, "pressure_angle_deg"), Fn = column(rev, "normal_load_N"),
                            p0 = column(rev, "p0_Pa"), arc = column(rev, "contact_arc_m");
  const std::vector<double> power = column(dis, "power_W"), alpha = column(dis, "contact_angle_deg"),
                            radius = column(dis, "contact_radius_m");
  const std::vector<double> m_angle = column(map, "cam_angle_deg"), m_arc = column(map, "cam_arc_m"),
                            m_y = column(map, "y_m"), m_depth = column(map, "depth_m");
  if (power.size() != theta.size())
    throw bad_input(fmt::format("{}: {} rows, revolution.csv {}: not the same revolution", (dir / "dissipation.csv").string(),
                                power.size(), theta.size()));

  std::string script = "# rollwear plot: " + name + "\n" + terminal_script();
  // the data
  script += "$rev << EOD\n";
  for (std::size_t k = 0; k < theta.size(); ++k)
    script += fmt::format("{:.8g} {:.8g} {:.8g} {:.8g} {:.8g} {:.8g}\n", theta[k], lift[k] * 1e3, phi[k], Fn[k], p0[k] * 1e-6,
                          power[k] * 1e3);
  script += "EOD\n";
  const auto [divisor, revolutions_text] = revolutions_axis(N);
  script += "$life << EOD\n";
  for (std::size_t k = 0; k < N.size(); ++k)
    script += fmt::format("{:.8g} {:.8g} {:.8g}\n", N[k] / divisor, depth[k] * 1e6, loss[k] * 1e6);
  script += "EOD\n";
  // the map, arc row by arc row (pm3d's scans), and the deepest wear across the width at each arc cell
  std::vector<double> cell_arc, cell_deepest;
  script += "$map << EOD\n";
  for (std::size_t r = 0; r < m_arc.size(); ++r) {
    if (r > 0 && m_arc[r] != m_arc[r - 1]) script += "\n";
    if (cell_arc.empty() || m_arc[r] != cell_arc.back()) cell_arc.push_back(m_arc[r]), cell_deepest.push_back(0);
    cell_deepest.back() = std::max(cell_deepest.back(), m_depth[r]);
    script += fmt::format("{:.8g} {:.8g} {:.8g}\n", m_angle[r], m_y[r] * 1e3, m_depth[r] * 1e6);
  }
  script += "EOD\n";
  // the worn cam: each angle's contact point moved inwards by the deepest wear there (linear between the arc
  // cells' centres, periodic), exaggerated
  const double circumference = 2 * cell_arc.front() * static_cast<double>(cell_arc.size());  // cells of equal length
  const auto deepest_at = [&](double a) {
    const double ds = circumference / static_cast<double>(cell_arc.size());
    double u = a / ds - 0.5;
    const double n = static_cast<double>(cell_arc.size());
    u -= std::floor(u / n) * n;
    const std::size_t c0 = std::min(static_cast<std::size_t>(u), cell_arc.size() - 1), c1 = (c0 + 1) % cell_arc.size();
    const double w = u - static_cast<double>(c0);
    return (1 - w) * cell_deepest[c0] + w * cell_deepest[c1];
  };
  double deepest = 0, r_min = std::numeric_limits<double>::infinity();
  for (double d : cell_deepest) deepest = std::max(deepest, d);
  for (double r : radius) r_min = std::min(r_min, r);
  const double scale = deepest > 0 ? round_down_125(0.06 * r_min / deepest) : 1;
  script += "$cam << EOD\n";
  for (std::size_t k = 0; k <= theta.size(); ++k) {
    const std::size_t i = k % theta.size();
    const double a = alpha[i] * contact::kPi / 180, r = radius[i], rw = r - scale * deepest_at(arc[i]);
    script += fmt::format("{:.8g} {:.8g} {:.8g} {:.8g}\n", r * 1e3 * std::cos(a), r * 1e3 * std::sin(a),
                          rw * 1e3 * std::cos(a), rw * 1e3 * std::sin(a));
  }
  script += "EOD\n";

  Pictures picture{plots, {}};
  script += figure_start(picture("cam_revolution.png"), name + ": one revolution (unworn)") +
            "set multiplot layout 2,2\n"
            "set xlabel 'cam angle (deg)'\nset xrange [0:360]\nset xtics 60\nunset key\n"
            "set title 'lift (mm)'\nplot $rev using 1:2 with lines lw 2 lc rgb '#1f4e9c'\n"
            "set title 'pressure angle (deg)'\nplot $rev using 1:3 with lines lw 2 lc rgb '#2a9d8f'\n"
            "set title 'normal load (N), peak pressure (MPa)'\nset key right center box opaque\n"
            "plot $rev using 1:4 with lines lw 2 lc rgb '#e9a03b' title 'F_n (N)', "
            "$rev using 1:5 with lines lw 2 lc rgb '#c0392b' title 'p0 (MPa)'\n"
            "unset key\nset title 'dissipated power (mW)'\nplot $rev using 1:6 with lines lw 2 lc rgb '#c0392b'\n"
            "unset multiplot\n" +
            kFigureEnd;
  script += figure_start(picture("cam_life.png"), name + ": the life") +
            fmt::format("set xlabel {}\nset ylabel 'µm'\nset key top left\n"
                        "plot $life using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#c0392b' title 'max depth', "
                        "$life using 1:3 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#1f4e9c' title 'lift loss'\n",
                        quote(revolutions_text)) +
            kFigureEnd;
  script += figure_start(picture("cam_wear_map.png"),
                         fmt::format("{}: the cam track's wear depth (µm) at {}", name, revolutions_label(map_revolutions))) +
            "set view map\nset pm3d map corners2color c1\nset palette defined (0 '#ffffff', 1 '#e9a03b', 2 '#c0392b', 3 '#3b0f0f')\n"
            "set xlabel 'cam angle at which the contact passes (deg)'\nset ylabel 'across the track y (mm)'\n"
            "set xrange [0:360]\nset xtics 60\nset autoscale yfix\nset cbrange [0:*]\nset cblabel 'depth (µm)'\nunset key\nunset grid\n"
            "splot $map using 1:2:3 with pm3d\n" +
            kFigureEnd;
  script += figure_start(picture("cam_worn.png"),
                         fmt::format("{}: the worn cam beside the new one at {} (depth × {:g})", name,
                                     revolutions_label(map_revolutions), scale)) +
            "set size ratio -1\nset xlabel 'x (mm), cam frame'\nset ylabel 'y (mm)'\nset key outside right top\n"
            "plot $cam using 1:2 with lines lw 2.5 dt (8,6) lc rgb 'black' title 'new', "
            "$cam using 3:4 with lines lw 2 lc rgb '#c0392b' title " +
            quote(fmt::format("worn, depth × {:g}", scale)) + "\n" + kFigureEnd;
  if (has_cam_film(dis)) script += cam_film_script(dis, name, picture);  // a lubricated cam's life
  return render(script, picture.list, plots, err);
}

// ---- a steady contact's stresses below the surface (rollwear contact, docs/subsurface.md) -------------------

// the folder of `rollwear contact`: its section below the surface, which no life writes
bool is_contact_output(const fs::path& dir) {
  std::error_code ec;
  return fs::exists(dir / "subsurface_section.csv", ec) && fs::exists(dir / "strips.csv", ec);
}

// per body: von Mises and Tresca's (s1 - s3)/2 on the x-z section through the most loaded cell, depth down
std::vector<fs::path> draw_subsurface(const fs::path& dir, const fs::path& plots, std::ostream& err) {
  const Table t = read_table(dir / "subsurface_section.csv");
  const std::vector<double> body = column(t, "body"), y = column(t, "y_m"), x = column(t, "x_m"),
                            z = column(t, "z_m"), vm = column(t, "von_mises_Pa"), tr = column(t, "tresca_Pa");
  const fs::path normal = fs::absolute(dir).lexically_normal();
  const std::string name = (normal.has_filename() ? normal.filename() : normal.parent_path().filename()).string();
  Pictures picture{plots, {}};
  std::string script = "# rollwear plot: " + name + "\n" + terminal_script();
  for (const int b : {1, 2}) {
    std::string block;
    double last_z = std::numeric_limits<double>::quiet_NaN(), section_y = 0;
    for (std::size_t r = 0; r < body.size(); ++r) {
      if (body[r] != b) continue;
      if (!std::isnan(last_z) && z[r] != last_z) block += "\n";  // a new plane: a new scan for pm3d
      last_z = z[r], section_y = y[r];
      block += fmt::format("{:.8g} {:.8g} {:.8g} {:.8g}\n", x[r] * 1e3, z[r] * 1e3, vm[r] * 1e-6, tr[r] * 1e-6);
    }
    if (block.empty()) continue;
    script += fmt::format("$body{} << EOD\n{}EOD\n", b, block);
    script += figure_start(picture(fmt::format("subsurface_body{}.png", b)),
                           fmt::format("{}: below body {}, the section y = {:.4g} mm", name, b, section_y * 1e3)) +
              "set multiplot layout 2,1\n"
              "set view map\nset pm3d map corners2color c1\n"
              "set palette defined (0 '#ffffff', 1 '#e9a03b', 2 '#c0392b', 3 '#3b0f0f')\n"
              "set xlabel 'x (mm), rolling'\nset ylabel 'depth z (mm)'\nset yrange [*:*] reverse\n"
              "set autoscale xfix\nset autoscale yfix\nunset key\nunset grid\n" +
              fmt::format("set title 'von Mises (MPa)'\nset cblabel 'MPa'\nsplot $body{} using 1:2:3 with pm3d\n", b) +
              fmt::format("set title 'Tresca (s1 - s3)/2 (MPa)'\nsplot $body{} using 1:2:4 with pm3d\n", b) +
              "unset multiplot\n" + kFigureEnd;
  }
  return render(script, picture.list, plots, err);
}

}  // namespace

int plot_command(const std::string& output_dir, std::ostream& out, std::ostream& err) {
  const auto fail = [&err](const std::string& message) {
    std::string line = message;
    for (char& ch : line)
      if (ch == '\n' || ch == '\r') ch = ' ';
    err << "rollwear plot: " << line << '\n';
    err.flush();
  };
  try {
    const fs::path dir = output_dir;
    if (is_sweep_folder(dir)) {  // rollwear sweep's folder: results.csv and sweep.txt
      for (const fs::path& p : draw_sweep(read_sweep_output(dir), dir / "plots", err)) out << p.string() << '\n';
      out.flush();
      return 0;
    }
    if (is_cam_output(dir)) {
      for (const fs::path& p : draw_cam(dir, dir / "plots", err)) out << p.string() << '\n';
      out.flush();
      return 0;
    }
    if (is_cam_revolution_output(dir)) {  // rollwear cam's folder: a lubricated revolution's film and temperature
      for (const fs::path& p : draw_cam_revolution(dir, dir / "plots", err)) out << p.string() << '\n';
      out.flush();
      return 0;
    }
    if (is_contact_output(dir)) {  // rollwear contact's folder: the stresses below the surface
      for (const fs::path& p : draw_subsurface(dir, dir / "plots", err)) out << p.string() << '\n';
      out.flush();
      return 0;
    }
    const RunOutput run = read_run_output(dir);
    for (const fs::path& p : draw(run, dir / "plots", err)) out << p.string() << '\n';
    out.flush();
    if (run.bodies.empty()) {
      fail(fmt::format("no profile plot drawn: no snapshot in {} (no snapshots/snapshot_KKKK_BODY.csv)",
                       (dir / "snapshots").string()));
      return kExitBadInput;
    }
    return 0;
  } catch (const std::exception& e) {
    fail(e.what());
    return contact::exit_status_of(e);
  } catch (...) {
    fail("unknown failure");
    return kExitFailure;
  }
}

int plot_command(const std::string& output_dir) { return plot_command(output_dir, std::cout, std::cerr); }
