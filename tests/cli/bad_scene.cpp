#include "cli/bad_scene.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"
#include "support/test_paths.h"

namespace ochre::test {

std::string scene_text(const std::string& materials, const std::string& shapes, const std::string& extra) {
  return fmt::format(R"({{"film": {{"resolution": [8, 8]}}, "integrator": {{"spp": 1}}, {}{}, {}, )"
                     R"("lights": [{{"type": "environment", "radiance": 1}}]}})",
                     extra, materials, shapes);
}

std::string scene_with(const std::string& pointer, const std::string& value) {
  nlohmann::json scene =
      nlohmann::json::parse(scene_text(R"("materials": {"grey": {"type": "lambert", "color": 0.5}})",
                                       R"("shapes": [{"type": "plane", "material": "grey"}])"));
  scene[nlohmann::json::json_pointer(pointer)] = nlohmann::json::parse(value);
  return scene.dump();
}

void expect_rejected(const BadCase& c, const std::filesystem::path& where) {
  const auto dir = where.empty() ? scratch_dir() : where;
  write_text(dir / "scene.json", c.scene);
  const CommandResult r = run_ochre("render scene.json -o out.exr --png out.png", dir);
  EXPECT_EQ(r.exit_code, 2) << c.name << "\n" << r.output;
  EXPECT_NE(r.output.find("scene.json"), std::string::npos) << c.name << ": message must name the file\n"
                                                            << r.output;
  for (const std::string& s : c.expected)
    EXPECT_NE(r.output.find(s), std::string::npos) << c.name << ": message must contain '" << s << "'\n"
                                                   << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.exr")) << c.name;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.png")) << c.name;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos)
        << "temporary file left behind";
}

}  // namespace ochre::test
