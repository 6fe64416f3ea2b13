#include "materials/nodes/node_value.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

#include "spectra/constant_spectrum.h"
#include "spectra/rgb_spectrum.h"
#include "spectra/sampled_wavelengths.h"

namespace ochre {

namespace {

// Spectra are checked at every nm of the rendered range: enough to catch a negative or NaN entry
// of a tabulated file (whose entries lie at whole or coarser nm steps).
template <class F>
void for_each_nm(const Spectrum& s, F&& f) {
  for (int nm = static_cast<int>(kLambdaMin); nm <= static_cast<int>(kLambdaMax); ++nm) f(s.eval(float(nm)));
}

float min3(float a, float b, float c) {
  return std::min(a, std::min(b, c));
}
float max3(float a, float b, float c) {
  return std::max(a, std::max(b, c));
}

}  // namespace

NodeValue NodeValue::of_float(float v) {
  NodeValue n;
  n.type = SocketType::kFloat;
  n.f = v;
  return n;
}

NodeValue NodeValue::of_colour(const RGB& c) {
  NodeValue n;
  n.type = SocketType::kColour;
  n.colour = c;
  return n;
}

NodeValue NodeValue::of_vector(const Vec3& v) {
  NodeValue n;
  n.type = SocketType::kVector;
  n.vector = v;
  return n;
}

NodeValue NodeValue::of_spectrum(SpectrumPtr s) {
  NodeValue n;
  n.type = SocketType::kSpectrum;
  n.spectrum = std::move(s);
  return n;
}

std::string NodeValue::describe() const {
  std::ostringstream out;
  switch (type) {
    case SocketType::kFloat:
      out << f;
      break;
    case SocketType::kColour:
      out << '[' << colour.r << ", " << colour.g << ", " << colour.b << ']';
      break;
    case SocketType::kVector:
      out << "{vector: [" << vector.x << ", " << vector.y << ", " << vector.z << "]}";
      break;
    case SocketType::kSpectrum:
      if (spectrum->is_constant())
        out << "spectrum(" << spectrum->eval(550.0f) << ')';
      else
        out << "spectrum(max " << spectrum->max_value() << ')';
      break;
    case SocketType::kClosure:
      out << "closure";
      break;
  }
  return out.str();
}

bool is_finite(const NodeValue& v) {
  switch (v.type) {
    case SocketType::kFloat:
      return std::isfinite(v.f);
    case SocketType::kColour:
      return std::isfinite(v.colour.r) && std::isfinite(v.colour.g) && std::isfinite(v.colour.b);
    case SocketType::kVector:
      return std::isfinite(v.vector.x) && std::isfinite(v.vector.y) && std::isfinite(v.vector.z);
    case SocketType::kSpectrum: {
      bool finite = true;
      for_each_nm(*v.spectrum, [&finite](float x) { finite = finite && std::isfinite(x); });
      return finite;
    }
    case SocketType::kClosure:
      return true;
  }
  return true;
}

float min_component(const NodeValue& v) {
  switch (v.type) {
    case SocketType::kFloat:
      return v.f;
    case SocketType::kColour:
      return min3(v.colour.r, v.colour.g, v.colour.b);
    case SocketType::kVector:
      return min3(v.vector.x, v.vector.y, v.vector.z);
    case SocketType::kSpectrum: {
      float lo = std::numeric_limits<float>::infinity();
      for_each_nm(*v.spectrum, [&lo](float x) { lo = std::min(lo, x); });
      return lo;
    }
    case SocketType::kClosure:
      return 0.0f;
  }
  return 0.0f;
}

float max_component(const NodeValue& v) {
  switch (v.type) {
    case SocketType::kFloat:
      return v.f;
    case SocketType::kColour:
      return max3(v.colour.r, v.colour.g, v.colour.b);
    case SocketType::kVector:
      return max3(v.vector.x, v.vector.y, v.vector.z);
    case SocketType::kSpectrum:
      return v.spectrum->max_value();
    case SocketType::kClosure:
      return 0.0f;
  }
  return 0.0f;
}

bool is_zero(const NodeValue& v) {
  if (v.type == SocketType::kSpectrum) {
    bool zero = true;
    for_each_nm(*v.spectrum, [&zero](float x) { zero = zero && x == 0.0f; });
    return zero;
  }
  return v.type != SocketType::kClosure && min_component(v) == 0.0f && max_component(v) == 0.0f;
}

SpectrumPtr colour_to_spectrum(const RGB& c, SpectralRole role) {
  // Negative components have no smooth bounded spectrum; constants are range-checked before
  // this point, so clamping only affects values that were never meant to be reflectances.
  const RGB rgb{std::max(c.r, 0.0f), std::max(c.g, 0.0f), std::max(c.b, 0.0f)};
  if (role == SpectralRole::kIlluminant) return std::make_shared<RGBIlluminantSpectrum>(rgb);
  if (rgb.r == rgb.g && rgb.g == rgb.b) return std::make_shared<ConstantSpectrum>(rgb.r);
  if (max3(rgb.r, rgb.g, rgb.b) <= 1.0f) return std::make_shared<RGBAlbedoSpectrum>(rgb);
  return std::make_shared<RGBUnboundedSpectrum>(rgb);
}

NodeValue convert_constant(const NodeValue& v, SocketType to, SpectralRole role) {
  if (v.type == to) return v;
  if (v.type == SocketType::kFloat) {
    switch (to) {
      case SocketType::kColour:
        return NodeValue::of_colour({v.f, v.f, v.f});
      case SocketType::kVector:
        return NodeValue::of_vector({v.f, v.f, v.f});
      case SocketType::kSpectrum:
        return NodeValue::of_spectrum(std::make_shared<ConstantSpectrum>(v.f));
      default:
        break;
    }
  }
  if (v.type == SocketType::kColour && to == SocketType::kSpectrum)
    return NodeValue::of_spectrum(colour_to_spectrum(v.colour, role));
  return v;  // not a supported conversion: the caller checked, so this is unreachable in practice
}

}  // namespace ochre
