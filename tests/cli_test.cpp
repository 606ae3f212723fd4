// The output files (lib/csv.h) and the command line (app/main.cpp, run as a process).
#include "lib/csv.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "lib/grid.h"

namespace contact {
namespace {

namespace fs = std::filesystem;

// a directory of its own for each test, removed at the end
class TempDir : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("rollwear_cli_test_" + std::to_string(::getpid()) + "_" +
            testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  fs::path dir_;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

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
  EXPECT_EQ(last[3], "-125000000");
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
  EXPECT_EQ(summary[1].rfind("\"small, odd\",0.00033333333333333332,0.002,", 0), 0u) << summary[1];
  EXPECT_NE(summary[1].find(",-0.10000000000000001,"), std::string::npos) << summary[1];
  EXPECT_EQ(summary[1].substr(summary[1].size() - 12), ",classic,3,2");
}

TEST(CsvOutput, ShapeMismatchThrows) {
  SmallResult r = small_result();
  r.solution.tau_y_Pa = Eigen::ArrayXXd::Zero(2, 3);
  EXPECT_THROW(fields_csv(r.patch, r.solution), std::invalid_argument);
  r.solution.strip_power_W_per_m = Eigen::ArrayXd::Zero(3);
  EXPECT_THROW(strips_csv(r.patch, r.solution), std::invalid_argument);
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

TEST_F(CommandLine, ContactOnPaperCaseWritesThreeTables) {
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
  EXPECT_EQ(row[16], "consistent");
  EXPECT_EQ(row[17], "80");
  EXPECT_EQ(row[18], "80");

  // nothing else: no temporary files left behind
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 3);
}

TEST_F(CommandLine, NoFieldsSkipsFieldsTable) {
  const fs::path out = dir_ / "paper";
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
                       ":7:3: load.normal_laod_N: unknown key (valid: normal_load_N)\n");
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
  for (const char* word : {"case", "-o,--output", "--no-fields", "--log-level", "trace", "off", "--help"})
    EXPECT_NE(contact.out.find(word), std::string::npos) << word << " missing from:\n" << contact.out;
}

TEST_F(CommandLine, VersionPrintsVersion) {
  const ProcessResult r = rollwear("--version", dir_);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind("rollwear ", 0), 0u) << r.out;
}

}  // namespace
}  // namespace contact
