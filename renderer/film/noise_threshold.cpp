#include "renderer/film/noise_threshold.h"

#include <cmath>

namespace ochre {

bool is_noise_decision_point(uint64_t count) {
  return count >= kFirstNoiseDecision && (count & (count - 1)) == 0;
}

bool pixel_converged(const Film& film, int x, int y, double threshold) {
  const uint64_t n = film.sample_count(x, y);
  if (n < 2) return false;
  const double mean = film.mean(x, y).y;
  return std::sqrt(film.variance_y(x, y) / static_cast<double>(n)) <= threshold * std::fabs(mean);
}

bool pixel_takes_sample(const Film& film, int x, int y, uint32_t next, double threshold) {
  if (film.sample_count(x, y) < next) return false;  // stopped at an earlier decision point
  return !(is_noise_decision_point(next) && pixel_converged(film, x, y, threshold));
}

bool valid_noise_threshold_count(uint64_t count, uint64_t end) {
  return count == end || (count < end && is_noise_decision_point(count));
}

}  // namespace ochre
