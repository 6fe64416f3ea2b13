#include "renderer/loader/mitsuba/mitsuba_xml.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <pugixml.hpp>

#include "spectra/input_error.h"
#include "spectra/input_file.h"

namespace ochre {

namespace {

constexpr int kMaxIncludeDepth = 15;  // as Mitsuba 3
constexpr int kMaxNesting = 100;      // elements within elements: scenes use a handful; bounds the recursion
// Parameter substitution is bounded: defaults that expand each other ($b = "$a$a$a$a", $c = "$b$b$b$b", ...)
// grow exponentially (a 673-byte file became 53 MB, one level more 2 GB). An attribute may not grow beyond
// kMaxSubstitutedAttribute by substitution, nor the document's attributes beyond kMaxSubstitutedTotal in all.
constexpr size_t kMaxSubstitutedAttribute = size_t(1) << 20;
constexpr size_t kMaxSubstitutedTotal = size_t(64) << 20;

// One file's text, for line numbers of elements and of syntax errors.
struct SourceFile {
  std::string display;  // as named in messages
  std::filesystem::path path;
  std::string text;
  std::vector<size_t> line_starts;  // offset of each line's first character

  int line_of(ptrdiff_t offset) const {
    const auto it = std::upper_bound(line_starts.begin(), line_starts.end(), static_cast<size_t>(offset));
    return static_cast<int>(it - line_starts.begin());
  }
  int column_of(ptrdiff_t offset) const {
    return static_cast<int>(offset - static_cast<ptrdiff_t>(line_starts[line_of(offset) - 1])) + 1;
  }
};

struct Parameter {
  std::string name;
  std::string value;
  bool from_outside = false;
  bool used = false;
};

[[noreturn]] void fail_at_element(const MitsubaElement& element, const std::string& message) {
  throw InputError(fmt::format("{}: {}", element.where(), message));
}

// Checks that `element` has only the attributes in `allowed`; names prefixed with '!' are required.
void check_attributes(const MitsubaElement& element, std::initializer_list<std::string_view> allowed) {
  for (const auto& attribute : element.attributes) {
    const std::string& name = attribute.first;
    const bool known = std::any_of(allowed.begin(), allowed.end(), [&](std::string_view a) {
      return (a.front() == '!' ? a.substr(1) : a) == name;
    });
    if (!known) {
      std::string list;
      for (std::string_view a : allowed)
        list += (list.empty() ? "" : ", ") + std::string(a.front() == '!' ? a.substr(1) : a);
      fail_at_element(element,
                      fmt::format("unexpected attribute \"{}\" (<{}> takes: {})", name, element.tag, list));
    }
  }
  for (std::string_view a : allowed)
    if (a.front() == '!' && !element.has(a.substr(1)))
      fail_at_element(element, fmt::format("missing attribute \"{}\"", a.substr(1)));
}

class XmlReader {
 public:
  XmlReader(MitsubaDocument& document, const std::vector<std::pair<std::string, std::string>>& outside)
      : document_(document) {
    for (const auto& [name, value] : outside) {
      if (name.empty()) throw InputError("a scene parameter needs a name (NAME=VALUE)");
      if (find(name)) throw InputError(fmt::format("scene parameter '{}' is given twice", name));
      parameters_.push_back({name, value, true, false});
    }
  }

  // Reads the scene file into `root` (which must stay in place while it is read).
  void read_root(const std::filesystem::path& file, MitsubaElement& root) {
    main_display_dir_ = file.parent_path();
    const SourceFile& source = load(file, file.string());
    root = element_of(document_root(source), source);
    if (root.tag != "scene") fail_at_element(root, "the root element of a Mitsuba scene must be <scene>");
    check_version(root);
    check_attributes(root, {"!version"});
    root_ = &root;
    include_stack_.push_back(std::filesystem::weakly_canonical(file));
    read_children(document_root(source), source, root, 0);
    for (const Parameter& p : parameters_)
      if (p.from_outside && !p.used)
        throw InputError(fmt::format("{}: scene parameter '{}' is not used by the scene (no \"${}\" in it)",
                                     file.string(), p.name, p.name));
  }

 private:
  const SourceFile& load(const std::filesystem::path& path, std::string display) {
    auto source = std::make_unique<SourceFile>();
    source->display = std::move(display);
    source->path = path;
    source->text = read_input_file(path, kSceneFileInput);
    source->line_starts.push_back(0);
    for (size_t i = 0; i < source->text.size(); ++i)
      if (source->text[i] == '\n') source->line_starts.push_back(i + 1);
    auto doc = std::make_unique<pugi::xml_document>();
    const pugi::xml_parse_result result = doc->load_buffer(source->text.data(), source->text.size());
    if (!result)
      throw InputError(fmt::format("{}:{}: column {}: malformed XML ({})", source->display,
                                   source->line_of(result.offset), source->column_of(result.offset),
                                   result.description()));
    if (!doc->document_element())
      throw InputError(fmt::format("{}: the file holds no XML element", source->display));
    documents_.push_back(std::move(doc));
    sources_.push_back(std::move(source));
    return *sources_.back();
  }

  pugi::xml_node document_root(const SourceFile& source) const {
    for (size_t i = 0; i < sources_.size(); ++i)
      if (sources_[i].get() == &source) return documents_[i]->document_element();
    return {};
  }

  Parameter* find(const std::string& name) {
    for (Parameter& p : parameters_)
      if (p.name == name) return &p;
    return nullptr;
  }

  // $name -> value in one attribute value, longest names first (a name may be the prefix of another);
  // "\$" stays a literal "$".
  std::string substitute(const std::string& text, const MitsubaElement& element) {
    if (text.find('$') == std::string::npos) return text;
    std::vector<Parameter*> by_length;
    for (Parameter& p : parameters_) by_length.push_back(&p);
    std::stable_sort(by_length.begin(), by_length.end(),
                     [](const Parameter* a, const Parameter* b) { return a->name.size() > b->name.size(); });
    std::string result;
    for (size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == '$') {
        result += '$';
        ++i;
        continue;
      }
      if (text[i] != '$') {
        result += text[i];
        continue;
      }
      Parameter* match = nullptr;
      for (Parameter* p : by_length)
        if (text.compare(i + 1, p->name.size(), p->name) == 0) {
          match = p;
          break;
        }
      if (!match) {
        size_t end = i + 1;
        while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_'))
          ++end;
        fail_at_element(
            element,
            fmt::format("undefined parameter \"${}\" (define it with <default name=\"{}\" value=\"...\"/> "
                        "before its use, or give it from outside: ochre render -D {}=...)",
                        text.substr(i + 1, end - i - 1), text.substr(i + 1, end - i - 1),
                        text.substr(i + 1, end - i - 1)));
      }
      match->used = true;
      if (result.size() + match->value.size() > kMaxSubstitutedAttribute)
        fail_at_element(element, fmt::format("parameter substitution makes an attribute longer than {} bytes "
                                             "(\"${}\" and the parameters it names expand each other?)",
                                             kMaxSubstitutedAttribute, match->name));
      result += match->value;
      i += match->name.size();
    }
    substituted_bytes_ += result.size();
    if (substituted_bytes_ > kMaxSubstitutedTotal)
      fail_at_element(element,
                      fmt::format("parameter substitution makes the scene's attributes longer than {} "
                                  "bytes in all",
                                  kMaxSubstitutedTotal));
    return result;
  }

  MitsubaElement element_of(pugi::xml_node node, const SourceFile& source) {
    MitsubaElement e;
    e.tag = node.name();
    e.file = source.display;
    e.line = source.line_of(node.offset_debug());
    e.directory = source.path.parent_path();
    for (const pugi::xml_attribute& a : node.attributes()) e.attributes.emplace_back(a.name(), a.value());
    for (auto& [name, value] : e.attributes) value = substitute(value, e);
    return e;
  }

  void check_version(const MitsubaElement& root) {
    const std::string* version = root.attribute("version");
    if (!version)
      fail_at_element(root,
                      "missing attribute \"version\" (Mitsuba 3 scenes start <scene version=\"3.0.0\">)");
    int major = -1, minor = -1, patch = -1;
    char tail = 0;
    if (std::sscanf(version->c_str(), "%d.%d.%d%c", &major, &minor, &patch, &tail) != 3 || major < 0 ||
        minor < 0 || patch < 0)
      fail_at_element(root, fmt::format("version \"{}\" is not a version number x.y.z", *version));
    if (major < 2 || major > 3)
      fail_at_element(
          root,
          fmt::format("version {}: ochre reads Mitsuba 2.x and 3.x scenes (Mitsuba 0.x scenes name their "
                      "parameters differently: convert them with Mitsuba 3 first)",
                      *version));
  }

  void read_children(pugi::xml_node node, const SourceFile& source, MitsubaElement& parent, int depth) {
    struct Level {
      int& n;
      explicit Level(int& count) : n(++count) {}
      ~Level() { --n; }
    } level(nesting_);
    if (nesting_ > kMaxNesting)
      fail_at_element(parent, fmt::format("elements are nested more than {} deep", kMaxNesting));
    for (pugi::xml_node child : node.children()) {
      if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) {
        MitsubaElement where = parent;
        where.line = source.line_of(child.offset_debug());
        fail_at_element(where, fmt::format("unexpected text \"{}\" inside <{}>", child.value(), parent.tag));
      }
      if (child.type() != pugi::node_element) continue;  // comments, declarations, processing instructions
      MitsubaElement e = element_of(child, source);
      if (e.tag == "include") {
        include(e, parent, depth);
      } else if (e.tag == "default") {
        check_attributes(e, {"!name", "!value"});
        if (e.name().empty()) fail_at_element(e, "the name of a <default> must not be empty");
        if (!find(e.name())) parameters_.push_back({e.name(), *e.attribute("value"), false, false});
      } else if (e.tag == "path") {
        check_attributes(e, {"!value"});
        if (&parent != root_) fail_at_element(e, "<path> may only appear directly inside the root <scene>");
        std::filesystem::path dir = *e.attribute("value");
        if (dir.is_relative()) dir = e.directory / dir;
        std::error_code error;
        if (!std::filesystem::is_directory(dir, error))
          fail_at_element(e, fmt::format("\"{}\" is not a directory", dir.string()));
        document_.search_dirs.insert(document_.search_dirs.begin(), dir);
      } else {
        read_children(child, source, e, depth);
        parent.children.push_back(std::move(e));
      }
    }
  }

  void include(const MitsubaElement& e, MitsubaElement& parent, int depth) {
    check_attributes(e, {"!filename", "name"});
    const std::filesystem::path path = resolve_mitsuba_file(document_, e, *e.attribute("filename"));
    if (depth + 1 > kMaxIncludeDepth)
      fail_at_element(e, fmt::format("includes are nested more than {} deep", kMaxIncludeDepth));
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path);
    if (std::find(include_stack_.begin(), include_stack_.end(), canonical) != include_stack_.end())
      fail_at_element(
          e, fmt::format("\"{}\" includes itself (through the files that include it)", path.string()));
    // Named like the scene file: the path the user gave for it, followed into the include.
    const std::filesystem::path relative = path.lexically_relative(document_.main_directory);
    const std::string display =
        relative.empty() ? path.string() : (main_display_dir_ / relative).lexically_normal().string();
    const SourceFile* source = nullptr;
    try {
      source = &load(path, display);
    } catch (const InputError& error) {
      fail_at_element(e, error.what());
    }
    include_stack_.push_back(canonical);
    const pugi::xml_node root_node = document_root(*source);
    MitsubaElement root = element_of(root_node, *source);
    check_version(root);
    if (root.tag == "scene") {
      check_attributes(root, {"!version"});
      read_children(root_node, *source, parent, depth + 1);  // the included scene's children join the parent
    } else {
      root.attributes.erase(std::remove_if(root.attributes.begin(), root.attributes.end(),
                                           [](const auto& a) { return a.first == "version"; }),
                            root.attributes.end());
      if (const std::string* name = e.attribute("name")) root.attributes.emplace_back("name", *name);
      read_children(root_node, *source, root, depth + 1);
      parent.children.push_back(std::move(root));
    }
    include_stack_.pop_back();
  }

 private:
  MitsubaDocument& document_;
  const MitsubaElement* root_ = nullptr;
  std::filesystem::path main_display_dir_;
  std::vector<Parameter> parameters_;
  std::vector<std::unique_ptr<SourceFile>> sources_;
  std::vector<std::unique_ptr<pugi::xml_document>> documents_;
  std::vector<std::filesystem::path> include_stack_;
  int nesting_ = 0;
  size_t substituted_bytes_ = 0;  // attribute bytes after substitution, for kMaxSubstitutedTotal
};

void register_ids(const MitsubaElement& element, MitsubaDocument& document) {
  for (const MitsubaElement& child : element.children) {
    const std::string* id = child.attribute("id");
    if (id && child.tag != "ref" && child.tag != "alias") {
      const auto [it, inserted] = document.ids.emplace(*id, &child);
      if (!inserted)
        fail_at_element(child, fmt::format("duplicate id \"{}\" (first at {})", *id, it->second->where()));
    }
    register_ids(child, document);
  }
}

void register_aliases(const MitsubaElement& element, MitsubaDocument& document) {
  for (const MitsubaElement& child : element.children) {
    if (child.tag == "alias") {
      check_attributes(child, {"!id", "!as"});
      const auto source = document.ids.find(*child.attribute("id"));
      if (source == document.ids.end())
        fail_at_element(child, fmt::format("no element has id \"{}\"", *child.attribute("id")));
      const auto [it, inserted] = document.ids.emplace(*child.attribute("as"), source->second);
      if (!inserted)
        fail_at_element(child, fmt::format("duplicate id \"{}\" (first at {})", *child.attribute("as"),
                                           it->second->where()));
    }
    register_aliases(child, document);
  }
}

}  // namespace

const std::string* MitsubaElement::attribute(std::string_view name) const {
  for (const auto& [key, value] : attributes)
    if (key == name) return &value;
  return nullptr;
}

std::string MitsubaElement::name() const {
  const std::string* n = attribute("name");
  return n ? *n : std::string();
}

std::string MitsubaElement::where() const {
  std::string text = fmt::format("{}:{}: <{}", file, line, tag);
  for (const char* key : {"type", "name", "id"})
    if (const std::string* value = attribute(key)) text += fmt::format(" {}=\"{}\"", key, *value);
  return text + ">";
}

std::unique_ptr<MitsubaDocument> read_mitsuba_xml(
    const std::filesystem::path& file, const std::vector<std::pair<std::string, std::string>>& parameters) {
  auto document = std::make_unique<MitsubaDocument>();
  document->main_directory = std::filesystem::absolute(file).parent_path();
  XmlReader reader(*document, parameters);
  reader.read_root(file, document->scene);
  register_ids(document->scene, *document);
  register_aliases(document->scene, *document);
  return document;
}

std::filesystem::path resolve_mitsuba_file(const MitsubaDocument& document, const MitsubaElement& element,
                                           const std::string& name) {
  const std::filesystem::path given(name);
  if (name.empty()) fail_at_element(element, "the file name is empty");
  std::vector<std::filesystem::path> candidates;
  if (given.is_absolute()) {
    candidates.push_back(given);
  } else {
    candidates.push_back(element.directory / given);
    for (const auto& dir : document.search_dirs) candidates.push_back(dir / given);
    candidates.push_back(document.main_directory / given);
  }
  std::error_code error;
  for (const auto& c : candidates)
    if (std::filesystem::exists(c, error)) return c.lexically_normal();
  std::string looked;
  for (const auto& c : candidates) looked += (looked.empty() ? "" : ", ") + c.lexically_normal().string();
  fail_at_element(element, fmt::format("file \"{}\" not found (looked for {})", name, looked));
}

std::string mitsuba_file_for_json(const MitsubaDocument& document, const MitsubaElement& element,
                                  const std::string& name) {
  const std::filesystem::path path = std::filesystem::absolute(resolve_mitsuba_file(document, element, name));
  const std::filesystem::path relative = path.lexically_relative(document.main_directory);
  const bool inside = !relative.empty() && *relative.begin() != "..";
  return (inside ? relative : path).lexically_normal().string();
}

}  // namespace ochre
