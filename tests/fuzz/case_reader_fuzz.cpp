// libFuzzer target for the YAML case readers: the bytes become a case file, read by
// contact::read_contact_case and wear::read_wear_case (and, when a case reads, the conversions the
// commands apply next). A case that reads is fine; a contact::CaseError or std::invalid_argument is
// a fine rejection if its message starts with the file's path (it names the file, as the README
// promises). Anything else is a finding: another exception, a rejection that does not name the file,
// a crash, a sanitizer report, a hang or a blow-up of memory (libFuzzer's -timeout and -rss_limit_mb).
//
// The case is written to <tmp>/rollwear_fuzz_<pid>/cases/case.yaml, next to a copy of the shipped
// profiles/ (so cases/worn-crown.yaml's "../profiles/..." reads), made once per process.
// Built by tests/fuzz/CMakeLists.txt (-DROLLWEAR_BUILD_FUZZERS=ON, clang); run by scripts/fuzz.
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "lib/io/case.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/tangential.h"
#include "wear/wear_case.h"

namespace {

namespace fs = std::filesystem;

// the case file's path, with the shipped profiles beside it (made on the first call)
const std::string& case_path() {
  static const std::string path = [] {
    const fs::path dir = fs::temp_directory_path() / ("rollwear_fuzz_" + std::to_string(::getpid()));
    fs::create_directories(dir / "cases");
    std::error_code ignored;
    fs::copy(fs::path(ROLLWEAR_SOURCE_DIR) / "profiles", dir / "profiles", fs::copy_options::recursive, ignored);
    std::atexit([] {
      std::error_code e;
      fs::remove_all(fs::temp_directory_path() / ("rollwear_fuzz_" + std::to_string(::getpid())), e);
    });
    return (dir / "cases" / "case.yaml").string();
  }();
  return path;
}

[[noreturn]] void finding(const char* reader, const std::string& what) {
  std::fprintf(stderr, "rollwear fuzz finding: %s: %s\n", reader, what.c_str());
  std::fflush(stderr);
  std::abort();  // libFuzzer saves the input as crash-<sha1>
}

// a rejection must name the file first: "PATH:LINE:COL: key: ..." or "PATH: ..."
void check_rejection(const char* reader, const std::string& path, const std::exception& e) {
  const std::string m = e.what();
  if (m.compare(0, path.size(), path) != 0) finding(reader, "the rejection does not start with the file path: " + m);
  // a message quotes values cut to 80 characters (lib/errors.h clipped): never the input whole
  constexpr std::size_t kLongestMessage = 4096;
  if (m.size() > kLongestMessage + path.size()) finding(reader, "the rejection echoes too much: " + m.substr(0, 200));
}

// calls read(path); returns whether the case read
template <class Read>
bool read_checked(const char* reader, const std::string& path, Read read) {
  try {
    read(path);
    return true;
  } catch (const contact::CaseError& e) {
    check_rejection(reader, path, e);
  } catch (const std::invalid_argument& e) {
    check_rejection(reader, path, e);
  } catch (const std::exception& e) {
    finding(reader, std::string("unexpected exception: ") + e.what());
  } catch (...) {
    finding(reader, "unexpected non-standard exception");
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  spdlog::set_level(spdlog::level::off);  // the readers log at debug; warnings are not findings here
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = case_path();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  contact::ContactCase c;
  const bool contact_ok = read_checked("read_contact_case", path, [&](const std::string& p) { c = contact::read_contact_case(p); });
  if (contact_ok) {
    // what the commands apply next to a case that reads: the steady values or the transient run
    read_checked("validate_steady", path, [&](const std::string&) {
      contact::validate_steady(c);
      contact::normal_load_of(c);
      contact::creepages_of(c);
    });
    if (c.transient) read_checked("transient_case_of", path, [&](const std::string&) { contact::transient_case_of(c); });
  }
  read_checked("read_wear_case", path, [](const std::string& p) { wear::read_wear_case(p); });
  return 0;
}
