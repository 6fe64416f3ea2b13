#include "cli/process_control.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <thread>

#include "support/test_paths.h"

namespace ochre::test {

using Clock = std::chrono::steady_clock;

pid_t start_tool(const std::filesystem::path& dir, const std::string& tool, const std::string& args) {
  const std::string command = "exec '" + (bin_dir() / tool).string() + "' " + args + " >/dev/null 2>&1";
  const pid_t pid = ::fork();
  if (pid == 0) {
    // A shell running the suite as a background job (or under nohup) ignores SIGINT / SIGHUP, and an
    // ignored disposition survives exec: the tool would then rightly leave them ignored, and the tests that
    // signal it would see it finish instead. The tool starts here as from an interactive shell.
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) ::signal(signal_number, SIG_DFL);
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    ::setenv("OCHRE_PROGRESS", "none", 1);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

int wait_for(pid_t pid) {
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (Clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      ADD_FAILURE() << "the tool did not end within a minute";
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return status;
}

bool wait_until(pid_t pid, const std::function<bool()>& ready) {
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  while (!ready() && Clock::now() < deadline && ::waitpid(pid, nullptr, WNOHANG) == 0)
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  return ready();
}

}  // namespace ochre::test
