// A contact sweep (session/sweep.h, docs/sweeps.md "Contact sweeps"): a base case without wear: runs the steady
// contact of `rollwear contact` per case in the sweep's process. Its table against the command's own
// summary.csv for the same case (the reference: the command), a resumed run (case folders and the table
// alone) against an uninterrupted one, shards merged, and bad keys refused before any case runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "lib/errors.h"
#include "temp_dir.h"
#include "session/sweep.h"

namespace {

namespace fs = std::filesystem;
using namespace wear;
using namespace session;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream t;
  t << in.rdbuf();
  return t.str();
}
void write_text(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream ss(line);
  for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
  return f;
}
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> v;
  std::stringstream ss(text);
  for (std::string l; std::getline(ss, l);) v.push_back(l);
  return v;
}

class ContactSweep : public rollwear_test::TempDirTest {
 protected:
  // the base case: the paper's steady roller (cases/paper.yaml) on a 10 x 10 grid, no wear: section
  void SetUp() override {
    TempDirTest::SetUp();
    std::string base = read_text(fs::path(ROLLWEAR_SOURCE_DIR) / "cases" / "paper.yaml");
    base = std::regex_replace(base, std::regex("nx: 80, ny: 80"), "nx: 10, ny: 10");
    base = std::regex_replace(base, std::regex("output:.*\n"), "");
    write_text(dir_ / "base.yaml", base);
  }
  fs::path sweep_file(const std::string& body) {
    write_text(dir_ / "sweep.yaml", "base: base.yaml\n" + body);
    return dir_ / "sweep.yaml";
  }
  SweepRunSummary run(const fs::path& sweep, const fs::path& out, int k = 1, int n = 1, int threads = 1) {
    SweepRunOptions o;
    o.output_directory = out;
    o.shard_k = k;
    o.shard_n = n;
    o.threads = threads;
    return run_sweep(read_sweep(sweep.string()), o);
  }
  const std::string grid_ = "axes:\n  - { key: load.normal_load_N, values: [1000, 1500] }\n"
                            "  - { key: kinematics.xi, values: [0.0005, 0.002] }\n";
};

TEST_F(ContactSweep, RowsAreTheContactCommandsNumbers) {
  const fs::path sweep = sweep_file(grid_);
  EXPECT_EQ(read_sweep(sweep.string()).kind, SweepKind::Contact);
  const SweepRunSummary r = run(sweep, dir_ / "out");
  EXPECT_EQ(r.cases, 4);
  EXPECT_EQ(r.failed, 0);
  const std::vector<std::string> table = lines(read_text(dir_ / "out" / "results.csv"));
  ASSERT_EQ(table.size(), 5u);
  EXPECT_EQ(table[0], "index,load.normal_load_N,kinematics.xi,a_m,b_m,p0_Pa,approach_m,Fx_N,Fy_N,Mz_N_m,power_W,"
                      "stick_fraction,status,message");
  const char* outputs[] = {"a_m", "b_m", "p0_Pa", "approach_m", "Fx_N", "Fy_N", "Mz_N_m", "power_W", "stick_fraction"};
  for (long i = 0; i < 4; ++i) {
    // the reference: `rollwear contact` on the case as the sweep ran it (its case.yaml), its summary.csv
    const fs::path c = dir_ / "out" / case_folder_name(i);
    const std::string cmd = std::string("'") + ROLLWEAR_EXE + "' --log-level warn contact '" + (c / "case.yaml").string() +
                            "' -o '" + (dir_ / "cmd").string() + "' > /dev/null";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    const std::vector<std::string> summary = lines(read_text(dir_ / "cmd" / "summary.csv"));
    ASSERT_EQ(summary.size(), 2u);
    const std::vector<std::string> head = split(summary[0]), values = split(summary[1]), row = split(table[1 + i]);
    ASSERT_GE(row.size(), 13u) << table[1 + i];  // the message (empty) last
    EXPECT_EQ(row[0], std::to_string(i));
    EXPECT_EQ(row[12], "ok");
    for (std::size_t k = 0; k < 9; ++k) {
      const auto at = std::find(head.begin(), head.end(), outputs[k]);
      ASSERT_NE(at, head.end()) << outputs[k];
      EXPECT_EQ(row[3 + k], values[static_cast<std::size_t>(at - head.begin())]) << "case " << i << " " << outputs[k];
    }
    // the case's folder holds the command's files, the same bytes
    for (const char* f : {"summary.csv", "strips.csv", "fields.csv"})
      EXPECT_EQ(read_text(c / f), read_text(dir_ / "cmd" / f)) << "case " << i << " " << f;
  }
  EXPECT_NE(read_text(dir_ / "out" / "summary.txt").find("contact sweep: 4 cases, 0 not ok"), std::string::npos);
}

TEST_F(ContactSweep, ResumeAndShardsGiveTheWholeTable) {
  for (const bool case_files : {true, false}) {
    SCOPED_TRACE(case_files ? "case folders" : "the table alone");
    const fs::path sweep = sweep_file(std::string(case_files ? "" : "output: { case_files: false }\n") + grid_);
    const fs::path whole = dir_ / (case_files ? "whole" : "whole_table");
    run(sweep, whole, 1, 1, 2);
    const std::string table = read_text(whole / "results.csv");
    EXPECT_EQ(fs::exists(whole / "case_0003" / "row.csv"), case_files);
    EXPECT_EQ(fs::exists(whole / "finished.csv"), !case_files);
    if (case_files) {  // killed with two cases finished
      fs::remove(whole / "case_0001" / "row.csv");
      fs::remove(whole / "case_0002" / "row.csv");
    } else {  // killed with two rows written and a third cut short
      const std::vector<std::string> f = lines(read_text(whole / "finished.csv"));
      ASSERT_EQ(f.size(), 5u);
      write_text(whole / "finished.csv", f[0] + "\n" + f[1] + "\n" + f[2] + "\n" + f[3].substr(0, 9));
    }
    fs::remove(whole / "results.csv");
    const SweepRunSummary again = run(sweep, whole);
    EXPECT_EQ(again.resumed, 2);
    EXPECT_EQ(read_text(whole / "results.csv"), table);
    EXPECT_EQ(run(sweep, whole).resumed, 4);  // finished: nothing runs again
    // shards merged: the whole table, byte for byte
    std::vector<fs::path> shards;
    for (int k = 1; k <= 3; ++k) {
      shards.push_back(dir_ / ("shard" + std::to_string(k) + (case_files ? "" : "t")));
      run(sweep, shards.back(), k, 3);
    }
    EXPECT_EQ(merge_results(shards), table);
  }
}

TEST_F(ContactSweep, ChangedSweepDoesNotResumeAFolderWithoutCaseFiles) {
  run(sweep_file("output: { case_files: false }\n" + grid_), dir_ / "out");
  const fs::path changed = sweep_file("output: { case_files: false }\naxes:\n  - { key: load.normal_load_N, values: [900, 1500] }\n");
  EXPECT_THROW(run(changed, dir_ / "out"), contact::CaseError);
}

// the error of running the sweep, "" if none
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const contact::CaseError& e) {
    return e.what();
  }
  return "";
}

TEST_F(ContactSweep, BadKeyOrValueIsRefusedBeforeAnyCaseRuns) {
  const std::string key = error_of([&] { run(sweep_file("axes:\n  - { key: friction.muu, values: [0.3] }\n"), dir_ / "a"); });
  EXPECT_NE(key.find("sweep.yaml:3:5: friction.muu:"), std::string::npos) << key;
  EXPECT_NE(key.find("unknown key"), std::string::npos) << key;
  const std::string value = error_of([&] {
    run(sweep_file("axes:\n  - { key: load.normal_load_N, values: [1000, 1500] }\n  - { key: friction.mu, values: [0.3, -0.1] }\n"),
        dir_ / "b");
  });
  EXPECT_NE(value.find("sweep.yaml:4:5: friction.mu: case 1's value -0.1 is refused: case_0001/case.yaml:"), std::string::npos) << value;
  EXPECT_FALSE(fs::exists(dir_ / "b" / "case_0000")) << "a case ran before the sweep was validated";
  // the table alone is a contact sweep's option: on a wear base it is an error at its line
  write_text(dir_ / "wear.yaml", read_text(fs::path(ROLLWEAR_SOURCE_DIR) / "cases" / "paper-wear.yaml"));
  write_text(dir_ / "w.yaml", "base: wear.yaml\noutput: { case_files: false }\naxes:\n  - { key: friction.mu, values: [0.3] }\n");
  const std::string wear = error_of([&] { read_sweep((dir_ / "w.yaml").string()); });
  EXPECT_NE(wear.find("w.yaml:2:"), std::string::npos) << wear;
  EXPECT_NE(wear.find("case_files"), std::string::npos) << wear;
}

}  // namespace
