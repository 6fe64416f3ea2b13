#include "renderer/json/json_duplicate_keys.h"

#include <fmt/format.h>

#include <set>
#include <vector>

#include "spectra/input_error.h"

namespace ochre {

namespace {

using Event = nlohmann::json::parse_event_t;

// One open object or array while parsing: the keys seen so far, or the index of the current element.
struct Container {
  bool is_array = false;
  size_t elements = 0;  // arrays: elements completed so far (= index of the one being parsed)
  std::string key;      // objects: the member being parsed
  std::set<std::string> keys;
};

// "shapes[0].radius": the path to the member being parsed in the innermost container.
std::string json_path(const std::vector<Container>& open) {
  std::string path;
  for (const Container& c : open) {
    if (c.is_array)
      path += fmt::format("[{}]", c.elements);
    else
      path += (path.empty() ? "" : ".") + c.key;
  }
  return path;
}

void element_done(std::vector<Container>& open) {
  if (!open.empty() && open.back().is_array) ++open.back().elements;
}

}  // namespace

nlohmann::json parse_json_rejecting_duplicate_keys(const std::string& text, const std::string& file) {
  std::vector<Container> open;
  const auto check = [&](int, Event event, nlohmann::json& parsed) {
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        open.emplace_back();
        open.back().is_array = event == Event::array_start;
        break;
      case Event::key: {
        Container& object = open.back();
        object.key = parsed.get<std::string>();
        if (!object.keys.insert(object.key).second)
          throw InputError(fmt::format("{}: {}: duplicate key \"{}\" (a key may appear once per object)",
                                       file, json_path(open), object.key));
        break;
      }
      case Event::object_end:
      case Event::array_end:
        open.pop_back();
        element_done(open);
        break;
      case Event::value:
        element_done(open);
        break;
    }
    return true;
  };
  return nlohmann::json::parse(text, check, /*allow_exceptions=*/true, /*ignore_comments=*/true);
}

}  // namespace ochre
