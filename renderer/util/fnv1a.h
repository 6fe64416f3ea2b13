#pragma once
// FNV-1a, 64 bit (Fowler, Noll, Vo): a hash stable across compilers, runs and machines (unlike std::hash),
// for cache file names and content hashes. Not cryptographic: it detects accidental change, not forgery.

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace ochre {

class Fnv1a64 {
 public:
  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      hash_ ^= bytes[i];
      hash_ *= 0x100000001b3ull;
    }
  }
  void add(std::string_view text) { add(text.data(), text.size()); }
  // FNV-1a over a 64-bit word at once (a checksum of large integer arrays, 8 times faster than bytes).
  // Each step is a bijection of the state, so a change in any single word always changes the result.
  void add_word(std::uint64_t word) {
    hash_ ^= word;
    hash_ *= 0x100000001b3ull;
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

inline std::uint64_t fnv1a64(std::string_view text) {
  Fnv1a64 hash;
  hash.add(text);
  return hash.value();
}

}  // namespace ochre
