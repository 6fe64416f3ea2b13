// The named-spectrum registry (see named_spectra.h).

#include "spectra/named_spectra.h"

#include <memory>
#include <stdexcept>
#include <string>

#include "spectra/cie.h"
#include "spectra/constant_spectrum.h"
#include "spectra/embedded_tables.h"
#include "spectra/tabulated_spectrum.h"

namespace ochre {

namespace {

// A CIE 1931 colour matching function as a spectrum (0 outside 360-830 nm).
class CmfSpectrum final : public Spectrum {
 public:
  explicit CmfSpectrum(float (*cmf)(float)) : cmf_(cmf) {
    for (int l = 360; l <= 830; ++l) max_ = std::max(max_, cmf_(float(l)));
  }
  float eval(float lambda_nm) const override { return cmf_(lambda_nm); }
  float max_value() const override { return max_; }

 private:
  float (*cmf_)(float);
  float max_ = 0.0f;
};

// One column of an embedded table, e.g. embedded("ior_Au_5nm.csv", "n") for optical constants.
SpectrumPtr embedded(std::string_view file, std::string_view column) {
  return tabulated_spectrum(embedded_table(file), column);
}

struct NamedSpectrum {
  std::string_view name;
  SpectrumPtr (*make)();
};

constexpr NamedSpectrum kRegistry[] = {
    {"D65", [] { return d65(); }},
    {"A", [] { return illuminant_a(); }},
    {"E", [] { return normalized_to_unit_luminance(std::make_shared<ConstantSpectrum>(1.0f)); }},
    {"cie_x", []() -> SpectrumPtr { return std::make_shared<CmfSpectrum>(&cie_x); }},
    {"cie_y", []() -> SpectrumPtr { return std::make_shared<CmfSpectrum>(&cie_y); }},
    {"cie_z", []() -> SpectrumPtr { return std::make_shared<CmfSpectrum>(&cie_z); }},
    // Optical constants of metals and silicon (refractiveindex.info data; sources in the CSV headers),
    // 300-900 nm on a 5 nm grid. "-eta" is n and "-k" the extinction k of the index n + i k as
    // tabulated; materials/lobes/fresnel.h uses n - i k internally.
    {"metal-Au-eta", [] { return embedded("ior_Au_5nm.csv", "n"); }},
    {"metal-Au-k", [] { return embedded("ior_Au_5nm.csv", "k"); }},
    {"metal-Ag-eta", [] { return embedded("ior_Ag_5nm.csv", "n"); }},
    {"metal-Ag-k", [] { return embedded("ior_Ag_5nm.csv", "k"); }},
    {"metal-Cu-eta", [] { return embedded("ior_Cu_5nm.csv", "n"); }},
    {"metal-Cu-k", [] { return embedded("ior_Cu_5nm.csv", "k"); }},
    {"metal-Al-eta", [] { return embedded("ior_Al_5nm.csv", "n"); }},
    {"metal-Al-k", [] { return embedded("ior_Al_5nm.csv", "k"); }},
    {"metal-Si-eta", [] { return embedded("ior_Si_5nm.csv", "n"); }},
    {"metal-Si-k", [] { return embedded("ior_Si_5nm.csv", "k"); }},
    // Hematite (Querry 1985): randomly oriented grains (2 o + e) / 3, and the two rays.
    {"pigment-hematite-n", [] { return embedded("ior_Fe2O3_5nm.csv", "n"); }},
    {"pigment-hematite-k", [] { return embedded("ior_Fe2O3_5nm.csv", "k"); }},
    {"pigment-hematite_o-n", [] { return embedded("ior_Fe2O3_5nm.csv", "n_o"); }},
    {"pigment-hematite_o-k", [] { return embedded("ior_Fe2O3_5nm.csv", "k_o"); }},
    {"pigment-hematite_e-n", [] { return embedded("ior_Fe2O3_5nm.csv", "n_e"); }},
    {"pigment-hematite_e-k", [] { return embedded("ior_Fe2O3_5nm.csv", "k_e"); }},
    // A model of a phosphor-converted white LED at 4103 K (tools/data/make_led_spectrum.py), not a
    // measurement.
    {"LED-4100K-model",
     [] { return normalized_to_unit_luminance(embedded("led_white_4100k_model_5nm.csv", "S")); }},
};

}  // namespace

SpectrumPtr named_spectrum(std::string_view name) {
  for (const auto& entry : kRegistry)
    if (entry.name == name) return entry.make();
  std::string known;
  for (const auto& entry : kRegistry) known += (known.empty() ? "" : ", ") + std::string(entry.name);
  throw std::invalid_argument("unknown spectrum name '" + std::string(name) + "' (known: " + known + ")");
}

std::vector<std::string_view> list_named_spectra() {
  std::vector<std::string_view> names;
  for (const auto& entry : kRegistry) names.push_back(entry.name);
  return names;
}

}  // namespace ochre
