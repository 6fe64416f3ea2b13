#include "renderer/shapes/mesh_file_reader.h"

#include <assimp/postprocess.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/ProgressHandler.hpp>
#include <cerrno>
#include <cstring>
#include <exception>

#include "renderer/shapes/assimp_reader.h"
#include "renderer/util/load_progress.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"

namespace ochre {

namespace {

// Assimp's view of a checked input file.
class InputFileStream final : public Assimp::IOStream {
 public:
  explicit InputFileStream(InputFile file) : file_(std::move(file)) {}

  size_t Read(void* buffer, size_t size, size_t count) override {
    if (size == 0 || count == 0) return 0;
    auto* bytes = static_cast<char*>(buffer);
    const size_t wanted = size * count;
    size_t done = 0;
    while (done < wanted) {
      const ssize_t n = ::read(file_.fd(), bytes + done, wanted - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      done += static_cast<size_t>(n);
    }
    return done / size;
  }
  size_t Write(const void*, size_t, size_t) override { return 0; }
  aiReturn Seek(size_t offset, aiOrigin origin) override {
    const int whence = origin == aiOrigin_SET ? SEEK_SET : origin == aiOrigin_CUR ? SEEK_CUR : SEEK_END;
    return ::lseek(file_.fd(), static_cast<off_t>(offset), whence) < 0 ? aiReturn_FAILURE : aiReturn_SUCCESS;
  }
  size_t Tell() const override { return static_cast<size_t>(::lseek(file_.fd(), 0, SEEK_CUR)); }
  size_t FileSize() const override { return static_cast<size_t>(file_.size()); }
  void Flush() override {}

 private:
  InputFile file_;
};

// Opens every file Assimp asks for through InputFile::open. A file that does not exist is left to
// Assimp (a missing material library is only a warning); one that exists but is not an acceptable
// input is an error, kept to be thrown once Assimp returns.
class CheckedIOSystem final : public Assimp::IOSystem {
 public:
  bool Exists(const char* file) const override {
    struct stat info {};
    return ::stat(file, &info) == 0;  // no open(2): a FIFO would block it
  }
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (std::strpbrk(mode, "wa+") != nullptr) return nullptr;  // reading only
    if (!Exists(file)) return nullptr;
    try {
      return new InputFileStream(InputFile::open(file, kMeshFileInput));
    } catch (const InputError&) {
      if (!error_) error_ = std::current_exception();
      return nullptr;
    }
  }
  void Close(Assimp::IOStream* stream) override { delete stream; }

  void rethrow_error() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::exception_ptr error_;
};

class ImportProgress final : public Assimp::ProgressHandler {
 public:
  explicit ImportProgress(const std::filesystem::path& file)
      : progress_("loading " + file.filename().string()) {}
  bool Update(float percentage) override {
    if (percentage >= 0.0f) progress_.update(percentage);
    return true;
  }

 private:
  LoadProgress progress_;
};

// Throws when the polygons of `scene` would take too long to triangulate (see the header).
void check_triangulation_work(const aiScene& scene, const std::string& where) {
  double work = 0.0, largest = 0.0;
  unsigned largest_face = 0;
  const aiMesh* largest_mesh = nullptr;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const double n = mesh.mFaces[f].mNumIndices;
      if (n <= 3) continue;
      work += n * n * n;
      if (n > largest) largest = n, largest_face = f, largest_mesh = &mesh;
    }
  }
  constexpr double kMaxWork = kMaxTriangulatedPolygon * kMaxTriangulatedPolygon * kMaxTriangulatedPolygon;
  if (work <= kMaxWork) return;
  throw InputError(fmt::format(
      "{}: polygons too large to triangulate in reasonable time (face {} of mesh '{}' has {:.0f} vertices; "
      "the work grows with the cube of a polygon's size, and all polygons together may cost as much as "
      "one of {:.0f} vertices): split them into smaller polygons, or use \"subdivision\", which takes "
      "polygons of any size",
      where, largest_face, largest_mesh->mName.C_Str(), largest, kMaxTriangulatedPolygon));
}

}  // namespace

const aiScene* read_mesh_file(Assimp::Importer& importer, const std::filesystem::path& file, unsigned flags) {
  const std::string where = file.string();
  check_regular_input(file, kMeshFileInput);
  check_ply_header(file);
  auto* io = new CheckedIOSystem;  // the importer owns both
  importer.SetIOHandler(io);
  importer.SetProgressHandler(new ImportProgress(file));
  // Read without post-processing first, so that the polygons can be measured before triangulation.
  const aiScene* scene = importer.ReadFile(where, 0);
  io->rethrow_error();
  if (scene == nullptr)
    throw InputError(fmt::format("{}: cannot import mesh: {}", where, importer.GetErrorString()));
  check_mesh_faces(*scene, where);
  if (flags & aiProcess_Triangulate) check_triangulation_work(*scene, where);
  if (flags != 0) scene = importer.ApplyPostProcessing(flags);
  if (scene == nullptr)
    throw InputError(fmt::format("{}: cannot import mesh: {}", where, importer.GetErrorString()));
  return scene;
}

Transform to_transform(const aiMatrix4x4& a) {
  // Assimp matrices are row-major with column vectors (a4, b4, c4 = translation), as ours.
  Transform t;
  const float values[16] = {a.a1, a.a2, a.a3, a.a4, a.b1, a.b2, a.b3, a.b4,
                            a.c1, a.c2, a.c3, a.c4, a.d1, a.d2, a.d3, a.d4};
  std::copy(std::begin(values), std::end(values), t.m.begin());
  return t;
}

}  // namespace ochre
