#pragma once
// The exception thrown by image output and input (EXR, PNG, OCIO, atomic files). Its message always
// names the file (or the OCIO config) at fault, so a caller can print it as is and exit.

#include <stdexcept>
#include <string>

#include "spectra/input_error.h"

namespace ochre {

class ImageError : public std::runtime_error {
 public:
  // A NUL in a file name is written \0 (visible_nul): what() is read as a C string.
  explicit ImageError(const std::string& message) : std::runtime_error(visible_nul(message)) {}
  explicit ImageError(const char* message) : std::runtime_error(message) {}
};

}  // namespace ochre
