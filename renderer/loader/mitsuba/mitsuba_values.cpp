#include "renderer/loader/mitsuba/mitsuba_values.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <sstream>

#include "spectra/input_error.h"
#include "spectra/input_file.h"
#include "spectra/rgb_spectrum.h"

namespace ochre {

nlohmann::json to_json(Vec3d v) {
  return nlohmann::json::array({v.x, v.y, v.z});
}

Matrix4d Matrix4d::operator*(const Matrix4d& o) const {
  Matrix4d r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double sum = 0.0;
      for (int k = 0; k < 4; ++k) sum += m[4 * i + k] * o.m[4 * k + j];
      r.m[4 * i + j] = sum;
    }
  return r;
}

Vec3d Matrix4d::point(Vec3d p) const {
  return vector(p) + Vec3d{m[3], m[7], m[11]};
}

Vec3d Matrix4d::vector(Vec3d v) const {
  return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[4] * v.x + m[5] * v.y + m[6] * v.z,
          m[8] * v.x + m[9] * v.y + m[10] * v.z};
}

double Matrix4d::determinant3() const {
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
         m[2] * (m[4] * m[9] - m[5] * m[8]);
}

bool Matrix4d::is_identity() const {
  return m == Matrix4d().m;
}

nlohmann::json Matrix4d::to_json() const {
  return {{"matrix", m}};
}

void fail_at(const MitsubaElement& element, const std::string& message) {
  throw InputError(fmt::format("{}: {}", element.where(), message));
}

double parse_number(const std::string& text, const MitsubaElement& element, const std::string& what) {
  size_t begin = text.find_first_not_of(" \t\r\n"), end = text.find_last_not_of(" \t\r\n");
  double value = 0.0;
  if (begin != std::string::npos) {
    const char* first = text.data() + begin;
    const char* last = text.data() + end + 1;
    if (*first == '+') ++first;  // from_chars takes no plus sign; Mitsuba's parser does
    const auto [ptr, error] = std::from_chars(first, last, value);
    if (error == std::errc() && ptr == last && std::isfinite(value)) return value;
  }
  fail_at(element, fmt::format("{}: \"{}\" is not a finite number", what, text));
}

namespace {

// The words of a list: separated by commas and/or white space, as Mitsuba's tokenizer splits them.
std::vector<std::string> list_items(const std::string& text) {
  std::vector<std::string> items(1);
  for (char c : text) {
    if (c == ',' || std::isspace(static_cast<unsigned char>(c))) {
      if (!items.back().empty()) items.emplace_back();
    } else {
      items.back() += c;
    }
  }
  if (items.back().empty()) items.pop_back();
  return items;
}

}  // namespace

std::vector<double> parse_numbers(const std::string& text, const MitsubaElement& element,
                                  const std::string& what) {
  std::vector<double> numbers;
  for (const std::string& item : list_items(text)) numbers.push_back(parse_number(item, element, what));
  return numbers;
}

namespace {

const std::string& required(const MitsubaElement& element, const char* attribute) {
  const std::string* value = element.attribute(attribute);
  if (!value) fail_at(element, fmt::format("missing attribute \"{}\"", attribute));
  return *value;
}

void only_attributes(const MitsubaElement& element, std::initializer_list<const char*> allowed) {
  for (const auto& [name, value] : element.attributes) {
    bool known = false;
    for (const char* a : allowed) known = known || name == a;
    if (!known) {
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      fail_at(element, fmt::format("unexpected attribute \"{}\" (<{}> takes: {})", name, element.tag, list));
    }
  }
}

void no_children(const MitsubaElement& element) {
  if (!element.children.empty())
    fail_at(element.children.front(), fmt::format("<{}> cannot hold other elements", element.tag));
}

// x, y, z attributes (missing ones `fallback`) or "value" with 1 number (all three) or 3.
Vec3d xyz_value(const MitsubaElement& element, double fallback) {
  if (const std::string* value = element.attribute("value")) {
    if (element.has("x") || element.has("y") || element.has("z"))
      fail_at(element, "give either \"value\" or \"x\", \"y\", \"z\", not both");
    const std::vector<double> v = parse_numbers(*value, element, "value");
    if (v.size() == 1) return {v[0], v[0], v[0]};
    if (v.size() == 3) return {v[0], v[1], v[2]};
    fail_at(element, fmt::format("value: expected 1 or 3 numbers, got {}", v.size()));
  }
  Vec3d v{fallback, fallback, fallback};
  if (const std::string* x = element.attribute("x")) v.x = parse_number(*x, element, "x");
  if (const std::string* y = element.attribute("y")) v.y = parse_number(*y, element, "y");
  if (const std::string* z = element.attribute("z")) v.z = parse_number(*z, element, "z");
  return v;
}

Vec3d named_vector(const MitsubaElement& element, const char* attribute) {
  const std::vector<double> v = parse_numbers(required(element, attribute), element, attribute);
  if (v.size() != 3) fail_at(element, fmt::format("{}: expected 3 numbers, got {}", attribute, v.size()));
  return {v[0], v[1], v[2]};
}

Matrix4d rotation(Vec3d axis, double degrees) {
  const Vec3d k = normalize(axis);
  const double a = degrees * M_PI / 180.0, c = std::cos(a), s = std::sin(a);
  const double kk[3] = {k.x, k.y, k.z};
  const double cross_matrix[3][3] = {{0, -k.z, k.y}, {k.z, 0, -k.x}, {-k.y, k.x, 0}};
  Matrix4d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r.m[4 * i + j] = (i == j ? c : 0.0) + s * cross_matrix[i][j] + (1 - c) * kk[i] * kk[j];
  return r;
}

// Mitsuba's Transform4f::look_at: columns left = normalize(up x dir), up' = dir x left, dir, origin; an
// absent up is chosen perpendicular to dir (Duff et al. 2017's orthonormal basis, as Mitsuba).
Matrix4d look_at(const MitsubaElement& element) {
  only_attributes(element, {"origin", "target", "up"});
  const Vec3d origin = named_vector(element, "origin"), target = named_vector(element, "target");
  Vec3d up = element.has("up") ? named_vector(element, "up") : Vec3d{};
  if (!(length(target - origin) > 0.0)) fail_at(element, "origin and target coincide");
  const Vec3d dir = normalize(target - origin);
  if (length(up) == 0.0) {
    const double sign = std::copysign(1.0, dir.z), a = -1.0 / (sign + dir.z), b = dir.x * dir.y * a;
    up = {1.0 + sign * dir.x * dir.x * a, sign * b, -sign * dir.x};
  }
  const Vec3d left_raw = cross(up, dir);
  if (!(length(left_raw) > 1e-12 * length(up))) fail_at(element, "up is parallel to the view direction");
  const Vec3d left = normalize(left_raw), new_up = cross(dir, left);
  Matrix4d r;
  r.m = {left.x, new_up.x, dir.x, origin.x, left.y, new_up.y, dir.y, origin.y,
         left.z, new_up.z, dir.z, origin.z, 0,      0,        0,     1};
  return r;
}

Matrix4d transform_operation(const MitsubaElement& op) {
  no_children(op);
  if (op.tag == "translate") {
    only_attributes(op, {"x", "y", "z", "value"});
    const Vec3d t = xyz_value(op, 0.0);
    Matrix4d r;
    r.m[3] = t.x;
    r.m[7] = t.y;
    r.m[11] = t.z;
    return r;
  }
  if (op.tag == "scale") {
    only_attributes(op, {"x", "y", "z", "value"});
    const Vec3d s = xyz_value(op, 1.0);
    if (s.x == 0.0 || s.y == 0.0 || s.z == 0.0) fail_at(op, "a scale factor of 0 flattens the object");
    Matrix4d r;
    r.m[0] = s.x;
    r.m[5] = s.y;
    r.m[10] = s.z;
    return r;
  }
  if (op.tag == "rotate") {
    only_attributes(op, {"x", "y", "z", "value", "angle"});
    const Vec3d axis = xyz_value(op, 0.0);
    if (!(length(axis) > 0.0)) fail_at(op, "the rotation axis is zero");
    return rotation(axis, parse_number(required(op, "angle"), op, "angle"));
  }
  if (op.tag == "matrix") {
    only_attributes(op, {"value"});
    const std::vector<double> v = parse_numbers(required(op, "value"), op, "value");
    Matrix4d r;
    if (v.size() == 16) {
      std::copy(v.begin(), v.end(), r.m.begin());
      if (r.m[12] != 0.0 || r.m[13] != 0.0 || r.m[14] != 0.0 || r.m[15] != 1.0)
        fail_at(op, "the bottom row must be 0 0 0 1 (ochre places objects with affine transforms)");
    } else if (v.size() == 9) {
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.m[4 * i + j] = v[3 * i + j];
    } else {
      fail_at(op, fmt::format("value: expected 16 (or 9) numbers, got {}", v.size()));
    }
    return r;
  }
  if (op.tag == "lookat") return look_at(op);
  fail_at(op, "a <transform> holds only <translate>, <rotate>, <scale>, <matrix> and <lookat>");
}

// A spectrum's wavelength:value pairs.
nlohmann::json spectrum_table(const std::vector<std::pair<double, double>>& pairs,
                              const MitsubaElement& element) {
  if (pairs.size() < 2) fail_at(element, "a spectrum table needs at least 2 wavelength:value pairs");
  nlohmann::json wavelengths = nlohmann::json::array(), values = nlohmann::json::array();
  for (size_t i = 0; i < pairs.size(); ++i) {
    if (i > 0 && !(pairs[i].first > pairs[i - 1].first))
      fail_at(element, fmt::format("wavelengths must increase ({} nm follows {} nm)", pairs[i].first,
                                   pairs[i - 1].first));
    wavelengths.push_back(pairs[i].first);
    values.push_back(pairs[i].second);
  }
  return {{"wavelengths", wavelengths}, {"values", values}, {"extrapolate", "zero"}};
}

std::vector<std::pair<double, double>> inline_pairs(const std::string& text, const MitsubaElement& element) {
  std::vector<std::pair<double, double>> pairs;
  for (const std::string& item : list_items(text)) {
    const size_t colon = item.find(':');
    if (colon == std::string::npos || item.find(':', colon + 1) != std::string::npos)
      fail_at(element, fmt::format("value: \"{}\" is not a wavelength:value pair", item));
    pairs.emplace_back(parse_number(item.substr(0, colon), element, "wavelength"),
                       parse_number(item.substr(colon + 1), element, "value"));
  }
  return pairs;
}

// Mitsuba's spectrum files: one "wavelength value" pair a line, '#' comments.
std::vector<std::pair<double, double>> file_pairs(const MitsubaDocument& document,
                                                  const MitsubaElement& element, const std::string& name) {
  const std::filesystem::path path = resolve_mitsuba_file(document, element, name);
  std::string text;
  try {
    text = read_input_file(path, kCsvFileInput);
  } catch (const InputError& e) {
    fail_at(element, e.what());
  }
  std::vector<std::pair<double, double>> pairs;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    const std::vector<double> v =
        parse_numbers(line, element, fmt::format("{} line {}", path.string(), number));
    if (v.empty()) continue;
    if (v.size() != 2)
      fail_at(element, fmt::format("{} line {}: expected \"wavelength value\", got {} numbers", path.string(),
                                   number, v.size()));
    pairs.emplace_back(v[0], v[1]);
  }
  return pairs;
}

void check_non_negative(const std::vector<double>& values, const MitsubaElement& element,
                        MitsubaColourRole role) {
  if (role == MitsubaColourRole::Unbounded) return;
  for (double v : values)
    if (v < 0.0)
      fail_at(element, fmt::format("negative value {} ({} must be >= 0 at every wavelength)", v,
                                   role == MitsubaColourRole::Emission ? "emission" : "a reflectance"));
}

// Mitsuba upsamples an RGB eta or k without bound (its "unbounded" sRGB spectrum, as ochre's
// RGBUnboundedSpectrum); ochre's material inputs would upsample a colour as a reflectance, so the spectrum
// is written out as a table every 5 nm.
nlohmann::json unbounded_rgb_table(const std::vector<double>& rgb) {
  const RGBUnboundedSpectrum spectrum(
      RGB{static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2])});
  nlohmann::json wavelengths = nlohmann::json::array(), values = nlohmann::json::array();
  for (int nm = 360; nm <= 830; nm += 5) {
    wavelengths.push_back(nm);
    values.push_back(spectrum.eval(static_cast<float>(nm)));
  }
  return {{"wavelengths", wavelengths}, {"values", values}};
}

}  // namespace

double number_value(const MitsubaElement& element) {
  only_attributes(element, {"name", "value"});
  no_children(element);
  const double v = parse_number(required(element, "value"), element, "value");
  if (element.tag == "integer" && v != std::floor(v))
    fail_at(element, fmt::format("value: {} is not an integer", *element.attribute("value")));
  return v;
}

Vec3d vector_value(const MitsubaElement& element) {
  only_attributes(element, {"name", "x", "y", "z", "value"});
  no_children(element);
  return xyz_value(element, 0.0);
}

Matrix4d transform_value(const MitsubaElement& element) {
  only_attributes(element, {"name"});
  Matrix4d result;
  for (const MitsubaElement& op : element.children) result = transform_operation(op) * result;
  for (double v : result.m)
    if (!std::isfinite(v)) fail_at(element, "the transform is not finite");
  return result;
}

nlohmann::json colour_value(const MitsubaDocument& document, const MitsubaElement& element,
                            MitsubaColourRole role) {
  no_children(element);
  if (element.tag == "float") {
    const double v = number_value(element);
    check_non_negative({v}, element, role);
    return v;
  }
  if (element.tag == "rgb") {
    only_attributes(element, {"name", "value"});
    std::vector<double> rgb = parse_numbers(required(element, "value"), element, "value");
    if (rgb.size() == 1) rgb = {rgb[0], rgb[0], rgb[0]};
    if (rgb.size() != 3) fail_at(element, fmt::format("value: expected 1 or 3 numbers, got {}", rgb.size()));
    check_non_negative(rgb, element, role);
    if (role == MitsubaColourRole::Unbounded) {
      if (rgb[0] < 0 || rgb[1] < 0 || rgb[2] < 0) fail_at(element, "value: negative components");
      return unbounded_rgb_table(rgb);
    }
    return rgb;
  }
  if (element.tag == "spectrum") {
    if (element.has("type"))
      fail_at(element, "spectrum plugins (type=\"...\") are not supported: give \"value\" or \"filename\"");
    only_attributes(element, {"name", "value", "filename"});
    if (element.has("value") == element.has("filename"))
      fail_at(element, "a <spectrum> takes either \"value\" or \"filename\"");
    std::vector<std::pair<double, double>> pairs;
    if (const std::string* value = element.attribute("value")) {
      if (value->find(':') == std::string::npos) {
        const std::vector<double> v = parse_numbers(*value, element, "value");
        if (v.size() != 1)
          fail_at(element, "value: expected one number (a uniform spectrum) or wavelength:value pairs");
        check_non_negative(v, element, role);
        return v[0];
      }
      pairs = inline_pairs(*value, element);
    } else {
      pairs = file_pairs(document, element, *element.attribute("filename"));
    }
    std::vector<double> values;
    for (const auto& p : pairs) values.push_back(p.second);
    check_non_negative(values, element, role);
    return spectrum_table(pairs, element);
  }
  fail_at(element,
          fmt::format("<{}> is not a colour value (expected <float>, <rgb>, <spectrum> or a texture)",
                      element.tag));
}

}  // namespace ochre
