#pragma once
// Discrete distribution over n items proportional to non-negative weights: inverse CDF, found by a
// guide table (Chen & Asau 1974) that narrows the binary search to the one or two items of u's bucket,
// so sampling costs O(1) cache lines and gives exactly the index a full binary search would.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ochre {

class Distribution1D {
 public:
  Distribution1D() = default;
  explicit Distribution1D(const std::vector<double>& weights);

  size_t size() const { return pmf_.size(); }
  bool empty() const { return total_ <= 0.0; }
  double total() const { return total_; }
  float pmf(size_t i) const { return pmf_[i]; }
  // Picks an index for u in [0,1); `u_remapped` receives u rescaled to [0,1) inside the item.
  size_t sample(float u, float* u_remapped = nullptr) const;

 private:
  size_t upper_index(double u) const;  // first i >= 1 with cdf_[i] > u (cdf_.size() if none)
  size_t sample_without_guide(float u, float* u_remapped) const;
  // The item below CDF entry `upper`, skipping zero-weight items, and u rescaled inside it.
  size_t finish_sample(size_t upper, float u, float* u_remapped) const;

  std::vector<double> cdf_;  // cdf_[i] = sum of weights before item i, normalised; cdf_.back() == 1
  std::vector<float> pmf_;
  // guide_[k] = the answer of the full search for u = k / (guide_.size() - 1).
  std::vector<uint32_t> guide_;
  double total_ = 0.0;
};

}  // namespace ochre
