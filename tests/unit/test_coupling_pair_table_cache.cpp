// The FCM pair-resistance cache: a table is reused only with identical parameters (a cache file made with any
// other parameter is recomputed and replaced, never used), and what is read back equals what was computed.
// Small coarse table (L = 6 (a_i + a_j), h = 0.75, three gaps) so that the test is fast; the values themselves
// are checked against the exact two-sphere functions in tests/validation/test_coupling_two_spheres.cpp.
#include <gtest/gtest.h>

#include <filesystem>

#include "coupling/fcm_pair_resistance.hpp"
#include "coupling/pair_tensors.hpp"
#include "tests/scratch_dir.hpp"

using namespace suspend;
using namespace suspend::coupling;

TEST(CouplingPairTableCache, ReusedOnlyWithTheSameParameters) {
  const std::string dir = suspend::testing_support::scratch_dir() + "/coupling_cache";
  std::filesystem::remove_all(dir);
  FcmPairTableParams p;
  p.grid_spacing = 0.75;
  p.box_factor = 6.0;
  p.s_min = 2.0;
  p.s_max = 2.4;
  p.ds = 0.4;
  p.rigidity_tolerance = 1e-6;
  bool recomputed = false;
  const FcmPairTable a = FcmPairTable::load_or_compute(p, dir, &recomputed);
  EXPECT_TRUE(recomputed);
  const FcmPairTable b = FcmPairTable::load_or_compute(p, dir, &recomputed);
  EXPECT_FALSE(recomputed);
  for (double s : {2.0, 2.13, 2.4, 2.6}) {
    hydro::ResistanceScalars ai, aj, bi, bj;
    a.scalars(s, ai, aj);
    b.scalars(s, bi, bj);
    for (auto f : correction_functions) {
      EXPECT_NEAR(ai.*f, bi.*f, 1e-14 * (1.0 + std::abs(ai.*f)));
      EXPECT_NEAR(aj.*f, bj.*f, 1e-14 * (1.0 + std::abs(aj.*f)));
    }
    // Equal spheres: the same functions from either side, up to the grid-position error of this coarse grid
    // (h = 0.75 a, about 1%); FCM resolves X11A > 1 and X12A < 0 near contact.
    EXPECT_NEAR(ai.x11a, aj.x11a, 0.03 * ai.x11a);
    EXPECT_GT(ai.x11a, 1.0);
    EXPECT_LT(ai.x12a, 0.0);
  }
  // Another truncation: same file name, other parameters -> recomputed, and the file now holds the new table.
  FcmPairTableParams q = p;
  q.rigidity_tolerance = 1e-7;
  FcmPairTable c = FcmPairTable::load_or_compute(q, dir, &recomputed);
  EXPECT_TRUE(recomputed);
  EXPECT_EQ(c.file_name(), a.file_name());
  FcmPairTable d;
  EXPECT_FALSE(d.read((std::filesystem::path(dir) / a.file_name()).string(), p));
  EXPECT_TRUE(d.read((std::filesystem::path(dir) / a.file_name()).string(), q));
  std::filesystem::remove_all(dir);
}
