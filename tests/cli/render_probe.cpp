#include "cli/render_probe.h"

#include <gtest/gtest.h>

#include "cli/cli_runner.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test {

double LuminanceImage::mean(int x0, int y0, int x1, int y1) const {
  double sum = 0.0;
  for (int j = y0; j < y1; ++j)
    for (int i = x0; i < x1; ++i) sum += at(i, j);
  return sum / ((x1 - x0) * (y1 - y0));
}

LuminanceImage render_luminance(const std::string& scene_json, const std::string& extra_args) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", scene_json);
  const CommandResult r = run_ochre("render scene.json -o out.exr " + extra_args, dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  LuminanceImage img;
  if (r.exit_code != 0) return img;
  const ExrImage exr = read_exr(dir / "out.exr");
  img.width = exr.width;
  img.height = exr.height;
  const auto* R = exr.find_channel("R");
  const auto* G = exr.find_channel("G");
  const auto* B = exr.find_channel("B");
  img.y.resize(R->size());
  // Luminance of linear Rec.709 (the Y row of the RGB -> XYZ matrix).
  for (size_t i = 0; i < img.y.size(); ++i)
    img.y[i] = 0.2126729 * (*R)[i] + 0.7151522 * (*G)[i] + 0.0721750 * (*B)[i];
  return img;
}

}  // namespace ochre::test
