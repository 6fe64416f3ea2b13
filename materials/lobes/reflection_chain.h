#pragma once
// A chain of specular reflections seen by one ray (inside a V-groove or any explicit groove profile),
// and its response to light under the three polarization treatments of Saint-Pierre, Chavel, Simonot
// and Hebert 2019 ("Angular reflectance model for ridged specular surfaces", Sec 3), plus the paper's
// printed formula for comparison. docs/materials/vgroove.md has the derivations and decisions.
//
// Reflections are visited in the order LIGHT meets them. ChainFrames turns each reflection (the
// light's propagation direction before it and the facet normal) into a ChainStep: the incidence cosine
// and the rotation between successive planes of incidence. ChainResponse accumulates the steps for one
// facet index (one wavelength). Geometry is shared across wavelengths, so a caller builds the steps
// once and feeds them to one ChainResponse per wavelength.

#include <complex>

#include "materials/core/jones.h"
#include "materials/core/mueller.h"
#include "materials/core/vec3d.h"

namespace ochre {

enum class ChainModel {
  kRigorous,     // Jones calculus with correctly signed frame rotations (Sec 3.3, Eqs 21-32, erratum fixed)
  kUnpolarized,  // light stays unpolarized: product of (R_s + R_p) / 2 (Sec 3.1, Eq 19)
  kSeparateSP,   // s and p reflected separately, averaged (Sec 3.2, Eq 20 with the average)
  kPaperLiteral  // Eq 33 as printed: cos psi = |S_j . S_j+1| drops the rotation's sign (comparison only)
};

// The facet material: a complex index n - i k (k >= 0; a dielectric has k = 0), or an ideal mirror
// (r_s = -1, r_p = 1 in the Verdet form of materials/lobes/fresnel.h: reflectance 1, no retardance).
struct FacetIndex {
  std::complex<double> eta{1.5, 0.0};
  bool mirror = false;

  static FacetIndex conductor(double n, double k) { return {{n, -k}, false}; }
  static FacetIndex ideal_mirror() { return {{1.0, 0.0}, true}; }
};

// Fresnel amplitudes (r_s, r_p) of a facet at incidence cosine cos_i, in the frames of fresnel.h.
struct FacetAmplitudes {
  std::complex<double> r_s, r_p;
};
FacetAmplitudes facet_amplitudes(const FacetIndex& facet, double cos_i);

struct ChainStep {
  double cos_i = 1.0;          // incidence cosine on the facet
  double frame_angle = 0.0;    // signed angle from the previous reflection's s axis to this one's, about
                               // the propagation direction between them (0 for the first reflection)
  double literal_angle = 0.0;  // Eq 33 as printed: arccos |s_prev . s| (0 for the first reflection)
};

// Builds ChainSteps from reflections given in the light's order. The s axis of a reflection is
// normalize(cross(-d_in, n)) (the axis of materials/core/specular_frame.h with wi = -d_in), the x axis
// of both the incident and the reflected beam's Stokes frames.
class ChainFrames {
 public:
  // The light propagating along d_in (unit) reflects off a facet with unit normal n (facing the light,
  // dot(d_in, n) < 0). Returns the step; outgoing() is the reflected direction.
  ChainStep reflect(const Vec3d& d_in, const Vec3d& n);

  int count() const { return count_; }
  const Vec3d& outgoing() const { return outgoing_; }
  // Stokes x axes of the whole chain: of the light arriving at the first reflection and of the light
  // leaving the last one (valid once count() > 0).
  const Vec3d& first_s() const { return first_s_; }
  const Vec3d& last_s() const { return last_s_; }

 private:
  int count_ = 0;
  Vec3d first_s_, last_s_, outgoing_;
};

// Visits the reflections of a path traced from the viewer in the order light meets them: the light
// arrives along -exit and meets the traced reflections last to first. normal_of(j) is the facet normal
// of traced reflection j (1-based); on_step(ChainStep) is called for each. Returns the chain's frames.
template <class NormalOf, class OnStep>
ChainFrames reversed_light_chain(const Vec3d& exit, int reflections, NormalOf&& normal_of, OnStep&& on_step) {
  ChainFrames frames;
  Vec3d d = -exit;
  for (int j = reflections; j >= 1; --j) {
    on_step(frames.reflect(d, normal_of(j)));
    d = frames.outgoing();
  }
  return frames;
}

// The response of one chain at one facet index, accumulated step by step.
class ChainResponse {
 public:
  ChainResponse(ChainModel model, const FacetIndex& facet) : model_(model), facet_(facet) {}

  void add(const ChainStep& step);

  // Reflectance for unpolarized incident light (Mueller M00).
  double reflectance() const;
  // Mueller matrix from the Stokes frame of the incident light (x axis ChainFrames::first_s()) to that
  // of the exiting light (x axis last_s()). Rigorous: exact; separate s/p: a diattenuator
  // [[A, B], [B, A]] on (S0, S1) with A = (R_s + R_p) / 2, B = (R_s - R_p) / 2 and no coherence
  // between s and p; unpolarized and paper-literal: an ideal depolarizer with M00 = reflectance().
  Mueller mueller() const;

 private:
  ChainModel model_;
  FacetIndex facet_;
  Jones jones_;                               // rigorous and paper-literal
  double product_s_ = 1.0, product_p_ = 1.0;  // separate s/p
  double product_ = 1.0;                      // unpolarized
};

}  // namespace ochre
