#pragma once
// Per-item random streams that do not depend on which thread runs the item.
#include <cstdint>

namespace exactvis {

// A well-mixed 64-bit value of (seed, index): the splitmix64 finaliser of seed + golden-ratio increment times
// (index + 1). Seeds one std::mt19937_64 per triangle / cell so that answers and witnesses are the same for any
// thread count, shard or MPI distribution. Cost: a few integer operations.
inline std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ull * (index + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace exactvis
