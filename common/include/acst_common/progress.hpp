#pragma once
// One progress line for long runs: rewritten in place on a terminal, printed as plain lines
// (at a slower pace) when stderr is a file or a pipe, silent when disabled.
#include <chrono>
#include <iosfwd>
#include <string>

namespace acst::common {

class ProgressLine {
 public:
  // `tty_interval`: least time between rewrites on a terminal; `log_interval`: between plain
  // lines elsewhere (zero: no plain lines, only what finish() prints).
  ProgressLine(std::ostream& err, bool enabled, double tty_interval_s = 0.2, double log_interval_s = 0.0);

  // Whether a call of show() now would print (callers skip composing the text otherwise).
  bool due() const;
  void show(const std::string& text);
  // A line that stays (a finished part of the work); ends the in-place line first.
  void finish(const std::string& text);
  // Ends an in-place line so that the next output starts on a fresh line.
  void close();

  double elapsed_s() const;
  // "~4 min 05 s left" from the elapsed time and the fraction done ("? left" before any).
  static std::string time_left(double elapsed_s, double fraction_done);
  bool enabled() const { return enabled_; }
  bool on_terminal() const { return tty_; }

 private:
  using WallClock = std::chrono::steady_clock;
  std::ostream& err_;
  bool enabled_, tty_, open_ = false;
  double interval_s_;
  WallClock::time_point start_, last_;
};

}  // namespace acst::common
