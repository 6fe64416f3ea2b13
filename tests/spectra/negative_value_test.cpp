// first_negative_value: a table's first negative entry (also when scaled), else the first whole nm of the
// rendered range where a spectrum is negative.
#include "spectra/negative_value.h"

#include <gtest/gtest.h>

#include "spectra/constant_spectrum.h"
#include "spectra/named_spectra.h"
#include "spectra/scaled_spectrum.h"
#include "spectra/tabulated_spectrum.h"

namespace ochre::negative_value_test {
namespace {

TEST(FirstNegativeValue, TableEntryEvenWhereInterpolationStaysPositive) {
  // 300 nm lies outside the rendered range: the table is still wrong there.
  const auto table = std::make_shared<TabulatedSpectrum>(std::vector<float>{300, 400, 550, 700},
                                                         std::vector<float>{-0.1f, 1, -0.2f, 1});
  const auto v = first_negative_value(*table);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->lambda_nm, 300.0f);
  EXPECT_EQ(v->value, -0.1f);
  const auto scaled = first_negative_value(ScaledSpectrum(table, 10.0f));
  ASSERT_TRUE(scaled);
  EXPECT_EQ(scaled->lambda_nm, 300.0f);
  EXPECT_EQ(scaled->value, -0.1f);  // the entry as written in the table
}

TEST(FirstNegativeValue, NoneForNonNegativeSpectra) {
  EXPECT_FALSE(first_negative_value(ConstantSpectrum(0.0f)));
  EXPECT_FALSE(first_negative_value(*named_spectrum("D65")));
  EXPECT_FALSE(first_negative_value(TabulatedSpectrum({400, 700}, {0, 1})));
}

TEST(FirstNegativeValue, AnalyticSpectrumAtTheFirstWholeNanometre) {
  const auto v = first_negative_value(ConstantSpectrum(-2.0f));
  ASSERT_TRUE(v);
  EXPECT_EQ(v->lambda_nm, 360.0f);
  EXPECT_EQ(v->value, -2.0f);
  const auto negated = first_negative_value(ScaledSpectrum(named_spectrum("D65"), -1.0f));
  ASSERT_TRUE(negated);
  EXPECT_EQ(negated->lambda_nm, 360.0f);
}

}  // namespace
}  // namespace ochre::negative_value_test
