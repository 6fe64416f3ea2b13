#pragma once
// Whether single precision holds a mesh file's detail where its coordinates lie (docs/scene-format.md,
// "Coordinate range"): a file's vertices are stored, or read, in single precision, whose spacing grows with
// the coordinates (0.5 at 5e6). A scan exported in georeferenced coordinates without a local shift has its
// vertices rounded to that spacing before ochre sees them; no transform can give the digits back.

#include <optional>
#include <string>
#include <vector>

#include "materials/core/vec3.h"

namespace ochre {

// The spacing of single-precision numbers at the file's largest coordinate against its median edge
// length (edges of the triangles `indices`, in the file's own coordinates): a warning naming `where` and the
// numbers when the spacing exceeds 1/1000 of the median edge, nothing otherwise.
std::optional<std::string> float_detail_warning(const std::string& where, const std::vector<Vec3>& positions,
                                                const std::vector<uint32_t>& indices);

}  // namespace ochre
