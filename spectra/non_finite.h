#pragma once
// Non-finite floats made safe before they reach a table index or a lobe (docs/nodes.md, "Non-finite
// values"). std::clamp passes NaN through (every comparison with NaN is false), and converting NaN, an
// infinity or a value beyond the int range to int is undefined behaviour: an index computed that way may
// point anywhere.
//
//   finite_or_limit(v)           NaN -> 0, +inf -> the largest finite value, -inf -> the lowest
//   nan_safe_clamp(v, lo, hi)    std::clamp(v, lo, hi) for every v except NaN, which gives lo

#include <cmath>
#include <limits>

namespace ochre {

template <class T>
T finite_or_limit(T v) {
  if (std::isnan(v)) return T(0);
  if (std::isinf(v)) return v > T(0) ? std::numeric_limits<T>::max() : std::numeric_limits<T>::lowest();
  return v;
}

// Same result as std::clamp for every non-NaN v, signed zeros included (so images do not change).
template <class T>
T nan_safe_clamp(T v, T lo, T hi) {
  if (!(v >= lo)) return lo;
  return v > hi ? hi : v;
}

}  // namespace ochre
