// The output files (lib/io/csv.h) and the command line (app/, run as a process).
#include "lib/io/csv.h"

#include <gtest/gtest.h>

#include "tests/held_lock.h"
#include "tests/temp_dir.h"
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <csignal>
#include <cstdio>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "lib/grid.h"
#include "lib/io/case.h"
#include "lib/errors.h"
#include "lib/normal/hertz.h"
#include "lib/tangential/satran.h"
#include "session/output_folder.h"
#include "tests/test_text.h"

namespace contact {
namespace {
using rollwear_test::read_text;
using rollwear_test::lines_of;

namespace fs = std::filesystem;

// a directory of its own for each test, removed at the end
class TempDir : public rollwear_test::TempDirTest {
 protected:
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.push_back("");
  return cells;
}

bool is_number(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// a table: the header's columns, every row as wide, every cell a number except the named columns
::testing::AssertionResult is_numeric_table(const std::vector<std::string>& lines, const std::string& header,
                                           const std::vector<std::size_t>& text_columns = {}) {
  if (lines.empty()) return ::testing::AssertionFailure() << "empty file";
  if (lines[0] != header) return ::testing::AssertionFailure() << "header " << lines[0];
  const std::size_t width = split(header).size();
  for (std::size_t r = 1; r < lines.size(); ++r) {
    const std::vector<std::string> cells = split(lines[r]);
    if (cells.size() != width)
      return ::testing::AssertionFailure() << "row " << r << " has " << cells.size() << " cells: " << lines[r];
    for (std::size_t k = 0; k < width; ++k) {
      bool text = false;
      for (const std::size_t t : text_columns) text = text || t == k;
      if (!text && !is_number(cells[k]))
        return ::testing::AssertionFailure() << "row " << r << " cell " << k << " '" << cells[k] << "'";
    }
  }
  return ::testing::AssertionSuccess();
}

// ---- files ------------------------------------------------------------------------------------------

using AtomicWrite = TempDir;

TEST_F(AtomicWrite, ReplacesContentAndLeavesNoTempFile) {
  const fs::path p = dir_ / "sub" / "dir" / "summary.csv";  // parents are created
  write_file_atomic(p, "first\n");
  EXPECT_EQ(read_text(p), "first\n");
  write_file_atomic(p, "second, longer\n");
  EXPECT_EQ(read_text(p), "second, longer\n");
  std::vector<fs::path> entries;
  for (const auto& e : fs::directory_iterator(p.parent_path())) entries.push_back(e.path());
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0], p);
}

TEST_F(AtomicWrite, FailureLeavesNoFileAndNamesPath) {
  // the target is a directory: the rename fails after the temporary file was written
  const fs::path target = dir_ / "taken";
  fs::create_directories(target);
  try {
    write_file_atomic(target, "text\n");
    FAIL() << "wrote over a directory";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
  }
  // the parent is a file: nothing can be created
  const fs::path blocked = dir_ / "file" / "summary.csv";
  write_file_atomic(dir_ / "file", "a file\n");
  EXPECT_THROW(write_file_atomic(blocked, "text\n"), std::runtime_error);

  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"file", "taken"}));
  EXPECT_TRUE(fs::is_empty(target));
}

TEST_F(AtomicWrite, SeveralFilesAreAllWrittenOrNone) {
  fs::create_directories(dir_ / "taken");
  const std::vector<OutputFile> files = {{dir_ / "a.csv", "a\n"}, {dir_ / "taken" / "x" / "b.csv", "b\n"}};
  write_file_atomic(dir_ / "taken" / "x", "a file in the way\n");
  EXPECT_THROW(write_files_atomic(files), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir_ / "a.csv"));  // the first one was not renamed into place either
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(AtomicWrite, StreamedFileAppearsWholeOnlyWhenCommitted) {
  const fs::path p = dir_ / "run" / "timeseries.csv";
  {
    StreamedFile f(p);
    f.append("step\n");
    f.append("1\n");
    EXPECT_FALSE(fs::exists(p));  // only the temporary file while the run streams
    EXPECT_TRUE(fs::exists(f.temporary_path()));
    write_files_atomic({{dir_ / "run" / "summary.csv", "s\n"}}, {&f});
    EXPECT_TRUE(f.committed());
    EXPECT_FALSE(fs::exists(f.temporary_path()));
  }
  EXPECT_EQ(read_text(p), "step\n1\n");
  EXPECT_EQ(read_text(dir_ / "run" / "summary.csv"), "s\n");

  // a run that fails: the temporary file goes, the previous file stays
  fs::path tmp;
  {
    StreamedFile f(p);
    f.append("torn");
    tmp = f.temporary_path();
  }
  EXPECT_FALSE(fs::exists(tmp));
  EXPECT_EQ(read_text(p), "step\n1\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "run"), fs::directory_iterator()), 2);
}

// A signal that ends the process (the program's handler: session/output_folder.h) while write_files_atomic is
// writing leaves none of its temporaries (a checkpoint.txt.tmp.PID once outlived a SIGINT). Constructed so that
// the signal falls inside the write: the second file's temporary is a FIFO, whose opening for writing blocks
// (no reader comes), so the child is held after the first temporary is written and before any rename.
TEST_F(AtomicWrite, ASignalDuringTheWriteLeavesNoTemporary) {
  int go[2];
  ASSERT_EQ(::pipe(go), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::close(go[1]);
    session::interrupted::say_on_signal("");  // installs the handler as every command does
    char c = 0;
    if (::read(go[0], &c, 1) != 1) ::_exit(3);
    write_files_atomic({{dir_ / "a.csv", "a\n"}, {dir_ / "b.csv", "b\n"}});
    ::_exit(0);
  }
  ::close(go[0]);
  const fs::path tmp_a = dir_ / ("a.csv.tmp." + std::to_string(pid)), tmp_b = dir_ / ("b.csv.tmp." + std::to_string(pid));
  ASSERT_EQ(::mkfifo(tmp_b.c_str(), 0600), 0);
  ASSERT_EQ(::write(go[1], "x", 1), 1);
  for (int k = 0; k < 1000 && !fs::exists(tmp_a); ++k) ::usleep(10000);
  EXPECT_TRUE(fs::exists(tmp_a));  // the child is inside the write
  ::usleep(20000);                 // and held at the FIFO
  ::kill(pid, SIGINT);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ::close(go[1]);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << status;
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir_)) left.push_back(e.path().filename().string());
  EXPECT_TRUE(left.empty()) << left.front();
}

// a 3 x 2 patch and solution with distinct values in every cell
struct SmallResult {
  ContactPatch patch;
  TangentialProblem problem;
  TangentialSolution solution;
};
SmallResult small_result() {
  SmallResult r;
  ContactPatch& p = r.patch;
  p.a_m = 1e-3 / 3;
  p.b_m = 2e-3;
  p.grid = make_grid(1e-3, 2e-3, GridSpec{3, 2});
  p.half_length_m = Eigen::ArrayXd::Constant(2, 0.9e-3);
  p.strip_peak_Pa = Eigen::ArrayXd::Constant(2, 1e9);
  p.pressure_Pa = Eigen::ArrayXXd::Constant(3, 2, 1.0 / 3.0);
  TangentialSolution& s = r.solution;
  s.tau_x_Pa = Eigen::ArrayXXd::Zero(3, 2);
  s.tau_y_Pa = Eigen::ArrayXXd::Zero(3, 2);
  s.slip_x_m_per_s = Eigen::ArrayXXd::Zero(3, 2);
  s.slip_y_m_per_s = Eigen::ArrayXXd::Zero(3, 2);
  s.power_W_per_m2 = Eigen::ArrayXXd::Zero(3, 2);
  s.state = Eigen::ArrayXXi::Ones(3, 2);
  s.state(2, 1) = 2;
  s.tau_x_Pa(2, 1) = -1.25e8;
  for (Eigen::ArrayXd* a : {&s.strip_power_W_per_m, &s.strip_creep_power_W_per_m, &s.strip_trailing_W_per_m,
                            &s.strip_force_x_N_per_m, &s.strip_force_y_N_per_m})
    *a = Eigen::ArrayXd::Zero(2);
  s.Fx_N = -0.1;
  return r;
}

TEST(CsvOutput, FieldsHaveOneRowPerCellStripByStripAtFullPrecision) {
  const SmallResult r = small_result();
  const std::vector<std::string> lines = lines_of(fields_csv(r.patch, r.solution));
  ASSERT_EQ(lines.size(), 3u * 2u + 1u);
  EXPECT_TRUE(is_numeric_table(
      lines, "x_m,y_m,pressure_Pa,tau_x_Pa,tau_y_Pa,slip_x_m_per_s,slip_y_m_per_s,power_W_per_m2,state"));
  // the last row is cell (2, 1): x increases within a strip, strips follow one another
  const std::vector<std::string> last = split(lines.back());
  EXPECT_EQ(std::strtod(last[0].c_str(), nullptr), r.patch.grid.x_m(2));
  EXPECT_EQ(std::strtod(last[1].c_str(), nullptr), r.patch.grid.y_m(1));
  EXPECT_EQ(std::strtod(last[2].c_str(), nullptr), 1.0 / 3.0);  // reads back exactly
  EXPECT_EQ(last[3], "-1.25e+08");  // the fewest digits that read back exactly
  EXPECT_EQ(last[8], "2");
}

TEST(CsvOutput, StripsAndSummaryHaveTheirColumns) {
  const SmallResult r = small_result();
  const std::vector<std::string> strips = lines_of(strips_csv(r.patch, r.solution));
  ASSERT_EQ(strips.size(), 2u + 1u);
  EXPECT_TRUE(is_numeric_table(strips,
                               "y_m,half_length_m,peak_pressure_Pa,force_x_N_per_m,force_y_N_per_m,"
                               "power_W_per_m,creep_power_W_per_m,trailing_W_per_m"));
  const std::vector<std::string> summary =
      lines_of(summary_csv("small, odd", r.patch, r.problem, r.solution, TangentialScheme::Classic));
  ASSERT_EQ(summary.size(), 2u);
  EXPECT_EQ(summary[0],
            "name,a_m,b_m,p0_Pa,approach_m,C11,C22,C23,C33,L_m_per_Pa,Fx_N,Fy_N,Mz_N_m,power_W,creep_work_W,"
            "stick_fraction,scheme,nx,ny");
  EXPECT_EQ(summary[1].rfind("\"small, odd\",0.0003333333333333333,0.002,", 0), 0u) << summary[1];
  EXPECT_NE(summary[1].find(",-0.1,"), std::string::npos) << summary[1];
  EXPECT_EQ(summary[1].substr(summary[1].size() - 12), ",classic,3,2");
}

TEST(CsvOutput, ShapeMismatchThrows) {
  SmallResult r = small_result();
  r.solution.tau_y_Pa = Eigen::ArrayXXd::Zero(2, 3);
  EXPECT_THROW(fields_csv(r.patch, r.solution), std::invalid_argument);
  r.solution.strip_power_W_per_m = Eigen::ArrayXd::Zero(3);
  EXPECT_THROW(strips_csv(r.patch, r.solution), std::invalid_argument);
}

TEST(CsvOutput, TransientTablesHaveTheirColumnsAtFullPrecision) {
  TransientRecord r;
  r.step = 7;
  r.t_s = 1.0 / 3.0 * 1e-4;
  r.Fx_N = -449.78;
  r.cfl = 1;
  const std::vector<std::string> rows = lines_of(transient_header() + transient_row(r));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_TRUE(is_numeric_table(rows,
                               "step,t_s,q_m,dt_s,speed_m_per_s,xi,eta,phi_per_m,normal_load_N,omega1_rad_per_s,"
                               "Fx_N,Fy_N,Mz_N_m,power_W,stick_fraction,balance_residual_W,cfl,shortened,step_scheme",
                               {18}));
  EXPECT_EQ(rows[1].substr(rows[1].size() - 8), ",0,shift");
  const std::vector<std::string> cells = split(rows[1]);
  EXPECT_EQ(cells[0], "7");
  EXPECT_EQ(std::strtod(cells[1].c_str(), nullptr), r.t_s);  // reads back exactly
  EXPECT_EQ(cells[10], "-449.78");

  const Eigen::ArrayXd y = (Eigen::ArrayXd(2) << -1e-3, 1e-3).finished();
  const Eigen::ArrayXd power = (Eigen::ArrayXd(2) << 0.25, 0.5).finished();
  const std::vector<std::string> strips = lines_of(strip_power_header() + strip_power_rows(r, y, power));
  ASSERT_EQ(strips.size(), 3u);
  EXPECT_TRUE(is_numeric_table(strips, "step,t_s,y_m,power_W_per_m"));
  EXPECT_EQ(strips[2].substr(strips[2].size() - 10), ",0.001,0.5");
  EXPECT_THROW(strip_power_rows(r, y, Eigen::ArrayXd::Zero(3)), std::invalid_argument);

  // a snapshot: one row per cell, the step's end time last
  const Grid g = make_grid(1e-3, 2e-3, GridSpec{3, 2});
  Snapshot snap;
  snap.t_s = 2e-4;
  for (Eigen::ArrayXXd* a : {&snap.pressure_Pa, &snap.tau_x_Pa, &snap.tau_y_Pa, &snap.slip_x_m_per_s,
                             &snap.slip_y_m_per_s})
    *a = Eigen::ArrayXXd::Zero(3, 2);
  const std::vector<std::string> cells_csv = lines_of(snapshot_csv(g, snap));
  ASSERT_EQ(cells_csv.size(), 3u * 2u + 1u);
  EXPECT_TRUE(is_numeric_table(cells_csv,
                               "x_m,y_m,pressure_Pa,tau_x_Pa,tau_y_Pa,slip_x_m_per_s,slip_y_m_per_s,t_s"));
  EXPECT_EQ(split(cells_csv.back()).back(), "0.0002");
  snap.tau_y_Pa = Eigen::ArrayXXd::Zero(2, 3);
  EXPECT_THROW(snapshot_csv(g, snap), std::invalid_argument);
}

// ---- command line -----------------------------------------------------------------------------------

struct ProcessResult {
  int exit_code = -1;
  std::string out, err;
};

// runs "rollwear ARGS" with stdout and stderr captured in dir
ProcessResult rollwear(const std::string& args, const fs::path& dir) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command =
      "'" + std::string(ROLLWEAR_EXE) + "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  ProcessResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

const fs::path kSource = ROLLWEAR_SOURCE_DIR;

using CommandLine = TempDir;

TEST_F(CommandLine, ContactOnPaperCaseWritesItsTables) {
  const fs::path out = dir_ / "paper";
  const ProcessResult r = rollwear("contact " + quoted(kSource / "cases" / "paper.yaml") + " -o " + quoted(out) +
                             " --log-level warn",
                         dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  for (const char* unit : {" mm", " MPa", " µm", " N", " W", "m/Pa"})
    EXPECT_NE(r.out.find(unit), std::string::npos) << "summary lacks" << unit << ":\n" << r.out;

  const std::vector<std::string> fields = lines_of(read_text(out / "fields.csv"));
  EXPECT_EQ(fields.size(), 80u * 80u + 1u);
  EXPECT_TRUE(is_numeric_table(
      fields, "x_m,y_m,pressure_Pa,tau_x_Pa,tau_y_Pa,slip_x_m_per_s,slip_y_m_per_s,power_W_per_m2,state"));

  const std::vector<std::string> strips = lines_of(read_text(out / "strips.csv"));
  EXPECT_EQ(strips.size(), 80u + 1u);
  EXPECT_TRUE(is_numeric_table(strips,
                               "y_m,half_length_m,peak_pressure_Pa,force_x_N_per_m,force_y_N_per_m,"
                               "power_W_per_m,creep_power_W_per_m,trailing_W_per_m"));

  const std::vector<std::string> summary = lines_of(read_text(out / "summary.csv"));
  ASSERT_EQ(summary.size(), 2u);
  EXPECT_TRUE(is_numeric_table(summary,
                               "name,a_m,b_m,p0_Pa,approach_m,C11,C22,C23,C33,L_m_per_Pa,Fx_N,Fy_N,Mz_N_m,"
                               "power_W,creep_work_W,stick_fraction,scheme,nx,ny",
                               {0, 16}));
  const std::vector<std::string> row = split(summary[1]);
  EXPECT_EQ(row[0], "paper");
  EXPECT_EQ(row[16], "relaxed");  // the default scheme
  EXPECT_EQ(row[17], "80");
  EXPECT_EQ(row[18], "80");

  // the stresses below the surface: five maxima per body, the x-z section of each body (31 planes x 80 cells)
  const std::vector<std::string> maxima = lines_of(read_text(out / "subsurface.csv"));
  EXPECT_EQ(maxima.size(), 2u * 5u + 1u);
  EXPECT_TRUE(is_numeric_table(maxima, "body,nu,measure,value_Pa,x_m,y_m,z_m", {2}));
  const std::vector<std::string> section = lines_of(read_text(out / "subsurface_section.csv"));
  EXPECT_EQ(section.size(), 2u * 31u * 80u + 1u);
  EXPECT_TRUE(is_numeric_table(section,
                               "body,y_m,x_m,z_m,sigma_xx_Pa,sigma_yy_Pa,sigma_zz_Pa,sigma_xy_Pa,sigma_xz_Pa,"
                               "sigma_yz_Pa,von_mises_Pa,tresca_Pa,sigma_1_Pa,sigma_2_Pa,sigma_3_Pa"));
  EXPECT_NE(r.out.find("below body 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("below body 2"), std::string::npos) << r.out;
  // (the lines' own words: the case's path may hold any word)
  EXPECT_EQ(r.out.find("fatigue, k ="), std::string::npos) << "no shear_yield_Pa, no fatigue:\n" << r.out;
  EXPECT_EQ(r.out.find("surface fatigue"), std::string::npos) << r.out;

  // nothing else: no temporary files left behind
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 5);
}


TEST_F(CommandLine, NoFieldsSkipsFieldsTable) {
  const fs::path out = dir_ / "paper";
  fs::create_directories(out);
  std::ofstream(out / "fields.csv") << "an earlier run's fields\n";  // stale: removed, not left behind
  const ProcessResult r = rollwear("contact " + quoted(kSource / "cases" / "paper.yaml") + " -o " + quoted(out) +
                             " --no-fields --log-level off",
                         dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "summary.csv"));
  EXPECT_TRUE(fs::exists(out / "strips.csv"));
  EXPECT_FALSE(fs::exists(out / "fields.csv"));
}

TEST_F(CommandLine, BadCaseExitsTwoWithFileLineAndKey) {
  const fs::path out = dir_ / "bad";
  const fs::path bad_mu = kSource / "tests" / "data" / "bad_mu.yaml";
  const ProcessResult r = rollwear("contact " + quoted(bad_mu) + " -o " + quoted(out), dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "rollwear: error: " + bad_mu.string() + ":8:19: friction.mu: must be in [0, 10], got -0.3\n");
  EXPECT_FALSE(fs::exists(out));

  const fs::path typo = kSource / "tests" / "data" / "unknown_key.yaml";
  const ProcessResult t = rollwear("contact " + quoted(typo) + " -o " + quoted(out), dir_);
  EXPECT_EQ(t.exit_code, 2);
  EXPECT_EQ(t.err, "rollwear: error: " + typo.string() +
                       ":7:3: load.normal_laod_N: unknown key, did you mean 'normal_load_N'? (valid: normal_load_N)\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(CommandLine, MissingCaseFileExitsTwo) {
  const fs::path missing = dir_ / "no_such_case.yaml";
  const ProcessResult r = rollwear("contact " + quoted(missing) + " -o " + quoted(dir_ / "out"), dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "rollwear: error: " + missing.string() + ": cannot read: No such file or directory\n");
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(CommandLine, BadOptionsExitTwoOnOneLine) {
  for (const std::string args : {"contact", "contact x.yaml --bogus", "contact x.yaml --log-level loud", ""}) {
    const ProcessResult r = rollwear(args, dir_);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(r.err.rfind("rollwear: error: ", 0), 0u) << args << ": " << r.err;
    EXPECT_EQ(lines_of(r.err).size(), 1u) << args << ": " << r.err;
  }
}

TEST_F(CommandLine, HelpMentionsEveryOption) {
  const ProcessResult app = rollwear("--help", dir_);
  EXPECT_EQ(app.exit_code, 0);
  for (const char* word : {"--help", "--version", "--log-level", "contact"})
    EXPECT_NE(app.out.find(word), std::string::npos) << word << " missing from:\n" << app.out;

  const ProcessResult contact = rollwear("contact --help", dir_);
  EXPECT_EQ(contact.exit_code, 0);
  for (const char* word : {"case", "-o,--output", "--no-fields", "--log-level", "trace", "off", "--help", "edge"})
    EXPECT_NE(contact.out.find(word), std::string::npos) << word << " missing from:\n" << contact.out;
}

// -q is every command's: contact, cam and plot take it as run, transient and sweep do (they show no progress line)
TEST_F(CommandLine, EveryCommandTakesQuiet) {
  for (const std::string command : {"contact", "transient", "run", "cam", "sweep", "plot"}) {
    const ProcessResult help = rollwear(command + " --help", dir_);
    EXPECT_EQ(help.exit_code, 0) << command;
    EXPECT_NE(help.out.find("-q,--quiet"), std::string::npos) << command << ":\n" << help.out;
  }
  const ProcessResult contact = rollwear("contact -q " + quoted(kSource / "cases" / "paper.yaml") + " -o " +
                                             quoted(dir_ / "c") + " --no-fields --log-level warn",
                                         dir_);
  EXPECT_EQ(contact.exit_code, 0) << contact.err;
  EXPECT_NE(contact.out.find("peak pressure"), std::string::npos) << contact.out;  // the summary still printed
  const ProcessResult cam = rollwear("cam -q " + quoted(kSource / "cases" / "cam-follower.yaml") + " -o " +
                                         quoted(dir_ / "cam") + " --log-level warn",
                                     dir_);
  EXPECT_EQ(cam.exit_code, 0) << cam.err;
  EXPECT_TRUE(fs::exists(dir_ / "cam" / "revolution.csv"));
  const ProcessResult plot = rollwear("plot -q " + quoted(dir_ / "none"), dir_);
  EXPECT_EQ(plot.exit_code, 2) << plot.err;
  EXPECT_EQ(plot.err.find("not expected"), std::string::npos) << plot.err;  // refused for the folder, not for -q
}

// a cam case with its base circle in millimetres written as metres: bad input at the key (exit 2), not a roller
// that stalls (exit 1)
TEST_F(CommandLine, CamRefusesAUnitSlipAtItsKey) {
  std::string text = read_text(kSource / "cases" / "cam-follower.yaml");
  text.replace(text.find("base_radius_m: 0.040"), 20, "base_radius_m: 40");
  std::ofstream(dir_ / "cam.yaml") << text;
  for (const std::string command : {"cam", "run"}) {
    const ProcessResult r = rollwear(command + " -q " + quoted(dir_ / "cam.yaml") + " -o " + quoted(dir_ / "o"), dir_);
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("cam.yaml:14:18: cam.base_radius_m: is not plausible: must be in [0.0001, 10] m "
                         "(millimetres written as metres?), got 40"),
              std::string::npos)
        << command << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "o"));
}

TEST_F(CommandLine, VersionPrintsVersion) {
  const ProcessResult r = rollwear("--version", dir_);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind("rollwear ", 0), 0u) << r.out;
}

// ---- transient --------------------------------------------------------------------------------------

// cases/paper-startup.yaml made small: 20 x 20, to 2e-4 s (the ramp and 1e-4 s at 1.8 m/s), two snapshots
std::string small_startup_case() {
  std::string text = read_text(kSource / "cases" / "paper-startup.yaml");
  const std::pair<std::string, std::string> edits[] = {
      {"{ nx: 80, ny: 80 }", "{ nx: 20, ny: 20 }"},
      {"t_end_s: 4.0e-4", "t_end_s: 2.0e-4"},
      {"snapshots_s: [5.0e-5, 1.0e-4, 2.0e-4, 4.0e-4]", "snapshots_s: [5.0e-5, 2.0e-4]"},
  };
  for (const auto& [from, to] : edits) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos) return "cases/paper-startup.yaml lacks " + from;  // fails to read
    text.replace(at, from.size(), to);
  }
  return text;
}

// the cells of a column of a table, as numbers
std::vector<double> column(const std::vector<std::string>& lines, std::size_t k) {
  std::vector<double> out;
  for (std::size_t r = 1; r < lines.size(); ++r) out.push_back(std::strtod(split(lines[r])[k].c_str(), nullptr));
  return out;
}

TEST_F(CommandLine, TransientOnSmallStartupWritesEveryTable) {
  const fs::path case_path = dir_ / "startup.yaml";
  std::ofstream(case_path) << small_startup_case();
  const fs::path out = dir_ / "startup";
  const ProcessResult r = rollwear("transient " + quoted(case_path) + " -o " + quoted(out) + " --log-level warn", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  for (const char* word : {"steps", "Fx =", " W ", " J ", "stick fraction", "snapshot 2"})
    EXPECT_NE(r.out.find(word), std::string::npos) << "summary lacks '" << word << "':\n" << r.out;

  // summary.csv: the run's totals
  const std::vector<std::string> summary = lines_of(read_text(out / "summary.csv"));
  ASSERT_EQ(summary.size(), 2u);
  EXPECT_TRUE(is_numeric_table(summary,
                               "name,scheme,nx,ny,steps,t_end_s,q_end_m,dissipated_J,Fx_N,Fy_N,Mz_N_m,power_W,"
                               "stick_fraction,omega1_rad_per_s,sliding_end_s,end_step,fallback_steps",
                               {0, 1}));
  const std::vector<std::string> totals = split(summary[1]);
  EXPECT_EQ(totals[0], "paper-startup");  // the file's name:
  EXPECT_EQ(totals[1], "shift");
  EXPECT_EQ(totals[2], "20");
  const int steps = std::atoi(totals[4].c_str());
  const double t_end_s = std::strtod(totals[5].c_str(), nullptr);
  const double dissipated_J = std::strtod(totals[7].c_str(), nullptr);
  EXPECT_NEAR(t_end_s, 2.0e-4, 1e-16);
  // 0.9e-4 m rolled in the ramp and 1.8e-4 m after it, one step per dx = 2a/20 = 23 um, and a last partial one
  EXPECT_GE(steps, 12);
  EXPECT_LE(steps, 13);

  // timeseries.csv: one row per step, steps in order, their durations adding up to the run
  const std::vector<std::string> series = lines_of(read_text(out / "timeseries.csv"));
  ASSERT_EQ(series.size(), static_cast<std::size_t>(steps) + 1);
  EXPECT_TRUE(is_numeric_table(series,
                               "step,t_s,q_m,dt_s,speed_m_per_s,xi,eta,phi_per_m,normal_load_N,omega1_rad_per_s,"
                               "Fx_N,Fy_N,Mz_N_m,power_W,stick_fraction,balance_residual_W,cfl,shortened,step_scheme",
                               {18}));
  const std::vector<double> step = column(series, 0), dt = column(series, 3), power = column(series, 13);
  double t = 0, energy = 0;
  for (int k = 0; k < steps; ++k) {
    EXPECT_EQ(step[k], k + 1);
    t += dt[k];
    energy += power[k] * dt[k];
  }
  EXPECT_NEAR(t / t_end_s, 1, 1e-12);
  EXPECT_NEAR(energy / dissipated_J, 1, 1e-9);  // power_W is the step's dissipated energy over dt

  // strip_power.csv: a row per strip and step; strip_energy.csv: its time integral
  const std::vector<std::string> strip_power = lines_of(read_text(out / "strip_power.csv"));
  EXPECT_EQ(strip_power.size(), static_cast<std::size_t>(steps) * 20 + 1);
  EXPECT_TRUE(is_numeric_table(strip_power, "step,t_s,y_m,power_W_per_m"));
  const std::vector<std::string> strip_energy = lines_of(read_text(out / "strip_energy.csv"));
  ASSERT_EQ(strip_energy.size(), 20u + 1u);
  EXPECT_TRUE(is_numeric_table(strip_energy, "y_m,energy_J_per_m"));
  const std::vector<double> y = column(strip_energy, 0), e = column(strip_energy, 1);
  double across = 0;
  for (std::size_t j = 0; j < y.size(); ++j) across += e[j] * (y[1] - y[0]);
  EXPECT_NEAR(across / dissipated_J, 1, 1e-9);

  // a snapshot per time asked for, at the end of the step that reached it
  for (const auto& [k, asked_s] : {std::pair<int, double>{1, 5.0e-5}, {2, 2.0e-4}}) {
    const std::vector<std::string> cells = lines_of(read_text(out / ("snapshot_" + std::to_string(k) + ".csv")));
    ASSERT_EQ(cells.size(), 20u * 20u + 1u) << k;
    EXPECT_TRUE(is_numeric_table(cells, "x_m,y_m,pressure_Pa,tau_x_Pa,tau_y_Pa,slip_x_m_per_s,slip_y_m_per_s,t_s"));
    const double at_s = column(cells, 7).front();
    EXPECT_GE(at_s, asked_s * (1 - 1e-12)) << k;
    EXPECT_LT(at_s, asked_s + 3e-5) << k;  // within one step
  }

  // nothing else: no temporary files left behind
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 6);

  // --no-fields: no snapshots, no strip_power.csv (per strip and step: a field; an earlier run's removed),
  // timeseries.csv and strip_energy.csv as before
  const fs::path bare = dir_ / "bare";
  fs::create_directories(bare);
  std::ofstream(bare / "strip_power.csv") << "an earlier run's strip powers\n";
  const ProcessResult nf =
      rollwear("transient " + quoted(case_path) + " -o " + quoted(bare) + " --no-fields --quiet --log-level off", dir_);
  ASSERT_EQ(nf.exit_code, 0) << nf.err;
  EXPECT_FALSE(fs::exists(bare / "snapshot_1.csv"));
  EXPECT_FALSE(fs::exists(bare / "strip_power.csv"));
  EXPECT_EQ(lines_of(read_text(bare / "timeseries.csv")).size(), series.size());  // equal to rounding: the
  EXPECT_TRUE(fs::exists(bare / "strip_energy.csv"));  // snapshot steps compute their fields
  EXPECT_EQ(std::distance(fs::directory_iterator(bare), fs::directory_iterator()), 3);
}

// cases/roller-spinup.yaml: the roller at rest slides over the whole contact (|Fx| = mu F) until its
// surface catches up with the path; with omega1 = mu F R1 t / J1 (docs/physics.md §4.5) that is at
// t* = J1 V2 / (mu F R1^2) = 0.2192 ms. The run's first steps build the tractions up from none (stick at
// the leading edge): that is not the end of gross sliding.
TEST_F(CommandLine, TransientGrossSlidingEndsWhenTheRollerCatchesUpWithThePath) {
  constexpr double kJ1 = 3.9458e-5, kR1 = 0.020, kMuF = 0.3 * 1500, kV2 = 1.0, kDt = 2.0e-6;  // the case's
  const double t_catch_s = kJ1 * kV2 / (kMuF * kR1 * kR1);
  const fs::path out = dir_ / "spin";
  const ProcessResult r = rollwear("transient " + quoted(kSource / "cases" / "roller-spinup.yaml") + " -o " +
                                       quoted(out) + " --no-fields -q --log-level warn",
                                   dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> summary = lines_of(read_text(out / "summary.csv"));
  ASSERT_EQ(summary.size(), 2u);
  const double end_s = std::strtod(split(summary[1])[14].c_str(), nullptr);
  // the first step off the bound: the one that reaches t* or the next (the force leaves mu F within a step)
  EXPECT_GE(end_s, t_catch_s) << summary[1];
  EXPECT_LE(end_s, t_catch_s + 2 * kDt) << summary[1];
  EXPECT_NE(r.out.find("ended at t = 0.00022 s (step 110: |F| < mu F)"), std::string::npos) << r.out;
}

TEST_F(CommandLine, TransientCflBreachExitsTwoNamingDtAndAllowedStep) {
  const fs::path case_path = dir_ / "breach.yaml";
  std::ofstream(case_path) << "bodies:\n"                                                        // 1
                              "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
                              "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                              "load: { normal_load_N: 1500 }\n"                                  // 4
                              "kinematics: { speed_m_per_s: 1.8, xi: 0.001 }\n"                  // 5
                              "friction: { mu: 0.3 }\n"                                          // 6
                              "solver: { tangential: consistent, nx: 20, ny: 20 }\n"             // 7 (Satran)
                              "transient: { scheme: upwind, t_end_s: 2.0e-4, dt_s: 5.0e-5 }\n";  // 8
  const fs::path out = dir_ / "breach";
  const ProcessResult r = rollwear("transient " + quoted(case_path) + " -o " + quoted(out), dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("rollwear: error: " + case_path.string() + ":8:53: transient.dt_s: 5e-05 s breaks the CFL "
                                                                   "condition",
                        0),
            0u)
      << r.err;
  // dx / V on the run's grid (Hertz: dx = 2a/20)
  const HertzContact h = solve_hertz({{0.020, 0.500}, {0.025, kFlat}}, {{210e9, 0.28}, {210e9, 0.28}}, 1500);
  const double dt_max = make_grid(h.a_m, h.b_m, {20, 20}).dx_m / 1.8;
  const std::string key = "the largest allowed dt_s is ";
  const std::size_t at = r.err.find(key);
  ASSERT_NE(at, std::string::npos) << r.err;
  EXPECT_NEAR(std::strtod(r.err.c_str() + at + key.size(), nullptr) / dt_max, 1, 1e-5) << r.err;
  EXPECT_FALSE(fs::exists(out));  // refused before the first step: nothing written
}

TEST_F(CommandLine, EachCommandRefusesTheOthersCase) {
  // the steady command and a history
  const fs::path startup = dir_ / "startup.yaml";
  std::ofstream(startup) << small_startup_case();
  const ProcessResult steady = rollwear("contact " + quoted(startup) + " -o " + quoted(dir_ / "out"), dir_);
  EXPECT_EQ(steady.exit_code, 2);
  EXPECT_NE(steady.err.find(": kinematics.speed_m_per_s: the steady 'contact' command needs a constant; "
                            "histories are for 'transient'"),
            std::string::npos)
      << steady.err;
  // the transient command and a case without a transient: section
  const fs::path paper = kSource / "cases" / "paper.yaml";
  const ProcessResult transient = rollwear("transient " + quoted(paper) + " -o " + quoted(dir_ / "out"), dir_);
  EXPECT_EQ(transient.exit_code, 2);
  EXPECT_EQ(transient.err.rfind("rollwear: error: " + paper.string() + ": transient: the 'transient' command "
                                                                       "needs a transient: section",
                                0),
            0u)
      << transient.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(CommandLine, TransientHelpListsItsOptions) {
  const ProcessResult app = rollwear("--help", dir_);
  EXPECT_NE(app.out.find("transient"), std::string::npos) << app.out;
  const ProcessResult help = rollwear("transient --help", dir_);
  EXPECT_EQ(help.exit_code, 0);
  for (const char* word : {"case", "-o,--output", "--no-fields", "-q,--quiet", "--log-level", "trace", "--help",
                           "timeseries.csv", "strip_power.csv", "snapshot_"})
    EXPECT_NE(help.out.find(word), std::string::npos) << word << " missing from:\n" << help.out;
}

// ---- Kalker's exact theory (solver.tangential: exact) ---------------------------------------------

// a case's text with solver: { ... } replaced
std::string with_solver(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos) return "the case lacks " + from;  // fails to read
  return text.replace(at, from.size(), to);
}

// the CONTACT results stored with their provenance in tests/data/exact/contact_reference.csv
double contact_reference(const std::string& quantity, const std::string& grid) {
  for (const std::string& line : lines_of(read_text(kSource / "tests" / "data" / "exact" / "contact_reference.csv"))) {
    const std::vector<std::string> cells = split(line);
    if (cells.size() == 3 && cells[0] == quantity && cells[1] == grid) return std::strtod(cells[2].c_str(), nullptr);
  }
  ADD_FAILURE() << quantity << "," << grid << " not in contact_reference.csv";
  return std::nan("");
}

// Reference: CONTACT's steady Fx of the paper's case on 80 x 80 (tests/data/exact), within 0.5 %;
// the tables as the fast solvers write them, the per-cell power adding up to the strips' and the
// total, printed beside the creep forces' work.
TEST_F(CommandLine, ContactWithExactTheoryMatchesContactsForce) {
  const fs::path c = dir_ / "paper-exact.yaml";
  std::ofstream(c) << with_solver(read_text(kSource / "cases" / "paper.yaml"), "solver:     { nx",
                                  "solver:     { tangential: exact, nx");
  const fs::path out = dir_ / "exact";
  const ProcessResult r = rollwear("contact " + quoted(c) + " -o " + quoted(out) + " --log-level warn", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("exact scheme"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("creep work = "), std::string::npos) << r.out;
  // the summary names the exact solve, not the simplified theory's coefficients it does not use
  EXPECT_EQ(r.out.find("C11 ="), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("flexibility"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("exact solve     residual"), std::string::npos) << r.out;

  const std::vector<std::string> summary = lines_of(read_text(out / "summary.csv"));
  ASSERT_EQ(summary.size(), 2u);
  const std::vector<std::string> row = split(summary[1]);
  EXPECT_EQ(row[16], "exact");
  for (int k = 5; k <= 9; ++k) EXPECT_EQ(row[k], "nan") << "C11 ... L_m_per_Pa, column " << k;
  const double Fx = std::strtod(row[10].c_str(), nullptr), P = std::strtod(row[13].c_str(), nullptr);
  const double work = std::strtod(row[14].c_str(), nullptr);
  constexpr double kContactTol = 0.005;  // the target against CONTACT on the same grid
  EXPECT_NEAR(Fx / contact_reference("Fx_N", "80x80"), 1, kContactTol) << Fx;
  EXPECT_NEAR(work, 1.0 * 1e-3 * Fx, 1e-12);  // V xi Fx
  // the power is the creep work in steady rolling (docs/exact-theory.md §4, "Dissipation"; the solve's own
  // upwind product fell short of it by 7.5 % at 80 x 80)
  EXPECT_NEAR(P / -work, 1, 1e-9);

  const std::vector<std::string> fields = lines_of(read_text(out / "fields.csv"));
  ASSERT_EQ(fields.size(), 80u * 80u + 1u);
  EXPECT_TRUE(is_numeric_table(
      fields, "x_m,y_m,pressure_Pa,tau_x_Pa,tau_y_Pa,slip_x_m_per_s,slip_y_m_per_s,power_W_per_m2,state"));
  const std::vector<std::string> strips = lines_of(read_text(out / "strips.csv"));
  ASSERT_EQ(strips.size(), 80u + 1u);
  const std::vector<double> x = column(fields, 0), y = column(fields, 1), density = column(fields, 7),
                            state = column(fields, 8), strip_power = column(strips, 5);
  const double dx = x[1] - x[0], dy = y[80] - y[0];
  double total = 0, slip = 0, stick = 0;
  for (std::size_t k = 0; k < density.size(); ++k) {
    total += density[k] * dx * dy;
    EXPECT_GE(density[k], -1e-6 * P / (dx * dy)) << "cell " << k;  // Coulomb: tau opposes the slip
    slip += state[k] == 2;
    stick += state[k] == 1;
  }
  EXPECT_NEAR(total / P, 1, 1e-9);
  EXPECT_GT(slip, 0);
  EXPECT_GT(stick, slip);
  double across = 0;
  for (const double p : strip_power) across += p * dy;
  EXPECT_NEAR(across / P, 1, 1e-9);
}

// Reference: CONTACT's start-up of the paper's contact from rest (tests/data/exact), Fx/Fx_ss at
// q/a = 0.5, 2, 4, 8, run by 'transient' on 20 x 20 with the steady Fx of 'contact' on the same grid.
// The coarse grid's own error is up to 2 % (docs/exact-theory.md: 0.1554, 0.5127, 0.7659, 0.9460
// here against CONTACT's 80 x 80 0.1585, 0.5198, 0.7727, 0.9491).
TEST_F(CommandLine, TransientWithExactTheoryBuildsUpAsContactDoes) {
  std::string text = with_solver(read_text(kSource / "cases" / "paper.yaml"), "solver:     { nx: 80, ny: 80",
                                 "solver:     { tangential: exact, nx: 20, ny: 20");
  const fs::path steady_case = dir_ / "steady.yaml", transient_case = dir_ / "startup.yaml";
  std::ofstream(steady_case) << text;
  const double a = solve_hertz({{0.020, 0.500}, {0.025, kFlat}}, {{210e9, 0.28}, {210e9, 0.28}}, 1500).a_m;
  // 8 a at V = 1 m/s and a little more: the last step is a partial one (interpolated)
  std::ofstream(transient_case) << text << "transient: { scheme: shift, t_end_s: " << std::setprecision(17) << 8.35 * a
                                << " }\n";
  const ProcessResult s = rollwear("contact " + quoted(steady_case) + " -o " + quoted(dir_ / "s") + " --log-level warn", dir_);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const ProcessResult r =
      rollwear("transient " + quoted(transient_case) + " -o " + quoted(dir_ / "t") + " --log-level warn", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("exact theory"), std::string::npos) << r.out;
  // summary.csv names the theory that ran, not only its steps' scheme (shift)
  EXPECT_EQ(split(lines_of(read_text(dir_ / "t" / "summary.csv"))[1])[1], "exact");
  const double Fx_ss = std::strtod(split(lines_of(read_text(dir_ / "s" / "summary.csv"))[1])[10].c_str(), nullptr);
  const std::vector<std::string> series = lines_of(read_text(dir_ / "t" / "timeseries.csv"));
  ASSERT_EQ(series.size(), 84u + 1u);  // 83 steps of dx = a/10 and a last one of dx/2 (interpolated)
  const std::vector<double> q = column(series, 2), Fx = column(series, 10), cfl = column(series, 16);
  constexpr double kCoarseGridTol = 0.025;
  int checked = 0;
  for (const char* at : {"0.5", "2", "4", "8"}) {
    const double expected = contact_reference(std::string("Fx_over_Fx_ss_at_q_over_a_") + at, "80x80");
    for (std::size_t k = 0; k < q.size(); ++k)
      if (std::abs(q[k] / a - std::stod(at)) < 1e-6) {
        EXPECT_NEAR(Fx[k] / Fx_ss, expected, kCoarseGridTol * expected) << "q/a " << at;
        ++checked;
      }
  }
  EXPECT_EQ(checked, 4);
  for (std::size_t k = 0; k + 1 < q.size(); ++k) EXPECT_EQ(cfl[k], 1) << k;
  EXPECT_NEAR(cfl.back(), 0.5, 1e-6);
  // the start-up's force rises monotonically
  for (std::size_t k = 1; k < Fx.size(); ++k) EXPECT_LT(Fx[k], Fx[k - 1] + 1e-9 * std::abs(Fx_ss)) << k;
}

// ---- the relaxed model (solver.tangential: relaxed, docs/accuracy-vs-exact.md) -----------------------

// Reference: CONTACT's steady Fx (80 x 80) and start-up (Fx/Fx_ss at q/a = 0.5, 2, 4, 8) of the paper's
// contact (tests/data/exact). 'contact' with the relaxed model: Fx within the 2 % target, the power equal
// to the creep forces' work (the exact theory's steady balance); 'transient' on 20 x 20: the start-up within
// 2 % of the steady force of 'contact' on the same grid at each rolled distance.
TEST_F(CommandLine, RelaxedModelMatchesContactsForceAndStartUp) {
  constexpr double kTarget = 0.02;
  const fs::path c = dir_ / "paper-relaxed.yaml";
  std::ofstream(c) << with_solver(read_text(kSource / "cases" / "paper.yaml"), "solver:     { nx",
                                  "solver:     { tangential: relaxed, nx");
  const ProcessResult r = rollwear("contact " + quoted(c) + " -o " + quoted(dir_ / "r") + " --log-level warn", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("relaxed scheme"), std::string::npos) << r.out;
  const std::vector<std::string> row = split(lines_of(read_text(dir_ / "r" / "summary.csv"))[1]);
  EXPECT_EQ(row[16], "relaxed");
  const double Fx = std::strtod(row[10].c_str(), nullptr), P = std::strtod(row[13].c_str(), nullptr),
               work = std::strtod(row[14].c_str(), nullptr);
  EXPECT_NEAR(Fx / contact_reference("Fx_N", "80x80"), 1, kTarget) << Fx;
  EXPECT_NEAR(P / -work, 1, 1e-9);

  std::string text = with_solver(read_text(kSource / "cases" / "paper.yaml"), "solver:     { nx: 80, ny: 80",
                                 "solver:     { tangential: relaxed, nx: 20, ny: 20");
  const fs::path steady_case = dir_ / "steady.yaml", transient_case = dir_ / "startup.yaml";
  std::ofstream(steady_case) << text;
  const double a = solve_hertz({{0.020, 0.500}, {0.025, kFlat}}, {{210e9, 0.28}, {210e9, 0.28}}, 1500).a_m;
  std::ofstream(transient_case) << text << "transient: { scheme: shift, t_end_s: " << std::setprecision(17) << 8.05 * a
                                << " }\n";
  const ProcessResult s = rollwear("contact " + quoted(steady_case) + " -o " + quoted(dir_ / "s") + " --log-level warn", dir_);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const ProcessResult t =
      rollwear("transient " + quoted(transient_case) + " -o " + quoted(dir_ / "t") + " --log-level warn", dir_);
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find("relaxed model"), std::string::npos) << t.out;
  const double Fx_ss = std::strtod(split(lines_of(read_text(dir_ / "s" / "summary.csv"))[1])[10].c_str(), nullptr);
  const std::vector<std::string> series = lines_of(read_text(dir_ / "t" / "timeseries.csv"));
  const std::vector<double> q = column(series, 2), F = column(series, 10);
  int checked = 0;
  for (const char* at : {"0.5", "2", "4", "8"}) {
    const double expected = contact_reference(std::string("Fx_over_Fx_ss_at_q_over_a_") + at, "80x80");
    for (std::size_t k = 0; k < q.size(); ++k)
      if (std::abs(q[k] / a - std::stod(at)) < 1e-6) {
        EXPECT_NEAR(F[k] / Fx_ss, expected, kTarget) << "q/a " << at;
        ++checked;
      }
  }
  EXPECT_EQ(checked, 4);
}

// The exact solver is refused where it does not run, at the key: mu = 0, a transient scheme other than
// shift, a roller's inertia (exit 2, nothing written).
TEST_F(CommandLine, ExactTheoryRefusedWhereItDoesNotRun) {
  const fs::path c = dir_ / "nofriction.yaml";
  std::ofstream(c) << with_solver(with_solver(read_text(kSource / "cases" / "paper.yaml"), "solver:     { nx",
                                              "solver:     { tangential: exact, nx"),
                                  "{ mu: 0.3 }", "{ mu: 0 }");
  const ProcessResult r = rollwear("contact " + quoted(c) + " -o " + quoted(dir_ / "o"), dir_);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(": friction.mu, solver.tangential: the exact solver needs mu > 0"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "o"));
  // the transient run: the shift scheme's steps only, no inertia; refused before the first step
  const fs::path upwind = dir_ / "upwind.yaml";
  std::ofstream(upwind) << with_solver(read_text(kSource / "cases" / "paper.yaml"), "solver:     { nx: 80",
                                       "solver:     { tangential: exact, nx: 8, ny: 8 }\ntransient: { scheme: upwind, dt_s: 1.0e-6, "
                                       "t_end_s: 1.0e-5 }\n#");
  const ProcessResult u = rollwear("transient " + quoted(upwind) + " -o " + quoted(dir_ / "u"), dir_);
  EXPECT_EQ(u.exit_code, 2) << u.err;
  EXPECT_NE(u.err.find(": transient.scheme: the exact solver rolls by steps of dq <= dx"), std::string::npos) << u.err;
  const fs::path spin = dir_ / "spin.yaml";
  std::ofstream(spin) << with_solver(read_text(kSource / "cases" / "roller-spinup.yaml"), "solver:     { nx: 40",
                                     "solver:     { tangential: exact, nx: 40");
  const ProcessResult i = rollwear("transient " + quoted(spin) + " -o " + quoted(dir_ / "i"), dir_);
  EXPECT_EQ(i.exit_code, 2) << i.err;
  EXPECT_NE(i.err.find(": inertia: the exact solver's run has no roller inertia"), std::string::npos) << i.err;
  EXPECT_FALSE(fs::exists(dir_ / "u"));
  EXPECT_FALSE(fs::exists(dir_ / "i"));
}

// ---- contact on profiles ---------------------------------------------------------------------------

// cases/paper.yaml on 24 x 24 with `extra` added to body 2's keys (the path), written to dir/name; its text too
std::pair<fs::path, std::string> paper_case_with_body2_keys(const fs::path& dir, const std::string& name,
                                                            const std::string& extra) {
  std::string text = read_text(kSource / "cases" / "paper.yaml");
  const std::string path_body = "body2: { Rx_m: 0.025, Ry_m: .inf,  E_Pa: 210.0e9, nu: 0.28";
  const std::size_t at = text.find(path_body);
  if (at == std::string::npos) throw std::runtime_error("cases/paper.yaml: body 2's line not found");
  text.insert(at + path_body.size(), extra);
  text = with_solver(text, "solver:     { nx: 80, ny: 80", "solver:     { nx: 24, ny: 24");
  std::ofstream(dir / name) << text;
  return {dir / name, text};
}

// the worn crown is not of constant curvature: solver.normal auto runs the semi-Hertzian solver
// bodies.body2.shear_yield_Pa: the path's fatigue indicators (fatigue.csv, the summary); --no-subsurface
// writes none of the three and removes an earlier run's; a k out of range is bad input naming the key
TEST_F(CommandLine, ContactWithShearYieldReportsFatigueOfThatBody) {
  const auto [c, text] = paper_case_with_body2_keys(dir_, "paper-k.yaml", ", shear_yield_Pa: 350.0e6");
  const fs::path out = dir_ / "k";
  const ProcessResult r = rollwear("contact " + quoted(c) + " -o " + quoted(out) + " --log-level warn", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> fatigue = lines_of(read_text(out / "fatigue.csv"));
  ASSERT_EQ(fatigue.size(), 2u);
  EXPECT_TRUE(is_numeric_table(fatigue,
                               "body,shear_yield_Pa,contact,traction_coefficient,p0_over_k,limit_p0_over_k,"
                               "surface_limit,margin,FI_surf,cell_index_max,cell_x_m,cell_y_m",
                               {2}));
  const std::vector<std::string> row = split(fatigue[1]);
  EXPECT_EQ(row[0], "2");
  EXPECT_EQ(row[2], "line");  // a/b = 0.088
  EXPECT_NE(r.out.find("fatigue, k = 350.0 MPa"), std::string::npos) << r.out;

  const ProcessResult quiet =
      rollwear("contact " + quoted(c) + " -o " + quoted(out) + " --no-subsurface --log-level warn", dir_);
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  for (const char* name : {"subsurface.csv", "subsurface_section.csv", "fatigue.csv"})
    EXPECT_FALSE(fs::exists(out / name)) << name;

  std::ofstream(c) << with_solver(text, "shear_yield_Pa: 350.0e6", "shear_yield_Pa: -1");
  const ProcessResult bad = rollwear("contact " + quoted(c) + " -o " + quoted(out) + " --log-level warn", dir_);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("bodies.body2.shear_yield_Pa"), std::string::npos) << bad.err;
}

// Dang Van's index of a body with bodies.bodyN.dang_van: the summary line, dang_van.csv; its keys checked
TEST_F(CommandLine, ContactWithDangVanReportsItsIndex) {
  const auto [c, text] = paper_case_with_body2_keys(dir_, "paper-dv.yaml", ", dang_van: { a: 0.3, b_Pa: 300.0e6 }");
  const fs::path out = dir_ / "dv";
  const ProcessResult r = rollwear("contact " + quoted(c) + " -o " + quoted(out) + " --log-level warn", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> rows = lines_of(read_text(out / "dang_van.csv"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_TRUE(is_numeric_table(rows, "body,a,b_Pa,index_max,x_m,y_m,z_m,tau_Pa,hydrostatic_Pa", {}));
  const std::vector<std::string> row = split(rows[1]);
  EXPECT_EQ(row[0], "2");
  EXPECT_GT(std::stod(row[3]), 0);      // an index
  EXPECT_GE(std::stod(row[6]), 0);      // a depth
  EXPECT_NE(r.out.find("Dang Van         index"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out / "fatigue.csv"));  // no shear_yield_Pa

  const ProcessResult quiet =
      rollwear("contact " + quoted(c) + " -o " + quoted(out) + " --no-subsurface --log-level warn", dir_);
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_FALSE(fs::exists(out / "dang_van.csv"));

  for (const auto& [from, to, key] : {std::array<std::string, 3>{"b_Pa: 300.0e6", "b_Pa: 0", "bodies.body2.dang_van.b_Pa"},
                                      {"a: 0.3, ", "a: -0.3, ", "bodies.body2.dang_van.a"},
                                      {"a: 0.3, ", "", "a"}}) {
    std::ofstream(c) << with_solver(text, from, to);
    const ProcessResult bad = rollwear("contact " + quoted(c) + " -o " + quoted(out) + " --log-level warn", dir_);
    EXPECT_EQ(bad.exit_code, 2) << to;
    EXPECT_NE(bad.err.find(key), std::string::npos) << bad.err;
  }
}

TEST_F(CommandLine, ContactOnWornCrownRunsSemiHertz) {
  const fs::path out = dir_ / "worn";
  const ProcessResult r = rollwear("contact " + quoted(kSource / "cases" / "worn-crown.yaml") + " -o " + quoted(out) +
                                       " --no-fields --log-level warn",
                                   dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("normal solver      semi-hertz (solver.normal auto"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("contact patches    1"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;
  // strips.csv's y_m in the profiles' coordinate: the contact centred on the roller's crown
  const std::vector<double> y = column(lines_of(read_text(out / "strips.csv")), 0);
  ASSERT_EQ(y.size(), 80u);
  EXPECT_NEAR(y.front() + y.back(), 0, 1e-6);
}

// the paper's crown as a generated profile: auto takes Hertz, which agrees with cases/paper.yaml's radii
TEST_F(CommandLine, ContactOnCrownedProfileRunsHertzLikeThePaperCase) {
  constexpr double kFitTol = 1e-3;  // Ry from a parabola fit through the profile's 401 nodes
  std::string text = read_text(kSource / "cases" / "worn-crown.yaml");
  const std::string from = "file: ../profiles/flat_worn_R500_w20_band1p5.csv";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), "crowned: { Ry_m: 0.5, width_m: 0.020 }");
  std::ofstream(dir_ / "crowned.yaml") << text;

  const ProcessResult crowned = rollwear("contact " + quoted(dir_ / "crowned.yaml") + " -o " + quoted(dir_ / "c") +
                                             " --no-fields --log-level warn",
                                         dir_);
  ASSERT_EQ(crowned.exit_code, 0) << crowned.err;
  EXPECT_NE(crowned.out.find("normal solver      hertz (solver.normal auto: both profiles have constant curvature)"),
            std::string::npos)
      << crowned.out;
  const ProcessResult paper = rollwear("contact " + quoted(kSource / "cases" / "paper.yaml") + " -o " +
                                           quoted(dir_ / "p") + " --no-fields --log-level warn",
                                       dir_);
  ASSERT_EQ(paper.exit_code, 0) << paper.err;
  const std::vector<std::string> c = split(lines_of(read_text(dir_ / "c" / "summary.csv"))[1]);
  const std::vector<std::string> p = split(lines_of(read_text(dir_ / "p" / "summary.csv"))[1]);
  for (std::size_t k : {1u, 2u, 3u})  // a_m, b_m, p0_Pa
    EXPECT_NEAR(std::stod(c[k]) / std::stod(p[k]), 1, kFitTol) << "column " << k;
}

// cases/worn-crown.yaml written to DIR/name with its profile file absolute and one replacement made
fs::path worn_crown_case(const fs::path& dir, const std::string& name, const std::string& from, const std::string& to) {
  std::string text = read_text(kSource / "cases" / "worn-crown.yaml");
  const std::string file = "../profiles/";
  text.replace(text.find(file), file.size(), (kSource / "profiles").string() + "/");
  if (text.find(from) != std::string::npos) text.replace(text.find(from), from.size(), to);
  std::ofstream(dir / name) << text;
  return dir / name;
}

// a path narrower than the contact: a warning line, the outputs written, exit status 0
TEST_F(CommandLine, ContactReachingABodysEdgeWarnsAndStillWrites) {
  const fs::path c = worn_crown_case(dir_, "narrow.yaml", "flat: { width_m: 0.030 }", "flat: { width_m: 0.004 }");
  const ProcessResult r = rollwear("contact " + quoted(c) + " -o " + quoted(dir_ / "n") + " --log-level off", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("warning: the contact reaches a body's edge"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(dir_ / "n" / "summary.csv"));
  EXPECT_TRUE(fs::exists(dir_ / "n" / "strips.csv"));
}

// the exact solver on the worn crown: one patch, the load carried, near the semi-Hertzian semi-axes
TEST_F(CommandLine, ContactByHalfspaceOnWornCrownReportsIt) {
  constexpr double kSemiHertzTol = 0.1;  // semi-Hertz's approximation on a non-elliptic contact, 80x80 grid
  const fs::path c = worn_crown_case(dir_, "hs.yaml", "normal: auto", "normal: halfspace");
  const ProcessResult r =
      rollwear("contact " + quoted(c) + " -o " + quoted(dir_ / "h") + " --no-fields --log-level warn", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("normal solver      halfspace"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("contact patches    1"), std::string::npos) << r.out;
  const ProcessResult sh = rollwear("contact " + quoted(kSource / "cases" / "worn-crown.yaml") + " -o " +
                                        quoted(dir_ / "s") + " --no-fields --log-level warn",
                                    dir_);
  ASSERT_EQ(sh.exit_code, 0) << sh.err;
  const std::vector<std::string> h = split(lines_of(read_text(dir_ / "h" / "summary.csv"))[1]);
  const std::vector<std::string> s = split(lines_of(read_text(dir_ / "s" / "summary.csv"))[1]);
  for (std::size_t k : {1u, 2u})  // a_m, b_m
    EXPECT_NEAR(std::stod(h[k]) / std::stod(s[k]), 1, kSemiHertzTol) << "column " << k;
}

// ---- run: the wear loop over the life ---------------------------------------------------------------

// the shipped paper-wear case with the wear section's stepping and limits replaced (for the kill tests)
fs::path wear_case(const fs::path& dir, const std::string& name, const std::string& grid,
                   const std::string& stepping, const std::string& limits) {
  std::string text = read_text(kSource / "cases" / "paper-wear.yaml");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    if (at != std::string::npos) text.replace(at, from.size(), to);
  };
  replace("nx: 80, ny: 80", grid);
  replace("stepping: { method: adaptive, rtol: 1.0e-3, atol_m: 1.0e-9 }", stepping + "\n  checkpoint_interval_s: 0.02");
  replace("limits: { max_depth_m: 1.0e-4, edge: true }", limits);
  replace("snapshots_revolutions: [1.0e7, 3.0e7, 1.0e8]", "snapshots_revolutions: [5.0e6]");
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p;
}

TEST_F(CommandLine, RunOnPaperWearWritesSummarySnapshotsAndReport) {
  const fs::path out = dir_ / "w";
  const ProcessResult r = rollwear("run " + quoted(kSource / "cases" / "paper-wear.yaml") + " -o " + quoted(out) +
                                       " --log-level error",
                                   dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // the report: on stdout and in report.txt; the crown wears flat to the roller's edges
  EXPECT_EQ(r.out, read_text(out / "report.txt"));
  EXPECT_NE(r.out.find("ended_by: edge\n"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out / "checkpoint.txt"));  // a finished run leaves no checkpoint
  const std::vector<std::string> summary = lines_of(read_text(out / "summary.csv"));
  ASSERT_GT(summary.size(), 10u);
  EXPECT_EQ(summary[0], "# case: paper-wear");
  const std::string header = "step,revolutions,hours,max_depth_m,worn_volume_m3,dissipated_J,a_m,b_m,p0_Pa,Fx_N,"
                             "power_W,step_revolutions,error_estimate,rejected,rhs_evals";
  const auto at = std::find(summary.begin(), summary.end(), header);
  ASSERT_NE(at, summary.end());
  EXPECT_EQ(split(*(at + 1))[0], "0");  // step 0: the unworn state
  // snapshots: the unworn profile, 1e7 and 3e7 revolutions, the end
  for (const char* f : {"snapshot_0000_body1.csv", "snapshot_0001_body1.csv", "snapshot_0002_body1.csv",
                        "snapshot_0003_body1.csv"})
    EXPECT_TRUE(fs::exists(out / "snapshots" / f)) << f;
  const std::vector<std::string> snap = lines_of(read_text(out / "snapshots" / "snapshot_0001_body1.csv"));
  EXPECT_EQ(snap[2], "# revolutions: 1e+07");  // the shortest text of 1e7 (lib/number.h)
  EXPECT_EQ(snap[4], "y_m,z_original_m,z_m,depth_m");
  // and the plots of it
  const ProcessResult plot = rollwear("plot " + quoted(out), dir_);
  ASSERT_EQ(plot.exit_code, 0) << plot.err;
  for (const char* png : {"depth.png", "pressure.png", "profile_body1.png", "depth_profile_body1.png"})
    EXPECT_GT(fs::file_size(out / "plots" / png), 10000u) << png;
}

TEST_F(CommandLine, RunRefusesToOverwriteAnUnfinishedRunAndToResumeAnotherCase) {
  const fs::path out = dir_ / "w";
  fs::create_directories(out);
  std::ofstream(out / "checkpoint.txt") << "rollwear-wear-checkpoint 2\n";
  const std::string run = "run " + quoted(kSource / "cases" / "paper-wear.yaml") + " -o " + quoted(out);
  ProcessResult r = rollwear(run, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("holds an unfinished run (checkpoint.txt): continue it with --resume"), std::string::npos) << r.err;
  r = rollwear(run + " --resume", dir_);  // a torn checkpoint: named with its line
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("checkpoint.txt:2: the checkpoint ends early"), std::string::npos) << r.err;
  r = rollwear(run + " --resume --restart", dir_);
  EXPECT_EQ(r.exit_code, 2);
  // no checkpoint at all
  fs::remove(out / "checkpoint.txt");
  r = rollwear(run + " --resume", dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no checkpoint to resume from"), std::string::npos) << r.err;
}

TEST_F(CommandLine, RunWithBadWearSectionExitsTwoNamingFileLineAndKey) {
  const fs::path c = wear_case(dir_, "bad.yaml", "nx: 20, ny: 20", "stepping: { method: rk4 }",
                               "limits: { max_depth_m: 1.0e-4, edge: true }");
  const ProcessResult r = rollwear("run " + quoted(c) + " -o " + quoted(dir_ / "w"), dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(c.string() + ":27:23: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("wear.stepping.method: must be adaptive, fixed-depth or fixed-revolutions"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("terminate"), std::string::npos);
}

// Starts "rollwear ARGS" in the background, waits until its checkpoint has passed `steps` steps, and
// kills it (SIGKILL: no chance to tidy up). Fails if the run ended before it could be killed.
void run_and_kill(const std::vector<std::string>& args, const fs::path& checkpoint, long steps, const fs::path& log,
                  int signal = SIGKILL) {
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    // the run at the lowest priority: on a loaded machine (ctest -j) the watcher below still sees each checkpoint
    // before the run has gone far past it (a short run otherwise ends before it could be killed)
    (void)::nice(19);
    std::FILE* f = std::freopen(log.c_str(), "w", stdout);
    if (f) ::dup2(::fileno(stdout), 2);
    std::vector<char*> argv;
    std::string exe = ROLLWEAR_EXE;
    argv.push_back(exe.data());
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(exe.c_str(), argv.data());
    ::_exit(127);
  }
  bool killed = false;
  for (int k = 0; k < 60000 && !killed; ++k) {
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) FAIL() << "the run ended before it could be killed: " << read_text(log);
    std::ifstream in(checkpoint);
    std::string line;
    long at = -1;
    while (std::getline(in, line))
      if (line.rfind("steps ", 0) == 0) at = std::stol(line.substr(6));
    if (at >= steps) {
      ::kill(pid, signal);
      killed = true;
    } else {
      ::usleep(1000);
    }
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(killed) << "no checkpoint past step " << steps << " within 60 s";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal);
}

// the value of 'key: value' in a report
std::string report_value(const std::string& report, const std::string& key) {
  for (const std::string& line : lines_of(report))
    if (line.rfind(key + ": ", 0) == 0) return line.substr(key.size() + 2);
  return "";
}

// `rollwear run` of the case uninterrupted into DIR/whole
void run_whole(const fs::path& dir, const fs::path& c) {
  ASSERT_EQ(rollwear("run " + quoted(c) + " -o " + quoted(dir / "whole") + " --log-level error", dir).exit_code, 0);
}

// `rollwear run` of the case into DIR/killed, killed by SIGKILL once its checkpoint is past step `kill_at`, then
// resumed there with --resume to its end
void run_killed_and_resumed(const fs::path& dir, const fs::path& c, long kill_at) {
  const fs::path killed = dir / "killed";
  run_and_kill({"run", c.string(), "-o", killed.string(), "--quiet"}, killed / "checkpoint.txt", kill_at,
               dir / "killed.log");
  ASSERT_TRUE(fs::exists(killed / "checkpoint.txt"));
  const ProcessResult r = rollwear("run " + quoted(c) + " -o " + quoted(killed) + " --resume --log-level error", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

// every summary row of the two runs, column by column (the counters included)
void expect_same_summary(const fs::path& a, const fs::path& b) {
  const std::vector<std::string> sa = lines_of(read_text(a / "summary.csv"));
  const std::vector<std::string> sb = lines_of(read_text(b / "summary.csv"));
  ASSERT_EQ(sa.size(), sb.size());
  for (std::size_t k = 0; k < sa.size(); ++k) {
    const std::vector<std::string> ra = split(sa[k]), rb = split(sb[k]);
    ASSERT_EQ(ra.size(), rb.size());
    for (std::size_t col = 0; col < ra.size(); ++col)
      ASSERT_EQ(ra[col], rb[col]) << "row " << k << " column " << col;
  }
}

// Fixed stepping is memoryless: killed at any moment and resumed, the run ends bit-identical to an
// uninterrupted one (worn profiles, summary rows up to the counters, the life and what ended it).
TEST_F(CommandLine, RunKilledAndResumedEndsBitIdenticalWithFixedStepping) {
  const fs::path c = wear_case(dir_, "fixed.yaml", "nx: 40, ny: 40",
                               "stepping: { method: fixed-depth, max_depth_step_m: 1.0e-8 }",
                               "limits: { max_depth_m: 2.0e-5, edge: true }");
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  ASSERT_NO_FATAL_FAILURE(run_whole(dir_, c));
  ASSERT_NO_FATAL_FAILURE(run_killed_and_resumed(dir_, c, 300));
  // the temporaries a kill during a write leaves (never under a final name) are gone after the resume
  for (const fs::path& p : fs::recursive_directory_iterator(killed))
    EXPECT_EQ(p.filename().string().find(".tmp."), std::string::npos) << "left: " << p;
  const std::string a = read_text(whole / "report.txt"), b = read_text(killed / "report.txt");
  for (const char* key : {"ended_by", "message", "revolutions", "max_depth_m", "worn_volume_body1_m3", "dissipated_J",
                          "p0_Pa", "steps", "rejected_steps", "rhs_evals"})
    EXPECT_EQ(report_value(a, key), report_value(b, key)) << key;
  // the solves count both processes; the resumed one solves its start once more (its cache is new)
  for (const char* key : {"normal_solves", "tangential_solves"})
    EXPECT_EQ(std::stol(report_value(b, key)), std::stol(report_value(a, key)) + 1) << key;
  EXPECT_EQ(report_value(b, "resumed"), "true");
  EXPECT_EQ(report_value(a, "ended_by"), "max_depth");
  for (const char* f : {"snapshot_0000_body1.csv", "snapshot_0001_body1.csv", "snapshot_0002_body1.csv"})
    EXPECT_EQ(read_text(whole / "snapshots" / f), read_text(killed / "snapshots" / f)) << f;
  // the summary: every row, its counters included (the resumed run's first evaluation of f, at the state
  // the checkpoint's step had already evaluated, is not counted again)
  expect_same_summary(whole, killed);
}

// The corrected fidelity (docs/fidelity.md) keeps its correction in the checkpoint: killed and resumed, a
// fixed-stepping corrected run ends bit-identical to an uninterrupted one, its exact-physics solves and its error
// estimate included.
TEST_F(CommandLine, CorrectedRunKilledAndResumedEndsBitIdentical) {
  const fs::path c = wear_case(dir_, "corrected.yaml", "fidelity: corrected, correction_tolerance: 0.5, nx: 20, ny: 20",
                               "stepping: { method: fixed-depth, max_depth_step_m: 1.0e-6 }",
                               "limits: { max_depth_m: 3.0e-5, edge: true }");
  ASSERT_NO_FATAL_FAILURE(run_whole(dir_, c));
  ASSERT_NO_FATAL_FAILURE(run_killed_and_resumed(dir_, c, 12));
  const std::string a = read_text(dir_ / "whole" / "report.txt"), b = read_text(dir_ / "killed" / "report.txt");
  EXPECT_EQ(report_value(b, "resumed"), "true");
  EXPECT_EQ(report_value(a, "fidelity"), "corrected");
  EXPECT_GT(std::stol(report_value(a, "exact_solves")), 2);
  for (const char* key : {"ended_by", "revolutions", "max_depth_m", "worn_volume_body1_m3", "dissipated_J", "steps",
                          "exact_solves", "error_estimate_N", "error_power_rel", "error_power_l1"})
    EXPECT_EQ(report_value(a, key), report_value(b, key)) << key;
}

// Adaptive stepping: resumed from the checkpoint, the run restarts ARKODE with the step it had reached;
// it ends within the tolerance of an uninterrupted run.
TEST_F(CommandLine, RunKilledAndResumedEndsWithinToleranceWithAdaptiveStepping) {
  const fs::path c = wear_case(dir_, "adaptive.yaml", "nx: 40, ny: 40",
                               "stepping: { method: adaptive, rtol: 1.0e-7, atol_m: 1.0e-13 }",
                               "limits: { max_depth_m: 2.0e-5, edge: true }");
  ASSERT_NO_FATAL_FAILURE(run_whole(dir_, c));
  const std::string a = read_text(dir_ / "whole" / "report.txt");
  ASSERT_NO_FATAL_FAILURE(run_killed_and_resumed(dir_, c, std::stol(report_value(a, "steps")) / 4));
  const std::string b = read_text(dir_ / "killed" / "report.txt");
  EXPECT_EQ(report_value(b, "ended_by"), "max_depth");
  EXPECT_NEAR(std::stod(report_value(b, "revolutions")) / std::stod(report_value(a, "revolutions")), 1.0, 1e-5);
  EXPECT_NEAR(std::stod(report_value(b, "worn_volume_body1_m3")) / std::stod(report_value(a, "worn_volume_body1_m3")),
              1.0, 1e-5);
}

// ---- the output folder, interrupts and the exit-2 contract -------------------------------------------

// a small fixed-depth wear run of the shipped case (20 x 20, a few steps)
fs::path small_wear_case(const fs::path& dir, const std::string& name) {
  return wear_case(dir, name, "nx: 20, ny: 20", "stepping: { method: fixed-depth, max_depth_step_m: 1.0e-6 }",
                   "limits: { max_depth_m: 3.0e-6, edge: true }");
}

// the case file's text with one edit
void edit_file(const fs::path& p, const std::string& from, const std::string& to) {
  std::string text = read_text(p);
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  std::ofstream(p) << text;
}

// A half-space life (solver.normal halfspace) starts each solve from the last one's pressures; its checkpoint
// carries that solve, so killed and resumed it ends bit-identical to an uninterrupted run too: the paper's roller
// on 12 x 12, fixed-depth steps of 1 um to 20 um, SIGKILL past step 8. Its resumed start reuses the checkpoint's
// normal solve (normal_solves as the uninterrupted run's) and evaluates the rate there once more.
TEST_F(CommandLine, HalfspaceRunKilledAndResumedEndsBitIdenticalWithFixedStepping) {
  const fs::path c = wear_case(dir_, "halfspace.yaml", "nx: 12, ny: 12",
                               "stepping: { method: fixed-depth, max_depth_step_m: 1.0e-6 }",
                               "limits: { max_depth_m: 2.0e-5, edge: true }");
  ASSERT_NO_FATAL_FAILURE(edit_file(c, "normal: auto", "normal: halfspace"));
  ASSERT_NO_FATAL_FAILURE(run_whole(dir_, c));
  ASSERT_NO_FATAL_FAILURE(run_killed_and_resumed(dir_, c, 8));
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  const std::string a = read_text(whole / "report.txt"), b = read_text(killed / "report.txt");
  EXPECT_EQ(report_value(a, "normal_solver"), "halfspace");
  EXPECT_EQ(report_value(a, "ended_by"), "max_depth");
  EXPECT_EQ(report_value(b, "resumed"), "true");
  for (const char* key : {"ended_by", "message", "revolutions", "max_depth_m", "worn_volume_body1_m3", "dissipated_J",
                          "p0_Pa", "steps", "rejected_steps", "rhs_evals", "normal_solves"})
    EXPECT_EQ(report_value(a, key), report_value(b, key)) << key;
  EXPECT_EQ(std::stol(report_value(b, "tangential_solves")), std::stol(report_value(a, "tangential_solves")) + 1);
  for (const char* f : {"snapshot_0000_body1.csv", "snapshot_0001_body1.csv", "snapshot_0002_body1.csv"})
    EXPECT_TRUE(read_text(whole / "snapshots" / f) == read_text(killed / "snapshots" / f)) << f;
  expect_same_summary(whole, killed);
}

// the PID of a process that has ended (a child that exits at once, reaped)
pid_t dead_pid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return pid;
}

// A new run in a folder removes the previous run's snapshots (its own naming), never a file the user put
// there; it leaves no lock file behind.
TEST_F(CommandLine, RunRemovesOnlyItsOwnSnapshotFiles) {
  const fs::path c = small_wear_case(dir_, "small.yaml");
  const fs::path out = dir_ / "w";
  fs::create_directories(out / "snapshots");
  std::ofstream(out / "snapshots" / "my_notes.txt") << "the user's\n";
  std::ofstream(out / "snapshots" / "snapshot_0042_body1.csv") << "a previous run's\n";
  const ProcessResult r = rollwear("run " + quoted(c) + " -o " + quoted(out) + " --log-level error", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(out / "snapshots" / "my_notes.txt"), "the user's\n");
  EXPECT_FALSE(fs::exists(out / "snapshots" / "snapshot_0042_body1.csv"));
  EXPECT_TRUE(fs::exists(out / "snapshots" / "snapshot_0000_body1.csv"));
  EXPECT_FALSE(fs::exists(out / ".rollwear.lock"));
}

// Two runs in one folder: the second one exits non-zero, naming the folder and the PID holding it, and
// writes nothing there.
TEST_F(CommandLine, RunRefusesAFolderAnotherRunHolds) {
  const fs::path c = small_wear_case(dir_, "small.yaml");
  const fs::path out = dir_ / "w";
  fs::create_directories(out);
  rollwear_test::HeldLock other(out);  // this test process plays the other run
  ASSERT_TRUE(other.held());
  const std::string pid = other.pid();
  for (const std::string& command : {std::string("run"), std::string("run --restart")}) {
    const ProcessResult r = rollwear(command + " " + quoted(c) + " -o " + quoted(out), dir_);
    EXPECT_NE(r.exit_code, 0) << command;
    EXPECT_NE(r.err.find(out.string() + " is in use by another rollwear run (PID " + pid + ","), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(out / "summary.csv"));
    EXPECT_FALSE(fs::exists(out / "checkpoint.txt"));
  }
  const fs::path startup = dir_ / "startup.yaml";
  std::ofstream(startup) << small_startup_case();
  const ProcessResult t = rollwear("transient " + quoted(startup) + " -o " + quoted(out), dir_);
  EXPECT_NE(t.exit_code, 0);
  EXPECT_NE(t.err.find("(PID " + pid + ","), std::string::npos) << t.err;
  other.release();
  // released: the folder is free again
  EXPECT_EQ(rollwear("run " + quoted(c) + " -o " + quoted(out) + " --log-level error", dir_).exit_code, 0);
}

// Ctrl-C (SIGINT) on a run says how to continue it, and --resume then does.
TEST_F(CommandLine, RunInterruptedSaysResumeContinuesIt) {
  const fs::path c = wear_case(dir_, "fixed.yaml", "nx: 20, ny: 20",
                               "stepping: { method: fixed-depth, max_depth_step_m: 1.0e-8 }",
                               "limits: { max_depth_m: 2.0e-5, edge: true }");
  const fs::path out = dir_ / "w";
  run_and_kill({"run", c.string(), "-o", out.string(), "--quiet"}, out / "checkpoint.txt", 20, dir_ / "int.log",
               SIGINT);
  const std::string said = read_text(dir_ / "int.log");
  EXPECT_NE(said.find("interrupted; the run continues from its last checkpoint"), std::string::npos) << said;
  EXPECT_NE(said.find("rollwear run " + c.string() + " -o " + out.string() + " --resume"), std::string::npos) << said;
  EXPECT_FALSE(fs::exists(out / ".rollwear.lock"));  // the handler removes the lock file too
  const ProcessResult r = rollwear("run " + quoted(c) + " -o " + quoted(out) + " --resume --log-level error", dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// Bad input found at step 0 (a profile too coarse for the contact) exits 2 at the profile's key with
// advice the user can follow, and leaves no checkpoint: the corrected case then runs without --restart.
TEST_F(CommandLine, RunBadInputAtStepZeroLeavesNoCheckpoint) {
  const fs::path c = small_wear_case(dir_, "light.yaml");
  edit_file(c, "normal_load_N: 1500", "normal_load_N: 0.05");  // a contact about 0.1 mm wide
  const fs::path out = dir_ / "w";
  ProcessResult r = rollwear("run " + quoted(c) + " -o " + quoted(out), dir_);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(c.string() + ":13:10: "), std::string::npos) << r.err;  // the profiles.body1 value
  EXPECT_NE(r.err.find("profiles.body1: its nodes"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("give profiles.body1 as { file: PATH }"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "checkpoint.txt"));
  edit_file(c, "normal_load_N: 0.05", "normal_load_N: 1500");
  r = rollwear("run " + quoted(c) + " -o " + quoted(out) + " --log-level error", dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// A cross-key error (Archard's law without friction) exits 2 naming the file, line and keys.
TEST_F(CommandLine, RunArchardWithoutFrictionExitsTwoAtFrictionMu) {
  const fs::path c = small_wear_case(dir_, "mu0.yaml");
  edit_file(c, "friction:   { mu: 0.3 }", "friction:   { mu: 0 }");
  const ProcessResult r = rollwear("run " + quoted(c) + " -o " + quoted(dir_ / "w"), dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(c.string() + ":21:19: friction.mu, wear.body1.law: "), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "w"));
}

// The exit status follows the error's type (lib/errors.h): bad input 2; a solver's refusal of what it
// was given, std::invalid_argument included, 1.
TEST(ExitStatus, FollowsTheErrorsTypeNotItsText) {
  EXPECT_EQ(exit_status_of(CaseError("case.yaml:3:5: friction.mu: must be in [0, 10]")), kExitBadInput);
  EXPECT_EQ(exit_status_of(std::invalid_argument("halfspace: E* must be positive")), kExitFailure);
  EXPECT_EQ(exit_status_of(SettingError("", "dt_s", "must be >= 0")), kExitFailure);
  EXPECT_EQ(exit_status_of(SolverError("bad input: the approach was not found")), kExitFailure);
  EXPECT_EQ(exit_status_of(std::runtime_error("no space left")), kExitFailure);
}

// transient refuses a run whose output is estimated above output.max_bytes (default 1 GiB), naming the
// estimate and the keys, and writes nothing; --force runs it.
TEST_F(CommandLine, TransientRefusesAnAbsurdRunUnlessForced) {
  const fs::path c = dir_ / "huge.yaml";
  std::ofstream(c) << small_startup_case();
  edit_file(c, "t_end_s: 2.0e-4", "t_end_s: 1.0e9");
  const fs::path out = dir_ / "t";
  ProcessResult r = rollwear("transient " + quoted(c) + " -o " + quoted(out), dir_);
  EXPECT_EQ(r.exit_code, 2);
  for (const std::string& word : {c.string() + ":", std::string("transient.t_end_s"), std::string("output.max_bytes = 1073741824"),
                                  std::string("the run would write about "), std::string("--force")})
    EXPECT_NE(r.err.find(word), std::string::npos) << word << " in " << r.err;
  EXPECT_FALSE(fs::exists(out));
  // a small run above a small max_bytes: refused, then run with --force
  const fs::path small = dir_ / "small.yaml";
  std::ofstream(small) << small_startup_case() << "\n";
  edit_file(small, "output:     { directory: out/paper-startup, fields: true }",
            "output:     { directory: out/paper-startup, fields: true, max_bytes: 1000 }");
  r = rollwear("transient " + quoted(small) + " -o " + quoted(out), dir_);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("output.max_bytes = 1000;"), std::string::npos) << r.err;
  r = rollwear("transient " + quoted(small) + " -o " + quoted(out) + " --force --log-level warn", dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "timeseries.csv"));
}

// The size check is the library's (lib/io/case.h), which the Python bindings call too: t_end_s 1e9 is refused
// before the run at transient.t_end_s's key, naming output.max_bytes; force lets it through (issue 26).
TEST(TransientOutputCheck, LibraryRefusesAnAbsurdRunUnlessForced) {
  const ContactCase cc = read_contact_case(std::string(ROLLWEAR_SOURCE_DIR) + "/cases/paper-startup.yaml");
  TransientCase t = transient_case_of(cc);
  EXPECT_NO_THROW(check_transient_output(cc, t, true, false));  // the shipped case passes
  t.settings.t_end_s = 1e9;
  try {
    check_transient_output(cc, t, true, false);
    ADD_FAILURE() << "t_end_s 1e9 passed the library's check";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.location.key, "transient.t_end_s");
    EXPECT_NE(std::string(e.what()).find("output.max_bytes = 1073741824"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(check_transient_output(cc, t, true, true));
}

// the output of a run is at most its estimate (an upper bound: every number at full precision)
TEST_F(CommandLine, TransientOutputIsWithinItsEstimate) {
  const fs::path c = dir_ / "startup.yaml";
  std::ofstream(c) << small_startup_case();
  const ContactCase cc = read_contact_case(c.string());
  const TransientOutputEstimate e = estimate_transient_output(transient_case_of(cc), true);
  const fs::path out = dir_ / "t";
  ASSERT_EQ(rollwear("transient " + quoted(c) + " -o " + quoted(out) + " --log-level warn", dir_).exit_code, 0);
  double bytes = 0;
  for (const auto& f : fs::directory_iterator(out)) bytes += static_cast<double>(fs::file_size(f.path()));
  const double steps = static_cast<double>(lines_of(read_text(out / "timeseries.csv")).size() - 1);
  EXPECT_LE(bytes, e.bytes);
  EXPECT_GT(bytes, e.bytes / 4) << "the estimate is meant to be of the right size, not only an upper bound";
  EXPECT_LE(steps, e.steps);
  EXPECT_GE(steps, e.steps - 2);  // shift: one step per dx rolled, +1 for the last partial step
}

// A killed transient's temporaries (OWN_NAME.tmp.<dead pid>) are removed by the next command on the folder;
// files of other names, and those of a live process, stay.
TEST_F(CommandLine, TransientRemovesStaleTemporariesOfItsOwnNaming) {
  const fs::path c = dir_ / "startup.yaml";
  std::ofstream(c) << small_startup_case();
  const fs::path out = dir_ / "t";
  fs::create_directories(out);
  const std::string dead = std::to_string(dead_pid()), live = std::to_string(::getpid());
  for (const std::string& name : {"timeseries.csv.tmp." + dead, "strip_power.csv.tmp." + dead,
                                  "my_data.tmp." + dead, "strip_power.csv.tmp." + live})
    std::ofstream(out / name) << "x\n";
  ASSERT_EQ(rollwear("transient " + quoted(c) + " -o " + quoted(out) + " --log-level warn", dir_).exit_code, 0);
  EXPECT_FALSE(fs::exists(out / ("timeseries.csv.tmp." + dead)));
  EXPECT_FALSE(fs::exists(out / ("strip_power.csv.tmp." + dead)));
  EXPECT_TRUE(fs::exists(out / ("my_data.tmp." + dead)));
  EXPECT_TRUE(fs::exists(out / ("strip_power.csv.tmp." + live)));
}

// ---- run with wear.fatigue (docs/fatigue.md) ----

// the shipped fatigue case on a 40 x 40 grid with the stepping (and the solver's line) replaced
fs::path fatigue_case(const fs::path& dir, const std::string& name, const std::string& stepping,
                      const std::string& solver = "solver:     { normal: auto, nx: 40, ny: 40 }") {
  std::string text = read_text(kSource / "cases" / "paper-wear-fatigue.yaml");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  };
  replace("solver:     { normal: auto, nx: 80, ny: 80 }", solver);
  replace("stepping: { method: adaptive, rtol: 1.0e-3, atol_m: 1.0e-9 }", stepping + "\n  checkpoint_interval_s: 0.02");
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p;
}

// The damage is part of the life's state, so the checkpoint carries it: killed and resumed, a fixed-stepping life
// with fatigue ends bit-identical to an uninterrupted one, by fatigue, its damage column and margins included.
TEST_F(CommandLine, FatigueRunKilledAndResumedEndsBitIdentical) {
  const fs::path c = fatigue_case(dir_, "fatigue.yaml", "stepping: { method: fixed-depth, max_depth_step_m: 2.0e-7 }");
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  ASSERT_EQ(rollwear("run " + quoted(c) + " -o " + quoted(whole) + " --log-level error", dir_).exit_code, 0);
  run_and_kill({"run", c.string(), "-o", killed.string(), "--quiet"}, killed / "checkpoint.txt", 150,
               dir_ / "killed.log");
  ASSERT_TRUE(fs::exists(killed / "checkpoint.txt"));
  const ProcessResult r = rollwear("run " + quoted(c) + " -o " + quoted(killed) + " --resume --log-level error", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string a = read_text(whole / "report.txt"), b = read_text(killed / "report.txt");
  EXPECT_EQ(report_value(a, "ended_by"), "fatigue");
  EXPECT_EQ(report_value(b, "resumed"), "true");
  for (const char* key : {"ended_by", "message", "revolutions", "max_depth_m", "dissipated_J", "steps", "rhs_evals",
                          "depth_fraction", "max_damage", "max_damage_y_m", "max_tgamma_N"})
    EXPECT_EQ(report_value(a, key), report_value(b, key)) << key;
  EXPECT_EQ(read_text(whole / "summary.csv"), read_text(killed / "summary.csv"));
  const std::vector<std::string> summary = lines_of(read_text(whole / "summary.csv"));
  EXPECT_NE(std::find_if(summary.begin(), summary.end(),
                         [](const std::string& l) { return l.rfind("step,", 0) == 0 && l.find(",max_damage") != std::string::npos; }),
            summary.end());
}

// The corrected fidelity's correction holds the wear nodes' rates only (not the damage's): its checkpoint line says
// how many, and a killed corrected life with fatigue resumes bit-identical
TEST_F(CommandLine, CorrectedFatigueRunKilledAndResumedEndsBitIdentical) {
  const fs::path c = fatigue_case(dir_, "corrected.yaml", "stepping: { method: fixed-depth, max_depth_step_m: 2.0e-6 }",
                                  "solver:     { normal: auto, fidelity: corrected, correction_tolerance: 0.5, nx: 20, ny: 20 }");
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  ASSERT_EQ(rollwear("run " + quoted(c) + " -o " + quoted(whole) + " --log-level error", dir_).exit_code, 0);
  run_and_kill({"run", c.string(), "-o", killed.string(), "--quiet"}, killed / "checkpoint.txt", 12,
               dir_ / "killed.log");
  ASSERT_TRUE(fs::exists(killed / "checkpoint.txt"));
  const ProcessResult r = rollwear("run " + quoted(c) + " -o " + quoted(killed) + " --resume --log-level error", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string a = read_text(whole / "report.txt"), b = read_text(killed / "report.txt");
  EXPECT_EQ(report_value(b, "resumed"), "true");
  EXPECT_EQ(report_value(a, "fidelity"), "corrected");
  for (const char* key : {"ended_by", "revolutions", "max_depth_m", "dissipated_J", "steps", "exact_solves",
                          "error_power_rel", "max_damage", "depth_fraction"})
    EXPECT_EQ(report_value(a, key), report_value(b, key)) << key;
}

// ---- run with bodies.bodyN.dang_van (docs/fatigue.md §4c) ----

// Dang Van's index on a life's final worn contact, by two routes: the life's report.txt, and `rollwear contact` on
// the same case with the worn roller's final profile read from the life's last snapshot file (its z_m column) and
// the wear: section removed. Both solve the case's models on the same profile: equal to rounding. A life without
// the key reports no such field; a bad key is bad input naming file, line and key.
TEST_F(CommandLine, RunWithDangVanReportsTheIndexOfTheFinalWornContact) {
  const fs::path c = fatigue_case(dir_, "dv.yaml", "stepping: { method: fixed-depth, max_depth_step_m: 1.0e-5 }",
                                  "solver:     { normal: auto, nx: 24, ny: 24 }");
  const std::string plain = read_text(c);
  const std::string roller = "body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28";
  std::string text = plain;
  ASSERT_NE(text.find(roller), std::string::npos);
  text.insert(text.find(roller) + roller.size(), ", dang_van: { a: 0.3, b_Pa: 300.0e6 }");
  std::ofstream(c) << text;
  const fs::path life = dir_ / "life";
  const ProcessResult r = rollwear("run " + quoted(c) + " -o " + quoted(life) + " --log-level error", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = read_text(life / "report.txt");
  const double index = std::stod(report_value(report, "dang_van_body1_index"));
  EXPECT_GT(index, 0);
  EXPECT_GT(std::stod(report_value(report, "max_depth_m")), 0);  // a worn profile, not the unworn one
  EXPECT_EQ(report.find("dang_van_body2"), std::string::npos) << report;  // body 2 has no key

  // the final worn roller as a profile file: the last snapshot's y_m and z_m
  fs::path last;
  for (const auto& f : fs::directory_iterator(life / "snapshots"))
    if (f.path().filename().string().find("_body1.csv") != std::string::npos && f.path() > last) last = f.path();
  ASSERT_FALSE(last.empty());
  std::string profile = "y_m,z_m\n";
  for (const std::string& line : lines_of(read_text(last))) {
    if (line.empty() || line[0] == '#' || line.rfind("y_m,", 0) == 0) continue;
    const std::vector<std::string> v = split(line);  // y_m, z_original_m, z_m, depth_m, damage
    profile += v[0] + "," + v[2] + "\n";
  }
  std::ofstream(dir_ / "final_body1.csv") << profile;
  std::string contact_text = with_solver(text, "body1: { crowned: { Ry_m: 0.500, width_m: 0.020 } }",
                                         "body1: { file: final_body1.csv }");
  contact_text = contact_text.substr(0, contact_text.find("\nwear:\n") + 1) +
                 contact_text.substr(contact_text.find("\noutput:") + 1);
  std::ofstream(dir_ / "final.yaml") << contact_text;
  const fs::path out = dir_ / "contact";
  const ProcessResult k = rollwear("contact " + quoted(dir_ / "final.yaml") + " -o " + quoted(out) + " --log-level warn", dir_);
  ASSERT_EQ(k.exit_code, 0) << k.err << contact_text;
  const std::vector<std::string> rows = lines_of(read_text(out / "dang_van.csv"));
  ASSERT_EQ(rows.size(), 2u);  // body,a,b_Pa,index_max,x_m,y_m,z_m,...
  const std::vector<std::string> row = split(rows[1]);
  EXPECT_EQ(row[0], "1");
  EXPECT_NEAR(std::stod(row[3]), index, 1e-12 * index);
  EXPECT_NEAR(std::stod(row[5]), std::stod(report_value(report, "dang_van_body1_y_m")), 1e-12);
  EXPECT_NEAR(std::stod(row[6]), std::stod(report_value(report, "dang_van_body1_depth_m")), 1e-12);
  // the contact solved there is the life's final one (its models on its profile): a, b and p0 as the report's
  const std::vector<std::string> summary = lines_of(read_text(out / "summary.csv"));  // name,a_m,b_m,p0_Pa,...
  ASSERT_GE(summary.size(), 2u);
  const std::vector<std::string> contact = split(summary[1]);
  for (const auto& [column, key] : {std::pair{1, "a_m"}, std::pair{2, "b_m"}, std::pair{3, "p0_Pa"}}) {
    const double life_value = std::stod(report_value(report, key));
    EXPECT_NEAR(std::stod(contact[static_cast<std::size_t>(column)]), life_value, 1e-12 * life_value) << key;
  }

  // without the key: no such field
  std::ofstream(c) << plain;
  ASSERT_EQ(rollwear("run " + quoted(c) + " -o " + quoted(dir_ / "plain") + " --log-level error", dir_).exit_code, 0);
  EXPECT_EQ(read_text(dir_ / "plain" / "report.txt").find("dang_van"), std::string::npos);

  // a bad key: file, line and key
  std::string bad = text;
  bad.replace(bad.find("b_Pa: 300.0e6"), 13, "b_Pa: 0");
  std::ofstream(c) << bad;
  const ProcessResult b = rollwear("run " + quoted(c) + " -o " + quoted(dir_ / "bad"), dir_);
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find(c.string() + ":15:"), std::string::npos) << b.err;
  EXPECT_NE(b.err.find("bodies.body1.dang_van.b_Pa"), std::string::npos) << b.err;
  EXPECT_EQ(b.err.find("terminate"), std::string::npos);
}

TEST_F(CommandLine, RunWithBadFatigueKeyExitsTwoNamingFileLineAndKey) {
  const fs::path c = fatigue_case(dir_, "bad.yaml", "stepping: { method: adaptive }");
  std::string text = read_text(c);
  const std::size_t at = text.find("zero_at_N: 175");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 14, "zero_at_N: 50");
  std::ofstream(c) << text;
  const ProcessResult r = rollwear("run " + quoted(c) + " -o " + quoted(dir_ / "w"), dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(c.string() + ":28:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("wear.fatigue.zero_at_N: must be above peak_at_N = 65"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("terminate"), std::string::npos);
}

}  // namespace
}  // namespace contact
