#pragma once
// InputError: the exception for bad user input (malformed scene, missing or unreadable file,
// parameter out of range). The message names the file and the element at fault; the command
// line tools exit with code 2 on it. Defined in the lowest library so that every reader of user
// files (spectra's CSV tables included) can throw it; renderer/input_error.h re-exports it.

#include <stdexcept>

namespace ochre {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ochre
