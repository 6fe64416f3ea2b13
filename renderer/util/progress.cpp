#include "renderer/util/progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace ochre {

namespace {

constexpr std::int64_t bar_redraw_interval_ns = 100'000'000;  // at most ~10 redraws per second
constexpr int final_step = 10;                                // plain lines every 10 %

std::string eta_text(std::uint64_t done, std::uint64_t total, double elapsed_seconds) {
  const double eta = progress_eta_seconds(done, total, elapsed_seconds);
  return eta < 0.0 ? "ETA unknown" : "ETA " + format_duration(eta);
}

}  // namespace

ProgressStyle resolve_progress_style(bool interactive, const char* environment_value) {
  const std::string_view value = environment_value ? environment_value : "";
  if (value.empty()) return interactive ? ProgressStyle::bar : ProgressStyle::plain;
  if (value == "bar") return ProgressStyle::bar;
  if (value == "plain") return ProgressStyle::plain;
  if (value == "none") return ProgressStyle::none;
  throw std::invalid_argument(
      fmt::format("OCHRE_PROGRESS='{}' is not a progress style (expected plain, bar or none)", value));
}

int progress_percent(std::uint64_t done, std::uint64_t total) {
  if (total == 0 || done >= total) return 100;
  // done < total, so the quotient is below 100; long double keeps huge counts exact enough.
  return static_cast<int>(
      std::floor(100.0L * static_cast<long double>(done) / static_cast<long double>(total)));
}

double progress_eta_seconds(std::uint64_t done, std::uint64_t total, double elapsed_seconds) {
  if (done >= total) return 0.0;
  if (done == 0) return -1.0;
  return elapsed_seconds * static_cast<double>(total - done) / static_cast<double>(done);
}

std::string format_duration(double seconds) {
  seconds = std::max(seconds, 0.0);
  if (seconds < 59.95) return fmt::format("{:.1f} s", seconds);
  const auto whole_seconds = static_cast<long long>(std::llround(seconds));
  if (whole_seconds < 3600) return fmt::format("{} min {:02} s", whole_seconds / 60, whole_seconds % 60);
  const auto whole_minutes = static_cast<long long>(std::llround(seconds / 60.0));
  return fmt::format("{} h {:02} min", whole_minutes / 60, whole_minutes % 60);
}

std::string format_progress_line(std::string_view label, std::uint64_t done, std::uint64_t total,
                                 double elapsed_seconds) {
  const int percent = progress_percent(done, total);
  if (percent == 100) return fmt::format("{}: 100% (elapsed {})", label, format_duration(elapsed_seconds));
  return fmt::format("{}: {}% (elapsed {}, {})", label, percent, format_duration(elapsed_seconds),
                     eta_text(done, total, elapsed_seconds));
}

std::string format_progress_bar(std::string_view label, std::uint64_t done, std::uint64_t total,
                                double elapsed_seconds, int bar_width) {
  const int percent = progress_percent(done, total);
  const int width = std::max(bar_width, 1);
  const int filled = percent == 100
                         ? width
                         : static_cast<int>(static_cast<long double>(width) * static_cast<long double>(done) /
                                            static_cast<long double>(total));
  const std::string bar = std::string(filled, '#') + std::string(width - filled, '-');
  if (percent == 100)
    return fmt::format("{} [{}] 100% elapsed {}", label, bar, format_duration(elapsed_seconds));
  return fmt::format("{} [{}] {:3}% elapsed {}, {}", label, bar, percent, format_duration(elapsed_seconds),
                     eta_text(done, total, elapsed_seconds));
}

bool stderr_is_terminal() {
  return ::isatty(::fileno(stderr)) != 0;
}

ProgressReporter::ProgressReporter(std::string label, std::uint64_t total_units, std::ostream& out,
                                   bool interactive, Clock::time_point start)
    : label_(std::move(label)),
      total_(total_units),
      out_(out),
      style_(resolve_progress_style(interactive, std::getenv("OCHRE_PROGRESS"))),
      start_(start),
      last_draw_ns_(std::numeric_limits<std::int64_t>::min() / 2) {}

ProgressReporter::~ProgressReporter() {
  std::lock_guard lock(output_mutex_);
  if (bar_drawn_ && !finished_) out_ << '\n' << std::flush;
}

double ProgressReporter::elapsed_seconds() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

void ProgressReporter::advance(std::uint64_t units) {
  const std::uint64_t done = std::min(done_.fetch_add(units, std::memory_order_relaxed) + units, total_);
  if (style_ == ProgressStyle::plain) {
    // Steps 1..9 here; the 100 % line is finish()'s, with the final elapsed time.
    if (plain_step(done) > last_step_.load(std::memory_order_relaxed)) print_step();
  } else if (style_ == ProgressStyle::bar) {
    const auto now_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start_).count();
    std::int64_t last = last_draw_ns_.load();
    if (now_ns - last >= bar_redraw_interval_ns && last_draw_ns_.compare_exchange_strong(last, now_ns)) {
      redraw_bar(false);
    }
  }
}

void ProgressReporter::finish() {
  if (style_ == ProgressStyle::bar) {
    redraw_bar(true);
  } else if (style_ == ProgressStyle::plain) {
    std::lock_guard lock(output_mutex_);
    if (finished_) return;
    out_ << format_progress_line(label_, total_, total_, elapsed_seconds()) << '\n' << std::flush;
    finished_ = true;
  }
}

void ProgressReporter::redraw_bar(bool final) {
  std::lock_guard lock(output_mutex_);
  if (finished_) return;
  // Read under the lock so a slow worker never redraws an older count over a newer one.
  const std::uint64_t done = final ? total_ : std::min(done_.load(std::memory_order_relaxed), total_);
  std::string text = format_progress_bar(label_, done, total_, elapsed_seconds());
  const size_t length = text.size();
  // Blank out the rest of a longer previous line ("1 min 05 s" can become "59.9 s").
  if (length < last_bar_length_) text.append(last_bar_length_ - length, ' ');
  out_ << '\r' << text;
  if (final) {
    out_ << '\n';
    finished_ = true;
  }
  out_ << std::flush;
  last_bar_length_ = length;
  bar_drawn_ = true;
}

int ProgressReporter::plain_step(std::uint64_t done) const {
  return std::min(progress_percent(done, total_) / 10, final_step - 1);
}

void ProgressReporter::print_step() {
  std::lock_guard lock(output_mutex_);
  // Re-read under the lock so concurrent workers print steps in increasing order, each once.
  const std::uint64_t done = std::min(done_.load(std::memory_order_relaxed), total_);
  const int step = plain_step(done);
  if (finished_ || step <= last_step_.load(std::memory_order_relaxed)) return;
  last_step_.store(step, std::memory_order_relaxed);
  out_ << format_progress_line(label_, done, total_, elapsed_seconds()) << '\n' << std::flush;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace ochre
