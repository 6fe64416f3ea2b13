#pragma once
// Progress of long scene-loading steps (importing a large mesh, subdividing one): silent unless a tool
// turns it on (`ochre render` without -q), and then only for a step that has run longer than
// kLoadProgressDelay, so that ordinary scenes load without noise while a pathological one (millions of
// faces) shows that it is working. Lines go through ProgressReporter, so OCHRE_PROGRESS applies.

#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>

namespace ochre {

class ProgressReporter;

inline constexpr std::chrono::seconds kLoadProgressDelay{2};

// Where load progress goes (nullptr, the default: nowhere). Process-wide.
void enable_load_progress(std::ostream* out);

class LoadProgress {
 public:
  explicit LoadProgress(std::string label);
  ~LoadProgress();
  LoadProgress(const LoadProgress&) = delete;
  LoadProgress& operator=(const LoadProgress&) = delete;

  // The fraction of the step done so far (0..1, non-decreasing). Call from one thread.
  void update(double fraction);

 private:
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  std::unique_ptr<ProgressReporter> reporter_;  // created once the step is slow
  bool silent_ = false;
  std::uint64_t reported_ = 0;  // permille
};

}  // namespace ochre
