#pragma once
// Path throughput for the three polarization modes (docs/polarization.md, 'Modes').
//
// Backward tracing carries, from the sensor, the product T of the Mueller matrices met so far; light
// that reaches the path's current segment with Stokes vector s (in the segment's carried frame) adds
// T s to the sensor. Each policy keeps only what its film needs:
//   UnpolarizedThroughput (mode off)       : T00 per wavelength (every element treated as a depolarizer);
//   IntensityThroughput   (mode intensity) : the first row of T, a 4-vector per wavelength;
//   StokesThroughput      (mode stokes)    : all of T, 4x4 per wavelength.
// The carried frame is the world-space x axis of the current segment's Stokes frame (light propagating
// toward the sensor along d, y = cross(d, x)). It is handed from vertex to vertex, never recomputed from
// the direction, so no basis formula can flip it (docs/polarization.md, 'Discontinuous reference
// frames').

#include <array>

#include "materials/core/frame.h"
#include "materials/core/mueller.h"
#include "materials/lobes/lobe.h"
#include "renderer/lights/light_polarizer.h"

namespace ochre {

// What the sensor receives from one contribution: S0 only (off, intensity) or S0..S3 (stokes), per
// wavelength.
using SensorStokes = std::array<SampledSpectrum, 4>;

// A lobe's response moved to world space: the matrix and the frames of its outgoing and incident beams.
struct WorldResponse {
  const MuellerSpectrum* m = nullptr;  // null: an ideal depolarizer with gain `f` (always so in mode off)
  SampledSpectrum f;                   // M00
  Vec3 out_x, in_x;                    // world axes (out: toward the sensor along wo; in: along -wi)
  Vec3 wo;                             // world propagation direction of the outgoing beam
};

class UnpolarizedThroughput {
 public:
  static constexpr bool kPolarized = false;
  static constexpr bool kFullStokes = false;

  // analyzer: the camera's linear polarizer (Mueller matrix in the camera frame), or null. Without
  // polarization tracing it can only pass half of the unpolarized light it sees.
  UnpolarizedThroughput(const Mueller* analyzer, const Vec3&) : beta_(analyzer ? (*analyzer)(0, 0) : 1.0f) {}

  SampledSpectrum m00() const { return beta_; }
  void scale(float k) { beta_ *= k; }
  void scatter(const WorldResponse& r, const SampledSpectrum& weight) {
    (void)r;
    beta_ *= weight;
  }
  // Light along the current segment (propagating along d toward the sensor): S0 at the sensor.
  void receive(const IncomingLight& light, const Vec3&, SensorStokes& out) const {
    out[0] += beta_ * light.radiance;
  }
  // Light arriving through one more interaction (next-event estimation): T R M R' s times the scalar k
  // (cosine, MIS weight, 1 / pdf). Here M = M00 = r.f.
  void receive_through(const WorldResponse& r, float k, const IncomingLight& light, const Vec3&,
                       SensorStokes& out) const {
    out[0] += beta_ * r.f * light.radiance * k;
  }

 private:
  SampledSpectrum beta_;
};

// Shared by the two polarized policies: the frame change from a lobe's outgoing axis to the carried one.
inline Mueller outgoing_rotation(const WorldResponse& r, const Vec3& carried_x) {
  return stokes_basis_rotation(r.wo, r.out_x, carried_x);
}

// Stokes vector (in the frame whose x axis is `frame_x`, for light propagating along d) of incoming light.
inline Stokes incoming_stokes(const IncomingLight& light, int i, const Vec3& d, const Vec3& frame_x) {
  const float s0 = light.radiance[i];
  if (!light.polarized) return Stokes::unpolarized(s0);
  // Fully linearly polarized along `axis`: (S0, S0, 0, 0) in the frame of that axis, rotated into ours.
  return stokes_basis_rotation(d, light.axis, frame_x) * Stokes{{s0, s0, 0.0f, 0.0f}};
}

class IntensityThroughput {
 public:
  static constexpr bool kPolarized = true;
  static constexpr bool kFullStokes = false;

  IntensityThroughput(const Mueller* analyzer, const Vec3& camera_x) : x_(camera_x) {
    const Stokes first =
        analyzer ? Stokes{{(*analyzer)(0, 0), (*analyzer)(0, 1), (*analyzer)(0, 2), (*analyzer)(0, 3)}}
                 : Stokes::unpolarized(1.0f);
    rows_.fill(first);
    depolarized_ = !analyzer;
  }

  SampledSpectrum m00() const {
    SampledSpectrum s;
    for (int i = 0; i < kSpectrumSamples; ++i) s[i] = rows_[i][0];
    return s;
  }
  void scale(float k) {
    for (Stokes& r : rows_)
      for (float& v : r.s) v *= k;
  }
  // `weight` is M00 |cos| / pdf; r.m (when set) the full matrix with the same factor.
  void scatter(const WorldResponse& r, const SampledSpectrum& weight) {
    if (!r.m) {  // a depolarizer: only S0 survives, the frame no longer matters
      for (int i = 0; i < kSpectrumSamples; ++i) rows_[i] = Stokes::unpolarized(rows_[i][0] * weight[i]);
      depolarized_ = true;
      x_ = r.in_x;
      return;
    }
    const Mueller rot = outgoing_rotation(r, x_);
    for (int i = 0; i < kSpectrumSamples; ++i)
      rows_[i] = (depolarized_ ? rows_[i] : rows_[i] * rot) * (*r.m)[i];
    depolarized_ = false;
    x_ = r.in_x;
  }
  // Light along the current segment, which propagates along `d` (toward the sensor).
  void receive(const IncomingLight& light, const Vec3& d, SensorStokes& out) const {
    for (int i = 0; i < kSpectrumSamples; ++i) out[0][i] += dot4(rows_[i], incoming_stokes(light, i, d, x_));
  }
  void receive_through(const WorldResponse& r, float k, const IncomingLight& light, const Vec3& d_in,
                       SensorStokes& out) const {
    if (!r.m) {
      for (int i = 0; i < kSpectrumSamples; ++i) out[0][i] += rows_[i][0] * r.f[i] * light.radiance[i] * k;
      return;
    }
    const Mueller rot = outgoing_rotation(r, x_);
    for (int i = 0; i < kSpectrumSamples; ++i) {
      const Stokes row = (depolarized_ ? rows_[i] : rows_[i] * rot) * (*r.m)[i];
      out[0][i] += dot4(row, incoming_stokes(light, i, d_in, r.in_x)) * k;
    }
  }

 private:
  static float dot4(const Stokes& a, const Stokes& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  }

  std::array<Stokes, kSpectrumSamples> rows_;
  Vec3 x_;
  bool depolarized_ = true;  // rows are (r0, 0, 0, 0): frame rotations can be skipped
};

class StokesThroughput {
 public:
  static constexpr bool kPolarized = true;
  static constexpr bool kFullStokes = true;

  StokesThroughput(const Mueller* analyzer, const Vec3& camera_x)
      : t_(uniform_spectrum(analyzer ? *analyzer : Mueller::identity())), x_(camera_x) {}

  SampledSpectrum m00() const { return ochre::m00(t_); }
  void scale(float k) { t_ = t_ * k; }
  void scatter(const WorldResponse& r, const SampledSpectrum& weight) {
    if (!r.m) {
      t_ = t_ * depolarizer(weight);
    } else {
      const Mueller rot = outgoing_rotation(r, x_);
      for (int i = 0; i < kSpectrumSamples; ++i) t_[i] = t_[i] * rot * (*r.m)[i];
    }
    x_ = r.in_x;
  }
  void receive(const IncomingLight& light, const Vec3& d, SensorStokes& out) const {
    for (int i = 0; i < kSpectrumSamples; ++i) add(out, i, t_[i] * incoming_stokes(light, i, d, x_));
  }
  void receive_through(const WorldResponse& r, float k, const IncomingLight& light, const Vec3& d_in,
                       SensorStokes& out) const {
    if (!r.m) {  // T D s = column 0 of T times f S0
      for (int i = 0; i < kSpectrumSamples; ++i)
        for (int c = 0; c < 4; ++c) out[c][i] += t_[i](c, 0) * r.f[i] * light.radiance[i] * k;
      return;
    }
    const Mueller rot = outgoing_rotation(r, x_);
    for (int i = 0; i < kSpectrumSamples; ++i) {
      Stokes s = t_[i] * (rot * ((*r.m)[i] * incoming_stokes(light, i, d_in, r.in_x)));
      for (float& v : s.s) v *= k;
      add(out, i, s);
    }
  }

 private:
  static void add(SensorStokes& out, int i, const Stokes& s) {
    for (int c = 0; c < 4; ++c) out[c][i] += s[c];
  }

  MuellerSpectrum t_;
  Vec3 x_;
};

}  // namespace ochre
