// Byte counts in messages and --memory-limit sizes (spectra/byte_size.h).

#include "spectra/byte_size.h"

#include <gtest/gtest.h>

namespace ochre::byte_size_test {
namespace {

TEST(ByteSize, FormatsWithBinaryUnits) {
  EXPECT_EQ(format_bytes(0), "0 bytes");
  EXPECT_EQ(format_bytes(1), "1 byte");
  EXPECT_EQ(format_bytes(1023), "1023 bytes");
  EXPECT_EQ(format_bytes(1024), "1 KiB");
  EXPECT_EQ(format_bytes(1536), "1.5 KiB");
  EXPECT_EQ(format_bytes(256 * kMiB), "256 MiB");
  EXPECT_EQ(format_bytes(3 * kGiB + kGiB / 5), "3.2 GiB");
  EXPECT_EQ(format_bytes(412 * kGiB + kGiB / 3), "412 GiB");  // no decimal from 100 up
  EXPECT_EQ(format_bytes(2 * kTiB), "2 TiB");
}

TEST(ByteSize, ParsesSizesWithOptionalBinaryUnits) {
  EXPECT_EQ(parse_byte_size("1048576"), 1048576u);
  EXPECT_EQ(parse_byte_size("64k"), 64 * kKiB);
  EXPECT_EQ(parse_byte_size("512M"), 512 * kMiB);
  EXPECT_EQ(parse_byte_size("8G"), 8 * kGiB);
  EXPECT_EQ(parse_byte_size("8GiB"), 8 * kGiB);
  EXPECT_EQ(parse_byte_size("8gb"), 8 * kGiB);
  EXPECT_EQ(parse_byte_size("1.5G"), 3 * kGiB / 2);
  EXPECT_EQ(parse_byte_size("2T"), 2 * kTiB);
  EXPECT_EQ(parse_byte_size("100B"), 100u);
}

TEST(ByteSize, RefusesMalformedZeroAndHugeSizes) {
  for (const char* text : {"", "0", "0G", "-1G", "G", "1Q", "8 G", "8GiBs", "nan", "inf", "1e30T", "0.0001"})
    EXPECT_FALSE(parse_byte_size(text).has_value()) << text;
}

}  // namespace
}  // namespace ochre::byte_size_test
