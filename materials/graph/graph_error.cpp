#include "materials/graph/graph_error.h"

#include <utility>

#include "spectra/input_error.h"

namespace ochre {

namespace {

std::string format_message(const std::string& file, const std::string& material, const std::string& node,
                           const std::string& parameter, const std::string& what) {
  std::string location;
  auto append = [&location](const char* kind, const std::string& name) {
    if (name.empty()) return;
    if (!location.empty()) location += ", ";
    location += std::string(kind) + " '" + name + "'";
  };
  append("material", material);
  append("node", node);
  append("parameter", parameter);

  std::string message = file;
  if (!location.empty()) message += message.empty() ? location : ": " + location;
  if (!message.empty()) message += ": ";
  return message + what;
}

}  // namespace

GraphError::GraphError(std::string file, std::string material, std::string node, std::string parameter,
                       const std::string& what)
    : std::runtime_error(visible_nul(format_message(file, material, node, parameter, what))),
      file_(std::move(file)),
      material_(std::move(material)),
      node_(std::move(node)),
      parameter_(std::move(parameter)),
      reason_(what) {}

}  // namespace ochre
