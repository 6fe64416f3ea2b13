#pragma once
// Bradford chromatic adaptation (header-only).
//
//   bradford_adaptation(source_white_xyz, target_white_xyz) -> M with M source_white = target_white
// Lam 1985 / Hunt, "The Reproduction of Colour" 6th ed. (2004) §34; the von Kries scaling is done
// in the Bradford "sharpened cone" space. It is the transform the ACES/OCIO reference matrices use.

#include "spectra/mat3.h"

namespace ochre {

inline constexpr Mat3 kBradfordCone{
    {0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296}};

inline Mat3 bradford_adaptation(const Array3d& source_white, const Array3d& target_white) {
  const Array3d src = kBradfordCone * source_white, dst = kBradfordCone * target_white;
  return kBradfordCone.inverse() * Mat3::diagonal(dst[0] / src[0], dst[1] / src[1], dst[2] / src[2]) *
         kBradfordCone;
}

}  // namespace ochre
