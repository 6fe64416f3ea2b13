#include "materials/nodes/node_definition.h"

namespace ochre {

int NodeDefinition::input_index(std::string_view socket) const {
  for (size_t i = 0; i < inputs.size(); ++i)
    if (inputs[i].name == socket) return static_cast<int>(i);
  return -1;
}

int NodeDefinition::output_index(std::string_view socket) const {
  for (size_t i = 0; i < outputs.size(); ++i)
    if (outputs[i].name == socket) return static_cast<int>(i);
  return -1;
}

const ParamDef* NodeDefinition::param(std::string_view param_name) const {
  for (const ParamDef& p : params)
    if (p.name == param_name) return &p;
  return nullptr;
}

bool NodeDefinition::has_closure_output() const {
  for (const OutputDef& o : outputs)
    if (o.type == SocketType::kClosure) return true;
  return false;
}

}  // namespace ochre
