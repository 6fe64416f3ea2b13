#pragma once
// Paths the tests need: the source tree, the optional external assets folder, the built tools, scratch
// space.

#include <filesystem>
#include <string>

namespace ochre::test {

std::filesystem::path source_dir();
// The optional external assets folder (OCHRE_SHARED_DIR, default ../shared; docs/validation.md), or
// empty when it is absent (tests that need it skip).
std::filesystem::path shared_dir();
std::filesystem::path bin_dir();
// A fresh, empty scratch directory unique to the calling test.
std::filesystem::path scratch_dir();

}  // namespace ochre::test

// Skips the current test when the external assets folder is not present.
#define OCHRE_REQUIRE_SHARED()                                                                               \
  do {                                                                                                       \
    if (::ochre::test::shared_dir().empty()) GTEST_SKIP() << "no external assets folder (OCHRE_SHARED_DIR)"; \
  } while (0)
