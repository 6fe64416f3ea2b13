#pragma once
// The exception thrown by image output and input (EXR, PNG, OCIO, atomic files). Its message always
// names the file (or the OCIO config) at fault, so a caller can print it as is and exit.

#include <stdexcept>

namespace ochre {

class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ochre
