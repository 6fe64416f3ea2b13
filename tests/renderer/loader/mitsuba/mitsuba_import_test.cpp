// Mitsuba 3 XML import (docs/mitsuba-import.md): what each element becomes in ochre's scene JSON, the
// conventions that must agree with Mitsuba's (path depth, fov axis, uv orientation, environment map
// orientation), and every kind of refusal naming the file, line and element.
#include "renderer/loader/mitsuba/mitsuba_import.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/image/exr_writer.h"
#include "renderer/integrator/render.h"
#include "renderer/loader/scene_loader.h"
#include "support/input_error_of.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::mitsuba_import_test {
namespace {

using nlohmann::json;

std::filesystem::path data_dir() {
  return test::source_dir() / "tests/data/mitsuba";
}

// A scene with a 4x4 film around `body` (which starts on line 5).
std::string scene_xml(const std::string& body, const std::string& sensor_extra = "",
                      const std::string& film_extra = "") {
  return R"(<scene version="3.0.0">
    <sensor type="perspective">)" +
         sensor_extra + R"(
        <film type="hdrfilm"><integer name="width" value="4"/><integer name="height" value="4"/>)" +
         film_extra + R"(</film>
    </sensor>
)" + body +
         "\n</scene>\n";
}

std::filesystem::path write_scene(const std::string& text, const std::string& name = "scene.xml") {
  const auto dir = test::scratch_dir();
  test::write_text(dir / name, text);
  return dir / name;
}

json translated(const std::string& body, const std::string& sensor_extra = "") {
  return translate_mitsuba_scene(write_scene(scene_xml(body, sensor_extra))).scene;
}

// The one node of `material` whose type is `type`.
json node_of_type(const json& material, const std::string& type) {
  for (const auto& [name, node] : material.at("nodes").items())
    if (node.at("type") == type) return node;
  ADD_FAILURE() << "no " << type << " node in " << material.dump();
  return json();
}

TEST(MitsubaImport, EveryElementOfTheTestSceneTranslates) {
  const json s = translate_mitsuba_scene(data_dir() / "elements.xml").scene;
  // <integer name="max_depth" value="5"/>: 5 segments = 4 scattering events; rr_depth as written.
  EXPECT_EQ(s["integrator"]["max_depth"], 4);
  EXPECT_EQ(s["integrator"]["rr_depth"], 3);
  EXPECT_EQ(s["integrator"]["spp"], 2);  // $spp from <default>
  EXPECT_EQ(s["integrator"]["seed"], 3);
  EXPECT_EQ(s["integrator"]["sampler"], "sobol");  // stratified
  EXPECT_EQ(s["camera"]["fov"], 50.0);
  EXPECT_EQ(s["camera"]["fov_axis"], "x");
  EXPECT_EQ(s["camera"]["eye"], json({0.0, 1.0, 6.0}));
  EXPECT_EQ(s["film"]["resolution"], json({24, 16}));
  EXPECT_EQ(s["film"]["filter"], json({{"type", "gaussian"}, {"stddev", 0.5}}));

  const json& m = s["materials"];
  EXPECT_EQ(node_of_type(m["grey"], "lambert")["color"], json({0.5, 0.5, 0.5}));  // <rgb value="$grey">
  EXPECT_EQ(
      node_of_type(m["spectral"], "lambert")["color"],
      json({{"wavelengths", {400.0, 550.0, 700.0}}, {"values", {0.7, 0.6, 0.7}}, {"extrapolate", "zero"}}));
  EXPECT_EQ(node_of_type(m["gold"], "conductor")["metal"], "Au");
  EXPECT_EQ(node_of_type(m["custom-metal"], "multiply")["b"], json({0.9, 0.8, 0.7}));
  EXPECT_EQ(node_of_type(m["custom-metal"], "conductor")["eta"]["values"], json({0.2, 0.3}));
  EXPECT_EQ(node_of_type(m["rough"], "conductor")["roughness"], 0.2);
  EXPECT_EQ(node_of_type(m["rough"], "conductor")["eta"]["wavelengths"].size(), 95u);  // unbounded RGB table
  EXPECT_DOUBLE_EQ(node_of_type(m["glass"], "dielectric")["ior"].get<double>(), 1.5046);
  // to_uv scale 2, offset (0.25, 0): ochre's v runs the other way, so v' = 2 v + 1 - 2 - 0.
  EXPECT_EQ(node_of_type(m["textured"], "multiply")["b"], json({{"vector", {2.0, 2.0, 0.0}}}));
  EXPECT_EQ(node_of_type(m["textured"], "add")["b"], json({{"vector", {0.25, -1.0, 0.0}}}));
  EXPECT_EQ(node_of_type(m["textured"], "texture")["colorspace"], "auto");

  const json& shapes = s["shapes"];
  ASSERT_EQ(shapes.size(), 8u);
  EXPECT_EQ(shapes[0]["type"], "mesh");
  EXPECT_EQ(shapes[0]["smooth_normals"], true);
  EXPECT_FALSE(shapes[0].contains("flip_uv_v"));  // OBJ: Mitsuba flips v by default, as ochre reads it
  EXPECT_EQ(shapes[1]["face_normals"], true);
  EXPECT_EQ(shapes[1]["flip_uv_v"], true);  // PLY: Mitsuba does not flip
  EXPECT_EQ(shapes[2]["type"], "plane");
  EXPECT_EQ(shapes[2]["flip_uv_v"], true);
  EXPECT_EQ(shapes[2]["transform"]["matrix"][7], 0.5);
  EXPECT_EQ(shapes[3]["type"], "cube");
  EXPECT_EQ(shapes[3]["name"], "box");
  EXPECT_EQ(shapes[4]["center"], json({0.0, 0.0, 0.5}));
  EXPECT_EQ(shapes[4]["radius"], 0.5);
  EXPECT_EQ(shapes[5]["type"], "disk");
  const json& glow = m[shapes[5]["material"].get<std::string>()];
  EXPECT_EQ(node_of_type(glow, "emission")["color"], json({4.0, 3.5, 3.0}));
  EXPECT_EQ(node_of_type(glow, "lambert")["color"], 0.5);
  EXPECT_EQ(shapes[7]["flip_normals"], true);
  EXPECT_EQ(shapes[7]["material"], "grey");                       // through <alias id="grey" as="grey-too"/>
  EXPECT_EQ(node_of_type(m["mirror"], "conductor")["eta"], 0.0);  // Mitsuba's default conductor: a mirror
  EXPECT_EQ(node_of_type(m["mirror"], "conductor")["k"], 1.0);

  const json& lights = s["lights"];
  ASSERT_EQ(lights.size(), 3u);
  EXPECT_EQ(lights[0], json({{"type", "point"}, {"position", {2.0, 3.0, 2.0}}, {"intensity", 5.0}}));
  EXPECT_EQ(lights[1]["falloff"], "linear");
  EXPECT_EQ(lights[1]["cone_angle"], 30.0);
  EXPECT_EQ(lights[1]["falloff_start"], 20.0);
  EXPECT_EQ(lights[1]["position"], json({-2.0, 3.0, 2.0}));
  EXPECT_EQ(lights[2]["radiance"]["values"], json({0.1, 0.2}));

  // The translated scene loads through ochre's JSON loader.
  const auto scene = load_scene(data_dir() / "elements.xml");
  EXPECT_EQ(scene.scene->meshes.size(), 8u);
  EXPECT_EQ(scene.scene->lights.size(), 4u);  // the emissive disk is an area light
}

TEST(MitsubaImport, MaxDepthCountsSegmentsIncludingTheCameraRay) {
  auto depth = [](const std::string& value) {
    return translated(R"(<integrator type="path"><integer name="max_depth" value=")" + value +
                      R"("/></integrator>)")["integrator"]["max_depth"];
  };
  EXPECT_EQ(depth("1"), 0);      // emitters seen directly: ochre's emission only
  EXPECT_EQ(depth("2"), 1);      // direct lighting
  EXPECT_EQ(depth("6"), 5);      // the Cornell box's
  EXPECT_EQ(depth("-1"), 1024);  // no limit: ochre's longest path
  EXPECT_EQ(translated("")["integrator"]["max_depth"], 1024);  // Mitsuba's default is -1
  EXPECT_EQ(translated("")["integrator"]["rr_depth"], 5);
  EXPECT_EQ(translated("")["integrator"]["spp"], 4);
  EXPECT_EQ(translated("")["film"]["filter"]["type"], "gaussian");
}

TEST(MitsubaImport, FocalLengthIsAFieldOfViewAcrossTheDiagonal) {
  const json camera = translated("", R"(<string name="focal_length" value="50mm"/>)")["camera"];
  EXPECT_NEAR(camera["fov"].get<double>(), 46.7930, 1e-3);  // 2 atan(43.27 / 100)
  EXPECT_EQ(camera["fov_axis"], "diagonal");
  EXPECT_EQ(translated("", R"(<float name="fov" value="30"/>)")["camera"]["fov_axis"],
            "x");  // Mitsuba's default
}

TEST(MitsubaImport, ParametersFromOutsideOverrideDefaults) {
  const auto file = write_scene(scene_xml(R"(<default name="d" value="3"/>
    <integrator type="path"><integer name="max_depth" value="$d"/></integrator>)"));
  EXPECT_EQ(translate_mitsuba_scene(file).scene["integrator"]["max_depth"], 2);
  EXPECT_EQ(translate_mitsuba_scene(file, {{"d", "7"}}).scene["integrator"]["max_depth"], 6);
  const std::string unused = test::input_error_of([&] { translate_mitsuba_scene(file, {{"dd", "7"}}); });
  EXPECT_NE(unused.find("scene parameter 'dd' is not used"), std::string::npos) << unused;
}

TEST(MitsubaImport, EnvironmentMapTurnsLikeMitsubas) {
  const json light = translate_mitsuba_scene(data_dir() / "envmap.xml").scene["lights"][0];
  EXPECT_EQ(light["type"], "environment");
  EXPECT_EQ(light["scale"], 2.0);
  EXPECT_NEAR(light["rotation"].get<double>(), -90.0, 1e-9);  // 90 about +y, plus the 180 between the maps
}

// Mean of the linear luminance (Y) over a block of the film.
double mean_y(const Film& film, int x0, int y0, int x1, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) sum += film.mean(x, y).y;
  return sum / ((x1 - x0) * (y1 - y0));
}

std::unique_ptr<Film> render_xml(const std::string& text, const std::filesystem::path& dir) {
  test::write_text(dir / "scene.xml", text);
  auto scene = load_scene(dir / "scene.xml");
  auto film = std::make_unique<Film>(scene.job.settings.width, scene.job.settings.height);
  render(*scene.scene, scene.job, *film);
  return film;
}

// A bitmap whose top half is white and bottom half black, seen head on under a uniform white sky: in
// Mitsuba, v = 0 is the image's top row, a rectangle's v runs along +y from its bottom edge and an OBJ's v
// is flipped on loading. So the rectangle shows the white half at its bottom, the OBJ quad at its top.
TEST(MitsubaImport, TexturesAppearTheWayUpMitsubaShowsThem) {
  const auto dir = test::scratch_dir();
  std::string ppm = "P3\n1 8\n255\n";  // 4 white rows over 4 black ones
  for (int row = 0; row < 8; ++row) ppm += row < 4 ? "255 255 255\n" : "0 0 0\n";
  test::write_text(dir / "half.ppm", ppm);
  std::filesystem::copy_file(test::source_dir() / "tests/data/quad.obj", dir / "quad.obj");
  const std::string sensor = R"(<scene version="3.0.0">
    <sensor type="perspective">
      <float name="fov" value="20"/>
      <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
      <sampler type="independent"><integer name="sample_count" value="16"/></sampler>
      <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/>
        <rfilter type="box"/></film>
    </sensor>
    <texture type="bitmap" id="half"><string name="filename" value="half.ppm"/></texture>
    <bsdf type="diffuse" id="m"><ref name="reflectance" id="half"/></bsdf>
    <emitter type="constant"><spectrum name="radiance" value="1"/></emitter>)";
  const auto rectangle = render_xml(sensor + R"(<shape type="rectangle"><ref id="m"/></shape></scene>)", dir);
  // Rows 4-5 of the frame see y = 0.39 to 0.28, rows 10-11 y = -0.28 to -0.39 (away from the texture's
  // edge between its halves).
  EXPECT_GT(mean_y(*rectangle, 5, 10, 11, 12), 0.5);  // bottom of the frame
  EXPECT_LT(mean_y(*rectangle, 5, 4, 11, 6), 0.05);   // top
  const auto quad = render_xml(sensor + R"(<shape type="obj"><string name="filename" value="quad.obj"/>
      <ref id="m"/></shape></scene>)",
                               dir);
  EXPECT_LT(mean_y(*quad, 5, 10, 11, 12), 0.05);
  EXPECT_GT(mean_y(*quad, 5, 4, 11, 6), 0.5);
}

// A map bright only in its first column: Mitsuba looks that column up for directions with u in [0, 1/8),
// from -z a little toward +x. A camera looking along -z sees it right of centre; one looking along +z
// sees none of it; the map turned 180 degrees about +y swaps them.
TEST(MitsubaImport, EnvironmentMapDirectionsAreMitsubas) {
  const auto dir = test::scratch_dir();
  ExrImage map;
  map.width = 8;
  map.height = 4;
  for (const char* c : {"R", "G", "B"}) {
    std::vector<float> texels(32, 0.0f);
    for (int row = 0; row < 4; ++row) texels[8 * row] = 1.0f;
    map.channels.emplace_back(c, texels);
  }
  write_exr(dir / "map.exr", map);
  auto view = [&](const std::string& target, const std::string& turn) {
    return render_xml(R"(<scene version="3.0.0">
      <sensor type="perspective"><float name="fov" value="60"/>
        <transform name="to_world"><lookat origin="0, 0, 0" target=")" +
                          target + R"(" up="0, 1, 0"/></transform>
        <sampler type="independent"><integer name="sample_count" value="8"/></sampler>
        <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film>
      </sensor>
      <emitter type="envmap"><string name="filename" value="map.exr"/>
        <transform name="to_world"><rotate y="1" angle=")" +
                          turn + R"("/></transform></emitter>
    </scene>)",
                      dir);
  };
  const auto front = view("0, 0, -1", "0");
  EXPECT_GT(mean_y(*front, 4, 0, 8, 8), 10.0 * mean_y(*front, 0, 0, 4, 8) + 0.01);  // right half bright
  EXPECT_EQ(mean_y(*view("0, 0, 1", "0"), 0, 0, 8, 8), 0.0);
  EXPECT_EQ(mean_y(*view("0, 0, -1", "180"), 0, 0, 8, 8), 0.0);
  EXPECT_GT(mean_y(*view("0, 0, 1", "180"), 0, 0, 8, 8), 0.01);
}

struct Refusal {
  std::string name;
  std::string body;
  std::vector<std::string> expected;  // parts of the message, besides the file name
};

void PrintTo(const Refusal& r, std::ostream* os) {
  *os << r.name;
}

class MitsubaRefusal : public ::testing::TestWithParam<Refusal> {};

TEST_P(MitsubaRefusal, NamesFileLineElementAndWhatIsSupported) {
  const Refusal& r = GetParam();
  const auto file = write_scene(r.body);
  const std::string message = test::input_error_of([&] { load_scene(file); });
  ASSERT_FALSE(message.empty()) << r.name << ": accepted";
  EXPECT_NE(message.find("scene.xml"), std::string::npos) << message;
  for (const std::string& part : r.expected) EXPECT_NE(message.find(part), std::string::npos) << message;
}

std::vector<Refusal> refusals() {
  const std::string sphere = R"(<shape type="sphere"><bsdf type="diffuse"/></shape>)";
  return {
      {"unsupported element",
       scene_xml(R"(<medium type="homogeneous"/>)"),
       {"scene.xml:5: <medium type=\"homogeneous\">", "unsupported element <medium>", "sensor, shape"}},
      {"unsupported bsdf",
       scene_xml(R"(<bsdf type="measured" id="m"/>)"),
       {":5: <bsdf type=\"measured\" id=\"m\">", "diffuse, conductor, roughconductor, dielectric, twosided"}},
      {"plastic",
       scene_xml(R"(<bsdf type="plastic" id="p"/>)"),
       {"<bsdf type=\"plastic\"", "no plastic model"}},
      {"rough dielectric", scene_xml(R"(<bsdf type="roughdielectric" id="g"/>)"), {"rough glass"}},
      {"unsupported property",
       scene_xml(R"(<bsdf type="diffuse" id="d"><float name="roughness" value="0.3"/></bsdf>)"),
       {":5: <float name=\"roughness\">", "unsupported property \"roughness\"", "reflectance"}},
      {"unexpected attribute",
       scene_xml(R"(<shape type="sphere" colour="red"/>)"),
       {"unexpected attribute \"colour\"", "type, id, name"}},
      {"unexpected attribute of a value",
       scene_xml("", R"(<float name="fov" value="40" units="deg"/>)"),
       {"<float name=\"fov\">", "unexpected attribute \"units\""}},
      {"malformed",
       "<scene version=\"3.0.0\">\n  <shape type=\"sphere\">\n</scene>\n",
       {"scene.xml:3", "malformed XML"}},
      {"missing include",
       scene_xml(R"(<include filename="nowhere.xml"/>)"),
       {"<include>", "\"nowhere.xml\" not found"}},
      {"undefined parameter",
       scene_xml(R"(<shape type="sphere"><float name="radius" value="$r"/></shape>)"),
       {"undefined parameter \"$r\"", "-D r="}},
      {"duplicate id",
       scene_xml(R"(<bsdf type="diffuse" id="a"/><bsdf type="diffuse" id="a"/>)"),
       {"duplicate id \"a\"", "first at"}},
      {"missing reference",
       scene_xml(R"(<shape type="sphere"><ref id="nothing"/></shape>)"),
       {"<ref id=\"nothing\">", "no element has id \"nothing\""}},
      {"beckmann",
       scene_xml(R"(<bsdf type="roughconductor" id="r"/>)"),
       {"distribution \"beckmann\"", "GGX", "value=\"ggx\""}},
      {"metal",
       scene_xml(R"(<bsdf type="conductor" id="c"><string name="material" value="Pt"/></bsdf>)"),
       {"\"Pt\"", "Ag, Al, Au, Cu"}},
      {"no sensor", "<scene version=\"3.0.0\">\n" + sphere + "\n</scene>\n", {"no <sensor>"}},
      {"second sensor", scene_xml(R"(<sensor type="perspective"/>)"), {"a second <sensor>"}},
      {"bad number", scene_xml("", R"(<float name="fov" value="4o"/>)"), {"\"4o\" is not a finite number"}},
      {"old version", "<scene version=\"0.6.0\">\n</scene>\n", {"version 0.6.0", "2.x and 3.x"}},
      {"textured disk",
       scene_xml(R"(<shape type="disk"><bsdf type="diffuse"><texture type="bitmap" name="reflectance">
           <string name="filename" value="scene.xml"/></texture></bsdf></shape>)"),
       {"<shape type=\"disk\">", "textured disk"}},
      {"unreferenced area emitter", scene_xml(R"(<emitter type="area" id="lamp"/>)"), {"no shape refers to"}},
      {"hide emitters",
       scene_xml(R"(<integrator type="path"><boolean name="hide_emitters" value="true"/></integrator>)"),
       {"hide_emitters"}},
      {"max depth 0",
       scene_xml(R"(<integrator type="path"><integer name="max_depth" value="0"/></integrator>)"),
       {"max_depth 0"}},
      {"tilted envmap",
       scene_xml(R"(<emitter type="envmap"><string name="filename" value="scene.xml"/>
           <transform name="to_world"><rotate x="1" angle="90"/></transform></emitter>)"),
       {"only turn it about +y"}},
      {"scaled sensor",
       scene_xml("", R"(<transform name="to_world"><scale value="2"/></transform>)"),
       {"to_world of a sensor must be a rotation"}},
      {"filter",
       scene_xml("", "", R"(<rfilter type="tent"/>)"),
       {"<rfilter type=\"tent\">", "box, gaussian"}},
      {"negative reflectance",
       scene_xml(
           R"(<bsdf type="diffuse" id="d"><spectrum name="reflectance" value="400:0.5, 700:-0.1"/></bsdf>)"),
       {"negative value -0.1"}},
      {"no file name",
       scene_xml(R"(<shape type="ply"/>)"),
       {"<shape type=\"ply\"> needs <string name=\"filename\" value=\"...\"/>"}},
      {"missing mesh",
       scene_xml(R"(<shape type="obj"><string name="filename" value="gone.obj"/></shape>)"),
       {"<shape type=\"obj\">", "\"gone.obj\" not found"}},
      // A problem found by the JSON loader is told at the element it came from.
      {"loader error",
       scene_xml(R"(<shape type="sphere"><float name="radius" value="-1"/></shape>)"),
       {"scene.xml:5: <shape type=\"sphere\">: shapes[0].radius"}},
  };
}

INSTANTIATE_TEST_SUITE_P(All, MitsubaRefusal, ::testing::ValuesIn(refusals()),
                         [](const ::testing::TestParamInfo<Refusal>& info) {
                           std::string name = info.param.name;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST(MitsubaImport, DeepNestingIsRefusedNotACrash) {
  std::string text = "<scene version=\"3.0.0\">\n";
  for (int i = 0; i < 100000; ++i) text += "<bsdf type=\"twosided\">";
  for (int i = 0; i < 100000; ++i) text += "</bsdf>";
  text += "\n</scene>\n";
  const std::string message = test::input_error_of([&] { translate_mitsuba_scene(write_scene(text)); });
  EXPECT_NE(message.find("nested more than 100 deep"), std::string::npos) << message.substr(0, 300);
}

// Defaults that expand each other grow exponentially ($e is 64 x 16^4 bytes = 4 MiB here; the audit's
// 673-byte file reached 53 MB, one level more 2 GB): substitution is bounded per attribute and per document.
TEST(MitsubaImport, SelfExpandingParametersAreRefused) {
  std::string defaults = "<default name=\"a\" value=\"" + std::string(64, 'x') + "\"/>\n";
  for (const char* level : {"b", "c", "d", "e"}) {
    std::string value;
    for (int i = 0; i < 16; ++i) value += std::string("$") + char(level[0] - 1);
    defaults += fmt::format("<default name=\"{}\" value=\"{}\"/>\n", level, value);
  }
  const std::string message = test::input_error_of([&] {
    translate_mitsuba_scene(write_scene(scene_xml(defaults + R"(<bsdf type="diffuse" id="$e"/>)")));
  });
  EXPECT_NE(message.find("parameter substitution makes an attribute longer than 1048576 bytes"),
            std::string::npos)
      << message.substr(0, 300);
  EXPECT_LT(message.size(), 2000u);
}

TEST(MitsubaImport, SubstitutionIsBoundedForTheWholeDocument) {
  // $d is 256 KiB, under the per-attribute bound; 300 uses of it are 75 MiB, over the 64 MiB in all.
  std::string text = "<default name=\"a\" value=\"" + std::string(64, 'x') + "\"/>\n";
  for (const char* level : {"b", "c", "d"}) {
    std::string value;
    for (int i = 0; i < 16; ++i) value += std::string("$") + char(level[0] - 1);
    text += fmt::format("<default name=\"{}\" value=\"{}\"/>\n", level, value);
  }
  for (int i = 0; i < 300; ++i) text += fmt::format("<bsdf type=\"diffuse\" id=\"m{}$d\"/>\n", i);
  const std::string message =
      test::input_error_of([&] { translate_mitsuba_scene(write_scene(scene_xml(text))); });
  EXPECT_NE(message.find("longer than 67108864 bytes in all"), std::string::npos) << message.substr(0, 300);
}

TEST(MitsubaImport, IncludeCyclesAreRefused) {
  const auto dir = test::scratch_dir();
  test::write_text(dir / "a.xml", "<scene version=\"3.0.0\">\n<include filename=\"b.xml\"/>\n</scene>\n");
  test::write_text(dir / "b.xml", "<scene version=\"3.0.0\">\n<include filename=\"a.xml\"/>\n</scene>\n");
  const std::string message = test::input_error_of([&] { translate_mitsuba_scene(dir / "a.xml"); });
  EXPECT_NE(message.find("b.xml:2: <include>"), std::string::npos) << message;
  EXPECT_NE(message.find("includes itself"), std::string::npos) << message;
}

TEST(MitsubaImport, ErrorsInIncludedFilesNameThatFile) {
  const auto dir = test::scratch_dir();
  test::write_text(dir / "parts/bad.xml",
                   "<scene version=\"3.0.0\">\n\n<bsdf type=\"plastic\" id=\"p\"/>\n</scene>\n");
  test::write_text(dir / "scene.xml", scene_xml(R"(<include filename="parts/bad.xml"/>)"));
  const std::string message = test::input_error_of([&] { load_scene(dir / "scene.xml"); });
  EXPECT_NE(message.find("parts/bad.xml:3: <bsdf type=\"plastic\" id=\"p\">"), std::string::npos) << message;
}

}  // namespace
}  // namespace ochre::mitsuba_import_test
