#include "tools/fit/fit_output_set.h"

#include <fmt/format.h>

#include <fstream>

#include "renderer/image_error.h"
#include "renderer/input_error.h"

namespace ochre {

namespace fs = std::filesystem;

namespace {

// Two spellings of one file: the same path once resolved, or (existing files) the same inode.
bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error) && fs::equivalent(a, b, error)) return true;
  const fs::path ra = fs::weakly_canonical(fs::absolute(a), error), rb = fs::weakly_canonical(fs::absolute(b), error);
  return ra == rb;
}

}  // namespace

void check_fit_outputs(const std::vector<fs::path>& outputs, const std::vector<fs::path>& inputs) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    try {
      check_output_writable(outputs[i]);
    } catch (const ImageError& e) {
      throw InputError(e.what());
    }
    for (size_t j = 0; j < i; ++j)
      if (same_file(outputs[i], outputs[j]))
        throw InputError(fmt::format("cannot write {}: it is also given as output {}; two outputs cannot be one file",
                                     outputs[i].string(), outputs[j].string()));
    for (const fs::path& input : inputs)
      if (same_file(outputs[i], input))
        throw InputError(
            fmt::format("cannot write {}: it is {}, an input of this command", outputs[i].string(), input.string()));
  }
}

AtomicOutput& FitOutputSet::add(const fs::path& final_path) {
  outputs_.push_back(std::make_unique<AtomicOutput>(final_path));
  return *outputs_.back();
}

void write_temporary_text(const fs::path& path, std::string_view text, const fs::path& name) {
  std::ofstream out(path, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw ImageError(fmt::format("cannot write {}", name.string()));
}

void FitOutputSet::add_text(const fs::path& final_path, std::string_view text) {
  write_temporary_text(add(final_path).temp_path(), text, final_path);
}

void FitOutputSet::commit() {
  for (const std::unique_ptr<AtomicOutput>& output : outputs_) output->commit();
}

}  // namespace ochre
