#include "renderer/distribution_1d.h"

#include <algorithm>

namespace ochre {

Distribution1D::Distribution1D(const std::vector<double>& weights)
    : cdf_(weights.size() + 1, 0.0), pmf_(weights.size()) {
  for (size_t i = 0; i < weights.size(); ++i) cdf_[i + 1] = cdf_[i] + std::max(0.0, weights[i]);
  total_ = cdf_.back();
  if (total_ <= 0.0) return;
  for (size_t i = 0; i < weights.size(); ++i) {
    pmf_[i] = static_cast<float>((cdf_[i + 1] - cdf_[i]) / total_);
    cdf_[i] /= total_;
  }
  cdf_.back() = 1.0;
}

size_t Distribution1D::sample(float u, float* u_remapped) const {
  // First index whose upper CDF bound exceeds u, skipping zero-weight items.
  const auto it = std::upper_bound(cdf_.begin() + 1, cdf_.end(), static_cast<double>(u));
  size_t i = std::min(static_cast<size_t>(it - cdf_.begin()) - 1, pmf_.size() - 1);
  while (pmf_[i] == 0.0f && i > 0) --i;
  if (u_remapped) {
    const double width = cdf_[i + 1] - cdf_[i];
    const double r = width > 0.0 ? (u - cdf_[i]) / width : 0.0;
    *u_remapped = static_cast<float>(std::clamp(r, 0.0, 0.99999994));
  }
  return i;
}

}  // namespace ochre
