#include "acst_common/progress.hpp"

#include <algorithm>
#include <iostream>
#include <unistd.h>

#include "acst_common/duration.hpp"

namespace acst::common {

ProgressLine::ProgressLine(std::ostream& err, bool enabled, double tty_interval_s, double log_interval_s)
    : err_(err),
      enabled_(enabled),
      tty_(::isatty(2) == 1 && &err == &std::cerr),
      interval_s_(tty_ ? tty_interval_s : log_interval_s),
      start_(WallClock::now()),
      last_(start_) {}

bool ProgressLine::due() const {
  if (!enabled_ || interval_s_ <= 0.0) return false;
  return std::chrono::duration<double>(WallClock::now() - last_).count() >= interval_s_;
}

void ProgressLine::show(const std::string& text) {
  if (!due()) return;
  last_ = WallClock::now();
  if (tty_) {
    err_ << '\r' << text << "\033[K" << std::flush;
    open_ = true;
  } else {
    err_ << text << '\n' << std::flush;
  }
}

void ProgressLine::finish(const std::string& text) {
  if (!enabled_) return;
  err_ << (tty_ ? "\r" : "") << text << (tty_ ? "\033[K" : "") << '\n' << std::flush;
  open_ = false;
}

void ProgressLine::close() {
  if (open_) err_ << '\n' << std::flush;
  open_ = false;
}

double ProgressLine::elapsed_s() const { return std::chrono::duration<double>(WallClock::now() - start_).count(); }

std::string ProgressLine::time_left(double elapsed_s, double fraction_done) {
  if (!(fraction_done > 0.0)) return "? left";
  return "~" + duration_text(std::max(0.0, elapsed_s * (1.0 - fraction_done) / fraction_done)) + " left";
}

}  // namespace acst::common
