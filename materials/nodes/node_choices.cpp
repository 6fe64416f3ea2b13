#include "materials/nodes/node_choices.h"

#include <algorithm>
#include <stdexcept>

#include "materials/nodes/json_literal.h"

namespace ochre {

namespace {

const ParamDef& declared_choice(const PrepareArgs& args, std::string_view name) {
  const ParamDef* p = args.node.param(name);
  if (!p || p->choices.empty())
    throw std::logic_error("node '" + args.node.name + "' declares no choice parameter '" +
                           std::string(name) + "'");
  return *p;
}

}  // namespace

std::string unknown_choice(const ParamDef& p, const std::string& value) {
  std::string words;
  for (const std::string& c : p.choices) words += (words.empty() ? "" : ", ") + c;
  return "'" + value + "' is not one of: " + words;
}

int choice_index(const PrepareArgs& args, std::string_view name) {
  const ParamDef& p = declared_choice(args, name);
  const auto given = args.params.find(name);
  if (given == args.params.end()) return -1;
  if (!given->is_string()) throw NodeError(p.name, "expected a string, got " + json_excerpt(*given));
  const std::string value = given->get<std::string>();
  const auto it = std::find(p.choices.begin(), p.choices.end(), value);
  if (it == p.choices.end()) throw NodeError(p.name, unknown_choice(p, value));
  return static_cast<int>(it - p.choices.begin());
}

std::optional<std::string> choice_name(const PrepareArgs& args, std::string_view name) {
  const int i = choice_index(args, name);
  if (i < 0) return std::nullopt;
  return args.node.param(name)->choices[i];
}

std::size_t table_choice_index(const PrepareArgs& args, std::string_view name,
                               std::span<const char* const> words) {
  const ParamDef& p = declared_choice(args, name);
  const bool same = std::equal(p.choices.begin(), p.choices.end(), words.begin(), words.end(),
                               [](const std::string& a, const char* b) { return a == b; });
  if (!same)
    throw std::logic_error("node '" + args.node.name + "': the choices of '" + p.name +
                           "' are not the table it is read with");
  const int i = choice_index(args, name);
  if (i < 0) throw std::logic_error("node '" + args.node.name + "': '" + p.name + "' has no value");
  return static_cast<std::size_t>(i);
}

}  // namespace ochre
