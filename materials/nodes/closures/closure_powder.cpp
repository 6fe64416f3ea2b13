// powder(volume_amplitude, g, kappa, radius, surface_amplitude, correlation_length, thickness, rho; pigment,
// pigment_file, ladder, ladder_decay, normalisation, surface, surface_sigma, tau): the dry-powder BRDF of
// Gerardin, Martinetto and Holzschuch 2023 (materials/lobes/powder/powder_lobe.h), with the grains'
// single-scattering albedo from Mie theory for the pigment's optical constants and the grain radius
// (materials/lobes/powder/pigment_table.h), unless `rho` overrides it.

#include <array>
#include <cmath>
#include <memory>
#include <string>

#include "materials/lobes/powder/pigment_table.h"
#include "materials/lobes/powder/powder_lobe.h"
#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_choices.h"
#include "materials/nodes/node_definition.h"
#include "materials/nodes/spectrum_source.h"

namespace ochre {

namespace {

enum Input { kVolumeAmplitude, kG, kKappa, kRadius, kSurfaceAmplitude, kCorrelationLength, kThickness, kRho };

struct PowderSettings {
  std::shared_ptr<const PigmentTable> pigment;
  PowderParams<float> options;  // the option enums (the numbers come from the inputs)
  PowderSamplingStrategy sampling = PowderSamplingStrategy::kMixture;
};

constexpr std::array kPowderLadders{Choice{"symmetric", PowderLadder::kSymmetric},
                                    Choice{"printed", PowderLadder::kPrinted}};
constexpr std::array kLadderDecays{Choice{"c0", PowderLadderDecay::kC0},
                                   Choice{"alpha", PowderLadderDecay::kWithAlpha}};
constexpr std::array kPowderNormalisations{Choice{"brdf", PowderNormalisation::kPerSteradian},
                                           Choice{"printed", PowderNormalisation::kPrinted}};
constexpr std::array kPowderSurfaces{Choice{"harvey_shack", PowderSurface::kHarveyShack},
                                     Choice{"gaussian", PowderSurface::kGaussian}};
constexpr std::array kPowderTaus{Choice{"paper", PowderTau::kPaper},
                                 Choice{"zhu_pine_weitz", PowderTau::kZhuPineWeitz},
                                 Choice{"two_thirds", PowderTau::kTwoThirds}};
constexpr std::array kPowderSamplings{Choice{"mixture", PowderSamplingStrategy::kMixture},
                                      Choice{"cosine", PowderSamplingStrategy::kCosine}};

Prepared prepare_powder(const PrepareArgs& args) {
  auto s = std::make_shared<PowderSettings>();
  PowderParams<float>& o = s->options;
  o.ladder = choice_value(args, "ladder", kPowderLadders);
  o.ladder_decay = choice_value(args, "ladder_decay", kLadderDecays);
  o.normalisation = choice_value(args, "normalisation", kPowderNormalisations);
  o.surface = choice_value(args, "surface", kPowderSurfaces);
  s->sampling = choice_value(args, "sampling", kPowderSamplings);
  const PowderTau tau = choice_value(args, "tau", kPowderTaus);
  const std::string pigment = *choice_name(args, "pigment");
  if (args.params.contains("pigment_file")) {
    const std::string file = args.params.at("pigment_file").get<std::string>();
    try {
      const SpectrumPtr n = spectrum_from_file(file, "n", args.resolver),
                        k = spectrum_from_file(file, "k", args.resolver);
      s->pigment = std::make_shared<PigmentTable>(*n, *k, tau);
    } catch (const std::runtime_error& e) {
      throw NodeError("pigment_file", e.what());
    }
  } else {
    s->pigment = PigmentTable::named(pigment, tau);
  }
  if (args.params.contains("surface_sigma"))
    o.gaussian_sigma = static_cast<float>(args.params.at("surface_sigma").get<double>() * kPi / 180.0);
  Prepared p;
  p.payload = s;
  return p;
}

void emit_powder(const NodeArgs& a) {
  const SampledSpectrum w = a.weight();
  if (w.is_black()) return;
  const PowderSettings& s = a.data<PowderSettings>();
  const SampledSpectrum volume = a.in_spectrum(kVolumeAmplitude), g = a.in_spectrum(kG),
                        kappa = a.in_spectrum(kKappa), surface = a.in_spectrum(kSurfaceAmplitude),
                        rho = a.in_spectrum(kRho);
  const float radius = a.in_float(kRadius), correlation = a.in_float(kCorrelationLength);
  const float thickness = a.in_float(kThickness);
  std::array<PowderParams<float>, kSpectrumSamples> params;
  std::array<PowderWavelength<float>, kSpectrumSamples> waves;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    PowderParams<float>& p = params[i];
    p = s.options;
    // Linked values are kept inside the model's domain (the ranges of docs/nodes.md).
    p.volume_amplitude = std::max(volume[i], 0.0f);
    p.g = std::clamp(g[i], -0.99f, 0.99f);
    p.kappa = std::clamp(kappa[i], 1e-6f, 1e6f);
    p.surface_amplitude = std::max(surface[i], 0.0f);
    p.correlation_length = std::clamp(correlation, 1e-6f, 1e6f);
    p.thickness = std::clamp(thickness, 1e-9f, 1e30f);
    const float lambda_nm = a.lambda()[i];
    waves[i].lambda_um = lambda_nm * 1e-3f;
    waves[i].rho =
        rho[i] >= 0.0f ? std::min(rho[i], 1.0f) : s.pigment->albedo(lambda_nm, std::max(radius, 1e-6f));
    waves[i].tau_o = s.pigment->tau_o(lambda_nm);
  }
  a.add_lobe(a.arena.make<PowderLobe>(params, waves, s.sampling), w);
}

ClosureTraits powder_traits(std::span<const InputView>, const void*) {
  return {kLobeReflection | kLobeDiffuse | kLobeGlossy, false};
}

}  // namespace

NodeDefinition powder_node() {
  NodeDefinition d;
  d.name = "powder";
  d.doc =
      "Dry powder (pigments such as hematite): enhanced-backscattering BRDF of Gerardin, Martinetto and "
      "Holzschuch 2023; the grains' albedo from Mie theory and the pigment's optical constants. A "
      "depolarizer.";
  d.inputs = {
      float_input("volume_amplitude", SocketType::kSpectrum, 1.0f, clamped_range(0.0f, std::nullopt),
                  "A_v: scale of the volume terms (1 = physically normalised)"),
      float_input("g", SocketType::kSpectrum, 0.0f, clamped_range(-0.99f, 0.99f),
                  "Henyey-Greenstein anisotropy of the grains"),
      float_input("kappa", SocketType::kSpectrum, 0.25f, clamped_range(1e-6f, 1e6f),
                  "extinction coefficient, 1/um"),
      float_input("radius", SocketType::kFloat, 0.05f, clamped_range(1e-6f, 1e6f),
                  "effective grain radius in um (Mie albedo; tabulated for 0.002-20 um)"),
      float_input("surface_amplitude", SocketType::kSpectrum, 3e-6f, clamped_range(0.0f, std::nullopt),
                  "A_s' = A_s sigma_s^2 of the Harvey-Shack surface term, um^2"),
      float_input("correlation_length", SocketType::kFloat, 2.0f, clamped_range(1e-6f, 1e6f),
                  "surface correlation length l_c, um"),
      float_input("thickness", SocketType::kFloat, 1e30f, clamped_range(1e-9f, 1e30f),
                  "layer thickness d in um (single scattering only); default 1e30: infinite"),
      float_input("rho", SocketType::kSpectrum, -1.0f, constant_range(std::nullopt, 1.0f),
                  "single-scattering albedo of the grains; when >= 0 it replaces the Mie albedo "
                  "(default -1)")};
  d.params = {
      choice_param("pigment", "hematite", PigmentTable::names(),
                   "built-in optical constants: hematite (Querry 1985; randomly oriented grains, "
                   "(2 o + e) / 3), or one of its rays"),
      string_param("pigment_file",
                   "a CSV of the grains' optical constants with columns n and k (index n + i k); replaces "
                   "`pigment`")};
  // The paper as printed, the literature's alternatives and the sampler's baseline, beside the corrected
  // model as their defaults (docs/materials/powder.md, 'Product and research settings').
  for (ParamDef& p : research_params(
           {choice_param("ladder", "symmetric", choice_names(kPowderLadders),
                         "multiple-scattering ladder: Eq 21 with its sign fixed (symmetric, reciprocal), "
                         "or as printed (for comparison)"),
            choice_param("ladder_decay", "c0", choice_names(kLadderDecays),
                         "the ladder's decay: c0 (no interference term), or the printed c with alpha"),
            choice_param("normalisation", "brdf", choice_names(kPowderNormalisations),
                         "L2 and C divided by 4 pi (a true BRDF), or as printed (4 pi larger)"),
            choice_param("surface", "harvey_shack", choice_names(kPowderSurfaces),
                         "surface term: Harvey-Shack (Eqs 27-28) or the Gaussian of Eq 26"),
            number_param("surface_sigma", 5.7, 0.01, 90.0,
                         "Gaussian surface term only: its width in degrees"),
            choice_param("tau", "paper", choice_names(kPowderTaus),
                         "extrapolation ratio tau_o: Eq 16 as printed, its inverse (Zhu, Pine and Weitz "
                         "1991), or 2/3"),
            choice_param("sampling", "mixture", choice_names(kPowderSamplings),
                         "importance sampling: the cone / surface / cosine mixture, or cosine only (for "
                         "comparison)")}))
    d.params.push_back(std::move(p));
  d.outputs = {{"closure", SocketType::kClosure, false, "the powder lobe"}};
  d.prepare = prepare_powder;
  d.eval = emit_powder;
  d.closure_traits = powder_traits;
  d.context_usage = kUsesWavelengths;
  return d;
}

}  // namespace ochre
