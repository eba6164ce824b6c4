#pragma once
// A full disk, simulated for the tests (issue 57): while a FileSizeLimit lives, this process and
// the programs it starts (gnuplot) cannot make a file larger than `bytes`. By default SIGXFSZ is
// ignored, so that a write beyond the limit fails with EFBIG instead of killing the writer: what
// a full disk (ENOSPC) does to a program that does not check its writes, as gnuplot does not.
// With `writer_killed`, the signal keeps its default: gnuplot dies at the limit (`ulimit -f`).
#include <signal.h>
#include <sys/resource.h>

#include <gtest/gtest.h>

namespace acst::test {

class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes, bool writer_killed = false) {
    EXPECT_EQ(::getrlimit(RLIMIT_FSIZE, &before_), 0);
    rlimit limited = before_;
    limited.rlim_cur = bytes;
    EXPECT_EQ(::setrlimit(RLIMIT_FSIZE, &limited), 0);
    signal_before_ = ::signal(SIGXFSZ, writer_killed ? SIG_DFL : SIG_IGN);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &before_);
    ::signal(SIGXFSZ, signal_before_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit before_{};
  sighandler_t signal_before_ = SIG_DFL;
};

}  // namespace acst::test
