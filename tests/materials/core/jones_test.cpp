// Jones matrices and their Mueller matrices: the conversion reproduces the Fresnel Mueller matrix and
// the frame rotator of mueller.h, so a chain computed in Jones form uses the renderer's conventions.

#include "materials/core/jones.h"

#include <gtest/gtest.h>

#include "materials/lobes/fresnel.h"
#include "materials/polarization_test_support.h"

namespace ochre::test::jones_test {
namespace {

TEST(Jones, DiagonalFresnelAmplitudesGiveTheFresnelMuellerMatrix) {
  for (double cos_i : {1.0, 0.8, 0.3, 0.05}) {
    const FresnelAmplitudes<double> a = fresnel_amplitudes(cos_i, std::complex<double>(0.27, -2.78));
    const Mueller want = fresnel_reflection_mueller(std::complex<float>(a.r_s), std::complex<float>(a.r_p));
    expect_mueller(jones_to_mueller(Jones::diagonal(a.r_s, a.r_p)), want, 1e-6f);
  }
}

TEST(Jones, FrameRotationGivesTheRotator) {
  for (double theta : {0.0, 0.3, -1.1, 2.5})
    expect_mueller(jones_to_mueller(Jones::frame_rotation(theta)), rotator(static_cast<float>(theta)), 1e-6f);
}

TEST(Jones, ProductMapsToTheProductOfMuellerMatrices) {
  const Jones p{{0.3, 0.1}, {-0.2, 0.4}, {0.05, -0.6}, {0.7, 0.2}};
  const Jones q = Jones::diagonal({-0.9, 0.1}, {0.8, -0.3}) * Jones::frame_rotation(0.7);
  expect_mueller(jones_to_mueller(p * q), jones_to_mueller(p) * jones_to_mueller(q), 1e-6f);
  EXPECT_NEAR(unpolarized_gain(p * q), jones_to_mueller(p * q)(0, 0), 1e-7);
}

}  // namespace
}  // namespace ochre::test::jones_test
