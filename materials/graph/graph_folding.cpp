#include "materials/graph/graph_folding.h"

#include "materials/graph/frame_layout.h"
#include "materials/nodes/json_literal.h"
#include "spectra/negative_value.h"

namespace ochre {

namespace {

// " (-0.5 at 400 nm)": where a spectrum constant is negative (for a CSV, its first negative entry).
std::string negative_wavelength(const NodeValue& v) {
  if (v.type != SocketType::kSpectrum) return "";
  const auto negative = first_negative_value(*v.spectrum);
  if (!negative) return "";
  return " (" + number_text(negative->value) + " at " + number_text(negative->lambda_nm) + " nm)";
}

class Folder {
 public:
  Folder(const MaterialGraph& g, const GraphTyping& t) : g_(g), t_(t) {}

  FoldedGraph run() {
    const size_t count = g_.nodes.size();
    f_.inputs.resize(count);
    f_.outputs.resize(count);
    f_.runtime.assign(count, false);
    for (int n : t_.order) fold_node(n);
    return std::move(f_);
  }

 private:
  void fold_node(int n) {
    const GraphNode& node = g_.nodes[n];
    const TypeResolution& types = t_.types[n];
    for (size_t i = 0; i < node.inputs.size(); ++i)
      f_.inputs[n].push_back(resolve_input(n, static_cast<int>(i)));

    std::vector<Operand>& outs = f_.outputs[n];
    bool all_constant = true;
    for (size_t o = 0; o < types.outputs.size(); ++o) {
      const std::optional<NodeValue>& prepared = node.prepared.constant_outputs[o];
      outs.push_back(prepared ? constant(*prepared) : produced_by(n, static_cast<int>(o)));
      all_constant = all_constant && prepared;
    }
    if (all_constant || fold_by_definition(n) || fold_by_evaluation(n)) return;
    f_.runtime[n] = true;
  }

  static Operand constant(const NodeValue& v) {
    Operand op;
    op.constant = true;
    op.value = v;
    op.type = v.type;
    return op;
  }

  Operand produced_by(int n, int o) const {
    Operand op;
    op.source = {n, o};
    op.source_type = op.type = t_.types[n].outputs[o];
    return op;
  }

  SpectralRole role_at(int n, int i) const {
    const SpectralRole socket = g_.nodes[n].def->inputs[i].role;
    return socket == SpectralRole::kInherit ? t_.conversion_role[n] : socket;
  }

  Operand resolve_input(int n, int i) {
    const GraphNode& node = g_.nodes[n];
    const GraphInput& in = node.inputs[i];
    const SocketType to = t_.types[n].inputs[i];
    Operand op = in.linked ? f_.outputs[in.link.node][in.link.output] : constant(in.constant);
    const SocketType from = op.constant ? op.value.type : op.source_type;

    SpectralRole role = role_at(n, i);
    if (role == SpectralRole::kNone) {
      if (from == SocketType::kColour && to == SocketType::kSpectrum)
        g_.fail(n, node.def->inputs[i].name,
                "this colour becomes a spectrum whose result feeds both reflectance and illuminant inputs; "
                "convert "
                "it explicitly with an rgb_to_spectrum node");
      role = SpectralRole::kReflectance;
    }
    if (op.constant) {
      validate(n, i, op.value, in.linked ? " (from " + g_.describe(in.link) + ")" : "");
      op.value = convert_constant(op.value, to, role);
    }
    op.type = to;
    op.role = role;
    return op;
  }

  // NaN / infinity and the socket's range, on the constant that reaches the input.
  void validate(int n, int i, const NodeValue& v, const std::string& origin) const {
    const SocketDef& s = g_.nodes[n].def->inputs[i];
    if (v.type == SocketType::kClosure) return;
    if (!is_finite(v)) g_.fail(n, s.name, "NaN or infinite value " + v.describe() + origin);
    const bool below = s.min && min_component(v) < *s.min;
    const bool above = s.max && max_component(v) > *s.max;
    if (!below && !above) return;
    std::string what;
    if (s.min && s.max)
      what = "value " + v.describe() + origin + " is outside [" + number_text(*s.min) + ", " +
             number_text(*s.max) + "]";
    else if (below && *s.min == 0.0f)
      what = "negative value " + v.describe() + origin + negative_wavelength(v) + " is not allowed";
    else if (below)
      what = "value " + v.describe() + origin + " is below the minimum " + number_text(*s.min);
    else
      what = "value " + v.describe() + origin + " is above the maximum " + number_text(*s.max);
    g_.fail(n, s.name, what);
  }

  bool fold_by_definition(int n) {
    const GraphNode& node = g_.nodes[n];
    if (!node.def->fold) return false;
    const std::vector<Operand>& ops = f_.inputs[n];
    std::vector<InputView> views;
    for (const Operand& op : ops) views.push_back({op.type, op.constant ? &op.value : nullptr});
    const FoldResult r = node.def->fold(FoldArgs{views, t_.types[n], node.prepared.payload.get()});

    std::vector<Operand>& outs = f_.outputs[n];
    switch (r.kind) {
      case FoldResult::Kind::kNone:
        return false;
      case FoldResult::Kind::kConstants:
        for (size_t o = 0; o < outs.size(); ++o) outs[o] = constant(r.outputs.at(o));
        return true;
      case FoldResult::Kind::kForward: {
        const Operand& in = ops.at(r.forward_input);
        // Only a value that needs no conversion can stand for the output (else the node still
        // has work to do: converting).
        if (in.type != t_.types[n].outputs[0]) return false;
        if (!in.constant && in.source_type != in.type) return false;
        outs[0] = in;
        return true;
      }
    }
    return false;
  }

  // Nodes that read nothing but their inputs, all constant, are run once now. A spectrum result
  // is only folded from flat spectra and floats (it is then flat too); an upsampled colour is not.
  bool fold_by_evaluation(int n) {
    const GraphNode& node = g_.nodes[n];
    const TypeResolution& types = t_.types[n];
    if (node.def->context_usage != 0) return false;
    bool spectral_result = false;
    for (SocketType t : types.outputs) {
      if (t == SocketType::kClosure) return false;
      spectral_result = spectral_result || t == SocketType::kSpectrum;
    }
    for (const Operand& op : f_.inputs[n]) {
      if (!op.constant) return false;
      if (op.type == SocketType::kSpectrum && !op.value.spectrum->is_constant()) return false;
      if (spectral_result && op.type != SocketType::kSpectrum && op.type != SocketType::kFloat) return false;
    }
    const NodeFn fn = runtime_function(*node.def, types);
    if (!fn) return false;

    std::vector<float> frame;
    std::vector<uint16_t> in, out;
    auto allocate = [&frame](SocketType t) {
      const auto at = static_cast<uint16_t>(frame.size());
      frame.resize(frame.size() + register_floats(t));
      return at;
    };
    for (const Operand& op : f_.inputs[n]) {
      in.push_back(allocate(op.type));
      store_constant(frame, in.back(), op.value);
    }
    for (SocketType t : types.outputs) out.push_back(allocate(t));

    const SampledWavelengths lambda = SampledWavelengths::fixed(SampledSpectrum(550.0f));
    ShadingContext ctx;
    ctx.lambda = &lambda;
    // A NaN or an overflow here stays in the folded constant: the input it reaches rejects it by name.
    NonFiniteTally keep_non_finite;
    keep_non_finite.keep_values = true;
    ctx.nonfinite = &keep_non_finite;
    LobeArena arena(64);
    Closure closure;
    fn(NodeArgs{ctx, frame.data(), in.data(), out.data(), node.prepared.payload.get(), ~0u, arena, closure});
    for (size_t o = 0; o < out.size(); ++o)
      f_.outputs[n][o] = constant(load_constant(frame, out[o], types.outputs[o]));
    return true;
  }

  const MaterialGraph& g_;
  const GraphTyping& t_;
  FoldedGraph f_;
};

}  // namespace

FoldedGraph fold_constants(const MaterialGraph& graph, const GraphTyping& typing) {
  return Folder(graph, typing).run();
}

NodeFn runtime_function(const NodeDefinition& def, const TypeResolution& types) {
  return def.select ? def.select(types) : def.eval;
}

}  // namespace ochre
