// rollwear plot (app/plot.h): the pictures of a synthetic wear-run output folder, drawn by gnuplot,
// and the one-line errors of a folder that is missing, incomplete or malformed, or of a gnuplot that
// is missing or fails. No test leaves a torn PNG or a temporary file behind.
#include "app/plot.h"
#include "lib/io/csv.h"
#include "lib/normal/hertz.h"
#include "lib/subsurface/subsurface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "tests/temp_dir.h"
#include "tests/test_text.h"

namespace {
using rollwear_test::read_text;
using rollwear_test::lines_of;

namespace fs = std::filesystem;

constexpr std::uintmax_t kMinPngBytes = 5000;  // a 1000 x 650 picture with axes, text and curves

const char* const kSummaryHeader =
    "step,revolutions,hours,max_depth_m,worn_volume_m3,a_m,b_m,p0_Pa,Fx_N,power_W,step_revolutions,"
    "error_estimate,rejected,rhs_evals";

void write_text(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

// the files under dir, names relative to it, sorted
std::vector<std::string> files_under(const fs::path& dir) {
  std::vector<std::string> names;
  if (!fs::exists(dir)) return names;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) names.push_back(fs::relative(e.path(), dir).string());
  std::sort(names.begin(), names.end());
  return names;
}

bool has_temporary(const fs::path& dir) {
  for (const std::string& name : files_under(dir))
    if (name.find(".tmp.") != std::string::npos || name.find(".gp") != std::string::npos) return true;
  return false;
}

::testing::AssertionResult is_png(const fs::path& p) {
  if (!fs::exists(p)) return ::testing::AssertionFailure() << p << " does not exist";
  const std::string bytes = read_text(p);
  if (bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return ::testing::AssertionFailure() << p << " is no PNG";
  if (bytes.size() <= kMinPngBytes)
    return ::testing::AssertionFailure() << p << " has only " << bytes.size() << " bytes";
  return ::testing::AssertionSuccess();
}

// one line on stderr, starting with the command's prefix
::testing::AssertionResult is_one_error_line(const std::string& err) {
  if (err.rfind("rollwear plot: ", 0) != 0) return ::testing::AssertionFailure() << "no prefix: " << err;
  if (err.find('\n') != err.size() - 1) return ::testing::AssertionFailure() << "not one line: " << err;
  return ::testing::AssertionSuccess();
}

// summary.csv of a run: a roller wearing in, the depth growing, p0 falling as the contact widens
std::string summary_csv() {
  std::string s = "# rollwear run\n# case: synthetic_roller\n# units: SI\n" + std::string(kSummaryHeader) + "\n";
  const double revolutions[] = {0, 2.0e6, 6.0e6, 1.5e7, 3.0e7};
  for (int k = 0; k < 5; ++k) {
    const double n = revolutions[k];
    const double depth_m = 6e-6 * (1 - std::exp(-n / 1.2e7));
    const double p0_Pa = 1.6e9 - 4e8 * (1 - std::exp(-n / 1.2e7));
    std::ostringstream row;
    row.precision(17);
    row << k << ',' << n << ',' << n * 3.49e-5 << ',' << depth_m << ",1e-12,3.1e-4,1.2e-3," << p0_Pa << ",4.5,0.45,"
        << (k == 0 ? 0 : n - revolutions[k - 1]) << ",1e-4,0,12\n";
    s += row.str();
  }
  return s;
}

// a snapshot of body1's profile: a 0.5 m crown over +-10 mm, worn to max_depth_m over +-3 mm
std::string snapshot_csv(double revolutions, double max_depth_m) {
  std::ostringstream s;
  s.precision(17);
  s << "# case: synthetic_roller\n# body: body1\n# revolutions: " << revolutions
    << "\n# hours: " << revolutions * 3.49e-5 << "\ny_m,z_original_m,z_m,depth_m\n";
  for (int i = 0; i <= 80; ++i) {
    const double y = -0.010 + 0.020 * i / 80;
    const double z_original = y * y / (2 * 0.5);
    const double depth = std::fabs(y) < 0.003 ? max_depth_m * (1 - (y / 0.003) * (y / 0.003)) : 0.0;
    s << y << ',' << z_original << ',' << z_original + depth << ',' << depth << '\n';
  }
  return s.str();
}

// the output folder of a run with two snapshots of body1
void write_run_output(const fs::path& dir) {
  write_text(dir / "summary.csv", summary_csv());
  write_text(dir / "snapshots" / "snapshot_0000_body1.csv", snapshot_csv(1.5e7, 4.4e-6));
  write_text(dir / "snapshots" / "snapshot_0001_body1.csv", snapshot_csv(3.0e7, 5.6e-6));
  write_text(dir / "report.txt", "case: synthetic_roller\nended_by: revolutions\n");
}

struct Result {
  int status = -1;
  std::string out, err;
};

Result plot(const fs::path& dir) {
  std::ostringstream out, err;
  Result r;
  r.status = plot_command(dir.string(), out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

// PATH set to one directory for the life of the guard
class PathGuard {
 public:
  explicit PathGuard(const fs::path& dir) : old_(std::getenv("PATH") ? std::getenv("PATH") : "") {
    ::setenv("PATH", dir.c_str(), 1);
  }
  ~PathGuard() { ::setenv("PATH", old_.c_str(), 1); }
  PathGuard(const PathGuard&) = delete;
  PathGuard& operator=(const PathGuard&) = delete;

 private:
  std::string old_;
};

// an executable "gnuplot" in dir that writes a torn file to every "set output" of its script, says
// something on stderr and fails
void write_failing_gnuplot(const fs::path& dir) {
  const fs::path p = dir / "gnuplot";
  write_text(p,
             "#!/bin/sh\n"
             "sed -n \"s/^set output '\\(.*\\)'$/\\1/p\" \"$1\" | while IFS= read -r f; do printf torn > \"$f\"; "
             "done\n"
             "echo 'fake gnuplot: line 7: the pen broke' >&2\n"
             "exit 3\n");
  fs::permissions(p, fs::perms::owner_all);
}

const std::vector<std::string> kAllPictures = {"depth.png", "depth_profile_body1.png", "pressure.png",
                                               "profile_body1.png"};

using PlotCommand = rollwear_test::TempDirTest;

TEST_F(PlotCommand, DrawsEveryPictureOfARunAndListsThem) {
  const fs::path run = dir_ / "run";
  write_run_output(run);
  const Result r = plot(run);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(files_under(run / "plots"), kAllPictures);
  for (const std::string& name : kAllPictures) {
    EXPECT_TRUE(is_png(run / "plots" / name));
    EXPECT_NE(r.out.find((run / "plots" / name).string() + "\n"), std::string::npos) << r.out;
  }
  EXPECT_FALSE(has_temporary(run));
}

// a fatigue run's folder (docs/fatigue.md): the reference body's snapshots carry the Miner damage per node, the other
// body's do not; the damage along the track is drawn for body1 beside its worn profiles, for body2 not
TEST_F(PlotCommand, FatigueRunDrawsTheDamageAlongTheTrackOfTheBodyThatHasIt) {
  const fs::path run = dir_ / "run";
  write_run_output(run);
  for (const auto& [file, revolutions, peak] : {std::tuple{"snapshot_0000_body1.csv", 1.5e7, 0.4},
                                                std::tuple{"snapshot_0001_body1.csv", 3.0e7, 0.8}}) {
    std::istringstream in(snapshot_csv(revolutions, 5e-6));
    std::string text, line;
    while (std::getline(in, line)) {
      if (line.rfind("#", 0) == 0) text += line + "\n";
      else if (line.rfind("y_m", 0) == 0) text += line + ",damage\n";
      else {
        const double y = std::stod(line.substr(0, line.find(',')));
        text += line + "," + fmt::format("{}", peak * std::exp(-(y / 0.004) * (y / 0.004))) + "\n";
      }
    }
    write_text(run / "snapshots" / file, text);
  }
  write_text(run / "snapshots" / "snapshot_0000_body2.csv", snapshot_csv(3.0e7, 1e-6));
  const Result r = plot(run);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<std::string> pictures = {"damage_profile_body1.png", "depth.png", "depth_profile_body1.png",
                                             "depth_profile_body2.png", "pressure.png", "profile_body1.png",
                                             "profile_body2.png"};
  EXPECT_EQ(files_under(run / "plots"), pictures);
  EXPECT_TRUE(is_png(run / "plots" / "damage_profile_body1.png"));
  EXPECT_NE(r.out.find((run / "plots" / "damage_profile_body1.png").string() + "\n"), std::string::npos) << r.out;
  EXPECT_FALSE(has_temporary(run));
}

TEST_F(PlotCommand, FindsColumnsByNameWhateverTheirOrder) {
  // the columns used (revolutions, max_depth_m, p0_Pa; y_m, z_original_m, z_m, depth_m) moved and
  // joined by columns the plot does not know, some of them text
  const fs::path run = dir_ / "run";
  write_text(run / "summary.csv",
             "# case: reordered\nnote,p0_Pa,revolutions,extra_column,max_depth_m\n"
             "\"start, unworn\",1.6e9,0,x,0\nrun,1.5e9,1e6,y,1e-6\nrun,1.45e9,3e6,z,2.5e-6\n");
  write_text(run / "snapshots" / "snapshot_0000_body2.csv",
             "# revolutions: 3e6\ndepth_m,label,z_m,y_m,z_original_m\n"
             "0,a,0.0001,-0.01,0.0001\n2e-6,b,2e-6,0,0\n0,c,0.0001,0.01,0.0001\n");
  const Result r = plot(run);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(files_under(run / "plots"),
            (std::vector<std::string>{"depth.png", "depth_profile_body2.png", "pressure.png", "profile_body2.png"}));
  EXPECT_TRUE(is_png(run / "plots" / "profile_body2.png"));
}

TEST_F(PlotCommand, IgnoresFilesThatAreNoSnapshots) {
  // a running wear loop's temporary snapshot, and files of other names, are not read
  const fs::path run = dir_ / "run";
  write_run_output(run);
  write_text(run / "snapshots" / "snapshot_0002_body1.csv.tmp.4242", "torn,");
  write_text(run / "snapshots" / "notes.csv", "not,a,snapshot\n");
  write_text(run / "snapshots" / "snapshot_x_body1.csv", "not a snapshot\n");
  const Result r = plot(run);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(files_under(run / "plots"), kAllPictures);
}

TEST_F(PlotCommand, WithoutSnapshotsDrawsHistoriesAndSaysNoProfile) {
  const fs::path run = dir_ / "run";
  write_text(run / "summary.csv", summary_csv());
  const Result r = plot(run);
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(is_one_error_line(r.err));
  EXPECT_NE(r.err.find("no profile plot"), std::string::npos) << r.err;
  EXPECT_EQ(files_under(run / "plots"), (std::vector<std::string>{"depth.png", "pressure.png"}));
  EXPECT_TRUE(is_png(run / "plots" / "depth.png"));
  EXPECT_TRUE(is_png(run / "plots" / "pressure.png"));
  EXPECT_FALSE(has_temporary(run));
}

using PlotInput = rollwear_test::TempDirTest;

TEST_F(PlotInput, MissingFolderIsNamed) {
  const Result r = plot(dir_ / "no_such_run");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(is_one_error_line(r.err));
  EXPECT_NE(r.err.find("no_such_run"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "no_such_run"));
  EXPECT_EQ(r.out, "");
}

TEST_F(PlotInput, MissingSummaryIsNamed) {
  const fs::path run = dir_ / "run";
  write_text(run / "snapshots" / "snapshot_0000_body1.csv", snapshot_csv(1.5e7, 4.4e-6));
  const Result r = plot(run);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(is_one_error_line(r.err));
  EXPECT_NE(r.err.find((run / "summary.csv").string()), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(run / "plots"));
}

TEST_F(PlotInput, MalformedSummaryRowNamesFileAndLine) {
  const fs::path run = dir_ / "run";
  write_run_output(run);
  std::vector<std::string> lines = lines_of(summary_csv());  // 3 comments, the header, 5 rows
  ASSERT_EQ(lines.size(), 9u);
  lines[6] = lines[6].substr(0, lines[6].rfind(','));  // line 7: a cell short
  write_text(run / "summary.csv", joined(lines));

  const Result r = plot(run);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(is_one_error_line(r.err));
  EXPECT_NE(r.err.find((run / "summary.csv").string() + " line 7"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(run / "plots"));
}

TEST_F(PlotInput, NonNumericSnapshotCellNamesFileLineAndColumn) {
  const fs::path run = dir_ / "run";
  write_run_output(run);
  std::vector<std::string> lines = lines_of(snapshot_csv(3.0e7, 5.6e-6));  // 4 comments, the header, rows
  ASSERT_EQ(lines[4], "y_m,z_original_m,z_m,depth_m");
  lines[7] = "abc" + lines[7].substr(lines[7].find(','));  // line 8: y_m is no number
  const fs::path snapshot = run / "snapshots" / "snapshot_0001_body1.csv";
  write_text(snapshot, joined(lines));

  const Result r = plot(run);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(is_one_error_line(r.err));
  EXPECT_NE(r.err.find(snapshot.string() + " line 8"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("y_m"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(run / "plots"));
}

TEST_F(PlotInput, MissingColumnIsNamedWithTheHeaderLine) {
  const fs::path run = dir_ / "run";
  write_text(run / "summary.csv", "# case: x\nstep,revolutions,max_depth_m\n0,0,0\n1,1e6,1e-6\n");
  const Result r = plot(run);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(is_one_error_line(r.err));
  EXPECT_NE(r.err.find((run / "summary.csv").string() + " line 2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'p0_Pa'"), std::string::npos) << r.err;
}

using PlotGnuplot = rollwear_test::TempDirTest;

TEST_F(PlotGnuplot, MissingGnuplotNamesTheDebianPackage) {
  const fs::path run = dir_ / "run";
  write_run_output(run);
  fs::create_directories(dir_ / "empty_bin");
  Result r;
  {
    const PathGuard path(dir_ / "empty_bin");
    r = plot(run);
  }
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(is_one_error_line(r.err));
  EXPECT_NE(r.err.find("gnuplot-nox"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("sudo apt-get install -y gnuplot-nox"), std::string::npos) << r.err;
  EXPECT_EQ(files_under(run / "plots"), std::vector<std::string>{});
}

TEST_F(PlotGnuplot, FailureShowsItsMessageAndKeepsTheOldPictures) {
  const fs::path run = dir_ / "run";
  write_run_output(run);
  ASSERT_EQ(plot(run).status, 0);
  const std::string old_profile = read_text(run / "plots" / "profile_body1.png");

  write_failing_gnuplot(dir_);
  Result r;
  {
    const PathGuard path(dir_);
    r = plot(run);
  }
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(is_one_error_line(r.err));
  EXPECT_NE(r.err.find("exit status 3"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the pen broke"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  // the torn temporaries are gone, the pictures of the run before untouched
  EXPECT_EQ(files_under(run / "plots"), kAllPictures);
  EXPECT_FALSE(has_temporary(run));
  EXPECT_EQ(read_text(run / "plots" / "profile_body1.png"), old_profile);
}

// ---- a sweep's output folder (rollwear sweep: results.csv, sweep.txt) ----

std::string fmt_row(int i, double input, double life, const std::string& ended_by) {
  std::ostringstream r;
  r.precision(17);
  r << i << ',' << input << ',' << life << ',' << ended_by << ",1e-4,2e-7,ok,\n";
  return r.str();
}

// a product grid of 3 x 2 cases over friction.mu and load.normal_load_N: one failed (its message quoted,
// with a comma), one that reached the budget (censored)
void write_grid_sweep(const fs::path& dir) {
  write_text(dir / "sweep.txt", "fingerprint 0123456789abcdef\ncases 6\nshard 1/1\nsampling product\nseed 0\n"
                                "axis friction.mu 3 0.3\naxis load.normal_load_N 2 1500\n");
  write_text(dir / "results.csv",
             "index,friction.mu,load.normal_load_N,life_revolutions,ended_by,max_depth_m,worn_volume_m3,status,message\n"
             "0,0.2,1000,2.5e8,max_depth,1e-4,2e-7,ok,max_depth reached at N 2.5e8\n"
             "1,0.2,2000,1.1e8,edge,8e-5,1.9e-7,ok,edge reached\n"
             "2,0.3,1000,3.4e8,max_depth,1e-4,2e-7,ok,\n"
             "3,0.3,2000,,failed,,,failed,\"ended at N 1e6, the last accepted step: the normal problem did not converge\"\n"
             "4,0.4,1000,1e10,revolutions,6e-5,1e-7,ok,the life budget reached\n"
             "5,0.4,2000,1.9e8,edge,9e-5,1.8e-7,ok,edge reached\n");
}

// a Latin hypercube of 8 cases over one input, two of them censored at the budget
void write_random_sweep(const fs::path& dir) {
  write_text(dir / "sweep.txt", "fingerprint 0123456789abcdef\ncases 8\nshard 1/1\nsampling latin-hypercube\nseed 7\n");
  std::string t = "index,wear.body1.archard_k,life_revolutions,ended_by,max_depth_m,worn_volume_m3,status,message\n";
  const double lives[] = {3e7, 5e7, 8e7, 1e8, 1.3e8, 2e8, 1e9, 1e9};
  for (int i = 0; i < 8; ++i)
    t += fmt_row(i, 1e-4 / (1 + i), lives[i], i >= 6 ? "revolutions" : "max_depth");
  write_text(dir / "results.csv", t);
}

// a contact's folder (rollwear contact): the section below the surface of a small Hertz contact, each body a map
TEST_F(PlotCommand, ContactFolderDrawsTheSectionBelowTheSurfaceOfEachBody) {
  const fs::path folder = dir_ / "contact";
  const contact::ElasticPair steel{{210e9, 0.3}, {210e9, 0.3}};
  const contact::ContactPatch patch =
      contact::solve_normal_hertz({{0.010, 0.010}, {0.010, 0.010}}, steel, 100, {9, 9});
  contact::SubsurfaceOptions opt;
  opt.planes = 5;
  const contact::Subsurface below =
      contact::solve_subsurface(contact::surface_tractions(patch, nullptr, 1), 0.3, patch.a_m, opt);
  write_text(folder / "subsurface_section.csv", contact::subsurface_section_csv(patch.grid, {&below, &below}));
  write_text(folder / "strips.csv", "y_m\n0\n");
  const Result r = plot(folder);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<std::string> pictures = {"subsurface_body1.png", "subsurface_body2.png"};
  EXPECT_EQ(files_under(folder / "plots"), pictures);
  for (const std::string& name : pictures) EXPECT_TRUE(is_png(folder / "plots" / name)) << name;
  EXPECT_FALSE(has_temporary(folder));
}

// a lubricated cam revolution's folder (rollwear cam: revolution.csv alone, with the film's and the flash temperature's
// columns among the others, found by name): the film, lambda and the flash temperature over the cam angle; a dry
// revolution's folder has nothing to draw and says so (exit 2)
TEST_F(PlotCommand, CamRevolutionFolderDrawsTheFilmAndFlashTemperatureOverTheCamAngle) {
  const fs::path folder = dir_ / "cam";
  std::string t = "cam_angle_deg,lift_m,normal_load_N,h_min_m,h_central_m,lambda,lubrication_regime,flash_max_K\n";
  for (int k = 0; k < 72; ++k) {
    const double theta = 5.0 * k, bump = k < 26 ? std::sin(3.14159265 * k / 26) : 0.0;
    t += fmt::format("{},{},{},{},{},{},{},{}\n", theta, 0.0075 * bump, 680 + 800 * bump, 1.3e-7 - 3e-8 * bump,
                     1.6e-7 - 3e-8 * bump, (1.3e-7 - 3e-8 * bump) / 2.7e-7, "boundary", 0.01 + 0.02 * bump);
  }
  write_text(folder / "revolution.csv", t);
  const Result r = plot(folder);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(files_under(folder / "plots"), std::vector<std::string>{"cam_film.png"});
  EXPECT_TRUE(is_png(folder / "plots" / "cam_film.png"));
  EXPECT_NE(r.out.find("cam_film.png"), std::string::npos) << r.out;
  EXPECT_FALSE(has_temporary(folder));

  const fs::path dry = dir_ / "dry";
  write_text(dry / "revolution.csv", "cam_angle_deg,lift_m,normal_load_N\n0,0,680\n5,0.001,700\n");
  const Result d = plot(dry);
  EXPECT_EQ(d.status, 2);
  EXPECT_NE(d.err.find("revolution.csv line 1: a cam revolution without the film's or the flash temperature's"),
            std::string::npos) << d.err;
  EXPECT_FALSE(fs::exists(dry / "plots" / "cam_film.png"));
}

TEST_F(PlotCommand, SweepGridDrawsTheLifeAgainstEveryAxis) {
  const fs::path sweep = dir_ / "sweep-grid";
  write_grid_sweep(sweep);
  const Result r = plot(sweep);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<std::string> pictures = {"life_vs_friction_mu.png", "life_vs_load_normal_load_N.png"};
  EXPECT_EQ(files_under(sweep / "plots"), pictures);  // a grid: no distribution
  for (const std::string& name : pictures) {
    EXPECT_TRUE(is_png(sweep / "plots" / name));
    EXPECT_NE(r.out.find((sweep / "plots" / name).string() + "\n"), std::string::npos) << r.out;
  }
  EXPECT_FALSE(has_temporary(sweep));
}

TEST_F(PlotCommand, RandomSweepDrawsTheLifesDistributionWithKaplanMeier) {
  const fs::path sweep = dir_ / "mc";
  write_random_sweep(sweep);
  const Result r = plot(sweep);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> pictures = {"life_distribution.png", "life_vs_wear_body1_archard_k.png"};
  EXPECT_EQ(files_under(sweep / "plots"), pictures);
  for (const std::string& name : pictures) EXPECT_TRUE(is_png(sweep / "plots" / name));
  EXPECT_FALSE(has_temporary(sweep));
}

// a contact sweep's folder (rollwear sweep on a case without wear:, cases/sweep-contact.yaml): the contact against
// each varied key, not "not a sweep's results table"
TEST_F(PlotCommand, ContactSweepDrawsTheContactAgainstEveryAxis) {
  const fs::path sweep = dir_ / "sweep-contact";
  write_text(sweep / "sweep.txt", "fingerprint 0123456789abcdef\ncases 4\nshard 1/1\nsampling product\nseed 0\nkind contact\n"
                                  "axis load.normal_load_N 2 1500\naxis kinematics.xi 2 0.001\n");
  write_text(sweep / "results.csv",
             "index,load.normal_load_N,kinematics.xi,a_m,b_m,p0_Pa,approach_m,Fx_N,Fy_N,Mz_N_m,power_W,stick_fraction,"
             "status,message\n"
             "0,1000,0.001,0.0002,0.0023,1.04e9,6.9e-6,-115,0,0,0.115,0.8,ok,\n"
             "1,1000,0.002,0.0002,0.0023,1.04e9,6.9e-6,-200,0,0,0.4,0.6,ok,\n"
             "2,2000,0.001,0.00025,0.0029,1.3e9,1.1e-5,-190,0,0,0.19,0.85,ok,\n"
             "3,2000,0.002,,,,,,,,,,failed,\"the normal problem did not converge\"\n");
  const Result r = plot(sweep);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<std::string> pictures = {"contact_vs_kinematics_xi.png", "contact_vs_load_normal_load_N.png"};
  EXPECT_EQ(files_under(sweep / "plots"), pictures);
  for (const std::string& name : pictures) {
    EXPECT_TRUE(is_png(sweep / "plots" / name));
    EXPECT_NE(r.out.find((sweep / "plots" / name).string() + "\n"), std::string::npos) << r.out;
  }
  EXPECT_FALSE(has_temporary(sweep));
}

TEST_F(PlotInput, SweepTableRowThatIsNoNumberNamesFileAndLine) {
  const fs::path sweep = dir_ / "bad";
  write_grid_sweep(sweep);
  std::string table = read_text(sweep / "results.csv");
  table.replace(table.find("3.4e8"), 5, "lots");
  write_text(sweep / "results.csv", table);
  const Result r = plot(sweep);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(is_one_error_line(r.err));
  EXPECT_NE(r.err.find((sweep / "results.csv").string() + " line 4: malformed row: column life_revolutions is 'lots'"),
            std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(sweep / "plots"));
}

TEST_F(PlotGnuplot, SweepFailureKeepsTheOldPictures) {
  const fs::path sweep = dir_ / "sweep-grid";
  write_grid_sweep(sweep);
  ASSERT_EQ(plot(sweep).status, 0);
  const std::string old = read_text(sweep / "plots" / "life_vs_friction_mu.png");
  write_failing_gnuplot(dir_);
  Result r;
  {
    const PathGuard path(dir_);
    r = plot(sweep);
  }
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("the pen broke"), std::string::npos) << r.err;
  EXPECT_FALSE(has_temporary(sweep));
  EXPECT_EQ(read_text(sweep / "plots" / "life_vs_friction_mu.png"), old);
}

}  // namespace
