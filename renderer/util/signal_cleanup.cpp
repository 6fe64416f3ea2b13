#include "renderer/util/signal_cleanup.h"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace ochre {

namespace {

constexpr int kSlots = 64;
constexpr int kHandledSignals[] = {SIGINT, SIGTERM, SIGHUP};

enum SlotState : int { kFree = 0, kClaimed = 1, kReady = 2 };

// Fixed storage: the handler reads paths without allocating. A slot's path is written while it is
// kClaimed and read by the handler only once it is kReady.
struct Slot {
  std::atomic<int> state{kFree};
  bool directory = false;
  char path[PATH_MAX];
};
std::array<Slot, kSlots> slots;

std::atomic<int> deferrals{0};
std::atomic<int> pending_signal{0};
std::atomic<bool> graceful_active{false};
std::atomic<int> graceful_signal{0};

static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");

// Unlinks every entry of a directory holding only files, then the directory, with system calls only
// (getdents64 is the system call opendir and readdir use, without their allocation). Entries are read
// again from the start until none is left, since unlinking while reading may skip some.
void remove_scratch_directory(const char* path) {
  const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  alignas(struct dirent64) char buffer[4096];
  for (int pass = 0; pass < 1000; ++pass) {
    bool removed = false;
    ::lseek(fd, 0, SEEK_SET);
    for (ssize_t n; (n = ::getdents64(fd, buffer, sizeof buffer)) > 0;) {
      for (ssize_t offset = 0; offset < n;) {
        const auto* entry = reinterpret_cast<const struct dirent64*>(buffer + offset);
        offset += entry->d_reclen;
        const char* name = entry->d_name;
        if (name[0] == '.' && (name[1] == '\0' || (name[1] == '.' && name[2] == '\0'))) continue;
        removed |= ::unlinkat(fd, name, 0) == 0;
      }
    }
    if (!removed) break;
  }
  ::close(fd);
  ::rmdir(path);
}

void remove_temporaries_and_reraise(int signal_number) {
  for (Slot& slot : slots)
    if (slot.state.load(std::memory_order_acquire) == kReady && !slot.directory) ::unlink(slot.path);
  for (Slot& slot : slots)
    if (slot.state.load(std::memory_order_acquire) == kReady && slot.directory)
      remove_scratch_directory(slot.path);
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  sigemptyset(&default_action.sa_mask);
  ::sigaction(signal_number, &default_action, nullptr);
  ::raise(signal_number);
}

extern "C" void on_signal(int signal_number) {
  const int saved_errno = errno;
  // A graceful stop records the first signal only; the render acts on it at its next pass boundary.
  int none = 0;
  if (graceful_active.load() && graceful_signal.compare_exchange_strong(none, signal_number)) {
    errno = saved_errno;
    return;
  }
  // Pending first, then the check: a deferral ending concurrently then sees the signal (and acts on it).
  pending_signal.store(signal_number);
  if (deferrals.load() > 0) {
    errno = saved_errno;
    return;
  }
  remove_temporaries_and_reraise(signal_number);
  errno = saved_errno;
}

}  // namespace

void install_signal_cleanup() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int signal_number : kHandledSignals) {
      struct sigaction previous {};
      if (::sigaction(signal_number, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
      struct sigaction action {};
      action.sa_handler = on_signal;
      sigemptyset(&action.sa_mask);
      for (int other : kHandledSignals) sigaddset(&action.sa_mask, other);
      ::sigaction(signal_number, &action, nullptr);
    }
  });
}

TemporaryFileRegistration::TemporaryFileRegistration(const std::filesystem::path& path, TemporaryKind kind) {
  std::error_code error;
  const std::string absolute = std::filesystem::absolute(path, error).string();
  if (error || absolute.size() >= PATH_MAX) return;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kClaimed)) continue;
    std::memcpy(slots[i].path, absolute.c_str(), absolute.size() + 1);
    slots[i].directory = kind == TemporaryKind::kDirectory;
    slots[i].state.store(kReady, std::memory_order_release);
    slot_ = i;
    return;
  }
}

TemporaryFileRegistration::~TemporaryFileRegistration() {
  release();
}

void TemporaryFileRegistration::release() {
  if (slot_ < 0) return;
  slots[slot_].state.store(kFree, std::memory_order_release);
  slot_ = -1;
}

GracefulStop::GracefulStop() {
  graceful_signal.store(0);
  graceful_active.store(true);
}

GracefulStop::~GracefulStop() {
  graceful_active.store(false);
}

int GracefulStop::requested_signal() {
  return graceful_signal.load();
}

void GracefulStop::end_by_signal() {
  graceful_active.store(false);
  remove_temporaries_and_reraise(graceful_signal.load());
  std::abort();  // not reached: the signal's default action ends the process
}

SignalDeferral::SignalDeferral() {
  deferrals.fetch_add(1);
}

SignalDeferral::~SignalDeferral() {
  if (deferrals.fetch_sub(1) != 1) return;
  if (const int signal_number = pending_signal.exchange(0); signal_number != 0)
    remove_temporaries_and_reraise(signal_number);
}

}  // namespace ochre
