#pragma once
// Scene numbers are read as JSON doubles but the renderer computes in single precision: a value that is
// a finite double can become infinite (|x| > 3.4e38) or vanish (0 < |x| < 1.18e-38, below the smallest
// normal float) once converted. Both are rejected with the same wording everywhere (docs/scene-format.md,
// "Validation").

#include <cmath>
#include <limits>
#include <string>

namespace ochre {

// "" when `x` converts to a finite normal float (or 0), else what the conversion does to it, for
// messages such as "must be > 0 (got 1e-50, which is 0 in single precision)".
inline std::string single_precision_problem(double x) {
  if (!std::isfinite(x)) return "which is not a finite number";
  const float f = static_cast<float>(x);
  if (!std::isfinite(f)) return "which is infinite in single precision";
  if (f == 0.0f && x != 0.0) return "which is 0 in single precision";
  if (x != 0.0 && std::fabs(f) < std::numeric_limits<float>::min())
    return "which is below the smallest normal single-precision number (1.18e-38)";
  return "";
}

}  // namespace ochre
