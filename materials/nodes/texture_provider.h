#pragma once
// TextureProvider: filtered texture lookups for the texture node. The renderer implements it with
// the OIIO TextureSystem; tests use a stub. materials/ never sees an image library.

#include "materials/core/vec3.h"

namespace ochre {

class TextureProvider {
 public:
  virtual ~TextureProvider() = default;
  // Filtered lookup: nchannels (1 or 3) linear values starting at first_channel, written to out.
  // uv wraps periodically; footprint is the filter width in uv units (0 = point lookup). Any uv and
  // footprint is allowed: NaN or infinite uv read 0 (docs/nodes.md, "Non-finite values").
  virtual void lookup(int texture_id, const Vec2& uv, float footprint, int first_channel, int nchannels,
                      float* out) const = 0;
};

}  // namespace ochre
