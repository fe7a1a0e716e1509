// O(N)-memory contact history (paper 000, section 2.1): per particle a bounded list of (partner, history), sorted
// by partner index. Paper 000 reserves N x M slots; here the rows are packed one after the other (compressed rows,
// offsets per particle), so the store holds only the pairs actually in contact: 4 B per particle plus 60 B per
// contact (partner index, tangential and rolling stretch, normal state) instead of N x M x 64 B (6 KB per particle
// for the a_2/a_1 = 3 suspension of paper 000 Table 3, M = 98). The buffers keep their capacity: no per-step
// allocation once the largest contact count has been seen.
//
// A pair (i, j) is stored once, in the row of min(i, j), with its history oriented for (min, max); lookups for
// (max, min) return PairHistory::swapped(), so a pair listed in either order sees the same physical stretch.
// M bounds the contacts a particle can have with higher-indexed partners; capacity_for() gives paper 000's
// estimate: the number of smallest spheres whose volume fits in the shell of thickness 2 a_min around the largest
// sphere. Exceeding M is reported (NumericalError), never silently dropped.
// Indices are particle labels, untouched by periodic wraps, so history survives wraps by construction.
//
// Typical step of a driver with pair list P (any order, rebuilt or not):
//   gather(P, h)          h[k] = history of pair P[k] (zero stretch, not in contact, when unknown); thread-safe
//   ... contact law on each pair, updating h[k] in place (threads over k) ...
//   scatter(P, h)         store exactly the pairs with h[k].in_contact; everything else is released
// Pairs that separated or left the list are released by scatter, so the store never holds stale contacts.
// scatter rebuilds the rows in O(N + |P|); store() and release() of a single pair shift the rows behind it
// (O(N + contacts)): they are for set-up, checkpoints and tests, not for the step loop.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "dem/contact/pair_history.hpp"
#include "dem/neighbour_search.hpp"

namespace suspend {

class ContactHistory {
 public:
  ContactHistory() = default;
  ContactHistory(std::size_t n_particles, std::size_t capacity_per_particle);

  // Paper 000 estimate of M: ((a_max + 2 a_min)^3 - a_max^3) / a_min^3, rounded up (26 for equal spheres).
  static std::size_t capacity_for(double a_min, double a_max);

  std::size_t particles() const { return row_start_.empty() ? 0 : row_start_.size() - 1; }
  std::size_t capacity_per_particle() const { return capacity_; }
  std::size_t size() const { return partner_.size(); }  // stored pairs
  // Bytes held by the store's buffers (their capacity, i.e. the high-water mark of the run).
  std::size_t memory_bytes() const;

  // History of (i, j) oriented for d = r_j - r_i; a fresh PairHistory when the pair is not stored.
  PairHistory lookup(std::uint32_t i, std::uint32_t j) const;
  bool contains(std::uint32_t i, std::uint32_t j) const;
  // Inserts or updates (i, j); a history with in_contact == false releases the pair instead.
  void store(std::uint32_t i, std::uint32_t j, const PairHistory& h);
  void release(std::uint32_t i, std::uint32_t j);
  void clear();

  // Every stored pair, in row order (checkpoints), and the inverse: restore(entries()) reproduces the store.
  struct Entry {
    std::uint32_t i, j;  // i < j
    PairHistory history;
  };
  std::vector<Entry> entries() const;
  void restore(const std::vector<Entry>& entries);

  void gather(std::span<const NeighbourPair> pairs, std::span<PairHistory> out) const;
  void scatter(std::span<const NeighbourPair> pairs, std::span<const PairHistory> in);

 private:
  // The stretches and scalar slots of a stored pair, oriented for (row, partner) (in_contact is implied by being
  // stored; PairHistory::swapped turns a pair's history the other way).
  struct Stretch {
    Vec3 tangential, rolling;
    std::array<double, scalar_slots.size()> scalars;
    static Stretch of(const PairHistory& h, bool swapped) {
      const PairHistory o = swapped ? h.swapped() : h;
      Stretch s{o.tangential_stretch, o.rolling_stretch, {}};
      for (std::size_t q = 0; q < scalar_slots.size(); ++q) s.scalars[q] = o.*scalar_slots[q].member;
      return s;
    }
    PairHistory history(bool swapped) const {
      PairHistory h;
      h.tangential_stretch = tangential;
      h.rolling_stretch = rolling;
      h.in_contact = true;
      for (std::size_t q = 0; q < scalar_slots.size(); ++q) h.*scalar_slots[q].member = scalars[q];
      return swapped ? h.swapped() : h;
    }
  };
  // The row of the lower index, the partner and whether the caller's order is swapped.
  struct Key {
    std::uint32_t row, partner;
    bool swapped;
  };
  Key key(std::uint32_t i, std::uint32_t j) const;
  // Position of the partner in the row, or -1.
  std::ptrdiff_t find(const Key& k) const;
  [[noreturn]] void overflow(std::uint32_t row) const;

  std::size_t capacity_ = 0;
  std::vector<std::uint32_t> row_start_;  // N + 1 offsets into partner_ / stretch_
  std::vector<std::uint32_t> partner_;    // per stored pair, rows sorted by partner
  std::vector<Stretch> stretch_;          // per stored pair, oriented for (row, partner)
  std::vector<std::uint32_t> cursor_;     // scatter scratch: fill position per row
  std::vector<std::uint32_t> source_;     // scatter scratch: input index per stored pair
};

}  // namespace suspend
