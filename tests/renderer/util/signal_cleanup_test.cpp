// Signal cleanup (renderer/util/signal_cleanup.h): a process ended by SIGINT or SIGTERM leaves no temporary
// output behind, still ends by that signal, and a signal during the renames of an OutputTransaction
// waits until the set is complete. Each case runs in a forked child.

#include "renderer/util/signal_cleanup.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>

#include "renderer/util/atomic_file.h"
#include "renderer/util/output_transaction.h"
#include "support/test_paths.h"

namespace ochre::signal_cleanup_test {
namespace {

namespace fs = std::filesystem;

// Runs `child` in a forked process and returns its wait status.
template <class F>
int run_in_child(F&& child) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    child();
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

size_t entry_count(const fs::path& dir) {
  return static_cast<size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

void expect_temporary_removed_on(int signal_number) {
  const fs::path dir = test::scratch_dir();
  std::ofstream(dir / "out.exr") << "old";
  const int status = run_in_child([&] {
    install_signal_cleanup();
    AtomicOutput output(dir / "out.exr");
    std::ofstream(output.temp_path()) << "half-written";
    ::raise(signal_number);
    ::_exit(3);  // not reached
  });
  ASSERT_TRUE(WIFSIGNALED(status)) << "the child must end by the signal, status " << status;
  EXPECT_EQ(WTERMSIG(status), signal_number);
  EXPECT_EQ(entry_count(dir), 1u) << "the temporary is removed";
  std::ifstream in(dir / "out.exr");
  std::string content;
  in >> content;
  EXPECT_EQ(content, "old");
}

TEST(SignalCleanup, SigintRemovesTemporariesAndEndsTheProcessBySigint) {
  expect_temporary_removed_on(SIGINT);
}

TEST(SignalCleanup, SigtermRemovesTemporariesAndEndsTheProcessBySigterm) {
  expect_temporary_removed_on(SIGTERM);
}

// A scratch directory (the panels of ochre-vgroove's grids) is emptied and removed; a temporary file
// registered inside it after the directory goes too, and the user's files beside it stay.
TEST(SignalCleanup, ScratchDirectoryIsEmptiedAndRemoved) {
  const fs::path dir = test::scratch_dir();
  std::ofstream(dir / "keep.png") << "the user's";
  const int status = run_in_child([&] {
    install_signal_cleanup();
    const fs::path scratch = dir / "grid.png.panels.tmp-1";
    fs::create_directory(scratch);
    const TemporaryFileRegistration registration(scratch, TemporaryKind::kDirectory);
    for (int i = 0; i < 300; ++i)  // more entries than one read of the directory returns
      std::ofstream(scratch / ("colour_with_a_long_name_to_fill_the_buffer_" + std::to_string(i) + ".png"))
          << i;
    AtomicOutput panel(scratch / "panels.csv");
    std::ofstream(panel.temp_path()) << "half-written";
    ::raise(SIGTERM);
    ::_exit(3);  // not reached
  });
  ASSERT_TRUE(WIFSIGNALED(status)) << status;
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_FALSE(fs::exists(dir / "grid.png.panels.tmp-1"));
  EXPECT_EQ(entry_count(dir), 1u);
  EXPECT_TRUE(fs::exists(dir / "keep.png"));
}

TEST(SignalCleanup, SignalDuringTheRenamesActsWhenTheSetIsComplete) {
  const fs::path dir = test::scratch_dir();
  const int status = run_in_child([&] {
    install_signal_cleanup();
    OutputTransaction outputs;
    std::ofstream(outputs.add(dir / "a.txt").temp_path()) << "a";
    std::ofstream(outputs.add(dir / "b.txt").temp_path()) << "b";
    {
      const SignalDeferral held;  // as commit() holds them; nested deferrals are allowed
      ::raise(SIGTERM);
      outputs.commit();
    }
    ::_exit(3);  // not reached: the deferred signal acts when the deferral ends
  });
  ASSERT_TRUE(WIFSIGNALED(status)) << status;
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_TRUE(fs::exists(dir / "a.txt"));
  EXPECT_TRUE(fs::exists(dir / "b.txt"));
  EXPECT_EQ(entry_count(dir), 2u);
}

TEST(SignalCleanup, ReleasedRegistrationIsNotRemoved) {
  const fs::path dir = test::scratch_dir();
  const int status = run_in_child([&] {
    install_signal_cleanup();
    AtomicOutput output(dir / "out.txt");
    std::ofstream(output.temp_path()) << "complete";
    output.commit();
    ::raise(SIGINT);
  });
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_TRUE(fs::exists(dir / "out.txt")) << "a committed output is the user's file";
}

}  // namespace
}  // namespace ochre::signal_cleanup_test
