#pragma once
// The input of `ochre-brdf eval`: a CSV with a header naming the columns wi_x, wi_y, wi_z, wo_x, wo_y,
// wo_z, lambda_nm (any order), one (wi, wo, wavelength) per line, directions in the local shading frame
// (z = normal, both pointing away from the surface). Directions need not be unit vectors: they are
// normalised here; a zero vector is an error. Blank lines and lines starting with '#' are skipped.

#include <filesystem>
#include <string>
#include <vector>

#include "materials/core/vec3.h"

namespace ochre {

struct DirectionPair {
  Vec3 wi, wo;  // normalised
  float lambda_nm = 0;
  int line = 0;                     // in the file, from 1
  std::vector<std::string> fields;  // the line's fields as written, in the header's order
};

struct DirectionPairTable {
  std::vector<std::string> header;
  std::vector<DirectionPair> rows;
};

// Throws InputError "FILE: line N: ..." naming the column at fault (missing file, missing or unknown
// column, wrong field count, a value that is not a finite number, a zero direction).
DirectionPairTable read_direction_pairs(const std::filesystem::path& file);

}  // namespace ochre
