// rgb_to_spectrum(color; mode): an explicit colour -> spectrum conversion, choosing the upsampling
// (reflectance or illuminant) instead of taking it from the socket the result feeds.

#include <array>
#include <memory>

#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_choices.h"
#include "materials/nodes/node_definition.h"
#include "materials/nodes/rgb_upsampling.h"

namespace ochre {

namespace {

struct Mode {
  SpectralRole role;
};

constexpr std::array kUpsamplingModes{Choice{"reflectance", SpectralRole::kReflectance},
                                      Choice{"illuminant", SpectralRole::kIlluminant}};

Prepared prepare_rgb_to_spectrum(const PrepareArgs& args) {
  Prepared p;
  p.payload = std::make_shared<Mode>(Mode{choice_value(args, "mode", kUpsamplingModes)});
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
  d.inputs = {colour_input("color", SocketType::kColour, {1.0f, 1.0f, 1.0f}, SpectralRole::kNone,
                           constant_range(0.0f, std::nullopt),
                           "linear Rec.709 colour (negative constants are errors)")};
  d.params = {choice_param(
      "mode", "reflectance", choice_names(kUpsamplingModes),
      "reflectance: smooth bounded spectrum (unbounded above 1); illuminant: times D65 at luminance 1")};
  d.outputs = {{"spectrum", SocketType::kSpectrum, false, "the upsampled spectrum"}};
  d.prepare = prepare_rgb_to_spectrum;
  d.eval = eval_rgb_to_spectrum;
  d.fold = fold_rgb_to_spectrum;
  return d;
}

}  // namespace ochre
