#pragma once
// Progress reports for long renders: a single-line bar with percentage, elapsed time and ETA on a
// terminal (redrawn at most ~10 times a second), plain lines at each 10 % step otherwise (logs, CI).
// The environment variable OCHRE_PROGRESS=plain|bar|none overrides the choice.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <iostream>
#include <mutex>
#include <string>
#include <string_view>

namespace ochre {

enum class ProgressStyle { bar, plain, none };

// The style for a stream that is (or is not) a terminal, given the value of OCHRE_PROGRESS (nullptr or
// "" when unset). Throws std::invalid_argument naming OCHRE_PROGRESS for any other value.
ProgressStyle resolve_progress_style(bool interactive, const char* environment_value);

// Whole percent done, rounded down so 100 % means finished; total 0 counts as finished.
int progress_percent(std::uint64_t done, std::uint64_t total);

// Remaining seconds extrapolated from the average rate so far; negative when unknown (nothing done).
double progress_eta_seconds(std::uint64_t done, std::uint64_t total, double elapsed_seconds);

// "4.1 s", "2 min 05 s", "1 h 02 min".
std::string format_duration(double seconds);

// "render: 30% (elapsed 4.1 s, ETA 9.6 s)"; "render: 100% (elapsed 13.7 s)" once done.
std::string format_progress_line(std::string_view label, std::uint64_t done, std::uint64_t total,
                                 double elapsed_seconds);

// "render [#########-------------------]  30% elapsed 4.1 s, ETA 9.6 s"
std::string format_progress_bar(std::string_view label, std::uint64_t done, std::uint64_t total,
                                double elapsed_seconds, int bar_width = 30);

bool stderr_is_terminal();

// Seconds from `start` to now (steady clock), for timings the tools print.
double seconds_since(std::chrono::steady_clock::time_point start);

class ProgressReporter {
 public:
  // `start`: when the work began (elapsed times and ETAs count from it).
  ProgressReporter(std::string label, std::uint64_t total_units, std::ostream& out = std::cerr,
                   bool interactive = stderr_is_terminal(),
                   std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now());
  // Ends an unfinished bar's line so later output starts on a fresh line (no 100 % is claimed).
  ~ProgressReporter();
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  // Thread-safe: called by every worker as it completes units of work.
  void advance(std::uint64_t units);
  // Reports completion (final bar or the 100 % line) once.
  void finish();

  ProgressStyle style() const { return style_; }

 private:
  using Clock = std::chrono::steady_clock;
  double elapsed_seconds() const;
  void redraw_bar(bool final);
  int plain_step(std::uint64_t done) const;
  void print_step();

  std::string label_;
  std::uint64_t total_;
  std::ostream& out_;
  ProgressStyle style_;
  Clock::time_point start_;
  std::atomic<std::uint64_t> done_{0};
  std::atomic<std::int64_t> last_draw_ns_;  // bar: time of the last redraw since start_
  std::atomic<int> last_step_{0};           // plain: last 10 % step printed
  std::mutex output_mutex_;
  size_t last_bar_length_ = 0;  // guarded by output_mutex_
  bool bar_drawn_ = false;      // guarded by output_mutex_
  bool finished_ = false;       // guarded by output_mutex_
};

}  // namespace ochre
