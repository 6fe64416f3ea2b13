#pragma once
// What makes two partial renders parts of one image (docs/distributed.md): ochre's version, the content of
// the scene and of every file it references, and the settings that change the image. Partial-sum files
// record these fields; `ochre merge` and `ochre render --resume` refuse files whose fields differ.

#include <string>
#include <utility>
#include <vector>

#include "renderer/scene/render_settings.h"
#include "spectra/input_file.h"

namespace ochre {

struct Scene;

// Named fields in a fixed order, e.g. {"ochre.seed", "0"}: the EXR attribute names of partial-sum files.
using RenderIdentity = std::vector<std::pair<std::string, std::string>>;

// "fnv1a64:0123456789abcdef": a hash of the contents of the files a scene load read (the scene file,
// meshes and the files they name, textures, environment maps, spectrum CSVs), independent of their paths
// and of the order they were read in, so parts rendered from copies of the scene at other paths merge.
// Throws InputError naming a file that can no longer be read.
std::string scene_content_hash(const std::vector<InputFileRecord>& scene_inputs);

// The identity of a render of `scene` (its settings and outputs already final) with that content hash.
// The film's layers follow from the fields "ochre.aovs", "ochre.stokes", "ochre.spectralBins" and
// "ochre.spectralRange".
RenderIdentity render_identity(const Scene& scene, const RenderJob& job, const std::string& content_hash);

// The names of the identity fields, in order.
const std::vector<std::string>& identity_field_names();

// The value of field `name`, or nullptr.
const std::string* identity_field(const RenderIdentity& identity, const std::string& name);

}  // namespace ochre
