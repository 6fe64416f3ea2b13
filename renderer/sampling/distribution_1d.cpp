#include "renderer/sampling/distribution_1d.h"

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
  // One bucket per item: the buckets then hold about one CDF step each.
  const size_t buckets = weights.size();
  guide_.resize(buckets + 1);
  for (size_t k = 0; k <= buckets; ++k)
    guide_[k] = static_cast<uint32_t>(upper_index(static_cast<double>(k) / buckets));
}

size_t Distribution1D::upper_index(double u) const {
  return static_cast<size_t>(std::upper_bound(cdf_.begin() + 1, cdf_.end(), u) - cdf_.begin());
}

size_t Distribution1D::sample(float u, float* u_remapped) const {
  // The item is the one below the first CDF entry above u, skipping zero-weight items. The answer for u lies
  // between the answers for the bucket bounds either side (one bucket of margin absorbs the rounding of u *
  // buckets), and the search on that range returns the same first CDF entry above u as a search of the whole
  // table.
  if (guide_.empty()) return sample_without_guide(u, u_remapped);  // all weights zero
  if (pmf_.size() == 1) {  // one light, one emitting triangle: the search below would return the same
    if (u_remapped) *u_remapped = std::clamp(u, 0.0f, 0.99999994f);
    return 0;
  }
  const size_t buckets = guide_.size() - 1;
  const double scaled = u > 0.0f ? static_cast<double>(u) * static_cast<double>(buckets) : 0.0;
  const size_t k = std::min(static_cast<size_t>(scaled), buckets - 1);
  const size_t lo = guide_[k > 0 ? k - 1 : 0];
  const size_t hi = std::min<size_t>(guide_[std::min(k + 2, buckets)] + 1, cdf_.size());
  const double x = u;
  if (hi - lo > 8) {
    const auto it = std::upper_bound(cdf_.begin() + lo, cdf_.begin() + hi, x);
    return finish_sample(static_cast<size_t>(it - cdf_.begin()), u, u_remapped);
  }
  // The usual few entries: the first one above u is lo plus the count of those not above it (the CDF is
  // sorted), counted without the branches of a binary search, which u makes unpredictable.
  size_t upper = lo;
  for (size_t j = lo; j < hi; ++j) upper += cdf_[j] <= x ? 1 : 0;
  return finish_sample(upper, u, u_remapped);
}

size_t Distribution1D::sample_without_guide(float u, float* u_remapped) const {
  return finish_sample(upper_index(u), u, u_remapped);
}

size_t Distribution1D::finish_sample(size_t upper, float u, float* u_remapped) const {
  size_t i = std::min(upper - 1, pmf_.size() - 1);
  while (pmf_[i] == 0.0f && i > 0) --i;
  if (u_remapped) {
    const double width = cdf_[i + 1] - cdf_[i];
    const double r = width > 0.0 ? (u - cdf_[i]) / width : 0.0;
    *u_remapped = static_cast<float>(std::clamp(r, 0.0, 0.99999994));
  }
  return i;
}

}  // namespace ochre
