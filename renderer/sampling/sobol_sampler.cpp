#include "renderer/sampling/sobol_sampler.h"

namespace ochre {

uint32_t sobol_dimension0(uint32_t index) {
  return sobol_detail::reverse_bits(index);
}

uint32_t sobol_dimension1(uint32_t index) {
  return sobol_detail::reverse_bits(
      sobol_detail::pascal_matrix_times(index));  // digit 0 becomes the most significant bit
}

uint32_t owen_scramble(uint32_t value, uint32_t seed) {
  return sobol_detail::reverse_bits(
      sobol_detail::laine_karras_permutation(sobol_detail::reverse_bits(value), seed));
}

// The sampler composes the functions above without the bit reversals that cancel:
// owen_scramble(sobol_dimension0(i), s) = reverse(LK(i, s)) and
// owen_scramble(sobol_dimension1(i), s) = reverse(LK(pascal(i), s)).

}  // namespace ochre
