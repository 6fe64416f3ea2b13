#pragma once
// Discrete distribution over n items proportional to non-negative weights (CDF + binary search).

#include <cstddef>
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
  std::vector<double> cdf_;  // cdf_[i] = sum of weights before item i, normalised; cdf_.back() == 1
  std::vector<float> pmf_;
  double total_ = 0.0;
};

}  // namespace ochre
