#include "materials/core/jones.h"

namespace ochre {

namespace {

using Complex = std::complex<double>;

// Coherency matrix [[<Ex Ex*>, <Ex Ey*>], [<Ey Ex*>, <Ey Ey*>]] of a Stokes vector (any real 4-vector).
struct Coherency {
  Complex xx, xy, yx, yy;
};

Coherency coherency(const double s[4]) {
  return {0.5 * (s[0] + s[1]), Complex(0.5 * s[2], -0.5 * s[3]), Complex(0.5 * s[2], 0.5 * s[3]),
          0.5 * (s[0] - s[1])};
}

// J C J^H.
Coherency transform(const Jones& j, const Coherency& c) {
  // T = J C
  const Complex t00 = j.a * c.xx + j.b * c.yx, t01 = j.a * c.xy + j.b * c.yy;
  const Complex t10 = j.c * c.xx + j.d * c.yx, t11 = j.c * c.xy + j.d * c.yy;
  // T J^H: (J^H)_{kl} = conj(J_{lk})
  return {t00 * std::conj(j.a) + t01 * std::conj(j.b), t00 * std::conj(j.c) + t01 * std::conj(j.d),
          t10 * std::conj(j.a) + t11 * std::conj(j.b), t10 * std::conj(j.c) + t11 * std::conj(j.d)};
}

}  // namespace

Mueller jones_to_mueller(const Jones& j) {
  Mueller m;
  for (int k = 0; k < 4; ++k) {
    double unit[4] = {0, 0, 0, 0};
    unit[k] = 1.0;
    const Coherency c = transform(j, coherency(unit));
    m(0, k) = static_cast<float>((c.xx + c.yy).real());
    m(1, k) = static_cast<float>((c.xx - c.yy).real());
    m(2, k) = static_cast<float>(2.0 * c.xy.real());
    m(3, k) = static_cast<float>(-2.0 * c.xy.imag());
  }
  return m;
}

}  // namespace ochre
