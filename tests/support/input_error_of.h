#pragma once
// The message of the InputError a call throws, for tests that compare whole messages.

#include <string>

#include "spectra/input_error.h"

namespace ochre::test {

// The InputError message `f` throws, or "" when it throws none (any other exception propagates).
template <class F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace ochre::test
