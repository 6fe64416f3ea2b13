#pragma once
// What every fuzz target shares (docs/validation.md, "Fuzzing"):
// - a private temporary directory, the only place a target writes to, holding copies of a few small
//   resource files (meshes, a texture, an environment map, a spectrum) that fuzzed scenes may name;
// - the verdict on an exception: the errors ochre reports as bad input (InputError, GraphError, ImageError
//   and the std::runtime_error family a parser documents) are expected, anything else is a finding and
//   aborts so that libFuzzer (or the corpus replay) reports the input.
//
// Each target defines LLVMFuzzerTestOneInput; the same source links either with libFuzzer (clang,
// -fsanitize=fuzzer) or with replay_main.cpp (any compiler), which feeds it every file of a corpus.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace ochre::fuzz {

// The process's temporary directory (created on first use, removed at normal exit), holding copies of
// the resource files under flat names: quad.obj, cube_quads.obj, colours.ply, two_triangles.gltf,
// checker.ppm, sky.exr, red.csv. $OCHRE_CACHE_DIR points into it, so converted textures stay there.
const std::filesystem::path& workspace();

// Writes `bytes` to workspace()/name (replacing it) and returns the path.
std::filesystem::path write_workspace_file(const std::string& name, std::string_view bytes);

std::string_view as_text(const uint8_t* data, size_t size);

// Runs `body`; returns normally when it succeeds or throws an error of ochre's bad-input kinds
// (InputError, GraphError, ImageError). With `parser_errors`, any std::runtime_error or
// std::invalid_argument counts as such (the CSV and image readers report bad files with them).
// Any other exception is printed and aborts the process.
void expect_only_input_errors(const std::function<void()>& body, bool parser_errors = false);

}  // namespace ochre::fuzz
