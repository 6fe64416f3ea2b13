#include "tools/fit/powder_fit_model.h"

#include <utility>

#include "materials/lobes/powder/powder_model.h"

namespace ochre {

PowderParts powder_parts(const PowderValues& values, const std::vector<Measurement>& data,
                         const FitPigment& pigment) {
  PowderParams<double> params;
  params.g = values[kAnisotropy];
  params.kappa = values[kKappa];
  params.correlation_length = values[kCorrelationLength];
  // Mie once per wavelength of the data (usually one or a few).
  std::vector<std::pair<double, PowderWavelength<double>>> waves;
  PowderParts parts;
  parts.volume.reserve(data.size());
  parts.surface.reserve(data.size());
  for (const Measurement& m : data) {
    size_t w = 0;
    while (w < waves.size() && waves[w].first != m.lambda_nm) ++w;
    if (w == waves.size())
      waves.emplace_back(m.lambda_nm, PowderWavelength<double>{m.lambda_nm * 1e-3,
                                                               pigment.albedo(m.lambda_nm, values[kRadius]),
                                                               pigment.tau_o(m.lambda_nm)});
    const PowderTerms<double> t = powder_terms(params, waves[w].second, m.wi, m.wo);
    parts.volume.push_back(t.volume());
    parts.surface.push_back(t.s);
  }
  return parts;
}

std::vector<double> powder_brdf_values(const PowderValues& values, const std::vector<Measurement>& data,
                                       const FitPigment& pigment) {
  const PowderParts parts = powder_parts(values, data, pigment);
  std::vector<double> brdf(data.size());
  for (size_t i = 0; i < data.size(); ++i)
    brdf[i] = values[kVolumeAmplitude] * parts.volume[i] + values[kSurfaceAmplitude] * parts.surface[i];
  return brdf;
}

}  // namespace ochre
