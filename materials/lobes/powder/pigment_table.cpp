#include "materials/lobes/powder/pigment_table.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "materials/core/pi.h"
#include "materials/numerics/mie.h"
#include "spectra/named_spectra.h"
#include "spectra/non_finite.h"

namespace ochre {

namespace {

// The radius axis is the size parameter x = 2 pi b / lambda: at a fixed x the albedo changes with the
// wavelength only through the (smooth) index, so the Mie resonances of weakly absorbing grains line up
// along the wavelength axis and bilinear interpolation follows them.
const float kLogXMin =
    float(std::log(kTwoPiD * PigmentTable::kRadiusMin / (PigmentTable::kLambdaMax * 1e-3)));
const float kLogXStep =
    float((std::log(kTwoPiD * PigmentTable::kRadiusMax / (PigmentTable::kLambdaMin * 1e-3)) - kLogXMin) /
          (PigmentTable::kSizes - 1));

// Position of x on a uniform grid of `count` knots: the lower knot and the weight of the upper one, clamped
// to the grid (NaN goes to the first knot).
struct GridPosition {
  int index;
  float weight;
};
GridPosition grid_position(float steps, int count) {
  const float t = nan_safe_clamp(steps, 0.0f, float(count - 1));
  const int i = std::min(static_cast<int>(t), count - 2);
  return {i, t - float(i)};
}

}  // namespace

PigmentTable::PigmentTable(const Spectrum& n, const Spectrum& k, PowderTau tau) {
  lambdas_ = static_cast<int>(std::lround((kLambdaMax - kLambdaMin) / kLambdaStep)) + 1;
  rho_.resize(size_t(lambdas_) * kSizes);
  tau_.resize(lambdas_);
  for (int l = 0; l < lambdas_; ++l) {
    const float lambda_nm = kLambdaMin + l * kLambdaStep;
    const double nn = n.eval(lambda_nm), kk = k.eval(lambda_nm);
    tau_[l] = static_cast<float>(powder_tau_o(nn, tau));
    for (int r = 0; r < kSizes; ++r) {
      const double x = std::exp(double(kLogXMin) + r * double(kLogXStep));
      rho_[size_t(l) * kSizes + r] = static_cast<float>(mie_efficiencies({nn, kk}, x).albedo());
    }
  }
}

float PigmentTable::albedo(float lambda_nm, float radius_um) const {
  const GridPosition l = grid_position((lambda_nm - kLambdaMin) / kLambdaStep, lambdas_);
  const float log_x = std::log(std::max(float(kTwoPiD) * radius_um / (lambda_nm * 1e-3f), 1e-30f));
  const GridPosition r = grid_position((log_x - kLogXMin) / kLogXStep, kSizes);
  const float* row0 = &rho_[size_t(l.index) * kSizes + r.index];
  const float* row1 = row0 + kSizes;
  const float a = row0[0] + r.weight * (row0[1] - row0[0]);
  const float b = row1[0] + r.weight * (row1[1] - row1[0]);
  return a + l.weight * (b - a);
}

float PigmentTable::tau_o(float lambda_nm) const {
  const GridPosition l = grid_position((lambda_nm - kLambdaMin) / kLambdaStep, lambdas_);
  return tau_[l.index] + l.weight * (tau_[l.index + 1] - tau_[l.index]);
}

const std::vector<std::string>& PigmentTable::names() {
  static const std::vector<std::string> pigments = {"hematite", "hematite_o", "hematite_e"};
  return pigments;
}

std::shared_ptr<const PigmentTable> PigmentTable::named(const std::string& pigment, PowderTau tau) {
  static std::mutex mutex;
  static std::map<std::pair<std::string, PowderTau>, std::shared_ptr<const PigmentTable>> tables;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& slot = tables[{pigment, tau}];
  if (!slot)
    slot = std::make_shared<PigmentTable>(*named_spectrum("pigment-" + pigment + "-n"),
                                          *named_spectrum("pigment-" + pigment + "-k"), tau);
  return slot;
}

}  // namespace ochre
