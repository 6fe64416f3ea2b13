#pragma once
// Temporary output files removed on SIGINT, SIGTERM and SIGHUP (docs/cli.md, "Signals").
//
// Outputs are written under temporary names and renamed when complete (renderer/util/atomic_file.h). A
// signal that ends the process in between would leave those temporaries behind; with
// install_signal_cleanup() the handler unlinks every registered temporary, then restores the default
// action and raises the signal again, so the process still ends by the signal (a shell reports 130
// for SIGINT, 143 for SIGTERM) and the existing outputs are untouched.
//
// The handler uses only async-signal-safe calls (unlink, sigaction, raise; for a scratch directory open,
// getdents64, unlinkat, rmdir) on a fixed table of paths written before registration, never memory
// allocation or locks.

#include <filesystem>

namespace ochre {

// Installs the handler for SIGINT, SIGTERM and SIGHUP (once; later calls do nothing). Signals that
// were ignored when the process started (e.g. SIGHUP under nohup) stay ignored.
void install_signal_cleanup();

enum class TemporaryKind {
  kFile,
  kDirectory,  // a scratch directory of files only (no subdirectories): emptied, then removed
};

// Registers a temporary file (or scratch directory) for removal by the handler while the object lives.
// The handler removes files before directories. Registration is best effort: beyond the table's
// capacity (64 paths) or for a path longer than PATH_MAX the file is not removed on a signal (it still
// is on every normal exit path, by its owner).
class TemporaryFileRegistration {
 public:
  explicit TemporaryFileRegistration(const std::filesystem::path& path,
                                     TemporaryKind kind = TemporaryKind::kFile);
  ~TemporaryFileRegistration();
  TemporaryFileRegistration(const TemporaryFileRegistration&) = delete;
  TemporaryFileRegistration& operator=(const TemporaryFileRegistration&) = delete;
  // Stops the registration early (the file was renamed or removed).
  void release();

 private:
  int slot_ = -1;
};

// While a GracefulStop lives, the first SIGINT, SIGTERM or SIGHUP does not end the process: it is recorded,
// so that a render can stop at its next pass boundary, write a checkpoint and then end by the signal
// (end_by_signal). A second signal ends the process at once, as without it (temporaries removed). One
// GracefulStop at a time.
class GracefulStop {
 public:
  GracefulStop();
  ~GracefulStop();
  GracefulStop(const GracefulStop&) = delete;
  GracefulStop& operator=(const GracefulStop&) = delete;
  // The signal recorded, 0 while none arrived (async-signal-safe, any thread).
  static int requested_signal();
  // Removes the registered temporaries and ends the process by the recorded signal.
  [[noreturn]] void end_by_signal();
};

// Holds back the handled signals while several renames must all happen (renderer/util/output_transaction.h):
// a signal arriving meanwhile is acted on when the last SignalDeferral ends.
class SignalDeferral {
 public:
  SignalDeferral();
  ~SignalDeferral();
  SignalDeferral(const SignalDeferral&) = delete;
  SignalDeferral& operator=(const SignalDeferral&) = delete;
};

}  // namespace ochre
