#pragma once
// NodeArgs: what one instruction of a compiled material sees at run time. Values live in a flat
// frame of floats; an instruction's operands are offsets into it (Cycles SVM style). Nodes read
// their inputs and write their outputs through these accessors only.
//
// Closure nodes run after every value node, from the material's output towards the leaves. Each
// closure output owns a weight register (a spectrum) holding the sum of the weights its
// consumers gave it: combinators (add, mix, multiply) pass weight on to their closure inputs with
// add_weight(); leaves (lambert, emission, ...) turn their weight into lobes or emission.

#include <cstdint>

#include "materials/lobes/closure.h"
#include "materials/lobes/lobe_arena.h"
#include "materials/nodes/shading_context.h"

namespace ochre {

struct NodeArgs {
  const ShadingContext& ctx;
  float* frame;
  const uint16_t* in;   // one frame offset per input
  const uint16_t* out;  // one frame offset per output
  const void* payload;  // the node's compile-time data (see NodeDefinition::prepare), or null
  uint32_t outputs_used;
  LobeArena& arena;
  Closure& closure;

  const SampledWavelengths& lambda() const { return *ctx.lambda; }
  template <class T>
  const T& data() const {
    return *static_cast<const T*>(payload);
  }

  float in_float(int i) const { return frame[in[i]]; }
  RGB in_colour(int i) const { return {frame[in[i]], frame[in[i] + 1], frame[in[i] + 2]}; }
  Vec3 in_vector(int i) const { return {frame[in[i]], frame[in[i] + 1], frame[in[i] + 2]}; }
  SampledSpectrum in_spectrum(int i) const { return load_spectrum(in[i]); }

  bool output_used(int o) const { return (outputs_used >> o) & 1u; }
  void set_float(int o, float v) const { frame[out[o]] = v; }
  void set_colour(int o, const RGB& c) const { store3(out[o], c.r, c.g, c.b); }
  void set_vector(int o, const Vec3& v) const { store3(out[o], v.x, v.y, v.z); }
  void set_spectrum(int o, const SampledSpectrum& s) const { store_spectrum(out[o], s); }

  // Closure nodes: the weight this node's closure output received from its consumers.
  SampledSpectrum weight() const { return load_spectrum(out[0]); }
  // Combinators: adds `w` to the weight of the closure connected to input i.
  void add_weight(int i, const SampledSpectrum& w) const { store_spectrum(in[i], load_spectrum(in[i]) + w); }

 private:
  SampledSpectrum load_spectrum(uint16_t at) const {
    return {frame[at], frame[at + 1], frame[at + 2], frame[at + 3]};
  }
  void store_spectrum(uint16_t at, const SampledSpectrum& s) const {
    for (int k = 0; k < kSpectrumSamples; ++k) frame[at + k] = s[k];
  }
  void store3(uint16_t at, float a, float b, float c) const {
    frame[at] = a;
    frame[at + 1] = b;
    frame[at + 2] = c;
  }
};

// One run-time operation. Value nodes write outputs; closure nodes distribute or consume weight.
using NodeFn = void (*)(const NodeArgs&);

}  // namespace ochre
