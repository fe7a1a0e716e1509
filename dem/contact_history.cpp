#include "dem/contact_history.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/error.hpp"

namespace suspend {

ContactHistory::ContactHistory(std::size_t n_particles, std::size_t capacity_per_particle)
    : capacity_(capacity_per_particle), slots_(n_particles * capacity_per_particle), count_(n_particles, 0) {
  if (capacity_per_particle == 0) throw InputError("contact history capacity per particle must be > 0");
}

std::size_t ContactHistory::capacity_for(double a_min, double a_max) {
  if (!(a_min > 0.0) || !(a_max >= a_min))
    throw InputError("contact history: radii must satisfy 0 < a_min <= a_max");
  const double outer = a_max + 2.0 * a_min;
  return static_cast<std::size_t>(std::ceil((outer * outer * outer - a_max * a_max * a_max) /
                                            (a_min * a_min * a_min) - 1e-9));
}

std::size_t ContactHistory::size() const {
  std::size_t n = 0;
  for (const auto c : count_) n += c;
  return n;
}

ContactHistory::Key ContactHistory::key(std::uint32_t i, std::uint32_t j) const {
  if (i == j || std::max(i, j) >= count_.size())
    throw InputError("contact history: invalid pair (" + std::to_string(i) + ", " + std::to_string(j) + ")");
  return i < j ? Key{i, j, false} : Key{j, i, true};
}

const ContactHistory::Slot* ContactHistory::find(const Key& k) const {
  const Slot* first = slots_.data() + k.row * capacity_;
  const Slot* last = first + count_[k.row];
  const Slot* it = std::lower_bound(first, last, k.partner, [](const Slot& s, std::uint32_t p) { return s.partner < p; });
  return it != last && it->partner == k.partner ? it : nullptr;
}

ContactHistory::Slot* ContactHistory::find(const Key& k) {
  return const_cast<Slot*>(std::as_const(*this).find(k));
}

PairHistory ContactHistory::lookup(std::uint32_t i, std::uint32_t j) const {
  const Key k = key(i, j);
  const Slot* s = find(k);
  if (s == nullptr) return {};
  return k.swapped ? s->history.swapped() : s->history;
}

bool ContactHistory::contains(std::uint32_t i, std::uint32_t j) const { return find(key(i, j)) != nullptr; }

void ContactHistory::store(std::uint32_t i, std::uint32_t j, const PairHistory& h) {
  if (!h.in_contact) {
    release(i, j);
    return;
  }
  const Key k = key(i, j);
  const PairHistory oriented = k.swapped ? h.swapped() : h;
  Slot* first = slots_.data() + k.row * capacity_;
  Slot* last = first + count_[k.row];
  Slot* it = std::lower_bound(first, last, k.partner, [](const Slot& s, std::uint32_t p) { return s.partner < p; });
  if (it != last && it->partner == k.partner) {
    it->history = oriented;
    return;
  }
  if (count_[k.row] == capacity_)
    throw NumericalError("contact history: particle " + std::to_string(k.row) + " has more than " +
                         std::to_string(capacity_) +
                         " contacts with higher-indexed partners; overlaps are far too large or the capacity too "
                         "small");
  std::move_backward(it, last, last + 1);
  *it = Slot{k.partner, oriented};
  ++count_[k.row];
}

void ContactHistory::release(std::uint32_t i, std::uint32_t j) {
  const Key k = key(i, j);
  Slot* s = find(k);
  if (s == nullptr) return;
  Slot* last = slots_.data() + k.row * capacity_ + count_[k.row];
  std::move(s + 1, last, s);
  --count_[k.row];
}

void ContactHistory::clear() { std::fill(count_.begin(), count_.end(), 0u); }

std::vector<ContactHistory::Entry> ContactHistory::entries() const {
  std::vector<Entry> out;
  for (std::uint32_t row = 0; row < count_.size(); ++row)
    for (std::uint32_t s = 0; s < count_[row]; ++s) {
      const Slot& slot = slots_[row * capacity_ + s];
      out.push_back({row, slot.partner, slot.history});
    }
  return out;
}

void ContactHistory::restore(const std::vector<Entry>& entries) {
  clear();
  for (const Entry& e : entries) store(e.i, e.j, e.history);
}

void ContactHistory::gather(std::span<const NeighbourPair> pairs, std::span<PairHistory> out) const {
  if (out.size() != pairs.size()) throw InputError("contact history: gather needs one history per pair");
  for (std::size_t k = 0; k < pairs.size(); ++k) out[k] = lookup(pairs[k].i, pairs[k].j);
}

void ContactHistory::scatter(std::span<const NeighbourPair> pairs, std::span<const PairHistory> in) {
  if (in.size() != pairs.size()) throw InputError("contact history: scatter needs one history per pair");
  clear();
  for (std::size_t k = 0; k < pairs.size(); ++k) store(pairs[k].i, pairs[k].j, in[k]);
}

}  // namespace suspend
