#pragma once
// NodeArgs: what one instruction of a compiled material sees at run time. Values live in a flat
// frame of floats; an instruction's operands are offsets into it (Cycles SVM style). Nodes read
// their inputs and write their outputs through these accessors only.
//
// Closure nodes run after every value node, from the material's output towards the leaves. Each
// closure output owns a weight register (a spectrum) holding the sum of the weights its
// consumers gave it: combinators (add, mix, multiply) pass weight on to their closure inputs with
// add_weight(); leaves (lambert, emission, ...) turn their weight into lobes or emission with
// add_lobe() and add_emission().
//
// Every write here is the boundary where NaN and infinities stop (non_finite_tally.h): the frame starts
// with finite constants (the compiler rejects others) and each write is made finite, so every value a
// node reads, and every lobe weight and emission, is finite by construction.

#include <bit>
#include <cstdint>

#include "materials/lobes/closure.h"
#include "materials/lobes/lobe_arena.h"
#include "materials/nodes/non_finite_tally.h"
#include "materials/nodes/shading_context.h"

namespace ochre {

class NodeArgs {
 public:
  NodeArgs(const ShadingContext& context, float* frame_floats, const uint16_t* inputs,
           const uint16_t* outputs, const void* node_payload, uint32_t used_outputs, LobeArena& lobe_arena,
           Closure& closure)
      : ctx(context),
        payload(node_payload),
        arena(lobe_arena),
        frame_(frame_floats),
        in_(inputs),
        out_(outputs),
        outputs_used_(used_outputs),
        closure_(closure) {}

  const ShadingContext& ctx;
  const void* payload;  // the node's compile-time data (see NodeDefinition::prepare), or null
  LobeArena& arena;     // where closure leaves build their lobes

  const SampledWavelengths& lambda() const { return *ctx.lambda; }
  template <class T>
  const T& data() const {
    return *static_cast<const T*>(payload);
  }

  float in_float(int i) const { return frame_[in_[i]]; }
  RGB in_colour(int i) const { return {frame_[in_[i]], frame_[in_[i] + 1], frame_[in_[i] + 2]}; }
  Vec3 in_vector(int i) const { return {frame_[in_[i]], frame_[in_[i] + 1], frame_[in_[i] + 2]}; }
  SampledSpectrum in_spectrum(int i) const { return load_spectrum(in_[i]); }

  bool output_used(int o) const { return (outputs_used_ >> o) & 1u; }
  void set_float(int o, float v) const { store(out_[o], &v, 1); }
  void set_colour(int o, const RGB& c) const { store3(out_[o], c.r, c.g, c.b); }
  void set_vector(int o, const Vec3& v) const { store3(out_[o], v.x, v.y, v.z); }
  void set_spectrum(int o, const SampledSpectrum& s) const { store_spectrum(out_[o], s); }

  // Closure nodes: the weight this node's closure output received from its consumers.
  SampledSpectrum weight() const { return load_spectrum(out_[0]); }
  // Combinators: adds `w` to the weight of the closure connected to input i.
  void add_weight(int i, const SampledSpectrum& w) const {
    if (w.is_black()) return;  // nothing to add (a mix at factor 0 or 1): no load, sum and check
    store_spectrum(in_[i], load_spectrum(in_[i]) + w);
  }
  // Leaves: a lobe (built in `arena`) with its weight, and emitted radiance. A product of finite values
  // may still overflow: the weight and the closure's total emission are made finite too.
  void add_lobe(const Lobe* lobe, SampledSpectrum w) const {
    make_finite_spectrum(w);
    closure_.add_lobe(lobe, w);
  }
  void add_emission(const SampledSpectrum& radiance) const {
    SampledSpectrum total = closure_.emission() + radiance;
    make_finite_spectrum(total);
    closure_.set_emission(total);
  }
  // Anisotropic leaves: the closure's tangent (closure.h, set_tangent), set by the first of them.
  bool has_tangent() const { return closure_.has_tangent(); }
  const Vec3& tangent() const { return closure_.tangent(); }
  void set_tangent(const Vec3& world_tangent) const { closure_.set_tangent(world_tangent); }

 private:
  // NaN and infinities are the floats whose exponent bits are all set: adding 1 to such an exponent carries
  // into bit 31. Integer operations only (no float compare per value, no slow path for subnormals), which
  // the compiler turns into a few vector instructions for a spectrum.
  static bool all_finite(const float* v, int n) {
    uint32_t carries = 0;
    for (int k = 0; k < n; ++k) carries |= (std::bit_cast<uint32_t>(v[k]) & 0x7f800000u) + 0x00800000u;
    return (carries & 0x80000000u) == 0;
  }
  void make_finite_spectrum(SampledSpectrum& s) const {
    float v[kSpectrumSamples];
    for (int k = 0; k < kSpectrumSamples; ++k) v[k] = s[k];
    if (all_finite(v, kSpectrumSamples)) [[likely]]
      return;
    make_finite(v, kSpectrumSamples, ctx.nonfinite);
    for (int k = 0; k < kSpectrumSamples; ++k) s[k] = v[k];
  }
  void store(uint16_t at, const float* v, int n) const {
    for (int k = 0; k < n; ++k) frame_[at + k] = v[k];
    if (!all_finite(v, n)) [[unlikely]]
      make_finite(frame_ + at, n, ctx.nonfinite);
  }
  void store3(uint16_t at, float a, float b, float c) const {
    const float v[3] = {a, b, c};
    store(at, v, 3);
  }
  void store_spectrum(uint16_t at, const SampledSpectrum& s) const {
    float v[kSpectrumSamples];
    for (int k = 0; k < kSpectrumSamples; ++k) v[k] = s[k];
    store(at, v, kSpectrumSamples);
  }
  SampledSpectrum load_spectrum(uint16_t at) const {
    SampledSpectrum s;
    for (int k = 0; k < kSpectrumSamples; ++k) s[k] = frame_[at + k];
    return s;
  }

  float* frame_;
  const uint16_t* in_;   // one frame offset per input
  const uint16_t* out_;  // one frame offset per output
  uint32_t outputs_used_;
  Closure& closure_;
};

// One run-time operation. Value nodes write outputs; closure nodes distribute or consume weight.
using NodeFn = void (*)(const NodeArgs&);

}  // namespace ochre
