#include "materials/nodes/non_finite_tally.h"

#include "spectra/non_finite.h"

namespace ochre {

[[gnu::cold]] void make_finite(float* values, int n, NonFiniteTally* tally) {
  if (tally) {
    ++tally->values;
    if (tally->keep_values) return;
  }
  for (int k = 0; k < n; ++k) values[k] = finite_or_limit(values[k]);
}

}  // namespace ochre
