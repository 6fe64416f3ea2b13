#include "renderer/integrator/render_passes.h"

#include <algorithm>
#include <cmath>

namespace ochre {

namespace {

using Clock = PassSchedule::Clock;

double seconds_between(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

// How many samples per pixel fit in `seconds` at the measured speed.
uint32_t samples_in(double seconds, double seconds_per_sample) {
  const double n = std::floor(seconds / seconds_per_sample);
  return n >= 1.0 ? static_cast<uint32_t>(std::min(n, 4.0e9)) : 0u;
}

}  // namespace

PassResult render_in_passes(const Scene& scene, const RenderJob& job, Film& film, const PixelRect& rect,
                            SampleRange samples, const PassSchedule& schedule,
                            const ProgressCallback& progress,
                            const std::function<void(uint32_t next, const RenderStats& so_far)>& checkpoint,
                            const std::function<bool()>& stop_requested) {
  PassResult result;
  result.next = samples.begin;
  double seconds_per_sample = 0.0;  // per sample of every pixel; 0 until the first pass is measured
  Clock::time_point last_checkpoint = Clock::now();
  while (result.next < samples.end) {
    if (stop_requested()) {
      result.stop = PassStop::stop_requested;
      return result;
    }
    const Clock::time_point now = Clock::now();
    uint32_t n = 1;  // the first pass measures the speed
    if (seconds_per_sample > 0.0) {
      n = std::max(1u, samples_in(schedule.pass_seconds, seconds_per_sample));
      if (schedule.checkpoint_interval > 0.0) {
        const double to_checkpoint = schedule.checkpoint_interval - seconds_between(last_checkpoint, now);
        n = std::min(n, std::max(1u, samples_in(to_checkpoint, seconds_per_sample)));
      }
    }
    if (schedule.deadline) {
      const double left = seconds_between(now, *schedule.deadline);
      const uint32_t fit =
          seconds_per_sample > 0.0 ? samples_in(left, seconds_per_sample) : (left > 0.0 ? 1 : 0);
      if (fit == 0) {
        result.stop = PassStop::deadline;
        return result;
      }
      n = std::min(n, fit);
    }
    n = std::min(n, samples.end - result.next);
    const RenderStats pass = render_range(scene, job, film, rect, {result.next, result.next + n}, progress);
    result.stats.add(pass);
    result.next += n;
    seconds_per_sample = std::max(pass.seconds / n, 1e-9);
    if (schedule.checkpoint_interval > 0.0 && result.next < samples.end &&
        seconds_between(last_checkpoint, Clock::now()) >= schedule.checkpoint_interval) {
      checkpoint(result.next, result.stats);
      last_checkpoint = Clock::now();
    }
  }
  return result;
}

}  // namespace ochre
