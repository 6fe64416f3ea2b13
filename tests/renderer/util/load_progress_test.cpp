// LoadProgress: silent for quick steps and when not enabled; plain progress lines once a step is slow.

#include "renderer/util/load_progress.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <sstream>
#include <thread>

namespace ochre::load_progress_test {
namespace {

struct PlainProgress {
  PlainProgress() { ::setenv("OCHRE_PROGRESS", "plain", 1); }
  ~PlainProgress() {
    ::unsetenv("OCHRE_PROGRESS");
    enable_load_progress(nullptr);
  }
};

TEST(LoadProgress, QuickStepsAndDisabledProgressPrintNothing) {
  const PlainProgress plain;
  std::ostringstream out;
  enable_load_progress(&out);
  {
    LoadProgress progress("loading quick.obj");
    progress.update(0.5);
    progress.update(1.0);
  }
  enable_load_progress(nullptr);
  {
    LoadProgress progress("loading slow.obj");
    std::this_thread::sleep_for(kLoadProgressDelay + std::chrono::milliseconds(100));
    progress.update(0.5);
  }
  EXPECT_EQ(out.str(), "");
}

TEST(LoadProgress, SlowStepPrintsLinesWithTheElapsedTimeSinceItBegan) {
  const PlainProgress plain;
  std::ostringstream out;
  enable_load_progress(&out);
  {
    LoadProgress progress("loading big.obj");
    progress.update(0.1);
    std::this_thread::sleep_for(kLoadProgressDelay + std::chrono::milliseconds(100));
    progress.update(0.45);
  }
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("loading big.obj: 45% (elapsed 2.", 0), 0u) << text;
  EXPECT_NE(text.find("\nloading big.obj: 100% (elapsed 2."), std::string::npos) << text;
}

}  // namespace
}  // namespace ochre::load_progress_test
