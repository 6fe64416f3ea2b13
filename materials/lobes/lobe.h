#pragma once
// Lobe: one BSDF component as pure math in the local shading frame (z = shading normal).
//
// Conventions (pbrt's): wo points toward the viewer (the previous path vertex), wi toward the
// light (the next vertex); both point away from the surface and are unit vectors. eval() is the
// BSDF without the cosine factor. Lobes are created per shading point in a LobeArena and must be
// trivially destructible.
//
// The interface is built for the models that come next:
// - delta lobes with several discrete exits (the analytic V-groove: a ray leaves after 1, 2, ...
//   reflections in different directions): sample() picks one exit with u_choice and reports its
//   discrete probability in `pdf` with `delta` set; eval()/pdf() return 0 for delta lobes;
// - a Mueller matrix per path: eval_mueller() and LobeSample::mueller carry one 4x4 matrix per
//   wavelength; non-polarizing lobes are ideal depolarizers (the default implementation);
// - a sharp backscatter peak with its own sampler (the powder BRDF): sample()/pdf() are the
//   lobe's own mixture, with u_choice selecting the mixture component.

#include <cstdint>
#include <optional>

#include "materials/core/mueller.h"
#include "materials/core/vec3.h"
#include "spectra/sampled_wavelengths.h"

namespace ochre {

enum LobeFlags : uint32_t {
  kLobeReflection = 1u << 0,
  kLobeTransmission = 1u << 1,
  kLobeDiffuse = 1u << 2,
  kLobeGlossy = 1u << 3,
  kLobeDelta = 1u << 4,       // sampled only; eval() and pdf() are 0
  kLobePolarizing = 1u << 5,  // eval_mueller() is not a depolarizer
  // A perfect mirror: one delta exit, wi = (-wo.x, -wo.y, wo.z), with probability 1. Lets the renderer
  // sample lights through planar mirrors (renderer/lights/planar_mirrors.h).
  kLobeMirror = 1u << 6,
};

// A Mueller matrix per wavelength together with the two Stokes reference frames it connects, in the
// local shading frame. `m` maps the Stokes vector of the light arriving at the surface (propagating
// along -wi, reference x axis `in_x`) to the Stokes vector of the light leaving it (propagating along
// wo, reference x axis `out_x`). Each x axis is a unit vector perpendicular to its propagation
// direction d; the frame's y axis is cross(d, x), so (x, y, d) is right-handed (docs/polarization.md).
// The integrator carries each path segment's frame along the path and rotates it into these axes, so a
// lobe may pick whatever axes make its matrix simple (e.g. s-polarization for Fresnel reflection).
struct MuellerResponse {
  MuellerSpectrum m{};
  Vec3 in_x;   // reference axis for the incident light (propagating along -wi)
  Vec3 out_x;  // reference axis for the exiting light (propagating along wo)
};

// Ideal depolarizer response: only M00 = f; the axes are any perpendiculars (irrelevant to a
// depolarizer, but kept valid so frame rotations stay well defined).
MuellerResponse depolarizing_response(const SampledSpectrum& f, const Vec3& wo, const Vec3& wi);
// A delta lobe has no density and an invalid configuration no value: a zero response, with frames
// perpendicular to their beams as MuellerResponse requires.
MuellerResponse zero_response(const Vec3& wo, const Vec3& wi);

struct LobeSample {
  Vec3 wi;  // sampled direction toward the light, local frame
  SampledSpectrum
      weight;        // f |cos wi| / pdf per wavelength (delta: reflectance of the exit / its probability)
  float pdf = 0.0f;  // solid-angle pdf, or the discrete probability of a delta exit
  bool delta = false;
  bool has_mueller = false;  // set by polarizing lobes: `mueller.m` is the exit's matrix times |cos|/pdf
  // eval(wo, wi) as the lobe computed it for the weight, where it did (has_value: the costly lobes, whose
  // `pdf` is then also exactly their pdf() in wi): a closure's mixture value and pdf in wi take them instead
  // of evaluating the lobe a second time.
  bool has_value = false;
  SampledSpectrum value;
  MuellerResponse mueller{};
};

// Local-frame cosine helpers.
inline float cos_theta(const Vec3& w) {
  return w.z;
}
inline float abs_cos_theta(const Vec3& w) {
  return w.z < 0.0f ? -w.z : w.z;
}
inline bool same_hemisphere(const Vec3& a, const Vec3& b) {
  return a.z * b.z > 0.0f;
}

class Lobe {
 public:
  virtual uint32_t flags() const = 0;
  // Unpolarized BSDF value (Mueller M00) at the path's wavelengths, without the cosine.
  virtual SampledSpectrum eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const = 0;
  // Solid-angle pdf with which sample() produces wi (hero wavelength).
  virtual float pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const = 0;
  // Draws wi. u_choice picks among discrete exits or mixture components; u is for the direction.
  virtual std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                           const SampledWavelengths& lambda) const = 0;
  // Mueller matrix per wavelength (without the cosine) with its reference frames, see
  // MuellerResponse. Its M00 equals eval(). Default: ideal depolarizer, correct for every
  // non-polarizing lobe.
  virtual MuellerResponse eval_mueller(const Vec3& wo, const Vec3& wi,
                                       const SampledWavelengths& lambda) const {
    return depolarizing_response(eval(wo, wi, lambda), wo, wi);
  }
  // Directional albedo estimate used to choose among lobes (need not be exact).
  virtual SampledSpectrum albedo_hint(const Vec3& wo, const SampledWavelengths& lambda) const = 0;

  bool is_delta() const { return (flags() & kLobeDelta) != 0; }
  bool polarizes() const { return (flags() & kLobePolarizing) != 0; }

 protected:
  ~Lobe() = default;  // lobes live in a LobeArena and are never deleted through this pointer
};

}  // namespace ochre
