// multiply(a, b): a * b for values (element-wise, promoted type); a closure times a float,
// colour or spectrum scales every lobe weight and the emission (OSL closure scale). A colour
// multiplied with a spectrum is a dimensionless tint (reflectance upsampling), whatever the
// result feeds.

#include <memory>

#include "materials/nodes/definition_builders.h"
#include "materials/nodes/math_kernels.h"
#include "materials/nodes/math_node_types.h"
#include "spectra/product_spectrum.h"
#include "spectra/scaled_spectrum.h"

namespace ochre {

namespace {

struct Times {
  static float apply(float x, float y) { return x * y; }
};

template <int kClosureInput, bool kSpectrumFactor>
void scale_closure(const NodeArgs& a) {
  constexpr int kFactor = 1 - kClosureInput;
  SampledSpectrum w = a.weight();
  if constexpr (kSpectrumFactor)
    w *= a.in_spectrum(kFactor);
  else
    w *= a.in_float(kFactor);
  a.add_weight(kClosureInput, w);
}

SocketType closure_factor_type(SocketType factor, const char* factor_name) {
  switch (factor) {
    case SocketType::kFloat:
      return SocketType::kFloat;
    case SocketType::kColour:
    case SocketType::kSpectrum:
      return SocketType::kSpectrum;
    case SocketType::kClosure:
      throw NodeError(
          factor_name,
          "type mismatch: closure x closure is not allowed (a closure is scaled by a float, colour or "
          "spectrum)");
    case SocketType::kVector:
      break;
  }
  throw NodeError(factor_name,
                  "type mismatch: a closure is scaled by a float, colour or spectrum, not a vector");
}

TypeResolution resolve_multiply(std::span<const SocketType> connected) {
  const SocketType a = connected[0], b = connected[1];
  if (a == SocketType::kClosure) return {{a, closure_factor_type(b, "b")}, {SocketType::kClosure}};
  if (b == SocketType::kClosure) return {{closure_factor_type(a, "a"), b}, {SocketType::kClosure}};
  const SocketType t = promote_values(a, b, "b");
  return {{t, t}, {t}};
}

NodeFn select_multiply(const TypeResolution& types) {
  if (types.outputs[0] != SocketType::kClosure) return binary_kernel<Times>(types.outputs[0]);
  const bool closure_in_a = types.inputs[0] == SocketType::kClosure;
  const bool spectral = types.inputs[closure_in_a ? 1 : 0] == SocketType::kSpectrum;
  if (closure_in_a) return spectral ? scale_closure<0, true> : scale_closure<0, false>;
  return spectral ? scale_closure<1, true> : scale_closure<1, false>;
}

// x * 1 = x; constant spectra multiply into one pre-built spectrum.
FoldResult fold_multiply(const FoldArgs& args) {
  const std::span<const InputView> in = args.inputs;
  FoldResult r;
  for (int i = 0; i < 2; ++i) {
    if (in[i].is_constant() && constant_equals(*in[i].value, 1.0f)) {
      r.kind = FoldResult::Kind::kForward;
      r.forward_input = 1 - i;
      return r;
    }
  }
  if (args.types.outputs[0] == SocketType::kSpectrum && in[0].is_constant() && in[1].is_constant()) {
    const SpectrumPtr& a = in[0].value->spectrum;
    const SpectrumPtr& b = in[1].value->spectrum;
    SpectrumPtr product;
    if (a->is_constant())
      product = std::make_shared<ScaledSpectrum>(b, a->eval(550.0f));
    else if (b->is_constant())
      product = std::make_shared<ScaledSpectrum>(a, b->eval(550.0f));
    else
      product = std::make_shared<ProductSpectrum>(a, b);
    r.kind = FoldResult::Kind::kConstants;
    r.outputs = {NodeValue::of_spectrum(product)};
  }
  return r;
}

}  // namespace

NodeDefinition multiply_node() {
  NodeDefinition d;
  d.name = "multiply";
  d.doc =
      "Product a * b. Values: element-wise, the result has the promoted type of a and b. A closure times a "
      "float, colour or spectrum scales its lobe weights and emission (OSL closure scale); closure x closure "
      "is an error.";
  d.inputs = {operand_input("a", 1.0f, "first factor"), operand_input("b", 1.0f, "second factor")};
  d.outputs = {{"result", SocketType::kFloat, true, "a * b"}};
  d.colour_operands_are_tints = true;
  d.resolve_types = resolve_multiply;
  d.select = select_multiply;
  d.fold = fold_multiply;
  return d;
}

}  // namespace ochre
