// The named-spectrum registry.

#include "spectra/named_spectra.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "spectra/cie.h"

namespace ochre::named_spectra_test {
namespace {

TEST(NamedSpectra, KnownNamesResolve) {
  const auto names = list_named_spectra();
  EXPECT_EQ(names, (std::vector<std::string_view>{"D65",
                                                  "A",
                                                  "E",
                                                  "cie_x",
                                                  "cie_y",
                                                  "cie_z",
                                                  "metal-Au-eta",
                                                  "metal-Au-k",
                                                  "metal-Ag-eta",
                                                  "metal-Ag-k",
                                                  "metal-Cu-eta",
                                                  "metal-Cu-k",
                                                  "metal-Al-eta",
                                                  "metal-Al-k",
                                                  "metal-Si-eta",
                                                  "metal-Si-k",
                                                  "pigment-hematite-n",
                                                  "pigment-hematite-k",
                                                  "pigment-hematite_o-n",
                                                  "pigment-hematite_o-k",
                                                  "pigment-hematite_e-n",
                                                  "pigment-hematite_e-k",
                                                  "LED-4100K-model"}));
  for (auto name : names) EXPECT_NE(named_spectrum(name), nullptr) << name;
}

TEST(NamedSpectra, IlluminantsHaveUnitLuminance) {
  for (auto name : {"D65", "A", "E", "LED-4100K-model"})
    EXPECT_NEAR(spectrum_to_xyz(*named_spectrum(name)).y, 1.0f, 1e-6f) << name;
  EXPECT_EQ(named_spectrum("D65"), d65());
  EXPECT_TRUE(named_spectrum("E")->is_constant());
  EXPECT_NEAR(named_spectrum("E")->eval(400.0f), 1.0f, 1e-6f);
  EXPECT_FLOAT_EQ(named_spectrum("A")->eval(612.0f), illuminant_a()->eval(612.0f));
}

TEST(NamedSpectra, MatchingFunctions) {
  EXPECT_FLOAT_EQ(named_spectrum("cie_x")->eval(600.0f), cie_x(600.0f));
  EXPECT_FLOAT_EQ(named_spectrum("cie_y")->eval(555.5f), cie_y(555.5f));
  EXPECT_FLOAT_EQ(named_spectrum("cie_z")->eval(445.0f), cie_z(445.0f));
  EXPECT_NEAR(named_spectrum("cie_y")->max_value(), 1.0f, 1e-4f);
  EXPECT_EQ(named_spectrum("cie_z")->eval(900.0f), 0.0f);
}

TEST(NamedSpectra, UnknownNameListsTheKnownOnes) {
  try {
    named_spectrum("D50");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(
        std::string(e.what()),
        "unknown spectrum name 'D50' (known: D65, A, E, cie_x, cie_y, cie_z, metal-Au-eta, metal-Au-k, "
        "metal-Ag-eta, metal-Ag-k, metal-Cu-eta, metal-Cu-k, metal-Al-eta, metal-Al-k, metal-Si-eta, "
        "metal-Si-k, pigment-hematite-n, pigment-hematite-k, pigment-hematite_o-n, pigment-hematite_o-k, "
        "pigment-hematite_e-n, pigment-hematite_e-k, LED-4100K-model)");
  }
}

}  // namespace
}  // namespace ochre::named_spectra_test
