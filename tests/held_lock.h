// The test process playing another rollwear run in an output folder: it holds DIR/.rollwear.lock (flock)
// with its PID in the file, as session/output_folder.h's OutputLock does, until release() or the end of scope.
#pragma once

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace rollwear_test {

class HeldLock {
 public:
  explicit HeldLock(const std::filesystem::path& dir) : pid_(std::to_string(::getpid())) {
    fd_ = ::open((dir / ".rollwear.lock").c_str(), O_RDWR | O_CREAT, 0644);
    held_ = fd_ >= 0 && ::flock(fd_, LOCK_EX | LOCK_NB) == 0 &&
            ::write(fd_, pid_.data(), pid_.size()) == static_cast<ssize_t>(pid_.size());
  }
  HeldLock(const HeldLock&) = delete;
  HeldLock& operator=(const HeldLock&) = delete;
  ~HeldLock() { release(); }
  void release() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  bool held() const { return held_; }
  const std::string& pid() const { return pid_; }

 private:
  std::string pid_;
  int fd_ = -1;
  bool held_ = false;
};

}  // namespace rollwear_test
