#include "tools/ochre/relight_command.h"

#include <fmt/format.h>

#include <iostream>

#include "renderer/image/exr_reader.h"
#include "renderer/output/relight.h"
#include "renderer/output/relight_page.h"
#include "renderer/util/signal_cleanup.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"

namespace ochre {

int run_relight(const RelightCommand& command) {
  install_signal_cleanup();
  if (command.exr.empty() && command.png.empty() && command.html.empty())
    throw InputError("relight: no output: give -o OUT.exr, --png OUT.png and/or --html DIR");
  if (!command.html.empty()) check_relight_page_destination(command.html);  // before anything is written
  InputFileLog inputs;
  ExrImage render;
  std::vector<GroupChange> changes;
  {
    const InputFileLog::Recording recording(inputs);  // the render and the CSV spectra, never replaced
    for (const std::string& text : command.groups) changes.push_back(parse_group_change(text));
    render = read_exr(command.render);
  }
  DisplayOptions display = recorded_display(render, command.render);
  if (command.ocio_config) display.ocio_config = *command.ocio_config;
  if (command.display) display.display = *command.display;
  if (command.view) display.view = *command.view;
  if (command.exposure) display.exposure_stops = *command.exposure;

  if (!command.exr.empty() || !command.png.empty()) {
    const ExrImage relit = relight(render, changes, command.render);
    const std::vector<std::string> written = write_relit(relit, display, command.exr, command.png, inputs);
    if (!command.quiet) {
      std::cerr << fmt::format("ochre: relit {}: {}\n", command.render,
                               relit.string_attributes.at("ochre.relight"));
      for (const std::string& line : written) std::cerr << "ochre: " << line << "\n";
    }
  }
  if (!command.html.empty()) {
    const RelightPageStats page = write_relight_page(render, display, command.render, command.html);
    if (!command.quiet)
      std::cerr << fmt::format(
          "ochre: wrote {}/index.html ({:.1f} MB: {} groups, {} with a colour-temperature slider ({} basis "
          "images), display lattice {}^3)\n",
          command.html, page.bytes / 1e6, page.groups, page.cct_groups, page.basis_images,
          page.lattice_points);
  }
  return 0;
}

}  // namespace ochre
