// Optical constants of Au, Ag, Cu, Al, Si carried into spectra/data and registered as named spectra
// ("metal-Au-eta", "metal-Au-k", ...): equal to the refractiveindex.info tables of the optional external
// assets folder when it is present (docs/validation.md), and physically plausible.

#include <gtest/gtest.h>

#include <cstdio>

#include "spectra/embedded_tables.h"
#include "spectra/named_spectra.h"
#include "support/test_paths.h"

namespace ochre::metal_spectra_test {
namespace {

constexpr const char* kMetals[] = {"Au", "Ag", "Cu", "Al", "Si"};

// Normal-incidence reflectance of the index n + i k (Born & Wolf 14.2.16), computed here
// independently of materials/lobes/fresnel.h.
double normal_reflectance(double n, double k) {
  return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
}

double reflectance(const std::string& metal, float lambda) {
  return normal_reflectance(named_spectrum("metal-" + metal + "-eta")->eval(lambda),
                            named_spectrum("metal-" + metal + "-k")->eval(lambda));
}

TEST(MetalSpectra, GoldAt550nmMatchesItsSourceHeader) {
  // The CSV header: n(550 nm) = 0.3239, k(550 nm) = 2.5972.
  EXPECT_NEAR(named_spectrum("metal-Au-eta")->eval(550.0f), 0.3239f, 1e-4f);
  EXPECT_NEAR(named_spectrum("metal-Au-k")->eval(550.0f), 2.5972f, 1e-4f);
  // Silicon, the V-groove note's values: n = 4.073, k = 0.028.
  EXPECT_NEAR(named_spectrum("metal-Si-eta")->eval(550.0f), 4.073f, 1e-3f);
  EXPECT_NEAR(named_spectrum("metal-Si-k")->eval(550.0f), 0.028f, 1e-3f);
  // Between grid points the value is linear in wavelength.
  const auto n = named_spectrum("metal-Cu-eta");
  EXPECT_NEAR(n->eval(552.5f), 0.5f * (n->eval(550.0f) + n->eval(555.0f)), 1e-6f);
}

TEST(MetalSpectra, EmbeddedCopiesMatchSharedData) {
  OCHRE_REQUIRE_SHARED();
  for (const char* metal : kMetals) {
    const auto shared =
        CsvTable::load(test::shared_dir() / "data" / "ior" / (std::string(metal) + "_5nm.csv"));
    const CsvTable& embedded = embedded_table("ior_" + std::string(metal) + "_5nm.csv");
    ASSERT_EQ(shared.column_count(), embedded.column_count()) << metal;
    for (std::size_t c = 0; c < shared.column_count(); ++c)
      EXPECT_EQ(shared.column(c), embedded.column(c)) << metal;
    // The named spectra are those columns.
    for (std::size_t row = 0; row < shared.row_count(); row += 7) {
      const float lambda = float(shared.wavelengths()[row]);
      EXPECT_FLOAT_EQ(named_spectrum("metal-" + std::string(metal) + "-eta")->eval(lambda),
                      float(shared.column("n")[row]));
      EXPECT_FLOAT_EQ(named_spectrum("metal-" + std::string(metal) + "-k")->eval(lambda),
                      float(shared.column("k")[row]));
    }
  }
}

TEST(MetalSpectra, CoverTheVisibleRangeWithPhysicalValues) {
  for (const char* metal : kMetals)
    for (const char* part : {"-eta", "-k"}) {
      const auto s = named_spectrum("metal-" + std::string(metal) + part);
      for (float lambda = 360.0f; lambda <= 830.0f; lambda += 1.0f) {
        EXPECT_GT(s->eval(lambda), 0.0f) << metal << part << " " << lambda;
        EXPECT_LT(s->eval(lambda), 10.0f) << metal << part << " " << lambda;
      }
    }
}

TEST(MetalSpectra, SilverIsAHighReflector) {
  // This dataset (Ferrera 2019, 298 K) reaches 0.95 only above ~460 nm (0.934 at 400 nm, 0.882 at
  // 360 nm): silver's reflectance falls towards its plasma edge near 320 nm.
  for (float lambda = 470.0f; lambda <= 830.0f; lambda += 5.0f)
    EXPECT_GT(reflectance("Ag", lambda), 0.95) << lambda;
  for (float lambda = 400.0f; lambda <= 830.0f; lambda += 5.0f)
    EXPECT_GT(reflectance("Ag", lambda), 0.93) << lambda;
  for (float lambda : {360.0f, 400.0f, 450.0f, 500.0f, 550.0f, 650.0f})
    std::printf("R_Ag(%g nm) = %.4f\n", lambda, reflectance("Ag", lambda));
}

TEST(MetalSpectra, GoldAndCopperAreRedderThanTheyAreBlue) {
  for (const char* metal : {"Au", "Cu"}) {
    const double red = reflectance(metal, 650.0f), green = reflectance(metal, 550.0f),
                 blue = reflectance(metal, 450.0f);
    EXPECT_GT(red, green) << metal;
    EXPECT_GT(green, blue) << metal;
    std::printf("%s: R(450) = %.4f, R(550) = %.4f, R(650) = %.4f\n", metal, blue, green, red);
  }
  // Aluminium is nearly flat and bright, silicon a dull ~0.35-0.5.
  EXPECT_GT(reflectance("Al", 550.0f), 0.9);
  EXPECT_NEAR(reflectance("Si", 550.0f), 0.367, 0.01);
}

}  // namespace
}  // namespace ochre::metal_spectra_test
