#pragma once
// A Mitsuba 3 XML scene file read into a tree of elements (docs/mitsuba-import.md): <include>s expanded in
// place, <default>s and $name parameters substituted into attribute values, <alias> and <path> applied,
// and every element's file and line kept so that each message can name them.
//
// What this reader enforces, as Mitsuba's own parser does: well-formed XML; a root <scene> with a version
// attribute (2.x and 3.x are read; 0.x scenes use other parameter names); no text content; every $name
// defined (by a <default> before its use or by a parameter from outside); every outside parameter used;
// includes at most 15 deep and never cyclic; ids unique. Every problem throws InputError starting with
// "file:line: <element ...>: ".

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ochre {

struct MitsubaElement {
  std::string tag;                                              // "shape", "float", "ref", ...
  std::vector<std::pair<std::string, std::string>> attributes;  // in document order, substituted
  std::vector<MitsubaElement> children;
  std::string file;                 // the file as named in messages
  int line = 0;                     // 1-based
  std::filesystem::path directory;  // directory of that file: its relative file names resolve here first

  const std::string* attribute(std::string_view name) const;
  bool has(std::string_view name) const { return attribute(name) != nullptr; }
  // `name` attribute, or "" (property and object names).
  std::string name() const;
  // "fragments/shapes.xml:5: <shape type="obj" id="box">", the start of every message about it.
  std::string where() const;
};

struct MitsubaDocument {
  MitsubaElement scene;                              // the root <scene>
  std::filesystem::path main_directory;              // of the scene file: relative file names resolve here
  std::vector<std::filesystem::path> search_dirs;    // from <path value="..."/>, searched first
  std::map<std::string, const MitsubaElement*> ids;  // id (and alias) -> element
};

// Reads `file` and everything it includes. `parameters` (name, value) override the scene's <default>s.
// Throws InputError.
std::unique_ptr<MitsubaDocument> read_mitsuba_xml(
    const std::filesystem::path& file, const std::vector<std::pair<std::string, std::string>>& parameters);

// A relative file name of `element` (a mesh, texture, environment map, included file) resolved as Mitsuba
// does: the directory of the element's own file, then the <path> directories, then the scene file's
// directory. Throws InputError naming the element and every place looked in when it is nowhere.
std::filesystem::path resolve_mitsuba_file(const MitsubaDocument& document, const MitsubaElement& element,
                                           const std::string& name);
// The same path as ochre's scene JSON gives it: relative to the scene file's directory when it lies there.
std::string mitsuba_file_for_json(const MitsubaDocument& document, const MitsubaElement& element,
                                  const std::string& name);

}  // namespace ochre
