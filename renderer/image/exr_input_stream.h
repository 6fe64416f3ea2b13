#pragma once
// OpenEXR's view of a checked input file (spectra/input_file.h): the library reads through the descriptor
// and never opens the path. Include only in .cpp files (it brings in OpenEXR headers).

#include <OpenEXR/ImfIO.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "spectra/input_file.h"

namespace ochre {

class InputFileIStream final : public Imf::IStream {
 public:
  explicit InputFileIStream(InputFile& file) : Imf::IStream(file.path().c_str()), file_(file) {}
  bool read(char c[], int n) override {
    size_t done = 0;
    while (done < static_cast<size_t>(n)) {
      const ssize_t got =
          ::pread(file_.fd(), c + done, static_cast<size_t>(n) - done, static_cast<off_t>(position_ + done));
      if (got < 0 && errno == EINTR) continue;
      if (got < 0) throw std::runtime_error(std::strerror(errno));
      if (got == 0) throw std::runtime_error("unexpected end of file");
      done += static_cast<size_t>(got);
    }
    position_ += done;
    return position_ < file_.size();
  }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t position) override { position_ = position; }

 private:
  InputFile& file_;
  uint64_t position_ = 0;
};

}  // namespace ochre
