// O(N)-memory contact history (paper 000, section 2.1): per particle a bounded list of (partner, history), sorted
// by partner index, in one flat array of N x M slots allocated once. No N^2 table, no per-step allocation.
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
#pragma once
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

  std::size_t particles() const { return count_.size(); }
  std::size_t capacity_per_particle() const { return capacity_; }
  std::size_t size() const;  // stored pairs
  std::size_t memory_slots() const { return slots_.size(); }

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
  struct Slot {
    std::uint32_t partner;
    PairHistory history;
  };
  // First slot of the row of the lower index, the partner and whether the caller's order is swapped.
  struct Key {
    std::uint32_t row, partner;
    bool swapped;
  };
  Key key(std::uint32_t i, std::uint32_t j) const;
  const Slot* find(const Key& k) const;
  Slot* find(const Key& k);

  std::size_t capacity_ = 0;
  std::vector<Slot> slots_;            // N x M
  std::vector<std::uint32_t> count_;   // used slots per row
};

}  // namespace suspend
