#pragma once
// CIE 1931 colorimetry: the 2-degree standard observer, spectrum -> XYZ, and the CIE standard
// illuminants D65 and A.
//
//   cie_x(l), cie_y(l), cie_z(l)   colour matching functions xbar, ybar, zbar at l nm: linear
//                                  interpolation of the 1 nm table (CIE 15:2004), 0 outside 360-830
//   kCieYIntegral                  sum of ybar over 360..830 nm at 1 nm steps (as in pbrt-v4)
//   spectrum_to_xyz(s)             1 nm Riemann sum of s xbar, s ybar, s zbar over 360..830 nm
//                                  divided by kCieYIntegral, so that a constant 1 spectrum has Y = 1
//   sampled_to_xyz(L, lambda)      Monte-Carlo estimate of spectrum_to_xyz from one path's 8 hero
//                                  wavelengths: mean over lanes of cmf(l_i) L_i / pdf_i over
//                                  kCieYIntegral (lanes with pdf 0, i.e. terminated, count as 0)
//   d65(), illuminant_a()          CIE illuminants scaled to luminance 1 (spectrum_to_xyz(s).y == 1):
//                                  a named illuminant only gives the colour, the scene sets the power
//   cie_illuminant_a_relative(l)   CIE 15:2004 formula of illuminant A, 100 at 560 nm
//   normalized_to_unit_luminance(s) s scaled so that spectrum_to_xyz(result).y == 1

#include "spectra/color_types.h"
#include "spectra/spectrum.h"

namespace ochre {

inline constexpr float kCieYIntegral = 106.856895f;

float cie_x(float lambda_nm);
float cie_y(float lambda_nm);
float cie_z(float lambda_nm);

XYZ spectrum_to_xyz(const Spectrum& s);
XYZ sampled_to_xyz(const SampledSpectrum& L, const SampledWavelengths& lambda);

double cie_illuminant_a_relative(double lambda_nm);
SpectrumPtr normalized_to_unit_luminance(SpectrumPtr s);
SpectrumPtr d65();
SpectrumPtr illuminant_a();

}  // namespace ochre
