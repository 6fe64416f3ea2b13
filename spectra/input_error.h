#pragma once
// InputError: the exception for bad user input (malformed scene, missing or unreadable file,
// parameter out of range). The message names the file and the element at fault; the command
// line tools exit with code 2 on it. Defined in the lowest library so that every reader of user
// files (spectra's CSV tables included) can throw it.

#include <stdexcept>
#include <string>
#include <string_view>

namespace ochre {

// A message with every NUL character written as the two characters \0: messages are read as C strings
// (what()), so a NUL that a name from a file or an argument brought in would cut them short.
inline std::string visible_nul(std::string message) {
  for (size_t at = message.find('\0'); at != std::string::npos; at = message.find('\0', at + 2))
    message.replace(at, 1, "\\0");
  return message;
}

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(visible_nul(message)) {}
  explicit InputError(const char* message) : std::runtime_error(message) {}
};

// A message as a person reads it: at most `limit` characters, the middle of a longer one (a 50 MB value a
// file gave, quoted in full) replaced by the count of what was left out. The programs print every error
// through it (tools/cli/program.h).
inline std::string message_excerpt(std::string_view message, size_t limit = 4096) {
  if (message.size() <= limit) return std::string(message);
  const size_t head = limit * 3 / 4, tail = limit / 8;
  return std::string(message.substr(0, head)) + " [... " + std::to_string(message.size() - head - tail) +
         " characters left out ...] " + std::string(message.substr(message.size() - tail));
}

}  // namespace ochre
