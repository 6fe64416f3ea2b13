#include "tools/halfspace/halfspace_mc.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "tools/halfspace/random_source.h"

namespace ochre::halfspace {

namespace {

// Paths per block of the deterministic split; each block has its own random stream.
constexpr uint64_t kPathsPerBlock = 4096;
// Below this weight a walk plays Russian roulette (survives with probability weight / threshold).
constexpr double kRouletteThreshold = 0.1;
// exp(-45) < 3e-20: collisions deeper than 45 mu_o cannot contribute toward wo.
constexpr double kMaxOpticalDepthToSurface = 45.0;

// Sum and sum of squares of one per-path quantity.
struct Moments {
  double sum = 0.0, sum_squares = 0.0;
  void add(double x) {
    sum += x;
    sum_squares += x * x;
  }
  void merge(const Moments& other) {
    sum += other.sum;
    sum_squares += other.sum_squares;
  }
  Estimate estimate(uint64_t n) const {
    if (n == 0) return {};
    const double mean = sum / n;
    const double variance = n > 1 ? std::max(0.0, (sum_squares / n - mean * mean) * n / (n - 1.0)) : 0.0;
    return {mean, std::sqrt(variance / n)};
  }
};

struct DirectionMoments {
  Moments single, multiple, total;
  void merge(const DirectionMoments& other) {
    single.merge(other.single);
    multiple.merge(other.multiple);
    total.merge(other.total);
  }
};

struct BlockTally {
  std::vector<DirectionMoments> directions;
  Moments escaped;
  double truncated = 0.0;
  uint64_t paths = 0, collisions = 0;
  void merge(const BlockTally& other) {
    for (size_t i = 0; i < directions.size(); ++i) directions[i].merge(other.directions[i]);
    escaped.merge(other.escaped);
    truncated += other.truncated;
    paths += other.paths;
    collisions += other.collisions;
  }
};

double exponential_free_path(RandomSource& random) {
  return -std::log1p(-random.uniform());  // unit extinction: s ~ Exp(1)
}

// The outgoing directions, with their cosines grouped so that each distinct exp(-t / mu_o) is computed
// once per collision.
struct OutgoingSet {
  std::vector<Direction> directions;
  std::vector<double> distinct_mu;
  std::vector<int> mu_index;  // per direction: index into distinct_mu, -1 below the surface
  double max_mu = 0.0;

  explicit OutgoingSet(const std::vector<Direction>& outgoing) : directions(outgoing) {
    for (const Direction& wo : outgoing) {
      if (!(wo.z > 0.0)) {
        mu_index.push_back(-1);
        continue;
      }
      auto it = std::find(distinct_mu.begin(), distinct_mu.end(), wo.z);
      if (it == distinct_mu.end()) it = distinct_mu.insert(distinct_mu.end(), wo.z);
      mu_index.push_back(static_cast<int>(it - distinct_mu.begin()));
      max_mu = std::max(max_mu, wo.z);
    }
  }
};

// One random walk per call; scores every outgoing direction at every collision.
class Walker {
 public:
  Walker(double c, const Direction& wi, const OutgoingSet& outgoing, const SimulationOptions& options)
      : c_(c),
        wi_(wi),
        outgoing_(outgoing),
        options_(options),
        single_(outgoing.directions.size()),
        multiple_(outgoing.directions.size()),
        attenuation_(outgoing.distinct_mu.size()) {}

  void run_path(RandomSource& random, BlockTally& tally) {
    std::fill(single_.begin(), single_.end(), 0.0);
    std::fill(multiple_.begin(), multiple_.end(), 0.0);
    double weight = 1.0;
    Direction d{-wi_.x, -wi_.y, -wi_.z};
    double depth = exponential_free_path(random) * wi_.z;
    double escaped = 0.0;
    for (uint64_t collision = 1;; ++collision) {
      ++tally.collisions;
      score(weight, d, depth, collision == 1 ? single_ : multiple_);
      weight *= c_;
      if (!survives_roulette(weight, random)) break;
      d = sample_phase(options_.phase, d, random);
      depth -= exponential_free_path(random) * d.z;
      if (depth <= 0.0) {
        escaped = weight;
        break;
      }
      if (collision == options_.max_collisions) {
        tally.truncated += weight;
        break;
      }
    }
    tally.escaped.add(escaped);
    for (size_t i = 0; i < single_.size(); ++i) {
      tally.directions[i].single.add(single_[i]);
      tally.directions[i].multiple.add(multiple_[i]);
      tally.directions[i].total.add(single_[i] + multiple_[i]);
    }
    ++tally.paths;
  }

 private:
  // Next-event (point) estimate toward each wo: w c p(d.wo) exp(-t / mu_o) / mu_o (see the header).
  void score(double weight, const Direction& d, double depth, std::vector<double>& target) {
    if (depth > kMaxOpticalDepthToSurface * outgoing_.max_mu) return;
    for (size_t j = 0; j < attenuation_.size(); ++j) {
      const double mu = outgoing_.distinct_mu[j];
      attenuation_[j] = depth < kMaxOpticalDepthToSurface * mu ? std::exp(-depth / mu) / mu : 0.0;
    }
    const double scale = weight * c_;
    for (size_t i = 0; i < target.size(); ++i) {
      const int j = outgoing_.mu_index[i];
      if (j < 0 || attenuation_[j] == 0.0) continue;
      target[i] += scale * phase_value(options_.phase, dot(d, outgoing_.directions[i])) * attenuation_[j];
    }
  }

  static bool survives_roulette(double& weight, RandomSource& random) {
    if (weight <= 0.0) return false;
    if (weight >= kRouletteThreshold) return true;
    if (random.uniform() * kRouletteThreshold >= weight) return false;
    weight = kRouletteThreshold;
    return true;
  }

  double c_;
  Direction wi_;
  const OutgoingSet& outgoing_;
  const SimulationOptions& options_;
  std::vector<double> single_, multiple_, attenuation_;
};

BlockTally run_block(double c, const Direction& wi, const OutgoingSet& outgoing, uint64_t paths,
                     uint64_t seed, uint64_t block, const SimulationOptions& options) {
  BlockTally tally;
  tally.directions.resize(outgoing.directions.size());
  RandomSource random(seed, block);
  Walker walker(c, wi, outgoing, options);
  for (uint64_t p = 0; p < paths; ++p) walker.run_path(random, tally);
  return tally;
}

unsigned thread_count(const SimulationOptions& options, uint64_t blocks) {
  unsigned n = options.threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : options.threads;
  return static_cast<unsigned>(std::min<uint64_t>(n, std::max<uint64_t>(blocks, 1)));
}

void check_arguments(double c, const Direction& wi) {
  if (!(c >= 0.0 && c <= 1.0)) throw std::invalid_argument("single-scattering albedo c must be in [0, 1]");
  if (!(wi.z > 0.0)) throw std::invalid_argument("wi must point above the surface (wi.z > 0)");
}

}  // namespace

GridResult simulate_brdf_grid(double c, const Direction& wi, const std::vector<Direction>& outgoing,
                              uint64_t paths, uint64_t seed, const SimulationOptions& options) {
  check_arguments(c, wi);
  const OutgoingSet set(outgoing);
  const uint64_t blocks = (paths + kPathsPerBlock - 1) / kPathsPerBlock;
  std::vector<BlockTally> tallies(blocks);
  std::atomic<uint64_t> next_block{0};
  const auto worker = [&] {
    for (uint64_t b = next_block++; b < blocks; b = next_block++) {
      const uint64_t n = std::min(kPathsPerBlock, paths - b * kPathsPerBlock);
      tallies[b] = run_block(c, wi, set, n, seed, b, options);
    }
  };
  std::vector<std::thread> threads;
  for (unsigned t = 1; t < thread_count(options, blocks); ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();

  BlockTally sum;
  sum.directions.resize(outgoing.size());
  for (const BlockTally& t : tallies) sum.merge(t);  // in block order: deterministic
  GridResult result;
  for (const DirectionMoments& m : sum.directions)
    result.brdf.push_back(
        {m.single.estimate(sum.paths), m.multiple.estimate(sum.paths), m.total.estimate(sum.paths)});
  result.albedo = sum.escaped.estimate(sum.paths);
  result.truncated_weight = sum.paths ? sum.truncated / sum.paths : 0.0;
  result.paths = sum.paths;
  result.collisions = sum.collisions;
  return result;
}

HalfspaceResult simulate_brdf(double c, const Direction& wi, const Direction& wo, uint64_t paths,
                              uint64_t seed, const SimulationOptions& options) {
  return simulate_brdf_grid(c, wi, {wo}, paths, seed, options).brdf.front();
}

}  // namespace ochre::halfspace
