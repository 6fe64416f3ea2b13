#include "renderer/util/output_transaction.h"

#include <unistd.h>

#include <optional>
#include <system_error>

#include "renderer/util/signal_cleanup.h"

namespace ochre {

namespace fs = std::filesystem;

namespace {

// A hard link to the file an output is about to replace, so that the file can be put back.
class Backup {
 public:
  explicit Backup(const fs::path& original) : original_(original) {
    std::error_code error;
    if (!fs::is_regular_file(fs::symlink_status(original, error))) return;  // nothing to keep
    existed_ = true;
    path_ = temporary_name(original);
    registration_.emplace(*path_);
    if (::link(original.c_str(), path_->c_str()) != 0) path_.reset();  // no hard links here: no backup
  }
  ~Backup() {
    if (path_) (void)::unlink(path_->c_str());
  }
  Backup(const Backup&) = delete;
  Backup& operator=(const Backup&) = delete;

  // Puts the original back after its output replaced it (or removes the output when there was none).
  void restore() {
    if (!existed_) {
      (void)::unlink(original_.c_str());
    } else if (path_ && ::rename(path_->c_str(), original_.c_str()) == 0) {
      path_.reset();
    }
  }

 private:
  fs::path original_;
  bool existed_ = false;
  std::optional<fs::path> path_;
  std::optional<TemporaryFileRegistration> registration_;
};

}  // namespace

AtomicOutput& OutputTransaction::add(const fs::path& final_path) {
  return add(std::make_unique<AtomicOutput>(final_path));
}

AtomicOutput& OutputTransaction::add(std::unique_ptr<AtomicOutput> output) {
  outputs_.push_back(std::move(output));
  return *outputs_.back();
}

void OutputTransaction::commit() {
  const SignalDeferral hold_signals;
  for (const auto& output : outputs_) output->check_written();
  std::vector<std::unique_ptr<Backup>> backups;
  for (const auto& output : outputs_) backups.push_back(std::make_unique<Backup>(output->final_path()));
  for (size_t i = 0; i < outputs_.size(); ++i) {
    try {
      outputs_[i]->commit();
    } catch (...) {
      for (size_t k = i; k-- > 0;) backups[k]->restore();
      throw;
    }
  }
}

}  // namespace ochre
