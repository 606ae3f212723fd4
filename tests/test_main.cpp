// GoogleTest main. spdlog's default logger gets a sink that records every message at warn or above;
// at the end of each test, a listener turns each such message into a failure of that test, unless
// it was logged while an ExpectWarnings guard (tests/log_capture.h) was alive.
#include <gtest/gtest.h>
#include <spdlog/sinks/base_sink.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "tests/log_capture.h"

namespace rollwear_test {
namespace {

// records warn and above, each marked with whether a guard allowed it
class CaptureSink final : public spdlog::sinks::base_sink<std::mutex> {
 public:
  struct Record {
    spdlog::level::level_enum level;
    std::string payload;  // the message's text
    bool allowed;         // logged while an ExpectWarnings was alive
  };

  void allow(int delta) {
    std::lock_guard<std::mutex> lock(mutex_);
    guards_ += delta;
  }
  std::size_t size() {
    std::lock_guard<std::mutex> lock(mutex_);
    return records_.size();
  }
  std::vector<Record> since(std::size_t first) {
    std::lock_guard<std::mutex> lock(mutex_);
    first = std::min(first, records_.size());
    return {records_.begin() + static_cast<std::ptrdiff_t>(first), records_.end()};
  }
  std::vector<Record> take() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(records_, {});
  }

 protected:
  void sink_it_(const spdlog::details::log_msg& msg) override {  // called under mutex_
    if (msg.level < spdlog::level::warn) return;
    records_.push_back({msg.level, std::string(msg.payload.begin(), msg.payload.end()), guards_ > 0});
  }
  void flush_() override {}

 private:
  std::vector<Record> records_;
  int guards_ = 0;  // ExpectWarnings alive
};

const std::shared_ptr<CaptureSink>& capture_sink() {
  static const std::shared_ptr<CaptureSink> sink = std::make_shared<CaptureSink>();
  return sink;
}
CaptureSink& capture() { return *capture_sink(); }

// fails a test that logged a warning it did not expect
class UnexpectedWarnings final : public testing::EmptyTestEventListener {
  void OnTestStart(const testing::TestInfo&) override { capture().take(); }
  void OnTestEnd(const testing::TestInfo&) override {
    for (const CaptureSink::Record& r : capture().take())
      if (!r.allowed)
        ADD_FAILURE() << "unexpected log message (wrap the call in rollwear_test::ExpectWarnings "
                         "if it is meant to warn): "
                      << "[" << spdlog::level::to_string_view(r.level).data() << "] " << r.payload;
  }
};

}  // namespace

ExpectWarnings::ExpectWarnings() : first_(capture().size()) { capture().allow(+1); }
ExpectWarnings::~ExpectWarnings() { capture().allow(-1); }

int ExpectWarnings::count() const { return static_cast<int>(capture().since(first_).size()); }

std::vector<std::string> ExpectWarnings::messages() const {
  std::vector<std::string> out;
  for (CaptureSink::Record& r : capture().since(first_)) out.push_back(std::move(r.payload));
  return out;
}

}  // namespace rollwear_test

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);

  // the library logs to the default logger; only warnings and above matter to the tests
  auto logger = std::make_shared<spdlog::logger>("rollwear", rollwear_test::capture_sink());
  logger->set_level(spdlog::level::warn);
  spdlog::set_default_logger(std::move(logger));

  // appended after the printer, so its OnTestEnd runs first and the printer reports the failure
  testing::UnitTest::GetInstance()->listeners().Append(new rollwear_test::UnexpectedWarnings);
  return RUN_ALL_TESTS();
}
