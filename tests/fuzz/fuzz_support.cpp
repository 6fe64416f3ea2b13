#include "fuzz_support.h"

#include <fmt/format.h>
#include <stdlib.h>

#include <cstdio>
#include <exception>
#include <fstream>
#include <stdexcept>

#include "materials/graph/graph_error.h"
#include "renderer/util/image_error.h"
#include "spectra/input_error.h"

namespace ochre::fuzz {

namespace {

// Source-tree file -> name in the workspace.
const std::pair<const char*, const char*> kResources[] = {
    {"tests/data/quad.obj", "quad.obj"},
    {"tests/data/cube_quads.obj", "cube_quads.obj"},
    {"tests/data/colours.ply", "colours.ply"},
    {"tests/data/two_triangles.gltf", "two_triangles.gltf"},
    {"tests/regression/assets/checker.ppm", "checker.ppm"},
    {"tests/regression/assets/sky.exr", "sky.exr"},
    {"scenes/cornell-box/spectra/red.csv", "red.csv"},
};

class Workspace {
 public:
  Workspace() {
    std::string pattern = (std::filesystem::temp_directory_path() / "ochre-fuzz-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      std::perror("ochre fuzz: cannot create a temporary directory");
      std::abort();
    }
    dir_ = pattern;
    for (const auto& [source, name] : kResources)
      std::filesystem::copy_file(std::filesystem::path(OCHRE_SOURCE_DIR) / source, dir_ / name);
    // Textures converted while loading a scene are cached here, not in the user's cache.
    setenv("OCHRE_CACHE_DIR", (dir_ / "texture-cache").c_str(), 1);
  }
  ~Workspace() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

[[noreturn]] void finding(const char* kind, const char* what) {
  std::fprintf(stderr, "ochre fuzz: FINDING: unexpected %s: %s\n", kind, what);
  std::fflush(stderr);
  std::abort();
}

}  // namespace

const std::filesystem::path& workspace() {
  static const Workspace instance;
  return instance.dir();
}

std::filesystem::path write_workspace_file(const std::string& name, std::string_view bytes) {
  const std::filesystem::path path = workspace() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) finding("failure", ("cannot write " + path.string()).c_str());
  return path;
}

std::string_view as_text(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

void expect_only_input_errors(const std::function<void()>& body, bool parser_errors) {
  try {
    body();
  } catch (const InputError&) {
  } catch (const GraphError&) {
  } catch (const ImageError&) {
  } catch (const std::runtime_error& e) {
    if (!parser_errors) finding("std::runtime_error", e.what());
  } catch (const std::invalid_argument& e) {
    if (!parser_errors) finding("std::invalid_argument", e.what());
  } catch (const std::exception& e) {
    finding(typeid(e).name(), e.what());
  } catch (...) {
    finding("exception", "not derived from std::exception");
  }
}

}  // namespace ochre::fuzz

// AddressSanitizer defaults of every target (unused without ASan). OpenImageIO 2.4 deletes its
// TextureSystem through a pointer to the base class that has a sized operator delete
// (TextureSystem::destroy), which ASan reports as new-delete-type-mismatch on every scene with a
// texture: a defect of the library, harmless with glibc's allocator, that would hide ours.
extern "C" const char* __asan_default_options() {
  return "new_delete_type_mismatch=0";
}

// LeakSanitizer: OpenImageIO keeps per-thread state (aligned_malloc in its ImageCache and TextureSystem)
// that it never frees, and Assimp 5.2 leaks parts of a scene on some import errors: defects of the
// libraries, not of ochre, whose own leaks are still reported.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOpenImageIO_Util.so\nleak:libOpenImageIO.so\nleak:libassimp.so\n";
}
