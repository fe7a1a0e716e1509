#include "analysis/contact_network.hpp"

#include <algorithm>
#include <cmath>

namespace suspend::analysis {

ContactNumbers contact_numbers(const Configuration& c) {
  const std::size_t n = c.size();
  ContactNumbers out;
  out.contacts = c.contacts.size();
  if (n == 0) return out;
  std::vector<int> count(n, 0);
  std::size_t sliding = 0;
  for (const Contact& k : c.contacts) {
    ++count[k.i];
    ++count[k.j];
    if (k.sliding) ++sliding;
  }
  out.contacts_per_particle = 2.0 * static_cast<double>(c.contacts.size()) / static_cast<double>(n);
  out.rattler_fraction =
      static_cast<double>(std::count_if(count.begin(), count.end(), [](int z) { return z < 2; })) /
      static_cast<double>(n);
  if (!c.contacts.empty())
    out.sliding_fraction = static_cast<double>(sliding) / static_cast<double>(c.contacts.size());
  const int species = c.species.empty() ? 1 : *std::max_element(c.species.begin(), c.species.end()) + 1;
  std::vector<double> members(species, 0.0), ends(species, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const int s = c.species.empty() ? 0 : c.species[i];
    members[s] += 1.0;
    ends[s] += count[i];
  }
  out.contacts_per_particle_of.resize(species);
  for (int s = 0; s < species; ++s) out.contacts_per_particle_of[s] = members[s] > 0.0 ? ends[s] / members[s] : 0.0;
  return out;
}

ClusterStatistics clusters(const Configuration& c) {
  const std::size_t n = c.size();
  ClusterStatistics out;
  // Adjacency in compressed rows: every contact listed from both ends.
  std::vector<std::size_t> start(n + 1, 0);
  for (const Contact& k : c.contacts) ++start[k.i + 1], ++start[k.j + 1];
  for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  struct Link {
    std::uint32_t to;
    Vec3 d;  // minimum-image separation from this particle to `to`
  };
  std::vector<Link> links(start[n]);
  for (const Contact& k : c.contacts) {
    const Vec3 d = c.box.minimum_image(c.position[k.i], c.position[k.j]).d;
    links[fill[k.i]++] = {k.j, d};
    links[fill[k.j]++] = {k.i, -d};
  }
  const Vec3& l = c.box.length();
  const double offset = c.box.shear_offset();
  std::vector<Vec3> unwrapped(n);
  std::vector<char> seen(n, 0);
  std::vector<std::uint32_t> stack;
  for (std::size_t root = 0; root < n; ++root) {
    if (seen[root]) continue;
    seen[root] = 1;
    unwrapped[root] = c.position[root];
    stack.assign(1, static_cast<std::uint32_t>(root));
    Cluster cluster;
    while (!stack.empty()) {
      const std::uint32_t i = stack.back();
      stack.pop_back();
      ++cluster.size;
      for (std::size_t e = start[i]; e < start[i + 1]; ++e) {
        const Link& link = links[e];
        const Vec3 there = unwrapped[i] + link.d;
        if (!seen[link.to]) {
          seen[link.to] = 1;
          unwrapped[link.to] = there;
          stack.push_back(link.to);
          continue;
        }
        // A loop closes: the mismatch is a lattice vector of the sheared cell (header).
        const Vec3 m = there - unwrapped[link.to];
        const double n2 = std::round(m.y() / l.y()), n3 = std::round(m.z() / l.z());
        const double n1 = std::round((m.x() - n2 * offset) / l.x());
        if (n1 != 0.0) cluster.percolates[0] = true;
        if (n2 != 0.0) cluster.percolates[1] = true;
        if (n3 != 0.0) cluster.percolates[2] = true;
      }
    }
    if (cluster.size < 2) {
      ++out.isolated;
      continue;
    }
    for (int a = 0; a < 3; ++a) out.percolates[a] = out.percolates[a] || cluster.percolates[a];
    out.clusters.push_back(cluster);
  }
  std::stable_sort(out.clusters.begin(), out.clusters.end(),
                   [](const Cluster& a, const Cluster& b) { return a.size > b.size; });
  out.largest = out.clusters.empty() ? (n > 0 ? 1 : 0) : out.clusters.front().size;
  double total = 0.0;
  for (const Cluster& k : out.clusters) total += static_cast<double>(k.size);
  if (!out.clusters.empty()) out.mean_size = total / static_cast<double>(out.clusters.size());
  return out;
}

}  // namespace suspend::analysis
