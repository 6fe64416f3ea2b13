// The CIE 1994 colour difference (spectra/cie94.h) against values worked by hand from its definition
// (CIE 116-1995; graphic-arts constants kL = kC = kH = 1, K1 = 0.045, K2 = 0.015). The working is in
// the comments so each expected value can be checked with a pocket calculator.
#include "spectra/cie94.h"

#include <gtest/gtest.h>

namespace ochre::cie94_test {
namespace {

TEST(Cie94, PureLightnessDifferenceIsDeltaL) {
  // SL = 1 whatever the chroma.
  EXPECT_NEAR(cie94({40, 10, -20}, {47.5, 10, -20}), 7.5, 1e-12);
  EXPECT_NEAR(cie94({40, 0, 0}, {30, 0, 0}), 10.0, 1e-12);
  EXPECT_EQ(cie94({40, 10, -20}, {40, 10, -20}), 0.0);
}

TEST(Cie94, PureChromaDifference) {
  // Reference (50, 10, 0): C*ref = 10, SC = 1 + 0.045 * 10 = 1.45; dC = 10, dH = 0: dE = 10 / 1.45.
  EXPECT_NEAR(cie94({50, 10, 0}, {50, 20, 0}), 6.8965517, 1e-6);
}

TEST(Cie94, PureHueDifference) {
  // Reference (50, 30, 0), sample (50, 0, 30): dC = 0, dH^2 = 30^2 + 30^2 = 1800,
  // SH = 1 + 0.015 * 30 = 1.45: dE = sqrt(1800) / 1.45 = 29.2595909.
  EXPECT_NEAR(cie94({50, 30, 0}, {50, 0, 30}), 29.2595909, 1e-6);
}

TEST(Cie94, AllThreeTermsAndTheReferenceSetsTheWeights) {
  // Reference (60, -20, 40), sample (55, -10, 35): C*ref = sqrt(2000) = 44.72136, C* = sqrt(1325) =
  // 36.40055, dC = -8.32081; da = 10, db = -5, dH^2 = 125 - 69.23588 = 55.76412; SC = 3.012461,
  // SH = 1.670820; dE^2 = 25 + 7.62936 + 19.97539 = 52.60476: dE = 7.252914.
  EXPECT_NEAR(cie94({60, -20, 40}, {55, -10, 35}), 7.252914, 2e-6);
  // The first pair of Sharma, Wu, Dalal 2005 (Table 1): C*ref = 79.82002, SC = 4.591901, SH = 2.197300,
  // dC = 2.92849, dH^2 = 16.00851 - 8.57605 = 7.43245: dE = sqrt(0.40673 + 1.53941) = 1.395039. Swapped,
  // the reference chroma is 82.7485: dE = 1.365285.
  const Lab first{50.0, 2.6772, -79.7751}, second{50.0, 0.0, -82.7485};
  EXPECT_NEAR(cie94(first, second), 1.395039, 2e-6);
  EXPECT_NEAR(cie94(second, first), 1.365285, 2e-6);
}

TEST(Cie94, TextileConstants) {
  // kL = 2, K1 = 0.048, K2 = 0.014: a pure lightness difference is halved; a pure chroma difference at
  // C*ref = 10 is divided by 1.48.
  const Cie94Weights textiles{2.0, 1.0, 1.0, 0.048, 0.014};
  EXPECT_NEAR(cie94({40, 0, 0}, {50, 0, 0}, textiles), 5.0, 1e-12);
  EXPECT_NEAR(cie94({50, 10, 0}, {50, 20, 0}, textiles), 10.0 / 1.48, 1e-12);
}

}  // namespace
}  // namespace ochre::cie94_test
