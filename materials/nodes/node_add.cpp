// add(a, b): a + b for values (float, colour, spectrum, vector); for closures, the union of the
// two lobe sets with their weights kept (OSL closure addition).

#include "materials/nodes/definition_builders.h"
#include "materials/nodes/math_kernels.h"
#include "materials/nodes/math_node_types.h"

namespace ochre {

namespace {

struct Plus {
  static float apply(float x, float y) { return x + y; }
};

void add_closures(const NodeArgs& a) {
  const SampledSpectrum w = a.weight();
  a.add_weight(0, w);
  a.add_weight(1, w);
}

TypeResolution resolve_add(std::span<const SocketType> connected) {
  const SocketType t = combine_operands(connected[0], connected[1], "add");
  return {{t, t}, {t}};
}

NodeFn select_add(const TypeResolution& types) {
  if (types.outputs[0] == SocketType::kClosure) return add_closures;
  return binary_kernel<Plus>(types.outputs[0]);
}

// x + 0 = x.
FoldResult fold_add(const FoldArgs& args) {
  const std::span<const InputView> in = args.inputs;
  FoldResult r;
  for (int i = 0; i < 2; ++i) {
    if (in[i].is_constant() && constant_equals(*in[i].value, 0.0f)) {
      r.kind = FoldResult::Kind::kForward;
      r.forward_input = 1 - i;
      break;
    }
  }
  return r;
}

}  // namespace

NodeDefinition add_node() {
  NodeDefinition d;
  d.name = "add";
  d.doc =
      "Sum a + b. Values: element-wise, the result has the promoted type of a and b. Closures: both "
      "lobe sets, weights kept (OSL closure add).";
  d.inputs = {operand_input("a", 0.0f, "first operand"), operand_input("b", 0.0f, "second operand")};
  d.outputs = {{"result", SocketType::kFloat, true, "a + b"}};
  d.resolve_types = resolve_add;
  d.select = select_add;
  d.fold = fold_add;
  return d;
}

}  // namespace ochre
