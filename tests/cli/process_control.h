#pragma once
// Starting a tool in the background and waiting for it, for the tests that signal a running tool
// (signals_test.cpp, checkpoint_test.cpp).

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>

namespace ochre::test {

// Starts `TOOL ARGS` in dir (output discarded, progress off) and returns its pid.
pid_t start_tool(const std::filesystem::path& dir, const std::string& tool, const std::string& args);

// Waits for pid (killing it after a minute, which fails the test) and returns its wait status.
int wait_for(pid_t pid);

// Waits until `ready` holds or the process ends (a minute at most); true when `ready` held.
bool wait_until(pid_t pid, const std::function<bool()>& ready);

}  // namespace ochre::test
