// Contact numbers, clusters, percolation and the contact tensors on configurations whose answers are known by
// counting: a chain, a ring closed through the periodic x face, a column closed through the sheared y face, and a
// simple cubic lattice (Z = 6, fabric I/3, contact stress -f/s^2 on the diagonal).
#include <gtest/gtest.h>

#include "analysis/contact_network.hpp"
#include "analysis/contact_stress.hpp"

using namespace suspend;
using namespace suspend::analysis;

namespace {

Configuration spheres(const Box& box, const std::vector<Vec3>& position) {
  Configuration c;
  c.box = box;
  c.position = position;
  c.radius.assign(position.size(), 1.0);
  c.species.assign(position.size(), 0);
  return c;
}

void touch(Configuration& c, std::uint32_t i, std::uint32_t j, bool sliding = false) {
  Contact k;
  k.i = i, k.j = j, k.sliding = sliding;
  c.contacts.push_back(k);
}

}  // namespace

TEST(ContactNetwork, ChainCountsContactsRattlersAndOneFiniteCluster) {
  // Four spheres in a row plus one alone: Z = 2 * 3 / 5, the chain's two ends and the loner are rattlers.
  Configuration c = spheres(Box(20, 20, 20), {{2, 5, 5}, {4, 5, 5}, {6, 5, 5}, {8, 5, 5}, {15, 15, 15}});
  c.species = {0, 1, 1, 0, 0};
  touch(c, 0, 1), touch(c, 1, 2, true), touch(c, 2, 3);
  const ContactNumbers z = contact_numbers(c);
  EXPECT_EQ(z.contacts, 3u);
  EXPECT_DOUBLE_EQ(z.contacts_per_particle, 6.0 / 5.0);
  EXPECT_DOUBLE_EQ(z.rattler_fraction, 3.0 / 5.0);
  EXPECT_DOUBLE_EQ(z.sliding_fraction, 1.0 / 3.0);
  ASSERT_EQ(z.contacts_per_particle_of.size(), 2u);
  EXPECT_DOUBLE_EQ(z.contacts_per_particle_of[0], 2.0 / 3.0);  // ends 1 + 1, loner 0
  EXPECT_DOUBLE_EQ(z.contacts_per_particle_of[1], 2.0);
  const ClusterStatistics cl = clusters(c);
  ASSERT_EQ(cl.clusters.size(), 1u);
  EXPECT_EQ(cl.largest, 4u);
  EXPECT_EQ(cl.isolated, 1u);
  EXPECT_DOUBLE_EQ(cl.mean_size, 4.0);
  EXPECT_FALSE(cl.percolates[0] || cl.percolates[1] || cl.percolates[2]);
}

TEST(ContactNetwork, RingThroughThePeriodicXFacePercolatesAlongXOnly) {
  // Five spheres 2 apart in a box of L_x = 10: the last touches the first through the x face.
  Configuration c = spheres(Box(10, 12, 12), {{1, 6, 6}, {3, 6, 6}, {5, 6, 6}, {7, 6, 6}, {9, 6, 6}});
  for (std::uint32_t i = 0; i < 5; ++i) touch(c, i, (i + 1) % 5);
  ClusterStatistics cl = clusters(c);
  ASSERT_EQ(cl.clusters.size(), 1u);
  EXPECT_EQ(cl.largest, 5u);
  EXPECT_TRUE(cl.percolates[0]);
  EXPECT_FALSE(cl.percolates[1]);
  EXPECT_FALSE(cl.percolates[2]);
  // Open the ring: the same chain no longer spans the box.
  c.contacts.pop_back();
  cl = clusters(c);
  EXPECT_EQ(cl.largest, 5u);
  EXPECT_FALSE(cl.percolates[0]);
}

TEST(ContactNetwork, ColumnClosedThroughTheShearedYFacePercolatesAlongY) {
  // Lees-Edwards: the image of sphere 0 above the top face sits at x + offset. The column leans so that its top
  // meets that image, not the unshifted one: a loop of lattice vector a_2 = (offset, L_y, 0), i.e. n = (0, 1, 0).
  Box box(12, 12, 12);
  box.set_shear_offset(5.0);
  Configuration c = spheres(box, {{1, 1, 6}, {3, 5, 6}, {5, 9, 6}});
  touch(c, 0, 1), touch(c, 1, 2), touch(c, 2, 0);
  const Vec3 d = c.box.minimum_image(c.position[2], c.position[0]).d;
  ASSERT_NEAR(d.x(), 1.0, 1e-12);  // (1 + 5) - 5: through the sheared face
  ASSERT_NEAR(d.y(), 4.0, 1e-12);
  ClusterStatistics cl = clusters(c);
  EXPECT_FALSE(cl.percolates[0]);
  EXPECT_TRUE(cl.percolates[1]);
  EXPECT_FALSE(cl.percolates[2]);
  // A single pair touching through the sheared face is no loop: nothing spans.
  Configuration pair = spheres(box, {{1, 0.5, 6}, {6, 11.5, 6}});  // the image of 1 below: (6 - 5, -0.5, 6)
  touch(pair, 0, 1);
  EXPECT_NEAR(pair.box.minimum_image(pair.position[0], pair.position[1]).d.norm(), 1.0, 1e-12);
  cl = clusters(pair);
  EXPECT_EQ(cl.largest, 2u);
  EXPECT_FALSE(cl.percolates[0] || cl.percolates[1] || cl.percolates[2]);
}

TEST(ContactNetwork, SimpleCubicLatticeSpansEveryDirectionWithIsotropicFabric) {
  constexpr int m = 4;
  constexpr double s = 2.0, f = 0.7;  // spacing, normal force of every contact
  std::vector<Vec3> position;
  for (int x = 0; x < m; ++x)
    for (int y = 0; y < m; ++y)
      for (int z = 0; z < m; ++z) position.emplace_back(s * (x + 0.5), s * (y + 0.5), s * (z + 0.5));
  Box box(m * s, m * s, m * s);
  box.set_shear_offset(s);  // sheared by one spacing: the y-face neighbours are still lattice sites
  Configuration c = spheres(box, position);
  auto site = [&](int x, int y, int z) { return static_cast<std::uint32_t>(((x + m) % m) * m * m + ((y + m) % m) * m + (z + m) % m); };
  for (int x = 0; x < m; ++x)
    for (int y = 0; y < m; ++y)
      for (int z = 0; z < m; ++z) {
        touch(c, site(x, y, z), site(x + 1, y, z));
        touch(c, site(x, y, z), site(x, y, z + 1));
        // Across the top face the neighbour above is the site one spacing back in x (image shifted by +s).
        touch(c, site(x, y, z), y + 1 < m ? site(x, y + 1, z) : site(x - 1, 0, z));
      }
  for (Contact& k : c.contacts) k.normal_force = f;
  const ContactNumbers z = contact_numbers(c);
  EXPECT_DOUBLE_EQ(z.contacts_per_particle, 6.0);
  EXPECT_DOUBLE_EQ(z.rattler_fraction, 0.0);
  const ClusterStatistics cl = clusters(c);
  ASSERT_EQ(cl.clusters.size(), 1u);
  EXPECT_EQ(cl.largest, static_cast<std::size_t>(m * m * m));
  EXPECT_TRUE(cl.percolates[0] && cl.percolates[1] && cl.percolates[2]);
  const ContactTensors t = contact_tensors(c);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      EXPECT_NEAR(t.fabric(a, b), a == b ? 1.0 / 3.0 : 0.0, 1e-12);
      // Repulsive contacts, one per site and direction: Sigma_aa = -N s f / V = -f / s^2.
      EXPECT_NEAR(t.contact_law_stress(a, b), a == b ? -f / (s * s) : 0.0, 1e-12);
    }
}

TEST(ContactTensors, ContactStressIsTheVirialOfTheLawForces) {
  // One pair along x, one sheared pair in the xy plane, forces of both kinds; -(1/V) sum sym(d F_j) by hand.
  Configuration c = spheres(Box(10, 10, 10), {{2, 2, 2}, {4, 2, 2}, {6, 6, 6}, {7.2, 7.6, 6}});
  touch(c, 0, 1), touch(c, 2, 3);
  c.contacts[0].normal_force = 2.0;
  c.contacts[0].tangential_force = Vec3(0, 0.5, 0);
  c.contacts[0].force_on_j = Vec3(1.5, 0.5, 0);  // with an adhesive pull of 0.5
  c.contacts[1].normal_force = 1.0;
  c.contacts[1].force_on_j = Vec3(0.6, 0.8, 0);
  const ContactTensors t = contact_tensors(c);
  const double v = 1000.0;
  EXPECT_NEAR(t.contact_law_stress(0, 0), -(2 * 2.0 + 1.2 * 0.6) / v, 1e-15);
  EXPECT_NEAR(t.contact_law_stress(0, 1), -(0.5 * 2 * 0.5 + 0.5 * (1.2 * 0.8 + 1.6 * 0.6)) / v, 1e-15);
  EXPECT_NEAR(t.contact_law_stress(1, 1), -(1.6 * 0.8) / v, 1e-15);
  EXPECT_NEAR(t.contact_pair_stress(0, 0), -(2 * 1.5 + 1.2 * 0.6) / v, 1e-15);
  EXPECT_NEAR(t.fabric(0, 0), (1.0 + 0.36) / 2.0, 1e-15);
  EXPECT_NEAR(t.fabric(0, 1), 0.48 / 2.0, 1e-15);
}
