// Fuzz target: the CSV spectrum reader (spectra/csv_table.h) and the tabulated spectra made from
// every value column (spectra/tabulated_spectrum.h), evaluated across and beyond the visible range.
// Expected errors: the std::runtime_error / std::invalid_argument the reader documents.

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "fuzz_support.h"
#include "spectra/csv_table.h"
#include "spectra/sampled_wavelengths.h"
#include "spectra/tabulated_spectrum.h"

namespace {

// A finite table gives finite values: NaN would poison every pixel that sees the spectrum.
void check(float value, const char* where) {
  if (std::isnan(value)) {
    std::fprintf(stderr, "ochre fuzz: FINDING: NaN from a tabulated spectrum (%s)\n", where);
    std::abort();
  }
}

void evaluate(const ochre::Spectrum& s) {
  check(s.max_value(), "max_value");
  for (float lambda = 300.0f; lambda <= 900.0f; lambda += 7.5f) check(s.eval(lambda), "eval");
  for (float lambda : {NAN, INFINITY, -INFINITY}) check(s.eval(lambda), "eval of a non-finite wavelength");
  const ochre::SampledSpectrum v = s.sample(ochre::SampledWavelengths::sample_visible(0.37f));
  for (int i = 0; i < ochre::kSpectrumSamples; ++i) check(v[i], "sample");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  ochre::fuzz::expect_only_input_errors(
      [&] {
        const auto table = ochre::CsvTable::parse(ochre::fuzz::as_text(data, size), "fuzz.csv");
        for (size_t column = 1; column < table.column_count(); ++column)
          evaluate(*ochre::tabulated_spectrum(table, column));
        for (const std::string& name : table.header()) table.column(name);
      },
      /*parser_errors=*/true);
  return 0;
}
