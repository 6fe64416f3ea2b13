// message_excerpt: how every program prints an error (tools/cli/program.h). A file may put a 50 MB value
// into a message; a person reads its beginning, its end and how much was left out.
#include "spectra/input_error.h"

#include <gtest/gtest.h>

#include <string>

namespace ochre::input_error_test {
namespace {

TEST(MessageExcerpt, ShortMessagesAreUnchanged) {
  const std::string message = "scene.json: materials.m.nodes.n: unknown type 'x'";
  EXPECT_EQ(message_excerpt(message), message);
  EXPECT_EQ(message_excerpt(std::string(4096, 'a')), std::string(4096, 'a'));
}

TEST(MessageExcerpt, LongMessagesKeepTheirEndsAndCountWhatWasLeftOut) {
  const std::string message = "scene.json: unknown type '" + std::string(50'000'000, 'x') + "' (known: a, b)";
  const std::string excerpt = message_excerpt(message);
  EXPECT_LT(excerpt.size(), 4200u);
  EXPECT_EQ(excerpt.rfind("scene.json: unknown type 'xxx", 0), 0u);
  EXPECT_TRUE(excerpt.ends_with("' (known: a, b)"));
  const size_t left_out = message.size() - 4096 * 3 / 4 - 4096 / 8;
  EXPECT_NE(excerpt.find("[... " + std::to_string(left_out) + " characters left out ...]"),
            std::string::npos);
}

TEST(InputError, ANulCharacterIsWrittenOutNotCutShort) {
  // A name from a scene or an argument may hold a NUL; what() is read as a C string.
  const InputError e(std::string("materials: no material '") + '\0' + "x' (known: rock)");
  EXPECT_EQ(std::string(e.what()), "materials: no material '\\0x' (known: rock)");
  EXPECT_EQ(visible_nul(std::string(2, '\0')), "\\0\\0");
  EXPECT_EQ(std::string(InputError("plain").what()), "plain");
}

}  // namespace
}  // namespace ochre::input_error_test
