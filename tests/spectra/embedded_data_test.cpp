// The tables embedded in the library: present, parsed, and equal to the project's shared data
// they were copied from.

#include "spectra/embedded_data.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "spectra/embedded_tables.h"
#include "support/test_paths.h"

namespace ochre::embedded_data_test {
namespace {

TEST(EmbeddedData, TablesAreEmbedded) {
  const auto& cie = embedded_table("cie1931_2deg_1nm.csv");
  EXPECT_EQ(cie.row_count(), 471u);
  EXPECT_EQ(cie.wavelengths().front(), 360.0);
  EXPECT_EQ(cie.wavelengths().back(), 830.0);
  const auto& d65 = embedded_table("d65_5nm.csv");
  EXPECT_EQ(d65.header(), (std::vector<std::string>{"wavelength_nm", "S"}));
  EXPECT_EQ(&d65, &embedded_table("d65_5nm.csv"));  // parsed once
  EXPECT_THROW(embedded_table("nope.csv"), std::runtime_error);
}

TEST(EmbeddedData, CopiesMatchSharedData) {
  OCHRE_REQUIRE_SHARED();
  for (const char* name : {"cie1931_2deg_1nm.csv", "d65_5nm.csv"}) {
    const auto shared = CsvTable::load(test::shared_dir() / "data" / "cie" / name);
    const auto& embedded = embedded_table(name);
    ASSERT_EQ(shared.column_count(), embedded.column_count()) << name;
    for (std::size_t c = 0; c < shared.column_count(); ++c)
      EXPECT_EQ(shared.column(c), embedded.column(c)) << name;
  }
}

}  // namespace
}  // namespace ochre::embedded_data_test
