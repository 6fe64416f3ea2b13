// parse_duration: the DURATION values of --checkpoint-interval and --time-limit (docs/cli.md).
#include "tools/cli/duration.h"

#include <gtest/gtest.h>

namespace ochre::duration_test {
namespace {

TEST(Duration, ParsesSecondsMinutesHoursAndCombinations) {
  EXPECT_EQ(parse_duration("90"), 90.0);
  EXPECT_EQ(parse_duration("90s"), 90.0);
  EXPECT_EQ(parse_duration("0.5"), 0.5);
  EXPECT_EQ(parse_duration("10m"), 600.0);
  EXPECT_EQ(parse_duration("1.5h"), 5400.0);
  EXPECT_EQ(parse_duration("1h30m"), 5400.0);
  EXPECT_EQ(parse_duration("2h0m5s"), 7205.0);
  for (const char* bad : {"", "0", "0s", "-5", "5x", "m", "1m2h", "1h1h", "1h30", "1e3", "0x10", " 5", "5 ",
                          "inf", "nan", "400d", "9000h"})
    EXPECT_FALSE(parse_duration(bad)) << bad;
}

}  // namespace
}  // namespace ochre::duration_test
