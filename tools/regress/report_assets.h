#pragma once
// The HTML report's stylesheet and script (tools/regress/report/*.css, *.js), embedded at build time
// (spectra/embed_files.cmake) so that the installed ochre-regress needs no file beside it.

#include <vector>

#include "spectra/embedded_data.h"

namespace ochre {

const std::vector<spectra::EmbeddedFile>& report_assets();

}  // namespace ochre
