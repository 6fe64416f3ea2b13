// main() of the test executables: GoogleTest's, plus one line when every test the run selected was skipped,
// so that CTest can report a whole-suite run (tests/cmake/gtest_suites.cmake) as skipped rather than passed.

#include <gtest/gtest.h>

#include <cstdio>

namespace {

class AllSkippedMarker : public ::testing::EmptyTestEventListener {
  void OnTestProgramEnd(const ::testing::UnitTest& run) override {
    if (run.skipped_test_count() > 0 && run.successful_test_count() == 0 && run.failed_test_count() == 0)
      std::printf("ochre-tests: every selected test was skipped\n");
  }
};

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ::testing::UnitTest::GetInstance()->listeners().Append(new AllSkippedMarker);  // GoogleTest owns it
  return RUN_ALL_TESTS();
}
