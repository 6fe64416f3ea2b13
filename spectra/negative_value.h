#pragma once
// Where a spectrum is negative. Lights, emission and reflectances must be >= 0 at every wavelength
// (docs/scene-format.md, "Validation"); the error names the wavelength found here.

#include <optional>

#include "spectra/spectrum.h"

namespace ochre {

struct NegativeValue {
  float lambda_nm;  // a table's wavelength, or a whole nm of [kLambdaMin, kLambdaMax]
  float value;      // there; for a scaled table the entry as written in the table
};

// The first negative value of `s`: for a table (a CSV spectrum, also scaled by a positive factor) its first
// negative entry, wherever it lies; otherwise the first whole nm of [kLambdaMin, kLambdaMax] where `s` is
// negative (tables hold whole or coarser nm steps, analytic spectra are smooth). nullopt when none is.
std::optional<NegativeValue> first_negative_value(const Spectrum& s);

}  // namespace ochre
