#pragma once
// The CIE 1994 colour difference Delta E*94 (CIE 116-1995, "Industrial colour-difference evaluation"):
//   dE94 = sqrt((dL / (kL SL))^2 + (dC / (kC SC))^2 + (dH / (kH SH))^2),
//   SL = 1, SC = 1 + K1 C*_ref, SH = 1 + K2 C*_ref,
// with dH^2 = da^2 + db^2 - dC^2 and C*_ref the chroma of the reference colour, so the difference is
// not symmetric. The defaults are the graphic-arts constants kL = kC = kH = 1, K1 = 0.045, K2 = 0.015
// (textiles use kL = 2, K1 = 0.048, K2 = 0.014).

#include "spectra/ciede2000.h"

namespace ochre {

struct Cie94Weights {
  double kL = 1.0, kC = 1.0, kH = 1.0;
  double K1 = 0.045, K2 = 0.015;
};

double cie94(const Lab& reference, const Lab& sample, const Cie94Weights& weights = {});

}  // namespace ochre
