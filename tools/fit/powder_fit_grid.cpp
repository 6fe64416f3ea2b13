#include "tools/fit/powder_fit_grid.h"

#include <algorithm>
#include <limits>

#include "tools/fit/powder_fit_model.h"

namespace ochre {

namespace {

// Points per nonlinear parameter. The radius axis is the finest: the radius acts through the grains'
// albedo alone, which Mie resonances make non-monotonic in it, so the sum of squares has a basin per
// branch of the albedo. The volume part is computed for each of the 7 x 9 x 32 (g, kappa, radius), about
// 0.4 s for 1000 measurements.
constexpr std::array<int, kPowderFitParams> kGridPoints = {0, 7, 9, 32, 0, 10};

// The sums of the normal equations of min over (A_v, A_s') of sum w^2 (A_v volume + A_s' surface - brdf)^2.
struct NormalSums {
  double vv = 0, ss = 0, vs = 0, vy = 0, sy = 0, yy = 0;
};

struct Amplitudes {
  double volume = 0, surface = 0, sum_of_squares = std::numeric_limits<double>::infinity();
};

// The amplitudes within their bounds (or held) minimising the sum. It is a convex quadratic in them, so
// its minimum over the box is the unconstrained one when that lies inside, else the best one-dimensional
// minimum along an edge.
Amplitudes best_amplitudes(const NormalSums& n, const GridProblem& problem) {
  const ParamBounds& va = problem.bounds[kVolumeAmplitude];
  const ParamBounds& sa = problem.bounds[kSurfaceAmplitude];
  const bool v_free = problem.free[kVolumeAmplitude], s_free = problem.free[kSurfaceAmplitude];
  const auto best_v = [&](double s) {
    if (!v_free) return problem.held[kVolumeAmplitude];
    return n.vv > 0 ? std::clamp((n.vy - s * n.vs) / n.vv, va.lower, va.upper) : va.lower;
  };
  const auto best_s = [&](double v) {
    if (!s_free) return problem.held[kSurfaceAmplitude];
    return n.ss > 0 ? std::clamp((n.sy - v * n.vs) / n.ss, sa.lower, sa.upper) : sa.lower;
  };
  Amplitudes best;
  const auto consider = [&](double v, double s) {
    const double sse = v * v * n.vv + 2 * v * s * n.vs + s * s * n.ss - 2 * v * n.vy - 2 * s * n.sy + n.yy;
    if (sse < best.sum_of_squares) best = {v, s, sse};
  };
  for (double v : v_free ? std::vector<double>{va.lower, va.upper} : std::vector<double>{best_v(0)})
    consider(v, best_s(v));
  for (double s : s_free ? std::vector<double>{sa.lower, sa.upper} : std::vector<double>{best_s(0)})
    consider(best_v(s), s);
  const double det = n.vv * n.ss - n.vs * n.vs;
  if (v_free && s_free && det > 1e-12 * n.vv * n.ss) {
    const double v = (n.vy * n.ss - n.sy * n.vs) / det, s = (n.sy * n.vv - n.vy * n.vs) / det;
    if (v >= va.lower && v <= va.upper && s >= sa.lower && s <= sa.upper) consider(v, s);
  }
  return best;
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
  return sum;
}

std::vector<double> axis_of(const GridProblem& problem, int param) {
  return problem.free[param] ? grid_axis(param, problem.bounds[param], kGridPoints[param])
                             : std::vector<double>{problem.held[param]};
}

// part x weight, per measurement.
std::vector<double> weighted(const std::vector<double>& part, const std::vector<double>& weights) {
  std::vector<double> w(part.size());
  for (size_t i = 0; i < part.size(); ++i) w[i] = part[i] * weights[i];
  return w;
}

}  // namespace

std::vector<double> grid_axis(int param, const ParamBounds& bounds, int count) {
  const double lo = to_coordinate(param, bounds.lower), hi = to_coordinate(param, bounds.upper);
  std::vector<double> axis;
  for (int k = 0; k < count; ++k) axis.push_back(from_coordinate(param, lo + (k + 0.5) * (hi - lo) / count));
  return axis;
}

GridStart with_best_amplitudes(const GridProblem& problem, PowderValues v) {
  const PowderParts parts = powder_parts(v, problem.data, problem.pigment);
  std::vector<double> y(problem.data.size());
  for (size_t i = 0; i < y.size(); ++i) y[i] = problem.weights[i] * problem.data[i].brdf;
  const std::vector<double> volume = weighted(parts.volume, problem.weights);
  const std::vector<double> surface = weighted(parts.surface, problem.weights);
  const Amplitudes a = best_amplitudes({dot(volume, volume), dot(surface, surface), dot(volume, surface),
                                        dot(volume, y), dot(surface, y), dot(y, y)},
                                       problem);
  v[kVolumeAmplitude] = a.volume;
  v[kSurfaceAmplitude] = a.surface;
  return {a.sum_of_squares, v};
}

std::vector<GridStart> powder_grid_starts(const GridProblem& problem, int count, int& grid_points) {
  // The volume part depends on g, kappa and the radius, the surface part on the correlation length alone
  // (materials/lobes/powder/powder_model.h): each is computed once per value of its parameters and the
  // amplitudes solved for every combination.
  const std::vector<double> gs = axis_of(problem, kAnisotropy), kappas = axis_of(problem, kKappa);
  const std::vector<double> radii = axis_of(problem, kRadius), lengths = axis_of(problem, kCorrelationLength);
  std::vector<double> y(problem.data.size());
  for (size_t i = 0; i < y.size(); ++i) y[i] = problem.weights[i] * problem.data[i].brdf;
  const double yy = dot(y, y);
  std::vector<std::vector<double>> surfaces;
  for (double length : lengths) {
    PowderValues v = problem.held;
    v[kCorrelationLength] = length;
    surfaces.push_back(weighted(powder_parts(v, problem.data, problem.pigment).surface, problem.weights));
  }
  std::vector<double> ss, sy;
  for (const std::vector<double>& s : surfaces) ss.push_back(dot(s, s)), sy.push_back(dot(s, y));

  // Every grid point, indexed [g][kappa][radius][length].
  const std::array<size_t, 4> size = {gs.size(), kappas.size(), radii.size(), lengths.size()};
  std::vector<GridStart> points(size[0] * size[1] * size[2] * size[3]);
  const auto index = [&](const std::array<size_t, 4>& at) {
    return ((at[0] * size[1] + at[1]) * size[2] + at[2]) * size[3] + at[3];
  };
  for (size_t gi = 0; gi < size[0]; ++gi)
    for (size_t ki = 0; ki < size[1]; ++ki)
      for (size_t ri = 0; ri < size[2]; ++ri) {
        PowderValues v = problem.held;
        v[kAnisotropy] = gs[gi], v[kKappa] = kappas[ki], v[kRadius] = radii[ri];
        const std::vector<double> volume =
            weighted(powder_parts(v, problem.data, problem.pigment).volume, problem.weights);
        const double vv = dot(volume, volume), vy = dot(volume, y);
        for (size_t li = 0; li < size[3]; ++li) {
          const Amplitudes a =
              best_amplitudes({vv, ss[li], dot(volume, surfaces[li]), vy, sy[li], yy}, problem);
          v[kCorrelationLength] = lengths[li];
          v[kVolumeAmplitude] = a.volume;
          v[kSurfaceAmplitude] = a.surface;
          points[index({gi, ki, ri, li})] = {a.sum_of_squares, v};
        }
      }
  grid_points = static_cast<int>(points.size());

  // The local minima of the grid: points no worse than any of their (up to 80) neighbours.
  std::vector<GridStart> starts;
  for (size_t i = 0; i < points.size(); ++i) {
    std::array<size_t, 4> at;
    for (size_t rest = i, d = 4; d-- > 0; rest /= size[d]) at[d] = rest % size[d];
    bool minimum = true;
    for (int offset = 0; offset < 81 && minimum; ++offset) {
      std::array<size_t, 4> neighbour = at;
      bool inside = offset != 40;  // 40: the point itself
      for (int d = 0, o = offset; d < 4; ++d, o /= 3) {
        const long long n = static_cast<long long>(at[d]) + o % 3 - 1;
        inside = inside && n >= 0 && n < static_cast<long long>(size[d]);
        neighbour[d] = static_cast<size_t>(std::max(n, 0LL));
      }
      if (inside && points[index(neighbour)].sum_of_squares < points[i].sum_of_squares) minimum = false;
    }
    if (minimum) starts.push_back(points[i]);
  }
  std::sort(starts.begin(), starts.end(),
            [](const GridStart& a, const GridStart& b) { return a.sum_of_squares < b.sum_of_squares; });
  if (starts.size() > static_cast<size_t>(std::max(count, 1))) starts.resize(std::max(count, 1));
  return starts;
}

}  // namespace ochre
