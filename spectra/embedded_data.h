#pragma once
// Data tables embedded at build time from spectra/data/*.csv (see embed_files.cmake).

#include <string_view>
#include <vector>

namespace ochre::spectra {

struct EmbeddedFile {
  std::string_view name;  // file name, e.g. "cie1931_2deg_1nm.csv"
  std::string_view content;
};

const std::vector<EmbeddedFile>& embedded_files();

}  // namespace ochre::spectra
