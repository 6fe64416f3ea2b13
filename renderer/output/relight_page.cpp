#include "renderer/output/relight_page.h"

#include <fmt/format.h>
#include <sys/stat.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <system_error>

#include "renderer/output/relight.h"
#include "renderer/output/render_output.h"
#include "renderer/util/atomic_directory.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/base64.h"
#include "renderer/util/xml_escape.h"
#include "spectra/input_error.h"

namespace ochre {

namespace {

namespace fs = std::filesystem;

// The colour-temperature slider's range and step; the page holds the bin weights at every step.
constexpr int kCctMin = 1000, kCctMax = 10000, kCctStep = 25;
// The low-rank basis reproduces every weight of that table within this (the weights are ratios near 1).
constexpr double kBasisTolerance = 1e-4;
// The intensity slider's top: the display lattice covers the image with every group at this scale.
constexpr double kMaxScale = 4.0;
// The display lattice: points per axis, over a log2 shaper of this many stops below its top.
constexpr int kLatticePoints = 33;
constexpr double kShaperStops = 16.0;
// Half floats top out at 65504; larger values are clamped there rather than made infinite, which a scale
// of 0 would turn into NaN.
constexpr float kHalfMax = 65504.0f;

// IEEE 754 binary16 bits of `value`, rounded to nearest even (F. Giesen's float_to_half_fast3_rtne).
std::uint16_t half_bits(float value) {
  std::uint32_t f = std::bit_cast<std::uint32_t>(std::clamp(value, -kHalfMax, kHalfMax));
  const std::uint32_t sign = f & 0x80000000u;
  f ^= sign;
  std::uint32_t h;
  if (f > 0x7f800000u) {
    h = 0x7e00u;  // NaN
  } else if (f < (113u << 23)) {
    // Subnormal or zero: let the float adder round the mantissa.
    const float magic = std::bit_cast<float>(((127u - 15u) + (23u - 10u) + 1u) << 23);
    h = std::bit_cast<std::uint32_t>(std::bit_cast<float>(f) + magic) - std::bit_cast<std::uint32_t>(magic);
  } else {
    const std::uint32_t odd = (f >> 13) & 1u;
    f += (static_cast<std::uint32_t>(15 - 127) << 23) + 0xfffu + odd;
    h = f >> 13;
  }
  return static_cast<std::uint16_t>(h | (sign >> 16));
}

// Little-endian, which the page reads as a Uint16Array.
std::string base64_uint16(const std::vector<std::uint16_t>& values) {
  std::vector<unsigned char> bytes;
  bytes.reserve(values.size() * 2);
  for (const std::uint16_t v : values) {
    bytes.push_back(static_cast<unsigned char>(v & 0xff));
    bytes.push_back(static_cast<unsigned char>(v >> 8));
  }
  return base64(bytes.data(), bytes.size());
}

// Binary16, which the page decodes through a table of the 65536 values (half the size of binary32, and
// 5e-4 of a value is far below a level of 8 bits).
std::string base64_halves(const std::vector<float>& values) {
  std::vector<std::uint16_t> halves(values.size());
  std::transform(values.begin(), values.end(), halves.begin(), half_bits);
  return base64_uint16(halves);
}

[[noreturn]] void refuse(const fs::path& dir, const std::string& why) {
  throw InputError(fmt::format("{}: cannot write the relighting page there: {}", dir.string(), why));
}

// The R, G, B channels of layer `base` (base.R, base.G, base.B), interleaved per pixel.
std::vector<float> interleaved_rgb(const ExrImage& image, const std::string& base, const std::string& file) {
  const size_t n = static_cast<size_t>(image.width) * image.height;
  std::vector<float> rgb(n * 3);
  for (int c = 0; c < 3; ++c) {
    const std::string name = fmt::format("{}.{}", base, "RGB"[c]);
    const std::vector<float>* channel = image.find_channel(name);
    if (!channel || channel->size() != n) throw InputError(fmt::format("{}: channel {} missing", file, name));
    for (size_t i = 0; i < n; ++i) rgb[i * 3 + c] = (*channel)[i];
  }
  return rgb;
}

double largest_magnitude(const std::vector<float>& values) {
  double largest = 0.0;
  for (const float v : values)
    if (std::isfinite(v)) largest = std::max(largest, static_cast<double>(std::fabs(v)));
  return largest;
}

// A colour-temperature slider's data: the bin weights of every temperature of the grid (three per bin, for
// X, Y and Z: BinWeights) as coefficients of a few orthonormal vectors over them (weights ~ coefficients x
// vectors), and the matrices between the image's RGB and XYZ.
struct CctBasis {
  std::vector<std::vector<double>> vectors;
  Mat3 to_xyz = Mat3::identity(), to_rgb = Mat3::identity();
  std::vector<double> coefficients;  // per temperature, vectors.size() each
  double largest_weight = 1.0;
  int unchanged_at = 0;  // the grid temperature whose weights are nearest 1, when within 1 %; else 0
};

// The weights `ochre relight --group GROUP:cct=T` gives the group's bins (X, Y, Z of bin b at 3 b + k), for
// each T of the grid; `basis` gets the matrices.
std::vector<std::vector<double>> cct_weights(const ExrImage& image, const std::string& group,
                                             const std::string& file, CctBasis& basis) {
  std::vector<std::vector<double>> table;
  for (int kelvin = kCctMin; kelvin <= kCctMax; kelvin += kCctStep) {
    const BinWeights w =
        group_bin_weights(image, parse_group_change(fmt::format("{}:cct={}", group, kelvin)), file);
    std::vector<double> row;
    for (const std::array<double, 3>& bin : w.weights) row.insert(row.end(), bin.begin(), bin.end());
    table.push_back(std::move(row));
    basis.to_xyz = w.to_xyz;
    basis.to_rgb = w.to_rgb;
  }
  return table;
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
  return sum;
}

double largest_entry(const std::vector<std::vector<double>>& table) {
  double largest = 0.0;
  for (const std::vector<double>& row : table)
    for (const double v : row) largest = std::max(largest, std::fabs(v));
  return largest;
}

// Gram-Schmidt with pivoting on the table's rows: each step takes the row least well represented so far
// as the next direction, until every weight is within kBasisTolerance. The weights are smooth in the
// temperature, so a few vectors suffice (the page then holds that many images, not one per bin).
std::vector<std::vector<double>> row_basis(const std::vector<std::vector<double>>& table) {
  std::vector<std::vector<double>> residual = table, vectors;
  const size_t bins = table.front().size();
  while (vectors.size() < bins && largest_entry(residual) > kBasisTolerance) {
    const auto pivot = std::max_element(residual.begin(), residual.end(),
                                        [](const auto& a, const auto& b) { return dot(a, a) < dot(b, b); });
    std::vector<double> q = *pivot;
    const double norm = std::sqrt(dot(q, q));
    for (double& v : q) v /= norm;
    for (std::vector<double>& row : residual) {
      const double d = dot(row, q);
      for (size_t b = 0; b < bins; ++b) row[b] -= d * q[b];
    }
    vectors.push_back(std::move(q));
  }
  return vectors;
}

CctBasis cct_basis(const ExrImage& image, const std::string& group, const std::string& file) {
  CctBasis basis;
  const std::vector<std::vector<double>> table = cct_weights(image, group, file, basis);
  basis.vectors = row_basis(table);
  basis.largest_weight = std::max(1.0, largest_entry(table));
  double nearest = 0.01;
  for (size_t t = 0; t < table.size(); ++t) {
    for (const std::vector<double>& q : basis.vectors) basis.coefficients.push_back(dot(table[t], q));
    double deviation = 0.0;
    for (const double w : table[t]) deviation = std::max(deviation, std::fabs(w - 1.0));
    if (deviation < nearest) {
      nearest = deviation;
      basis.unchanged_at = kCctMin + static_cast<int>(t) * kCctStep;
    }
  }
  return basis;
}

// The images the basis vectors weigh the group's bin layers into, R, G, B interleaved: vector j takes the
// X, Y, Z of bin b times its entries 3 b + k, back to RGB (BinWeights::apply).
std::vector<std::vector<float>> basis_images(const ExrImage& image, const std::vector<std::string>& bins,
                                             const CctBasis& basis, const std::string& file) {
  const size_t pixels = static_cast<size_t>(image.width) * image.height;
  std::vector<std::vector<double>> sums(basis.vectors.size(), std::vector<double>(pixels * 3, 0.0));
  for (size_t b = 0; b < bins.size(); ++b) {
    const std::vector<float> layer = interleaved_rgb(image, bins[b], file);
    for (size_t i = 0; i < pixels; ++i) {
      const Array3d xyz = basis.to_xyz * Array3d{layer[3 * i], layer[3 * i + 1], layer[3 * i + 2]};
      for (size_t j = 0; j < basis.vectors.size(); ++j) {
        const std::vector<double>& v = basis.vectors[j];
        const Array3d rgb =
            basis.to_rgb * Array3d{v[3 * b] * xyz[0], v[3 * b + 1] * xyz[1], v[3 * b + 2] * xyz[2]};
        for (size_t k = 0; k < 3; ++k) sums[j][3 * i + k] += rgb[k];
      }
    }
  }
  std::vector<std::vector<float>> images;
  for (const std::vector<double>& sum : sums) images.emplace_back(sum.begin(), sum.end());
  return images;
}

std::vector<float> to_floats(const std::vector<double>& values) {
  return std::vector<float>(values.begin(), values.end());
}

// Display values from which a channel is 255 in 8 bits (OCIO's white may fall short of 1 by rounding).
constexpr float kWhite = 254.5f / 255.0f;

// The linear value from which the display shows grey at full white (infinity when it never does): the
// lattice need not reach much beyond it.
double grey_saturation(const DisplayOptions& display) {
  std::vector<float> ramp;
  for (int i = 0; i <= 4 * 60; ++i)
    for (int c = 0; c < 3; ++c) ramp.push_back(static_cast<float>(std::exp2(i / 4.0 - 20.0)));
  const std::vector<float> shown = to_display_values(static_cast<int>(ramp.size() / 3), 1, ramp, display);
  for (size_t i = 0; i < shown.size(); i += 3)
    if (std::min({shown[i], shown[i + 1], shown[i + 2]}) >= kWhite) return ramp[i];
  return std::numeric_limits<double>::infinity();
}

// The display transform sampled on a lattice of kLatticePoints^3 linear RGB values, each axis spaced by
// the shaper log2(x + lo) from 0 to `top`, R fastest; the values display-encoded x 65535.
nlohmann::json display_lattice(const DisplayOptions& display, double top) {
  const double lo = top * std::exp2(-kShaperStops);
  const double span = std::log2((top + lo) / lo);
  std::vector<float> axis(kLatticePoints);
  for (int i = 0; i < kLatticePoints; ++i)
    axis[i] = static_cast<float>(lo * std::exp2(span * i / (kLatticePoints - 1)) - lo);
  axis.front() = 0.0f;
  const int n = kLatticePoints * kLatticePoints * kLatticePoints;
  std::vector<float> rgb;
  rgb.reserve(static_cast<size_t>(n) * 3);
  for (int b = 0; b < kLatticePoints; ++b)
    for (int g = 0; g < kLatticePoints; ++g)
      for (int r = 0; r < kLatticePoints; ++r) rgb.insert(rgb.end(), {axis[r], axis[g], axis[b]});
  const std::vector<float> shown = to_display_values(n, 1, rgb, display);
  std::vector<std::uint16_t> values(shown.size());
  for (size_t i = 0; i < shown.size(); ++i)
    values[i] = std::isnan(shown[i])
                    ? 0
                    : static_cast<std::uint16_t>(std::lround(std::clamp(shown[i], 0.0f, 1.0f) * 65535.0f));
  return {{"points", kLatticePoints}, {"lo", lo}, {"top", top}, {"values", base64_uint16(values)}};
}

// The page's script, which reads DATA (the JSON above it).
const char* kScript = R"JS(
"use strict";
const HALF = (() => {
  const t = new Float32Array(65536);
  for (let h = 0; h < 65536; h++) {
    const s = h & 0x8000 ? -1 : 1, e = (h >> 10) & 31, m = h & 1023;
    t[h] = e === 0 ? s * m * 2 ** -24 : e === 31 ? (m ? NaN : s * Infinity) : s * (1 + m / 1024) * 2 ** (e - 15);
  }
  return t;
})();
function bytes(text) {
  const b = atob(text), out = new Uint8Array(b.length);
  for (let i = 0; i < b.length; i++) out[i] = b.charCodeAt(i);
  return out;
}
function halves(text) {
  const u = new Uint16Array(bytes(text).buffer), f = new Float32Array(u.length);
  for (let i = 0; i < u.length; i++) f[i] = HALF[u[i]];
  return f;
}
const W = DATA.width, H = DATA.height, CCT = DATA.cct;
const groups = DATA.groups.map(g => ({
  name: g.name, on: true, scale: 1, cct: null, layer: halves(g.layer),
  basis: g.cct ? g.cct.basis.map(halves) : null,
  coefficients: g.cct ? new Float32Array(bytes(g.cct.coefficients).buffer) : null,
  unchangedAt: g.cct ? g.cct.unchanged_at : 0,
}));
const L = DATA.lattice, N = L.points, LUT = new Uint16Array(bytes(L.values).buffer);
const LOG_LO = Math.log2(L.lo), SPAN = Math.log2((L.top + L.lo) / L.lo);

// The relit linear image: each group's layer times its scale or, with a colour temperature, its basis
// images times the coefficients of that temperature (the bin weights of `ochre relight`).
function relit() {
  const sum = new Float32Array(W * H * 3);
  const add = (layer, w) => { for (let i = 0; i < sum.length; i++) sum[i] += w * layer[i]; };
  for (const g of groups) {
    if (!g.on || g.scale === 0) continue;
    if (g.cct === null) { add(g.layer, g.scale); continue; }
    const k = g.basis.length, row = Math.round((g.cct - CCT.min) / CCT.step);
    for (let j = 0; j < k; j++) add(g.basis[j], g.scale * g.coefficients[row * k + j]);
  }
  return sum;
}
function shaper(x) {
  const v = x > 0 ? Math.min(x, L.top) : 0;
  return Math.min(N - 1, Math.max(0, (Math.log2(v + L.lo) - LOG_LO) / SPAN * (N - 1)));
}
// The display transform: trilinear in the lattice, then 8 bits as the PNG is quantized.
function display(sum, pixels) {
  const u = [0, 0, 0], i0 = [0, 0, 0], f = [0, 0, 0];
  for (let p = 0; p < W * H; p++) {
    for (let c = 0; c < 3; c++) {
      u[c] = shaper(sum[p * 3 + c]);
      i0[c] = Math.min(Math.floor(u[c]), N - 2);
      f[c] = u[c] - i0[c];
    }
    for (let c = 0; c < 3; c++) {
      let v = 0;
      for (let corner = 0; corner < 8; corner++) {
        const dr = corner & 1, dg = (corner >> 1) & 1, db = corner >> 2;
        const w = (dr ? f[0] : 1 - f[0]) * (dg ? f[1] : 1 - f[1]) * (db ? f[2] : 1 - f[2]);
        if (w === 0) continue;
        v += w * LUT[(((i0[2] + db) * N + i0[1] + dg) * N + i0[0] + dr) * 3 + c];
      }
      pixels[p * 4 + c] = Math.round(Math.min(1, Math.max(0, v / 65535)) * 255);
    }
    pixels[p * 4 + 3] = 255;
  }
}
function quoted(word) {
  return /^[A-Za-z0-9_.\/=:,+-]+$/.test(word) ? word : "'" + word.replace(/'/g, "'\\''") + "'";
}
function command() {
  const words = ["ochre", "relight", quoted(DATA.render)];
  for (const g of groups) {
    const changes = [];
    if (!g.on) changes.push("off");
    else {
      if (g.scale !== 1) changes.push("scale=" + g.scale);
      if (g.cct !== null) changes.push("cct=" + g.cct);
    }
    if (changes.length) words.push("--group", g.name + ":" + changes.join(","));
  }
  words.push("--png", "relit.png");
  return words.join(" ");
}
const canvas = document.getElementById("image"), context = canvas.getContext("2d");
function draw() {
  const image = context.createImageData(W, H);
  display(relit(), image.data);
  context.putImageData(image, 0, 0);
  document.getElementById("command").value = command();
}
function element(tag, attributes, children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attributes || {})) e.setAttribute(k, v);
  for (const c of children || []) e.append(c);
  return e;
}
function controls(g) {
  const on = element("input", {type: "checkbox", id: "on-" + g.name, checked: ""});
  const scale = element("input", {type: "range", id: "scale-" + g.name, min: 0, max: 4, step: 0.01, value: 1});
  const scaleText = element("output", {id: "scale-" + g.name + "-value"}, ["1"]);
  on.addEventListener("change", () => { g.on = on.checked; draw(); });
  scale.addEventListener("input", () => { g.scale = Number(scale.value); scaleText.textContent = scale.value; draw(); });
  const box = element("fieldset", {"data-group": g.name}, [
    element("legend", {}, [element("label", {}, [on, " " + g.name])]),
    element("label", {}, ["intensity ", scale, " ", scaleText])]);
  if (g.basis) {
    const start = g.unchangedAt || (CCT.min + CCT.max) / 2;
    const cct = element("input", {type: "range", id: "cct-" + g.name, min: CCT.min, max: CCT.max, step: CCT.step, value: start});
    const label = g.unchangedAt ? "unchanged (about " + g.unchangedAt + " K)" : "unchanged";
    const cctText = element("output", {id: "cct-" + g.name + "-value"}, [label]);
    const reset = element("button", {id: "cct-" + g.name + "-reset", type: "button"}, ["unchanged"]);
    cct.addEventListener("input", () => { g.cct = Number(cct.value); cctText.textContent = cct.value + " K"; draw(); });
    reset.addEventListener("click", () => { g.cct = null; cct.value = start; cctText.textContent = label; draw(); });
    box.append(element("br"), element("label", {}, ["colour temperature ", cct, " ", cctText]), " ", reset);
  }
  return box;
}
for (const g of groups) document.getElementById("groups").append(controls(g));
document.getElementById("copy").addEventListener("click", () => {
  const field = document.getElementById("command");
  field.select();
  if (navigator.clipboard) navigator.clipboard.writeText(field.value).catch(() => document.execCommand("copy"));
  else document.execCommand("copy");
});
draw();
document.body.dataset.ready = "true";
)JS";

const char* kStyle = R"CSS(
body { font: 14px sans-serif; margin: 1em; background: #222; color: #ddd; }
fieldset { display: inline-block; vertical-align: top; margin: 0 1em 1em 0; border: 1px solid #555; }
input[type=range] { width: 16em; vertical-align: middle; }
canvas { display: block; margin: 1em 0; image-rendering: pixelated; min-width: 480px; max-width: 100%; }
#command { width: 70em; max-width: 90%; font-family: monospace; }
)CSS";

std::string page_html(const nlohmann::json& data, const std::string& render) {
  std::string json = data.dump();
  // The data sits in a <script> element: no "</script>" may end it early ('<' appears only in strings).
  for (size_t at; (at = json.find('<')) != std::string::npos;) json.replace(at, 1, "\\u003c");
  const std::string title = xml_escape(render);
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Relight {0}</title>\n"
      "<style>{1}</style>\n</head>\n<body>\n<h1>Relight {0}</h1>\n<div id=\"groups\"></div>\n"
      "<canvas id=\"image\" width=\"{2}\" height=\"{3}\"></canvas>\n"
      "<p><input id=\"command\" readonly> <button id=\"copy\" type=\"button\">Copy</button></p>\n"
      "<script>const DATA = {4};</script>\n<script>{5}</script>\n</body>\n</html>\n",
      title, kStyle, data.at("width").get<int>(), data.at("height").get<int>(), json, kScript);
}

// One group's part of the page's data; adds its share of the image's range to `top`.
nlohmann::json group_data(const ExrImage& image, const std::string& group, const std::string& file,
                          RelightPageStats& stats, double& top) {
  const std::vector<float> layer = interleaved_rgb(image, "group." + group, file);
  nlohmann::json data = {{"name", group}, {"layer", base64_halves(layer)}, {"cct", nullptr}};
  const std::vector<std::string> bins = group_bin_layer_names(image, group);
  double largest_weight = 1.0;
  if (!bins.empty() && image.string_attributes.count(light_group_emission_attribute(group))) {
    const CctBasis basis = cct_basis(image, group, file);
    nlohmann::json images = nlohmann::json::array();
    for (const std::vector<float>& b : basis_images(image, bins, basis, file))
      images.push_back(base64_halves(b));
    data["cct"] = {{"basis", images},
                   {"coefficients", base64_floats(to_floats(basis.coefficients))},
                   {"unchanged_at", basis.unchanged_at}};
    largest_weight = basis.largest_weight;
    ++stats.cct_groups;
    stats.basis_images += static_cast<int>(basis.vectors.size());
  }
  top += kMaxScale * largest_weight * largest_magnitude(layer);
  ++stats.groups;
  return data;
}

}  // namespace

void check_relight_page_destination(const fs::path& dir) {
  if (dir.empty()) throw InputError("--html: give a directory for the relighting page");
  const fs::path absolute = fs::absolute(dir).lexically_normal();
  const fs::path page = absolute.filename().empty() ? absolute.parent_path() : absolute;
  std::error_code error;
  if (!fs::is_directory(page.parent_path(), error))
    refuse(dir, fmt::format("directory {} does not exist", page.parent_path().string()));
  struct stat info {};
  if (::lstat(page.c_str(), &info) != 0) return;
  if (S_ISLNK(info.st_mode)) refuse(dir, "it is a symbolic link");
  if (!S_ISDIR(info.st_mode)) refuse(dir, "it exists and is not a directory");
  if (!fs::is_empty(page, error))
    refuse(dir, "the directory is not empty (the page is written into a new or empty directory)");
}

RelightPageStats write_relight_page(const ExrImage& image, const DisplayOptions& display,
                                    const std::string& render, const fs::path& dir) {
  check_relight_page_destination(dir);
  RelightPageStats stats;
  double top = 0.0;
  nlohmann::json groups = nlohmann::json::array();
  for (const std::string& group : light_group_names(image, render))
    groups.push_back(group_data(image, group, render, stats, top));
  // Beyond a few stops over the display's white, more range only coarsens the lattice where it matters.
  top = std::min(top, 8.0 * grey_saturation(display));
  if (!(top > 0.0) || !std::isfinite(top)) top = 1.0;
  const nlohmann::json data = {
      {"width", image.width}, {"height", image.height},
      {"render", render},     {"cct", {{"min", kCctMin}, {"max", kCctMax}, {"step", kCctStep}}},
      {"groups", groups},     {"lattice", display_lattice(display, top)}};
  stats.lattice_points = kLatticePoints;
  const std::string html = page_html(data, render);
  const fs::path absolute = fs::absolute(dir).lexically_normal();
  AtomicDirectory out(absolute.filename().empty() ? absolute.parent_path() : absolute);
  write_text_file(out.temp_path() / "index.html", html);
  out.commit();
  stats.bytes = html.size();
  return stats;
}

}  // namespace ochre
