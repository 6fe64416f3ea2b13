#include "materials/lobes/lobe.h"

#include "materials/core/frame.h"

namespace ochre {

MuellerResponse depolarizing_response(const SampledSpectrum& f, const Vec3& wo, const Vec3& wi) {
  MuellerResponse r;
  r.m = depolarizer(f);
  // Any perpendicular will do: a depolarizer's output does not depend on the input's S1..S3 and
  // carries none of its own. The incident light propagates along -wi.
  r.in_x = Frame::from_normal(-wi).s;
  r.out_x = Frame::from_normal(wo).s;
  return r;
}

MuellerResponse zero_response(const Vec3& wo, const Vec3& wi) {
  return depolarizing_response(SampledSpectrum(0.0f), wo, wi);
}

}  // namespace ochre
