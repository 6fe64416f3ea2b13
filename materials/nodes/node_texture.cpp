// texture(file, colorspace, channel; uv): a filtered image lookup through the renderer's
// TextureProvider. Wrap mode is periodic; the filter width is the shading point's uv footprint.

#include <stdexcept>
#include <string>

#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_choices.h"
#include "materials/nodes/node_definition.h"
#include "materials/nodes/resource_resolver.h"

namespace ochre {

namespace {

struct TextureData {
  int id = -1;
  int channels = 0;
  int channel = 0;  // channel read by the `value` output
};

Prepared prepare_texture(const PrepareArgs& args) {
  // The word goes to the renderer as it is (ResourceResolver::texture), which decodes it with the file.
  const std::string colorspace = *choice_name(args, "colorspace");
  const std::filesystem::path path = args.resolver.resolve(args.params.at("file").get<std::string>());
  auto data = std::make_shared<TextureData>();
  try {
    data->id = args.resolver.texture(path, colorspace, data->channels);
  } catch (const std::exception& e) {
    throw NodeError("file", "cannot open texture '" + path.string() + "': " + e.what());
  }
  data->channel = args.params.at("channel").get<int>();
  if (data->channel >= data->channels)
    throw NodeError("channel", "channel " + std::to_string(data->channel) + " does not exist: '" +
                                   path.string() + "' has " + std::to_string(data->channels) + " channel(s)");
  Prepared p;
  p.payload = data;
  return p;
}

void eval_texture(const NodeArgs& a) {
  const TextureData& t = a.data<TextureData>();
  if (!a.ctx.textures)
    throw std::logic_error("texture node evaluated without a TextureProvider in the ShadingContext");
  const Vec3 uvw = a.in_vector(0);
  const Vec2 uv{uvw.x, uvw.y};
  // A footprint given with computed coordinates (a projection's) replaces the mesh uv's.
  const float given_footprint = a.in_float(1);
  const float footprint = given_footprint >= 0.0f ? given_footprint : a.ctx.uv_footprint;
  // Images with fewer than 3 channels are grey: their first channel fills r, g and b.
  const int colour_channels = t.channels >= 3 ? 3 : 1;
  const bool value_in_colour = t.channel < colour_channels;
  float c[3] = {0.0f, 0.0f, 0.0f};
  if (a.output_used(0) || (a.output_used(1) && value_in_colour)) {
    a.ctx.textures->lookup(t.id, uv, footprint, 0, colour_channels, c);
    if (colour_channels == 1) c[1] = c[2] = c[0];
    a.set_colour(0, {c[0], c[1], c[2]});
  }
  if (a.output_used(1)) {
    float v = value_in_colour ? c[t.channel] : 0.0f;
    if (!value_in_colour) a.ctx.textures->lookup(t.id, uv, footprint, t.channel, 1, &v);
    a.set_float(1, v);
  }
}

}  // namespace

NodeDefinition texture_node() {
  NodeDefinition d;
  d.name = "texture";
  d.doc = "Filtered image lookup (periodic wrap). Images with 1 or 2 channels give a grey colour.";
  d.inputs = {
      context_input("uv", SocketType::kVector, "uv",
                    "lookup coordinates (u, v, ignored); default: the mesh uv"),
      float_input("footprint", SocketType::kFloat, -1.0f, kAnyValue,
                  "filter width in the units of `uv` (e.g. a projection's footprint); < 0: the mesh uv's")};
  d.params = {required_string_param("file", "image file, relative to the scene file"),
              choice_param("colorspace", "auto", {"auto", "srgb", "linear"},
                           "encoding of the stored values: auto (from the file: 8-bit images sRGB, float "
                           "linear), srgb, linear"),
              integer_param("channel", 0, 0, std::nullopt, "channel read by the value output")};
  d.outputs = {{"color", SocketType::kColour, false, "linear Rec.709 colour"},
               {"value", SocketType::kFloat, false, "the channel `channel`, linear"}};
  d.context_usage = kUsesUV | kUsesTextures;
  d.prepare = prepare_texture;
  d.eval = eval_texture;
  return d;
}

}  // namespace ochre
