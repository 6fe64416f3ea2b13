#include "materials/graph/program_builder.h"

#include <algorithm>
#include <map>
#include <optional>
#include <tuple>

#include "materials/graph/frame_layout.h"
#include "materials/lobes/lobe.h"
#include "materials/nodes/conversion_kernels.h"
#include "spectra/memoized_spectrum.h"

namespace ochre {

namespace {

class Builder {
 public:
  Builder(const MaterialGraph& g, const GraphTyping& t, const FoldedGraph& f)
      : g_(g),
        t_(t),
        f_(f),
        live_(g.nodes.size(), false),
        used_(g.nodes.size(), 0),
        registers_(g.nodes.size()),
        gate_register_(g.nodes.size(), kUngated) {}

  BuiltProgram run() {
    const Operand& output = f_.outputs[g_.output.node][g_.output.output];
    mark_live(output.source);
    for (int n : t_.order)
      if (live_[n]) allocate_outputs(n);
    const uint16_t output_weight = registers_[output.source.node][output.source.output];
    for (int k = 0; k < kSpectrumSamples; ++k) p_.initial_frame[output_weight + k] = 1.0f;

    find_gates();
    for (int n : t_.order)
      if (live_[n]) emit_node(n);
    // Closure weights flow from the output to the leaves: consumers before producers.
    std::reverse(p_.closures.begin(), p_.closures.end());
    std::reverse(p_.closure_labels.begin(), p_.closure_labels.end());
    collect_facts();
    return {std::move(p_), facts_};
  }

 private:
  // Dead-node removal: only what the output reaches, through non-constant operands, remains.
  void mark_live(const OutputRef& ref) {
    used_[ref.node] |= 1u << ref.output;
    if (live_[ref.node]) return;
    live_[ref.node] = true;
    for (const Operand& op : f_.inputs[ref.node])
      if (!op.constant) mark_live(op.source);
  }

  // Gated value nodes: a value node whose every use is as a factor of a value `multiply` whose other factor
  // is one and the same float, computed before it, need not run while that float is 0: the products are 0
  // whatever it computes (all values are finite). A texture mask times the `inside` of its projection is the
  // case that pays: most of a painted cave lies outside its panel, where its five mask lookups took about 10
  // % of the render time (docs/performance.md, cave-painting scene).
  void find_gates() {
    std::vector<int> position(g_.nodes.size(), -1);
    for (size_t i = 0; i < t_.order.size(); ++i) position[t_.order[i]] = static_cast<int>(i);
    std::vector<std::optional<OutputRef>> gate(g_.nodes.size());
    std::vector<bool> gateable(g_.nodes.size(), true);
    for (int n : t_.order) {
      if (!live_[n]) continue;
      for (size_t i = 0; i < f_.inputs[n].size(); ++i) {
        const Operand& op = f_.inputs[n][i];
        if (op.constant) continue;
        const int v = op.source.node;
        const std::optional<OutputRef> factor = other_float_factor(n, i);
        if (!factor || factor->node == v || position[factor->node] > position[v] ||
            (gate[v] && *gate[v] != *factor))
          gateable[v] = false;
        else
          gate[v] = factor;
      }
    }
    for (size_t v = 0; v < g_.nodes.size(); ++v)
      if (live_[v] && gateable[v] && gate[v] && t_.types[v].outputs[0] != SocketType::kClosure)
        gate_register_[v] = registers_[gate[v]->node][gate[v]->output];
  }

  // When node n is a value `multiply` whose input i reads its source unconverted and whose other input is a
  // non-constant float (converted or not): that float's source.
  std::optional<OutputRef> other_float_factor(int n, size_t i) const {
    const std::vector<Operand>& in = f_.inputs[n];
    if (g_.nodes[n].def->name != "multiply" || t_.types[n].outputs[0] == SocketType::kClosure ||
        in.size() != 2)
      return std::nullopt;
    const Operand &self = in[i], &other = in[1 - i];
    if (self.source_type != self.type || other.constant || other.source_type != SocketType::kFloat)
      return std::nullopt;
    return other.source;
  }

  uint16_t allocate(SocketType type) {
    const size_t at = p_.initial_frame.size();
    const size_t size = at + register_floats(type);
    if (size > static_cast<size_t>(kMaxFrameFloats))
      g_.fail(
          -1, "",
          "material too large: it needs more than " + std::to_string(kMaxFrameFloats) + " register floats");
    p_.initial_frame.resize(size, 0.0f);
    varying_.resize(size, false);
    return static_cast<uint16_t>(at);
  }

  void allocate_outputs(int n) {
    for (SocketType type : t_.types[n].outputs) registers_[n].push_back(allocate(type));
  }

  void emit(bool closure, NodeFn fn, const void* payload, const std::vector<uint16_t>& in,
            const std::vector<uint16_t>& out, uint32_t used, std::string label, uint16_t gate = kUngated) {
    Instruction ins;
    ins.gate = gate;
    ins.fn = fn;
    ins.payload = payload;
    ins.first_operand = static_cast<uint32_t>(p_.operands.size());
    ins.input_count = static_cast<uint16_t>(in.size());
    ins.output_count = static_cast<uint16_t>(out.size());
    ins.outputs_used = used;
    p_.operands.insert(p_.operands.end(), in.begin(), in.end());
    p_.operands.insert(p_.operands.end(), out.begin(), out.end());
    (closure ? p_.closures : p_.values).push_back(ins);
    (closure ? p_.closure_labels : p_.value_labels).push_back(std::move(label));
  }

  void emit_node(int n) {
    const GraphNode& node = g_.nodes[n];
    std::vector<uint16_t> in;
    bool varying_input = false, non_spectral_input = false;
    for (const Operand& op : f_.inputs[n]) {
      in.push_back(operand_register(op));
      if (op.type == SocketType::kSpectrum && varying_[in.back()])
        facts_.spectrally_varying = varying_input = true;
      non_spectral_input =
          non_spectral_input || (op.type != SocketType::kSpectrum && op.type != SocketType::kFloat);
    }
    // A spectrum computed from varying spectra, colours or the wavelengths themselves varies.
    const bool varying_output =
        varying_input || non_spectral_input || (node.def->context_usage & kUsesWavelengths) != 0;
    for (size_t o = 0; o < registers_[n].size(); ++o)
      if (t_.types[n].outputs[o] == SocketType::kSpectrum && varying_output)
        varying_[registers_[n][o]] = true;

    if (node.prepared.payload) p_.payloads.push_back(node.prepared.payload);
    const bool closure = t_.types[n].outputs[0] == SocketType::kClosure;
    emit(closure, runtime_function(*node.def, t_.types[n]), node.prepared.payload.get(), in, registers_[n],
         used_[n], node.def->name + " '" + node.name + "'", gate_register_[n]);
  }

  uint16_t operand_register(const Operand& op) {
    if (op.constant) {
      if (op.type == SocketType::kSpectrum && !op.value.spectrum->is_constant())
        return sampled(op.value.spectrum);
      const uint16_t at = allocate(op.type);
      store_constant(p_.initial_frame, at, op.value);
      return at;
    }
    const uint16_t source = registers_[op.source.node][op.source.output];
    if (op.source_type == op.type) return source;
    return converted(source, op);
  }

  // A pre-built spectrum that varies with wavelength is sampled once per evaluation.
  uint16_t sampled(const SpectrumPtr& s) {
    if (auto it = sampled_.find(s.get()); it != sampled_.end()) return it->second;
    const uint16_t at = allocate(SocketType::kSpectrum);
    varying_[at] = true;
    p_.spectra.push_back(s);
    auto payload = std::make_shared<const MemoizedSpectrum>(s);
    p_.payloads.push_back(payload);
    emit(false, sample_spectrum_kernel, payload.get(), {}, {at}, 1u,
         "sample spectrum " + NodeValue::of_spectrum(s).describe());
    sampled_[s.get()] = at;
    return at;
  }

  uint16_t converted(uint16_t source, const Operand& op) {
    const auto key = std::make_tuple(source, op.type, op.role);
    if (auto it = converted_.find(key); it != converted_.end()) return it->second;
    const uint16_t at = allocate(op.type);
    const bool upsampled = op.source_type == SocketType::kColour && op.type == SocketType::kSpectrum;
    varying_[at] = upsampled;
    std::string label = std::string("convert ") + to_string(op.source_type) + " -> " + to_string(op.type);
    if (upsampled) label += std::string(" (") + to_string(op.role) + ")";
    emit(false, conversion_kernel(op.source_type, op.type, op.role), nullptr, {source}, {at}, 1u, label);
    converted_[key] = at;
    return at;
  }

  void collect_facts() {
    uint32_t usage = 0, lobe_flags = 0;
    int max_lobes = 0;
    for (size_t n = 0; n < g_.nodes.size(); ++n) {
      if (!live_[n]) continue;
      const GraphNode& node = g_.nodes[n];
      usage |= node.def->context_usage;
      if (!node.hidden && n < static_cast<size_t>(g_.declared)) ++facts_.nodes_compiled;
      if (!node.def->closure_traits) continue;
      std::vector<InputView> views;
      for (const Operand& op : f_.inputs[n]) views.push_back({op.type, op.constant ? &op.value : nullptr});
      const ClosureTraits traits = node.def->closure_traits(views, node.prepared.payload.get());
      lobe_flags |= traits.lobe_flags;
      if (traits.lobe_flags != 0) max_lobes += traits.max_lobes;
      facts_.is_emissive = facts_.is_emissive || traits.emits;
    }
    // A leaf used twice still adds its lobes once (its weights are summed first).
    if (max_lobes > Closure::kMaxLobes)
      g_.fail(-1, "",
              "the material can produce " + std::to_string(max_lobes) + " BSDF lobes; at most " +
                  std::to_string(Closure::kMaxLobes) + " are supported");
    facts_.has_lobes = lobe_flags != 0;
    facts_.polarizes = (lobe_flags & kLobePolarizing) != 0;
    facts_.has_delta_lobes = (lobe_flags & kLobeDelta) != 0;
    facts_.needs_uv = (usage & kUsesUV) != 0;
    facts_.needs_vertex_colour = (usage & kUsesVertexColour) != 0;
    facts_.uniform_over_surface =
        (usage & (kUsesUV | kUsesVertexColour | kUsesTextures | kUsesGeometry)) == 0;
    facts_.nodes_declared = g_.declared;
  }

  const MaterialGraph& g_;
  const GraphTyping& t_;
  const FoldedGraph& f_;
  std::vector<bool> live_;
  std::vector<uint32_t> used_;
  std::vector<std::vector<uint16_t>> registers_;  // per node and output
  std::vector<uint16_t> gate_register_;           // per node: its gate (find_gates), or kUngated
  std::vector<bool> varying_;                     // per frame float: a spectrum that varies with lambda
  std::map<const Spectrum*, uint16_t> sampled_;
  std::map<std::tuple<uint16_t, SocketType, SpectralRole>, uint16_t> converted_;
  Program p_;
  MaterialFacts facts_;
};

}  // namespace

BuiltProgram build_program(const MaterialGraph& graph, const GraphTyping& typing, const FoldedGraph& folded) {
  return Builder(graph, typing, folded).run();
}

}  // namespace ochre
