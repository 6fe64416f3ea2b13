#pragma once
// NodeDefinition: everything the compiler and the documentation know about one node type. A new
// node (a closure such as conductor or vgroove, a texture operation, ...) is one .cpp file that
// builds its NodeDefinition and is listed in builtin_nodes.cpp; nothing else changes.
//
// Life of a node: the scene's keys are checked against `inputs` and `params`; prepare() turns the
// parameters into compile-time data (load a file, open a texture) and may declare outputs
// constant; resolve_types() settles polymorphic sockets; fold() may replace the node by constants
// or by one of its inputs; otherwise the node becomes one instruction running `eval` (or the
// function select() picks for the resolved types) on every evaluation.

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "materials/nodes/node_args.h"
#include "materials/nodes/node_value.h"
#include "materials/nodes/socket_type.h"
#include "spectra/input_error.h"

namespace ochre {

class ResourceResolver;
struct NodeDefinition;

// What a node reads from the ShadingContext besides its inputs (facts, and no constant folding).
enum ContextUsage : uint32_t {
  kUsesUV = 1u << 0,
  kUsesVertexColour = 1u << 1,
  kUsesTextures = 1u << 2,
  kUsesWavelengths = 1u << 3,  // a result that depends on lambda beyond its spectrum inputs
  kUsesGeometry = 1u << 4,     // position or normal
};

struct SocketDef {
  std::string name;
  SocketType type = SocketType::kFloat;
  bool polymorphic = false;  // the type comes from resolve_types() (math nodes)
  NodeValue default_value;   // used when the input is not given
  std::string default_node;  // when set, an absent input is linked to a hidden node of this type ("uv")
  SpectralRole role = SpectralRole::kNone;  // how a colour becomes a spectrum here
  std::optional<float> min, max;            // allowed range of constants (every component)
  bool clamped = false;  // non-constant values are clamped to [min, max] at run time (documentation)
  std::string doc;
};

struct OutputDef {
  std::string name;
  SocketType type = SocketType::kFloat;
  bool polymorphic = false;
  std::string doc;
};

enum class ParamKind { kString, kInt, kFloat, kValue /* a float, [r,g,b] or {"vector": [x,y,z]} */ };

struct ParamDef {
  std::string name;
  ParamKind kind = ParamKind::kString;
  nlohmann::json default_value;  // null = no default (optional unless `required`)
  bool required = false;
  std::vector<std::string> choices;  // allowed strings (kString), empty = any
  std::optional<double> min, max;    // kInt / kFloat range
  std::string doc;
  // A research variant, not a setting of the product: kept to compare with a paper as printed (or with the
  // literature it cites) and to measure the product's choices; its default is the product's. Its doc starts
  // with "research:", and docs/nodes.md lists it in the node's "Research parameters" table.
  bool research = false;
};

// A fault a node hook reports; the compiler adds file, material and node names.
class NodeError : public std::runtime_error {
 public:
  NodeError(std::string parameter, const std::string& what)
      : std::runtime_error(visible_nul(what)), parameter_(std::move(parameter)) {}
  const std::string& parameter() const { return parameter_; }

 private:
  std::string parameter_;
};

struct PrepareArgs {
  const nlohmann::json& params;  // every declared parameter present in the scene, others absent
  ResourceResolver& resolver;
  const NodeDefinition& node;  // the node's own definition (its declared choices: node_choices.h)
};

struct Prepared {
  std::shared_ptr<const void> payload;                     // passed to eval as NodeArgs::payload
  std::vector<std::optional<NodeValue>> constant_outputs;  // outputs known at compile time
};

// Types on both sides of a node once polymorphism is settled: `inputs` are the types each input is
// converted to before the node runs, `outputs` the types it produces.
struct TypeResolution {
  std::vector<SocketType> inputs;
  std::vector<SocketType> outputs;
};

// What the compiler knows about one input while folding.
struct InputView {
  SocketType type;         // after conversion to the resolved input type
  const NodeValue* value;  // non-null when the input is a compile-time constant
  bool is_constant() const { return value != nullptr; }
};

struct FoldArgs {
  std::span<const InputView> inputs;
  const TypeResolution& types;
  const void* payload;  // Prepared::payload
};

struct FoldResult {
  enum class Kind { kNone, kConstants, kForward } kind = Kind::kNone;
  std::vector<NodeValue> outputs;  // kConstants: one per output
  int forward_input = -1;          // kForward: the (single) output is this input, unchanged
};

// What a closure leaf may add: lobes with these flags (the facts OR them), and/or emission.
struct ClosureTraits {
  uint32_t lobe_flags = 0;
  bool emits = false;
  int max_lobes = 1;  // lobes added per evaluation when lobe_flags != 0 (Closure holds at most 8)
};

struct NodeDefinition {
  std::string name;
  std::string doc;
  std::vector<SocketDef> inputs;
  std::vector<OutputDef> outputs;
  std::vector<ParamDef> params;
  uint32_t context_usage = 0;
  // A colour this node converts to spectrum is a dimensionless tint (reflectance semantics)
  // whatever the role of the node's result (multiply: a colour times a spectrum).
  bool colour_operands_are_tints = false;

  // Compile-time data from the parameters. Throws NodeError naming the parameter at fault.
  Prepared (*prepare)(const PrepareArgs&) = nullptr;
  // Polymorphic nodes: types from the types connected to the inputs. Throws NodeError naming the input.
  TypeResolution (*resolve_types)(std::span<const SocketType> connected) = nullptr;
  // Simplification at compile time (inputs after conversion). Nodes without context usage whose
  // inputs are all constant are folded by running `eval` even when this is null.
  FoldResult (*fold)(const FoldArgs& args) = nullptr;
  // Run-time function: `eval`, or for polymorphic nodes the one select() picks.
  NodeFn eval = nullptr;
  NodeFn (*select)(const TypeResolution& types) = nullptr;
  // Closure leaves: what they can produce given their (possibly constant) inputs and their prepared
  // payload (parameters such as a polarization model).
  ClosureTraits (*closure_traits)(std::span<const InputView> inputs, const void* payload) = nullptr;

  int input_index(std::string_view socket) const;   // -1 when absent
  int output_index(std::string_view socket) const;  // -1 when absent
  const ParamDef* param(std::string_view name) const;
  bool has_closure_output() const;
};

}  // namespace ochre
