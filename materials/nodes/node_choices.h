#pragma once
// Choice parameters: string parameters that take one of a fixed list of words (ParamDef::choices). A node
// that turns the word into a value of its own (an enum) lists the words with their values once, in a
// table of Choice entries; its definition declares the words from that table (choice_names) and its
// prepare() reads the parameter through the same table (choice_value). So no node compares a word by hand,
// and no word falls back silently to a default: the graph parser rejects a value that is not declared
// (docs/nodes.md, 'Errors'), and the reading here rejects it too, for a prepare() called without the parser.

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "materials/nodes/node_definition.h"

namespace ochre {

// One word of a choice parameter and the value a node makes of it.
template <class E>
struct Choice {
  const char* name;
  E value;
};

// The words of a table, in order, for the ParamDef (choice_param in definition_builders.h).
template <class E, std::size_t N>
std::vector<std::string> choice_names(const std::array<Choice<E>, N>& table) {
  std::vector<std::string> names;
  for (const Choice<E>& c : table) names.emplace_back(c.name);
  return names;
}

// The message for a value of choice parameter `p` that is not one of its declared words: "'x' is not one
// of: a, b, c" (the graph parser's and choice_index's).
std::string unknown_choice(const ParamDef& p, const std::string& value);

// The value of choice parameter `name` as its index in the declared ParamDef::choices, or -1 when the
// parameter is absent (a choice without a default that the scene does not give). Any other value is a
// NodeError naming the parameter and listing the choices (the compiler adds the file, material and node).
int choice_index(const PrepareArgs& args, std::string_view name);

// The same as the declared word; empty when the parameter is absent.
std::optional<std::string> choice_name(const PrepareArgs& args, std::string_view name);

// The index of the value of `name` in `words`, which must be the parameter's declared choices in their
// order (std::logic_error otherwise, and when the parameter is absent). The checks of choice_index.
std::size_t table_choice_index(const PrepareArgs& args, std::string_view name,
                               std::span<const char* const> words);

// The value `table` pairs with the word parameter `name` holds; the parameter's choices are declared from
// `table` (choice_names). For a parameter with a default, or one the caller found present.
template <class E, std::size_t N>
E choice_value(const PrepareArgs& args, std::string_view name, const std::array<Choice<E>, N>& table) {
  std::array<const char*, N> words;
  for (std::size_t i = 0; i < N; ++i) words[i] = table[i].name;
  return table[table_choice_index(args, name, words)].value;
}

}  // namespace ochre
