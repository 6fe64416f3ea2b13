#pragma once
// Reads a JSON file (comments allowed) for the scene loader and the tools. Throws InputError naming the
// file ("cannot open <what>"; not a regular file or larger than 256 MiB, spectra/input_file.h), the
// line and column of a syntax error, or the path of a duplicate key.

#include <filesystem>
#include <nlohmann/json.hpp>

namespace ochre {

nlohmann::json read_json_file(const std::filesystem::path& file, const char* what);

}  // namespace ochre
