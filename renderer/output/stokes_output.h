#pragma once
// Stokes outputs of a render in mode stokes (docs/polarization.md): EXR layers and a false-colour PNG.
//   stokes.S0.X/Y/Z .. stokes.S3.X/Y/Z : each Stokes component weighted by the CIE 1931 colour matching
//                                        functions (linear, never through a display transform; S1..S3 can
//                                        be negative);
//   DoLP, AoLP                         : degree and angle (radians, (-pi/2, pi/2], from the image x axis
//                                        toward up) of linear polarization of the Y-weighted components;
//   S1.<nm> .. S3.<nm>                 : per spectral bin, beside S0.<nm> (Fichet et al. 2021 layout), with
//                                        the header attribute polarisationHandedness.
// The camera frame: x along the image x axis, y up, light propagating toward the camera.

#include <filesystem>

#include "renderer/film/film.h"
#include "renderer/image/exr_writer.h"

namespace ochre {

class AtomicOutput;

// Degree and angle of linear polarization from S0, S1, S2 (0 and 0 where S0 <= 0).
float degree_of_linear_polarization(float s0, float s1, float s2);
float angle_of_linear_polarization(float s1, float s2);

// Adds the XYZ-weighted Stokes layers and DoLP / AoLP to `image` (film.has_stokes() must be true).
void add_stokes_channels(const Film& film, ExrImage& image);

// False colour: hue = AoLP (red at 0, through the hue circle once per 180 degrees), brightness = DoLP.
void write_polarization_png(const std::filesystem::path& path, const Film& film);
// The same into output.temp_path(), without committing (renderer/util/output_transaction.h).
void write_polarization_png(AtomicOutput& output, const Film& film);

}  // namespace ochre
