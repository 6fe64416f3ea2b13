#pragma once
// Whether two films hold the same mean in every pixel, bit for bit (determinism and split tests).

#include "renderer/film/film.h"

namespace ochre::test {

inline bool same_pixels(const Film& a, const Film& b) {
  if (a.width() != b.width() || a.height() != b.height()) return false;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      if (!(a.mean(x, y) == b.mean(x, y))) return false;
  return true;
}

}  // namespace ochre::test
