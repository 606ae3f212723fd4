// `rollwear run` on a cam case as a user meets it (session/life_run.h, docs/cam-follower.md §13): the output
// folder held by one run at a time (session/output_folder.h, as a wear case's run) and a life stopped by Ctrl-C
// or SIGTERM saved at its last step, with the --resume command printed.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/held_lock.h"
#include "tests/temp_dir.h"

namespace {

namespace fs = std::filesystem;
const fs::path kSource = ROLLWEAR_SOURCE_DIR;

std::string text_of(const fs::path& p) {
  std::stringstream s;
  s << std::ifstream(p).rdbuf();
  return s.str();
}

struct Ran {
  int exit_code = -1;
  std::string out, err;
};

Ran rollwear(const std::string& args, const fs::path& dir) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const int status = std::system(("'" + std::string(ROLLWEAR_EXE) + "' " + args + " >'" + out.string() + "' 2>'" +
                                  err.string() + "'")
                                     .c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text_of(out), text_of(err)};
}

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

class CamRunCommand : public rollwear_test::TempDirTest {
 protected:
  // the shipped case at 72 angle steps, 72 x 28 cells, worn by fixed depth steps of `step_m` to a 2 um depth
  fs::path coarse_case(const std::string& step_m, const std::string& checkpoint_interval_s) {
    std::string s = text_of(kSource / "cases" / "cam-follower.yaml");
    const std::size_t a = s.find("\n  wear:"), b = s.find("\noutput:");
    EXPECT_NE(a, std::string::npos);
    EXPECT_NE(b, std::string::npos);
    s = s.substr(0, a + 1) +
        "  wear:\n    cam: { law: archard, archard_k: 1.0e-6, hardness_Pa: 6.9e9 }\n"
        "    roller: { law: archard, archard_k: 1.0e-6, hardness_Pa: 6.9e9 }\n    revolutions: 1.0e12\n"
        "    limits: { max_depth_m: 2.0e-6 }\n    stepping: { method: fixed-depth, max_depth_step_m: " +
        step_m + " }\n    arc_cells: 72\n    lateral_cells: 28\n    checkpoint_interval_s: " + checkpoint_interval_s +
        "\n" + s.substr(b);
    const std::size_t at = s.find("angle_steps: 720");
    EXPECT_NE(at, std::string::npos);
    s.replace(at, 16, "angle_steps: 72");
    const fs::path p = dir_ / "cam.yaml";
    std::ofstream(p) << s;
    return p;
  }
};

// A cam run in a folder another run holds exits 1 naming the folder and the holder's PID, before it
// computes or writes anything; released, the folder runs, and the run leaves no lock file behind.
TEST_F(CamRunCommand, RefusesAFolderAnotherRunHolds) {
  const fs::path c = coarse_case("1.0e-6", "10");
  const fs::path out = dir_ / "out";
  fs::create_directories(out);
  rollwear_test::HeldLock other(out);  // this test process plays the other run
  ASSERT_TRUE(other.held());
  const std::string pid = other.pid();
  for (const std::string& command : {std::string("run -q"), std::string("run -q --restart")}) {
    const Ran r = rollwear(command + " " + quoted(c) + " -o " + quoted(out), dir_);
    EXPECT_EQ(r.exit_code, 1) << command << ": " << r.out << r.err;
    EXPECT_NE(r.err.find(out.string() + " is in use by another rollwear run (PID " + pid + ","), std::string::npos)
        << r.err;
    EXPECT_EQ(r.out.find("cam cam-follower:"), std::string::npos) << "the revolution was computed: " << r.out;
    for (const char* f : {"revolution.csv", "life.csv", "checkpoint.txt", "report.txt"})
      EXPECT_FALSE(fs::exists(out / f)) << f;
  }
  other.release();
  const Ran r = rollwear("run -q " + quoted(c) + " -o " + quoted(out), dir_);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(fs::exists(out / "report.txt"));
  EXPECT_FALSE(fs::exists(out / ".rollwear.lock"));
}

// dissipation.csv carries the roller's periodic motion the life holds, per angle step. Checked on the base
// circle's dwell (300 deg) against its closed forms (docs/cam-follower.md §3, §7): phi = 0 and s = s'' = 0, so
// F_n = F_0 (150 N); the roller rolls at omega_r = -omega r_b / R_r to its creep (xi ~ 1e-5: 1e-4 allowed);
// F_t = T_b(omega_r) / R_r, T_b = T_0 sign + c_b omega_r, to the strips' depth moment M_z (some 1e-4 of the
// torque, §7: 1e-3 allowed).
TEST_F(CamRunCommand, DissipationTableHoldsThePeriodicMotion) {
  const fs::path c = coarse_case("1.0e-6", "10");
  const fs::path out = dir_ / "out";
  const Ran r = rollwear("run -q " + quoted(c) + " -o " + quoted(out), dir_);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  std::ifstream in(out / "dissipation.csv");
  std::string line, header;
  while (std::getline(in, line) && line.rfind("#", 0) == 0) {
  }
  header = line;
  EXPECT_EQ(header, "cam_angle_deg,cam_arc_m,rolling_speed_m_per_s,power_W,energy_J,contact_angle_deg,contact_radius_m,"
                    "normal_load_N,tangential_load_N,xi,slip_speed_m_per_s,roller_omega_rad_per_s");
  std::vector<double> row;
  while (std::getline(in, line))
    if (line.rfind("300,", 0) == 0) {
      std::stringstream cells(line);
      std::string cell;
      while (std::getline(cells, cell, ',')) row.push_back(std::stod(cell));
    }
  ASSERT_EQ(row.size(), 12u) << "no row at 300 deg";
  const double omega = 62.83185307179586, r_b = 0.040, R_r = 0.013, T0 = 0.004, c_b = 1.0e-5;  // the shipped case
  const double omega_r = -omega * r_b / R_r;
  EXPECT_NEAR(row[7], 150.0, 150.0 * 1e-9);
  EXPECT_NEAR(row[11], omega_r, std::abs(omega_r) * 1e-4);
  const double F_t = (-T0 + c_b * omega_r) / R_r;
  EXPECT_NEAR(row[8], F_t, std::abs(F_t) * 1e-3);
  EXPECT_LT(std::abs(row[9]), 1e-4);
}

// life.csv ends where the life ends: the depth limit 2 um, located within the 7th fixed step of 0.3 um, is its
// last row, numbered as the report counts the steps (the step the limit cut short included), at the report's
// revolutions.
TEST_F(CamRunCommand, LifeTableEndsAtTheLimitTheReportNames) {
  const fs::path c = coarse_case("0.3e-6", "10");
  const fs::path out = dir_ / "out";
  const Ran r = rollwear("run -q " + quoted(c) + " -o " + quoted(out), dir_);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  ASSERT_NE(r.out.find("ended_by: max_depth"), std::string::npos) << r.out;
  const auto value_of = [&](const std::string& key) {
    const std::size_t at = r.out.find("\n" + key + ": ");
    EXPECT_NE(at, std::string::npos) << key;
    return std::stod(r.out.substr(at + key.size() + 3));
  };
  std::vector<std::string> rows;
  std::istringstream life(text_of(out / "life.csv"));
  for (std::string line; std::getline(life, line);) rows.push_back(line);
  std::vector<double> last;
  std::istringstream cells(rows.back());
  for (std::string cell; std::getline(cells, cell, ',');) last.push_back(std::stod(cell));
  ASSERT_EQ(last.size(), 6u) << rows.back();
  EXPECT_EQ(last[0], value_of("steps")) << rows.back();
  EXPECT_NEAR(last[1], value_of("revolutions"), 1e-5 * last[1]) << rows.back();  // the report's 6 digits
  EXPECT_NEAR(last[2], 2.0e-6, 2.0e-6 * 1e-6) << rows.back();                      // the limit, located
}

// SIGINT (Ctrl-C) and SIGTERM during a cam life: the life stops after its current step, writes that step's
// checkpoint (none would be due for 1000 s), prints the --resume command, removes the lock file and ends by
// the signal; --resume then continues the life to its limit. About 0.5 s per signal at load 7.5.
class CamRunSignal : public CamRunCommand, public testing::WithParamInterface<int> {};

TEST_P(CamRunSignal, StopsAfterItsStepSavesItAndSaysResume) {
  const int sig = GetParam();
  const fs::path out = dir_ / "out", log = dir_ / "run.log";
  // the signal once the life has accepted its second step (its progress line, on stderr); a run that ends
  // first (this process starved on a loaded machine) is tried again with finer steps: a longer life
  fs::path c;
  bool sent = false;
  int status = 0;
  for (const char* step_m : {"5.0e-8", "1.0e-8", "2.0e-9"}) {
    c = coarse_case(step_m, "1000");
    fs::remove_all(out);
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      std::FILE* f = std::freopen(log.c_str(), "w", stdout);
      if (f) ::dup2(::fileno(stdout), 2);
      ::execl(ROLLWEAR_EXE, ROLLWEAR_EXE, "run", c.c_str(), "-o", out.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    bool ended = false;
    for (int k = 0; k < 60000 && !sent && !ended; ++k) {
      if (::waitpid(pid, &status, WNOHANG) == pid) {
        ended = true;
      } else if (text_of(log).find("step 2:") != std::string::npos) {
        ::kill(pid, sig);
        sent = true;
      } else {
        ::usleep(1000);
      }
    }
    if (ended) continue;
    if (!sent) ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
    break;
  }
  ASSERT_TRUE(sent) << "no run caught after its second step: " << text_of(log);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << text_of(log);

  const std::string said = text_of(log);
  EXPECT_NE(said.find("interrupted; the run continues from its last checkpoint"), std::string::npos) << said;
  EXPECT_NE(said.find("rollwear run " + c.string() + " -o " + out.string() + " --resume"), std::string::npos) << said;
  EXPECT_FALSE(fs::exists(out / ".rollwear.lock"));
  EXPECT_FALSE(fs::exists(out / "report.txt"));
  // the checkpoint is the last step life.csv holds (the step after the signal's)
  const std::string cp = text_of(out / "checkpoint.txt");
  const std::size_t at = cp.find("\nsteps ");
  ASSERT_NE(at, std::string::npos) << "no checkpoint written: " << said;
  const long steps = std::stol(cp.substr(at + 7));
  EXPECT_GE(steps, 2);
  const std::string life = text_of(out / "life.csv");
  const std::size_t last_row = life.rfind('\n', life.size() - 2) + 1;
  EXPECT_EQ(std::stol(life.substr(last_row)), steps) << life;

  // resumed: the life goes on from there to its limit (that a resumed life is the uninterrupted one:
  // CamWearCase.RunKilledAndResumedEndsWithTheUninterruptedLife)
  const Ran resumed = rollwear("run -q " + quoted(c) + " -o " + quoted(out) + " --resume", dir_);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.out << resumed.err;
  EXPECT_NE(resumed.err.find("resuming at cam revolution"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.out.find("ended_by: max_depth"), std::string::npos) << resumed.out;
  EXPECT_NE(resumed.out.find("resumed: true"), std::string::npos) << resumed.out;
  EXPECT_FALSE(fs::exists(out / "checkpoint.txt"));
  const std::string rows = text_of(out / "life.csv");
  EXPECT_NE(rows.find("\n" + std::to_string(steps) + ","), std::string::npos);
  EXPECT_NE(rows.find("\n" + std::to_string(steps + 1) + ","), std::string::npos) << "no step after the stop";
}

INSTANTIATE_TEST_SUITE_P(CtrlCAndTerm, CamRunSignal, testing::Values(SIGINT, SIGTERM),
                         [](const testing::TestParamInfo<int>& i) { return i.param == SIGINT ? "SIGINT" : "SIGTERM"; });

}  // namespace
