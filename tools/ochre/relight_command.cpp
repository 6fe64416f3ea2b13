#include "tools/ochre/relight_command.h"

#include <fmt/format.h>

#include <iostream>

#include "renderer/image/exr_reader.h"
#include "renderer/output/output_files.h"
#include "renderer/output/relight.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/image_error.h"
#include "renderer/util/output_transaction.h"
#include "renderer/util/signal_cleanup.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"

namespace ochre {

int run_relight(const RelightCommand& command) {
  install_signal_cleanup();
  if (command.exr.empty() && command.png.empty())
    throw InputError("relight: no output: give -o OUT.exr and/or --png OUT.png");
  std::vector<GroupChange> changes;
  for (const std::string& text : command.groups) changes.push_back(parse_group_change(text));
  InputFileLog inputs;
  ExrImage render;
  {
    const InputFileLog::Recording recording(inputs);
    render = read_exr(command.render);
  }
  const ExrImage relit = relight(render, changes, command.render);
  DisplayOptions display = recorded_display(render, command.render);
  if (command.ocio_config) display.ocio_config = *command.ocio_config;
  if (command.display) display.display = *command.display;
  if (command.view) display.view = *command.view;
  if (command.exposure) display.exposure_stops = *command.exposure;

  std::vector<std::filesystem::path> paths;
  try {
    for (const std::string& path : {command.exr, command.png})
      if (!path.empty()) {
        check_output_writable(path);
        paths.emplace_back(path);
      }
  } catch (const ImageError& e) {
    throw InputError(e.what());
  }
  check_output_files(paths, inputs);
  std::vector<float> rgb(static_cast<size_t>(relit.width) * relit.height * 3);
  for (int c = 0; c < 3; ++c) {
    const std::vector<float>& channel = *relit.find_channel(std::string(1, "RGB"[c]));
    for (size_t i = 0; i < channel.size(); ++i) rgb[i * 3 + c] = channel[i];
  }
  // The display transform is built before anything is written: a bad config or view is bad input.
  std::vector<std::uint8_t> png;
  if (!command.png.empty()) {
    try {
      png = to_display_rgb8(relit.width, relit.height, rgb, display);
    } catch (const ImageError& e) {
      throw InputError(e.what());
    }
  }
  OutputTransaction transaction;
  if (!command.exr.empty()) write_exr(transaction.add(command.exr), relit);
  if (!command.png.empty())
    write_rgb8(transaction.add(command.png), "png", relit.width, relit.height, png, "relit display image");
  transaction.commit();
  if (!command.quiet) {
    std::cerr << fmt::format("ochre: relit {}: {}\n", command.render,
                             relit.string_attributes.at("ochre.relight"));
    for (const std::string& path : {command.exr, command.png})
      if (!path.empty()) std::cerr << "ochre: wrote " << path << "\n";
  }
  return 0;
}

}  // namespace ochre
