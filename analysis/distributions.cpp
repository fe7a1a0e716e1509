#include "analysis/distributions.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dem/neighbour_search.hpp"

namespace suspend::analysis {

namespace {

Histogram linear_histogram(const std::vector<double>& values, double lo, double hi, int bins) {
  Histogram h;
  h.total = values.size();
  const double w = (hi - lo) / bins;
  for (int k = 0; k <= bins; ++k) h.edges.push_back(lo + k * w);
  h.density.assign(bins, 0.0);
  for (double v : values) {
    if (!(v >= lo)) {
      ++h.below;
    } else if (v >= hi) {
      ++h.above;
    } else {
      h.density[std::min(bins - 1, static_cast<int>((v - lo) / w))] += 1.0;
    }
  }
  if (h.total > 0)
    for (double& d : h.density) d /= static_cast<double>(h.total) * w;
  return h;
}

Histogram normalised_by_mean(const std::vector<double>& values) {
  double mean = 0.0;
  for (double v : values) mean += v;
  if (!values.empty()) mean /= static_cast<double>(values.size());
  std::vector<double> scaled(values);
  if (mean > 0.0)
    for (double& v : scaled) v /= mean;
  Histogram h = linear_histogram(mean > 0.0 ? scaled : std::vector<double>{}, 0.0, 5.0, 25);
  h.mean = mean;
  if (!(mean > 0.0)) h.below = h.total = values.size();
  return h;
}

double smallest_radius(const Configuration& c) {
  return c.radius.empty() ? 1.0 : *std::min_element(c.radius.begin(), c.radius.end());
}

}  // namespace

ForceDistributions force_distributions(const Configuration& c) {
  std::vector<double> normal, tangential;
  for (const Contact& k : c.contacts) {
    normal.push_back(k.normal_force);
    tangential.push_back(k.tangential_force.norm());
  }
  return {normalised_by_mean(normal), normalised_by_mean(tangential)};
}

GapDistribution gap_distribution(const Configuration& c) {
  std::vector<NeighbourPair> pairs;
  CellListSearch search;
  search.find_pairs(c.position, c.radius, c.box, 1.0, pairs);
  GapDistribution out;
  Histogram& h = out.gaps;
  constexpr int per_decade = 5, decades = 4;
  for (int k = 0; k <= per_decade * decades; ++k) h.edges.push_back(std::pow(10.0, -decades + double(k) / per_decade));
  h.density.assign(per_decade * decades, 0.0);
  for (const NeighbourPair& p : pairs) {
    const double gap = c.box.minimum_image(c.position[p.i], c.position[p.j]).d.norm() - c.radius[p.i] - c.radius[p.j];
    if (gap >= 1.0) continue;
    ++h.total;
    h.mean += gap;
    if (gap <= 0.0) ++out.overlapping;
    if (gap < h.edges.front()) {
      ++h.below;
      continue;
    }
    const int k = std::min(per_decade * decades - 1,
                           static_cast<int>(std::floor((std::log10(gap) + decades) * per_decade)));
    h.density[k] += 1.0;
  }
  if (h.total > 0) {
    h.mean /= static_cast<double>(h.total);
    for (std::size_t k = 0; k < h.density.size(); ++k)
      h.density[k] /= static_cast<double>(h.total) * (h.edges[k + 1] - h.edges[k]);
  }
  return out;
}

PairDistribution pair_distribution(const Configuration& c, double r_max, double dr, double dxy, double slab) {
  PairDistribution out;
  const Vec3& l = c.box.length();
  r_max = std::min(r_max, 0.5 * l.minCoeff());
  const int bins = std::max(1, static_cast<int>(std::floor(r_max / dr)));
  r_max = bins * dr;
  // The map's corners reach sqrt(2 half^2 + slab^2), which must stay within half the box (minimum image).
  const double lh = 0.5 * l.minCoeff();
  const double corner_limit = std::sqrt(std::max(0.0, lh * lh - slab * slab) / 2.0);
  const int map_bins = 2 * std::max(1, static_cast<int>(std::floor(std::min(r_max, corner_limit) / dxy)));
  const double half = 0.5 * map_bins * dxy;
  const double reach = std::max(r_max, std::sqrt(2.0 * half * half + slab * slab));
  out.r_max = r_max, out.dr = dr, out.dxy = dxy, out.slab = slab;
  std::vector<double> counts(bins, 0.0), map(static_cast<std::size_t>(map_bins) * map_bins, 0.0);
  std::vector<NeighbourPair> pairs;
  CellListSearch search;
  search.find_pairs(c.position, c.radius, c.box, reach - 2.0 * smallest_radius(c), pairs);
  for (const NeighbourPair& p : pairs) {
    const Vec3 d = c.box.minimum_image(c.position[p.i], c.position[p.j]).d;
    const double r = d.norm();
    if (r < r_max) counts[std::min(bins - 1, static_cast<int>(r / dr))] += 1.0;
    if (std::abs(d.z()) < slab && std::abs(d.x()) < half && std::abs(d.y()) < half) {
      for (const double s : {1.0, -1.0}) {  // the pair seen from both particles
        const int ix = std::min(map_bins - 1, static_cast<int>((s * d.x() + half) / dxy));
        const int iy = std::min(map_bins - 1, static_cast<int>((s * d.y() + half) / dxy));
        map[static_cast<std::size_t>(iy) * map_bins + ix] += 1.0;
      }
    }
  }
  const double n = static_cast<double>(c.size());
  const double pair_density = n > 1.0 ? n * (n - 1.0) / (2.0 * c.box.volume()) : 0.0;
  for (int k = 0; k < bins; ++k) {
    const double lo = k * dr, hi = lo + dr;
    const double shell = 4.0 / 3.0 * std::numbers::pi * (hi * hi * hi - lo * lo * lo);
    out.r.push_back(lo + 0.5 * dr);
    out.g.push_back(pair_density > 0.0 ? counts[k] / (pair_density * shell) : 0.0);
  }
  for (int k = 0; k < map_bins; ++k) out.xy_centres.push_back(-half + (k + 0.5) * dxy);
  const double cell = dxy * dxy * 2.0 * slab;
  out.g_xy.resize(map.size());
  for (std::size_t k = 0; k < map.size(); ++k)
    out.g_xy[k] = pair_density > 0.0 ? map[k] / (2.0 * pair_density * cell) : 0.0;
  return out;
}

}  // namespace suspend::analysis
