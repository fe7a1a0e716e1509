// Buffers kept from step to step (pair lists, pair histories, per-pair forces) grow with the pair count. std::vector
// doubles its capacity when a resize or push_back exceeds it, so a list that grows by one pair past a power of two
// holds twice the memory for the rest of the run. Growing with a fixed headroom of 1/8 instead bounds the
// high-water mark at 12.5% above the largest size seen; reallocation stays rare (the pair count changes slowly).
#pragma once
#include <cstddef>
#include <vector>

namespace suspend {

template <class T, class Alloc>
void resize_with_headroom(std::vector<T, Alloc>& v, std::size_t n) {
  if (n > v.capacity()) v.reserve(n + n / 8);
  v.resize(n);
}

// Before v.push_back(...): makes room for one more element the same way.
template <class T, class Alloc>
void reserve_one_more(std::vector<T, Alloc>& v) {
  if (v.size() == v.capacity()) v.reserve(v.size() + v.size() / 8 + 1024);
}

}  // namespace suspend
