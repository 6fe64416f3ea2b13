#pragma once
// Turns a rendered Film into the files a user asked for: an EXR in the linear working space
// and a display-referred PNG through OpenColorIO. Outputs are checked before rendering
// (check_outputs) so a bad path or display setting fails with no work done and no file written.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/film/film.h"
#include "renderer/image/display_image.h"
#include "renderer/image/exr_writer.h"
#include "renderer/integrator/render.h"
#include "renderer/scene/render_settings.h"

namespace ochre {

class OutputTransaction;

// Linear working-space RGB of the film (3 floats per pixel, row 0 at the top), of a film of XYZ.
std::vector<float> film_to_rgb(const Film& film, ColorSpace colorspace);
// The same for the film of a render with these outputs: a camera sensor's film (docs/cameras.md) is
// white-balanced to XYZ first (outputs.sensor_to_xyz), or written as camera RGB (outputs.camera_rgb).
std::vector<float> film_to_rgb(const Film& film, const OutputSettings& outputs);

// The display transform of the PNG output (OCIO config, display, view, working space, exposure).
DisplayOptions display_options(const OutputSettings& outputs);

// "S0.550,000000nm": the OpenEXR spectral layout of Fichet, Pacanowski & Wilkie (JCGT 2021): Stokes
// component, a dot, the bin centre with a decimal comma, the unit.
std::string spectral_channel_name(int component, float centre_nm);
// The bin centre of a channel so named for that Stokes component, or nothing for any other channel.
std::optional<float> spectral_channel_wavelength(std::string_view name, int component = 0);
// "group.torch.550,000000nm": the layer of a light group's bin (its channels .R, .G, .B), named like the
// spectral layers (docs/lights.md, "Light groups").
std::string group_bin_layer(const std::string& group, float centre_nm);
// "ochre.lightGroup.torch.emission": the attribute that holds the shape of a group's emission spectrum.
std::string light_group_emission_attribute(const std::string& group);
// Adds the film's spectral layers (S0.<nm>, and S1..S3.<nm> with Stokes) and the spectral layout's header
// attributes to image (film.spectral_bins() > 0).
void add_spectral_channels(const Film& film, ExrImage& image);

// The EXR write_outputs() writes, in memory: R, G, B (`rgb`, film_to_rgb(film, outputs)), then the AOV,
// spectral and Stokes layers the film has, and the render's settings and statistics in the header.
ExrImage render_exr_image(const Film& film, const std::vector<float>& rgb, const OutputSettings& outputs,
                          const RenderSettings& settings, const RenderStats& stats,
                          const std::string& scene_file);

// Stokes layers (and the polarization PNG that needs them) come from the full Mueller product: they need
// polarization mode stokes or auto. InputError naming the scene and integrator.polarization otherwise.
void check_stokes_mode(const RenderJob& job, const std::string& scene_name);

// Throws InputError when an output directory is missing or not writable, or the display
// transform cannot be built (unknown config, display or view).
void check_outputs(const OutputSettings& outputs);

// The film layers the outputs need (AOVs and spectral bins only with an EXR; Stokes for the Stokes
// layers and the polarization PNG).
FilmLayers film_layers(const OutputSettings& outputs);

// Throws InputError (renderer/util/memory_budget.h) when a width x height film with the layers of `outputs`,
// plus the buffers write_outputs() needs at its peak, exceeds the memory limit.
void check_render_memory(int width, int height, const OutputSettings& outputs);

// The paths write_outputs() writes (EXR, polarization PNG, display PNG; those that are set).
std::vector<std::string> output_paths(const OutputSettings& outputs);

// Writes the requested files, all or none: each is written completely under a temporary name before
// any is renamed over its final name (renderer/util/output_transaction.h). Returns human-readable lines
// describing what was written.
std::vector<std::string> write_outputs(const Film& film, const OutputSettings& outputs,
                                       const RenderSettings& settings, const RenderStats& stats,
                                       const std::string& scene_file);
// The same into `transaction`, which the caller commits (with other files of its own).
std::vector<std::string> add_outputs(OutputTransaction& transaction, const Film& film,
                                     const OutputSettings& outputs, const RenderSettings& settings,
                                     const RenderStats& stats, const std::string& scene_file);

}  // namespace ochre
