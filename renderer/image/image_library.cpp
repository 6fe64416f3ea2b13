#include "renderer/image/image_library.h"

#include <dlfcn.h>
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "renderer/util/image_error.h"

namespace ochre {

namespace fs = std::filesystem;

namespace {

constexpr const char* kModuleFile = "libochre_oiio.so";

std::atomic<bool> loaded{false};

// The directories of the running executable and of the shared object this code is linked into (the
// Python extension), symbolic links resolved. /proc/self/exe, as dladdr() names the executable by its
// argv[0], which may be a bare name found on PATH.
std::vector<fs::path> own_directories() {
  std::vector<fs::path> directories;
  std::error_code error;
  if (const fs::path exe = fs::canonical("/proc/self/exe", error); !error)
    directories.push_back(exe.parent_path());
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&own_directories), &info) != 0 && info.dli_fname != nullptr &&
      fs::path(info.dli_fname).is_absolute()) {
    if (const fs::path self = fs::canonical(info.dli_fname, error); !error)
      directories.push_back(self.parent_path());
  }
  return directories;
}

// Where the module may be, in order (renderer/image/image_library.h).
std::vector<fs::path> module_candidates() {
  if (const char* explicit_path = std::getenv("OCHRE_IMAGE_MODULE"); explicit_path && *explicit_path) {
    return {fs::path(explicit_path)};
  }
  std::vector<fs::path> candidates;
  for (const fs::path& here : own_directories()) {
    candidates.push_back(here / OCHRE_IMAGE_MODULE_FROM_BIN / kModuleFile);    // installed tools
    candidates.push_back(here / ".." / "lib" / "ochre" / kModuleFile);         // build tree: bin/
    candidates.push_back(here / ".." / ".." / "lib" / "ochre" / kModuleFile);  // build tree: python/ochre/
    // Installed Python package: PREFIX/lib/python3/dist-packages/ochre/ -> PREFIX/lib/ochre/.
    candidates.push_back(here / ".." / ".." / ".." / "ochre" / kModuleFile);
  }
  candidates.push_back(fs::path(OCHRE_IMAGE_MODULE_INSTALL_DIR) / kModuleFile);
  std::vector<fs::path> distinct;
  for (const fs::path& candidate : candidates) {
    const fs::path normal = candidate.lexically_normal();
    if (std::find(distinct.begin(), distinct.end(), normal) == distinct.end()) distinct.push_back(normal);
  }
  return distinct;
}

const ImageLibrary* load_image_library() {
  std::string tried;
  for (const fs::path& candidate : module_candidates()) {
    std::error_code error;
    if (!fs::is_regular_file(candidate, error)) {
      tried += fmt::format("\n  {}: not found", candidate.string());
      continue;
    }
    // RTLD_LOCAL: OpenImageIO's symbols stay out of the global namespace of the process. RTLD_LAZY: of the
    // ~240 libraries OpenImageIO pulls in, only the functions called get bound, on first call; binding them
    // all at load (RTLD_NOW) cost ~0.3 s per process (docs/performance.md, process start-up).
    void* module = dlopen(candidate.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (module == nullptr) {
      tried += fmt::format("\n  {}: {}", candidate.string(), dlerror());
      continue;
    }
    auto factory = reinterpret_cast<ImageLibraryFactory>(dlsym(module, kImageLibraryEntryPoint));
    ImageLibrary* library = factory ? factory(kImageLibraryInterfaceVersion) : nullptr;
    if (library == nullptr) {
      tried += fmt::format("\n  {}: not an ochre image module of this version", candidate.string());
      dlclose(module);
      continue;
    }
    loaded.store(true, std::memory_order_release);
    return library;  // kept for the life of the process, as is the module
  }
  throw ImageError(fmt::format(
      "cannot load ochre's image library module {} (OpenImageIO), needed to read or write this image; "
      "looked at:{}\nSet OCHRE_IMAGE_MODULE to its path if ochre was moved away from its lib/ochre folder",
      kModuleFile, tried));
}

}  // namespace

const ImageLibrary& image_library() {
  static const ImageLibrary* const library = load_image_library();
  return *library;
}

bool image_library_loaded() {
  return loaded.load(std::memory_order_acquire);
}

}  // namespace ochre
