#include "dem/contact_history.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace suspend {

ContactHistory::ContactHistory(std::size_t n_particles, std::size_t capacity_per_particle)
    : capacity_(capacity_per_particle), row_start_(n_particles + 1, 0), cursor_(n_particles, 0) {
  if (capacity_per_particle == 0) throw InputError("contact history capacity per particle must be > 0");
}

std::size_t ContactHistory::capacity_for(double a_min, double a_max) {
  if (!(a_min > 0.0) || !(a_max >= a_min))
    throw InputError("contact history: radii must satisfy 0 < a_min <= a_max");
  const double outer = a_max + 2.0 * a_min;
  return static_cast<std::size_t>(std::ceil((outer * outer * outer - a_max * a_max * a_max) /
                                            (a_min * a_min * a_min) - 1e-9));
}

std::size_t ContactHistory::memory_bytes() const {
  return (row_start_.capacity() + partner_.capacity() + cursor_.capacity() + source_.capacity()) *
             sizeof(std::uint32_t) +
         stretch_.capacity() * sizeof(Stretch);
}

ContactHistory::Key ContactHistory::key(std::uint32_t i, std::uint32_t j) const {
  if (i == j || std::max(i, j) >= particles())
    throw InputError("contact history: invalid pair (" + std::to_string(i) + ", " + std::to_string(j) + ")");
  return i < j ? Key{i, j, false} : Key{j, i, true};
}

std::ptrdiff_t ContactHistory::find(const Key& k) const {
  const std::uint32_t* first = partner_.data() + row_start_[k.row];
  const std::uint32_t* last = partner_.data() + row_start_[k.row + 1];
  const std::uint32_t* it = std::lower_bound(first, last, k.partner);
  return it != last && *it == k.partner ? it - partner_.data() : -1;
}

void ContactHistory::overflow(std::uint32_t row) const {
  throw NumericalError("contact history: particle " + std::to_string(row) + " has more than " +
                       std::to_string(capacity_) +
                       " contacts with higher-indexed partners; overlaps are far too large or the capacity too "
                       "small");
}

PairHistory ContactHistory::lookup(std::uint32_t i, std::uint32_t j) const {
  const Key k = key(i, j);
  const std::ptrdiff_t s = find(k);
  if (s < 0) return {};
  return stretch_[s].history(k.swapped);
}

bool ContactHistory::contains(std::uint32_t i, std::uint32_t j) const { return find(key(i, j)) >= 0; }

void ContactHistory::store(std::uint32_t i, std::uint32_t j, const PairHistory& h) {
  if (!h.in_contact) {
    release(i, j);
    return;
  }
  const Key k = key(i, j);
  const Stretch value = Stretch::of(h, k.swapped);
  const std::ptrdiff_t s = find(k);
  if (s >= 0) {
    stretch_[s] = value;
    return;
  }
  if (row_start_[k.row + 1] - row_start_[k.row] == capacity_) overflow(k.row);
  const auto first = partner_.begin() + row_start_[k.row];
  const auto last = partner_.begin() + row_start_[k.row + 1];
  const std::ptrdiff_t at = std::lower_bound(first, last, k.partner) - partner_.begin();
  partner_.insert(partner_.begin() + at, k.partner);
  stretch_.insert(stretch_.begin() + at, value);
  for (std::size_t r = k.row + 1; r < row_start_.size(); ++r) ++row_start_[r];
}

void ContactHistory::release(std::uint32_t i, std::uint32_t j) {
  const Key k = key(i, j);
  const std::ptrdiff_t s = find(k);
  if (s < 0) return;
  partner_.erase(partner_.begin() + s);
  stretch_.erase(stretch_.begin() + s);
  for (std::size_t r = k.row + 1; r < row_start_.size(); ++r) --row_start_[r];
}

void ContactHistory::clear() {
  std::fill(row_start_.begin(), row_start_.end(), 0u);
  partner_.clear();
  stretch_.clear();
}

std::vector<ContactHistory::Entry> ContactHistory::entries() const {
  std::vector<Entry> out;
  out.reserve(size());
  for (std::uint32_t row = 0; row < particles(); ++row)
    for (std::uint32_t s = row_start_[row]; s < row_start_[row + 1]; ++s)
      out.push_back({row, partner_[s], stretch_[s].history(false)});
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

// Counting sort of the pairs in contact by row, then each (short) row sorted by partner. A pair listed twice keeps
// its last history, as successive store() calls would.
void ContactHistory::scatter(std::span<const NeighbourPair> pairs, std::span<const PairHistory> in) {
  if (in.size() != pairs.size()) throw InputError("contact history: scatter needs one history per pair");
  const std::size_t n = particles();
  std::fill(row_start_.begin(), row_start_.end(), 0u);
  std::size_t stored = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const Key key_k = key(pairs[k].i, pairs[k].j);
    if (!in[k].in_contact) continue;
    if (++row_start_[key_k.row + 1] > capacity_) overflow(key_k.row);
    ++stored;
  }
  for (std::size_t r = 0; r < n; ++r) row_start_[r + 1] += row_start_[r];
  std::copy(row_start_.begin(), row_start_.end() - 1, cursor_.begin());
  partner_.resize(stored);
  source_.resize(stored);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (!in[k].in_contact) continue;
    const Key key_k = key(pairs[k].i, pairs[k].j);
    const std::uint32_t slot = cursor_[key_k.row]++;
    partner_[slot] = key_k.partner;
    source_[slot] = static_cast<std::uint32_t>(k);
  }
  // Sort each row by (partner, input position), drop all but the last of equal partners, and pack the rows.
  std::uint32_t write = 0;
  for (std::size_t r = 0; r < n; ++r) {
    const std::uint32_t begin = row_start_[r], end = row_start_[r + 1];
    for (std::uint32_t s = begin + 1; s < end; ++s) {  // insertion sort: rows hold a few contacts
      const std::uint32_t p = partner_[s], q = source_[s];
      std::uint32_t t = s;
      for (; t > begin && (partner_[t - 1] > p || (partner_[t - 1] == p && source_[t - 1] > q)); --t) {
        partner_[t] = partner_[t - 1];
        source_[t] = source_[t - 1];
      }
      partner_[t] = p;
      source_[t] = q;
    }
    row_start_[r] = write;
    for (std::uint32_t s = begin; s < end; ++s) {
      if (s + 1 < end && partner_[s + 1] == partner_[s]) continue;
      partner_[write] = partner_[s];
      source_[write] = source_[s];
      ++write;
    }
  }
  row_start_[n] = write;
  partner_.resize(write);
  stretch_.resize(write);
  for (std::uint32_t s = 0; s < write; ++s) {
    const NeighbourPair& pr = pairs[source_[s]];
    stretch_[s] = Stretch::of(in[source_[s]], !(pr.i < pr.j));
  }
}

}  // namespace suspend
