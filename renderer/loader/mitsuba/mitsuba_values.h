#pragma once
// Values written in Mitsuba 3 XML (docs/mitsuba-import.md): numbers and number lists, points and vectors,
// <transform> blocks, and <rgb> / <spectrum> / <float> colour values turned into ochre's JSON forms. Bad
// values throw InputError naming the element ("file:line: <float name="fov">: ...").

#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "materials/core/vec3d.h"
#include "renderer/loader/mitsuba/mitsuba_xml.h"

namespace ochre {

// [x, y, z] in ochre's scene JSON.
nlohmann::json to_json(Vec3d v);

// Row-major affine 4x4 matrix; points are column vectors (p' = M p), as Mitsuba's Transform4f.
struct Matrix4d {
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  double operator()(int row, int column) const { return m[4 * row + column]; }
  Matrix4d operator*(const Matrix4d& other) const;  // applies `other` first
  Vec3d point(Vec3d p) const;
  Vec3d vector(Vec3d v) const;
  double determinant3() const;
  bool is_identity() const;
  nlohmann::json to_json() const;  // {"matrix": [16 numbers]}, the form of ochre's "transform"
};

[[noreturn]] void fail_at(const MitsubaElement& element, const std::string& message);

// A finite number; `what` names it in the message ("value", "x").
double parse_number(const std::string& text, const MitsubaElement& element, const std::string& what);
// Numbers separated by commas and/or white space.
std::vector<double> parse_numbers(const std::string& text, const MitsubaElement& element,
                                  const std::string& what);

// The value of a <float> or <integer> element.
double number_value(const MitsubaElement& element);
// A <point> or <vector>: x, y, z attributes (missing ones 0) or one "value" of 1 or 3 numbers.
Vec3d vector_value(const MitsubaElement& element);
// A <transform>: its operations (<translate>, <rotate>, <scale>, <matrix>, <lookat>), each applied after
// the ones before it, as Mitsuba composes them.
Matrix4d transform_value(const MitsubaElement& element);

// How a colour value is turned into a spectrum: a reflectance, an emitted radiance or intensity, or an
// unbounded quantity (the index of refraction eta and absorption k of a conductor).
enum class MitsubaColourRole { Reflectance, Emission, Unbounded };

// An ochre JSON input value for a <float>, <rgb> or <spectrum> element (textures are the caller's):
//   <float value="v">                    v
//   <rgb value="r, g, b">, <rgb value="v">  [r, g, b] (ochre upsamples it for the role of the input it
//                                        reaches, as Mitsuba: a reflectance, or D65 times an unbounded
//                                        spectrum for emission); for the unbounded role, the unbounded
//                                        upsampled spectrum as a table
//   <spectrum value="v">                 v (a uniform spectrum)
//   <spectrum value="l1:v1, l2:v2, ..."> {"wavelengths": [...], "values": [...], "extrapolate": "zero"}
//                                        (Mitsuba's spectra are 0 outside their table)
//   <spectrum filename="x.spd">          the same, from the file's "wavelength value" lines
// Negative values of a reflectance or emission are refused.
nlohmann::json colour_value(const MitsubaDocument& document, const MitsubaElement& element,
                            MitsubaColourRole role);

}  // namespace ochre
