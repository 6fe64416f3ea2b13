#pragma once
// The fitted model's c-dependent constants (lambert_sphere.h), tabulated once over s = sqrt(1 - c) and
// interpolated linearly. A shading point builds them for each hero wavelength; computed directly that is four
// pow() calls per wavelength, about half the cost of an LS lobe in a render. In s (not c) every constant is
// smooth up to c = 1, where several behave like sqrt(1 - c); the largest relative error of an interpolated
// constant is below 1e-4 (tests/materials/lobes/lambert_sphere/constants_table_test.cpp).

#include "materials/lobes/lambert_sphere/lambert_sphere.h"

namespace ochre {

LambertSphereConstants<float> lambert_sphere_constants_interpolated(float c);

}  // namespace ochre
