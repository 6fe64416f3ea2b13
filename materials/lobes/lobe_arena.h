#pragma once
// LobeArena: per-thread bump allocator for the lobes of one shading point. reset() between
// path vertices; lobes are trivially destructible, so nothing is destroyed.

#include <cstddef>
#include <memory>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace ochre {

class LobeArena {
 public:
  explicit LobeArena(std::size_t bytes = 16 * 1024) : buffer_(new std::byte[bytes]), capacity_(bytes) {}

  template <class T, class... Args>
  T* make(Args&&... args) {
    static_assert(std::is_trivially_destructible_v<T>, "lobes must be trivially destructible");
    std::size_t offset = (used_ + alignof(T) - 1) & ~(alignof(T) - 1);
    if (offset + sizeof(T) > capacity_)
      throw std::length_error("LobeArena: too many lobes at one shading point");
    used_ = offset + sizeof(T);
    return new (buffer_.get() + offset) T(std::forward<Args>(args)...);
  }
  void reset(std::size_t floor = 0) { used_ = floor; }
  std::size_t used() const { return used_; }

 private:
  std::unique_ptr<std::byte[]> buffer_;
  std::size_t capacity_;
  std::size_t used_ = 0;
};

}  // namespace ochre
