// Cache of parsed embedded tables (see embedded_tables.h).

#include "spectra/embedded_tables.h"

#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "spectra/embedded_data.h"

namespace ochre {

namespace {

std::string_view embedded_content(std::string_view file_name) {
  for (const auto& file : spectra::embedded_files())
    if (file.name == file_name) return file.content;
  std::string known;
  for (const auto& file : spectra::embedded_files())
    known += (known.empty() ? "" : ", ") + std::string(file.name);
  throw std::runtime_error("embedded data: no table named '" + std::string(file_name) +
                           "' (embedded: " + known + ")");
}

}  // namespace

const CsvTable& embedded_table(std::string_view file_name) {
  static std::mutex mutex;
  // Node-based map: references handed out stay valid when other tables are added.
  static std::map<std::string, std::unique_ptr<const CsvTable>, std::less<>> cache;
  const std::lock_guard lock(mutex);
  if (const auto it = cache.find(file_name); it != cache.end()) return *it->second;
  const std::string source = "<embedded>/" + std::string(file_name);
  auto table = std::make_unique<const CsvTable>(CsvTable::parse(embedded_content(file_name), source));
  return *cache.emplace(std::string(file_name), std::move(table)).first->second;
}

}  // namespace ochre
