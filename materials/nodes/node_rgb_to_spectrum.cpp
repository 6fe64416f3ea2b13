// rgb_to_spectrum(color; mode): an explicit colour -> spectrum conversion, choosing the upsampling
// (reflectance or illuminant) instead of taking it from the socket the result feeds.

#include <memory>

#include "materials/nodes/node_definition.h"
#include "materials/nodes/rgb_upsampling.h"

namespace ochre {

namespace {

struct Mode {
  SpectralRole role;
};

Prepared prepare_rgb_to_spectrum(const PrepareArgs& args) {
  const bool illuminant = args.params.at("mode").get<std::string>() == "illuminant";
  Prepared p;
  p.payload =
      std::make_shared<Mode>(Mode{illuminant ? SpectralRole::kIlluminant : SpectralRole::kReflectance});
  return p;
}

void eval_rgb_to_spectrum(const NodeArgs& a) {
  const RGB c = a.in_colour(0);
  a.set_spectrum(0, a.data<Mode>().role == SpectralRole::kIlluminant ? upsample_illuminant(c, a.lambda())
                                                                     : upsample_reflectance(c, a.lambda()));
}

// Constant colours are converted once here; the generic folding cannot do it (the result is not
// constant over wavelength).
FoldResult fold_rgb_to_spectrum(const FoldArgs& args) {
  FoldResult r;
  if (!args.inputs[0].is_constant()) return r;
  const SpectralRole role = static_cast<const Mode*>(args.payload)->role;
  r.kind = FoldResult::Kind::kConstants;
  r.outputs = {NodeValue::of_spectrum(colour_to_spectrum(args.inputs[0].value->colour, role))};
  return r;
}

}  // namespace

NodeDefinition rgb_to_spectrum_node() {
  NodeDefinition d;
  d.name = "rgb_to_spectrum";
  d.doc = "Converts a colour to a spectrum with the chosen upsampling.";
  SocketDef color;
  color.name = "color";
  color.type = SocketType::kColour;
  color.default_value = NodeValue::of_colour({1.0f, 1.0f, 1.0f});
  color.min = 0.0f;
  color.doc = "linear Rec.709 colour (negative constants are errors)";
  d.inputs = {color};
  ParamDef mode;
  mode.name = "mode";
  mode.default_value = "reflectance";
  mode.choices = {"reflectance", "illuminant"};
  mode.doc = "reflectance: smooth bounded spectrum (unbounded above 1); illuminant: times D65 at luminance 1";
  d.params = {mode};
  d.outputs = {{"spectrum", SocketType::kSpectrum, false, "the upsampled spectrum"}};
  d.prepare = prepare_rgb_to_spectrum;
  d.eval = eval_rgb_to_spectrum;
  d.fold = fold_rgb_to_spectrum;
  return d;
}

}  // namespace ochre
