#pragma once
// PLY files are read by Assimp, whose PLY reader (5.2) loops forever on a header that never ends: a
// file that starts like a PLY ("ply" on its first line) is checked here first.

#include <filesystem>

namespace ochre {

// Throws InputError "<file>: malformed PLY header: no end_header line" when `file` starts with the PLY
// magic line but the header is not closed by an end_header line. Other files pass untouched.
void check_ply_header(const std::filesystem::path& file);

}  // namespace ochre
