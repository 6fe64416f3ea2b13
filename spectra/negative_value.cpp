#include "spectra/negative_value.h"

#include "spectra/sampled_wavelengths.h"
#include "spectra/scaled_spectrum.h"
#include "spectra/tabulated_spectrum.h"

namespace ochre {

std::optional<NegativeValue> first_negative_value(const Spectrum& s) {
  if (const auto* scaled = dynamic_cast<const ScaledSpectrum*>(&s); scaled && scaled->scale() > 0.0f)
    return first_negative_value(*scaled->base());
  if (const auto* table = dynamic_cast<const TabulatedSpectrum*>(&s)) {
    for (size_t i = 0; i < table->values().size(); ++i)
      if (table->values()[i] < 0.0f) return NegativeValue{table->wavelengths()[i], table->values()[i]};
    return std::nullopt;
  }
  for (int nm = static_cast<int>(kLambdaMin); nm <= static_cast<int>(kLambdaMax); ++nm) {
    const float value = s.eval(static_cast<float>(nm));
    if (value < 0.0f) return NegativeValue{static_cast<float>(nm), value};
  }
  return std::nullopt;
}

}  // namespace ochre
