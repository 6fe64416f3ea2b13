#include "support/test_paths.h"

#include <gtest/gtest.h>

namespace ochre::test {

std::filesystem::path source_dir() {
  return OCHRE_SOURCE_DIR;
}

std::filesystem::path shared_dir() {
  const std::filesystem::path p = OCHRE_SHARED_DIR;
  return std::filesystem::is_directory(p / "assets") ? std::filesystem::canonical(p)
                                                     : std::filesystem::path();
}

std::filesystem::path bin_dir() {
  return OCHRE_BIN_DIR;
}

std::filesystem::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir =
      std::filesystem::path(OCHRE_TEST_TMP_DIR) / (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace ochre::test
