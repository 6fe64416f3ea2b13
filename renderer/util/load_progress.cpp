#include "renderer/util/load_progress.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>

#include "renderer/util/progress.h"

namespace ochre {

namespace {

std::atomic<std::ostream*> load_progress_output{nullptr};
constexpr std::uint64_t kPermille = 1000;

}  // namespace

void enable_load_progress(std::ostream* out) {
  load_progress_output.store(out);
}

LoadProgress::LoadProgress(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()) {}

LoadProgress::~LoadProgress() {
  if (reporter_) reporter_->finish();
}

void LoadProgress::update(double fraction) {
  if (silent_) return;
  if (!reporter_) {
    std::ostream* out = load_progress_output.load();
    if (out == nullptr) return;
    if (std::chrono::steady_clock::now() - start_ < kLoadProgressDelay) return;
    try {
      reporter_ = std::make_unique<ProgressReporter>(label_, kPermille, *out, stderr_is_terminal(), start_);
    } catch (const std::invalid_argument&) {  // a bad OCHRE_PROGRESS: the render reports it
      silent_ = true;
      return;
    }
  }
  const auto permille = static_cast<std::uint64_t>(std::clamp(fraction, 0.0, 1.0) * kPermille);
  if (permille > reported_) {
    reporter_->advance(permille - reported_);
    reported_ = permille;
  }
}

}  // namespace ochre
