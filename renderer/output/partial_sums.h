#pragma once
// Partial-sum files (docs/distributed.md, "File format"): an OpenEXR file holding the exact per-pixel sums
// of a part of a render (a sample range, a region, a checkpoint, a merge of parts), so that parts merge
// bit for bit into the image of one render.
//
// - Each film accumulator (Film::accumulator_names(): XYZ, Y^2, the sample count, the AOV, Stokes and
//   spectral sums) is four UINT channels "sums.<name>.w0" .. "w3", the 32-bit words of its 128-bit
//   two's-complement value, least significant first, RLE-compressed. R, G, B hold the mean in the working
//   space as a preview any EXR viewer shows.
// - The data window is the rectangle of pixels held, inside a display window that is the whole image.
// - String attributes: the render identity (renderer/output/render_identity.h), "ochre.partialSums" (format
//   version "1"), "ochre.coverage" (the pieces held, renderer/film/coverage.h), the NaN/Inf counts, and
//   "ochre.sumsChecksum": FNV-1a over the 64-bit words of every sum, row by row, accumulator by
//   accumulator. Other "ochre.*" attributes (the scene path, display settings, checkpoint fields) are
//   kept as notes.
// Reading checks every field, the checksum, and that each pixel's sample count equals what the coverage
// says, so a damaged or edited file is refused with a message naming the file and the field.

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "renderer/film/coverage.h"
#include "renderer/film/film.h"
#include "renderer/output/render_identity.h"

namespace ochre {

class AtomicOutput;

struct PartialSumsHeader {
  RenderIdentity identity;                // must be equal for files to merge
  int image_width = 0, image_height = 0;  // from ochre.resolution
  uint32_t spp = 0;                       // the whole render's samples per pixel (ochre.spp)
  double noise_threshold = 0.0;           // ochre.noiseThreshold: > 0, pixels may hold fewer samples
  FilmLayers layers;                      // from ochre.aovs, ochre.stokes, ochre.spectralBins/Range
  PixelRect rect;                         // the pixels held
  std::vector<CoveragePiece> coverage;    // inside rect, samples inside [0, spp)
  uint64_t discarded_samples = 0, nonfinite_values = 0;
  std::map<std::string, std::string> notes;  // other "ochre.*" attributes, by name
};

// Fills image size, spp and layers from the identity; throws InputError naming `file` and the field.
void parse_identity_fields(const std::string& file, PartialSumsHeader& header);

// Writes `film` (header.rect's size) and `header` into output.temp_path() without committing. Throws
// ImageError naming the output when it cannot be written.
void write_partial_sums(AtomicOutput& output, const PartialSumsHeader& header, const Film& film);

// A partial-sum file opened for reading; the header is read and checked by the constructor.
class PartialSumsFile {
 public:
  // Throws InputError naming the file and the field when it is not a valid partial-sum file of ochre.
  explicit PartialSumsFile(const std::filesystem::path& path);
  ~PartialSumsFile();
  PartialSumsFile(PartialSumsFile&&) noexcept;
  PartialSumsFile& operator=(PartialSumsFile&&) noexcept;

  const std::filesystem::path& path() const;
  const PartialSumsHeader& header() const;
  // Adds the sums to `film` (which has the header's layers), the file's first pixel at film pixel
  // (x0, y0). Reads the file a band of rows at a time (memory: the film plus a few MB). Throws InputError
  // naming the file when the checksum or a sample count does not match (the film is then partly added).
  void add_to(Film& film, int x0, int y0) const;
  // A film of the header's rectangle holding the file's sums.
  Film read_film() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ochre
