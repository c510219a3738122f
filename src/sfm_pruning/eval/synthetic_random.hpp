// Seeding for the synthetic scene generator. Every random stream (one per view, per appearance,
// per image pair) gets its own generator derived from the user's seed and the stream's ids, so a
// scene does not depend on the order in which its parts are generated and may be generated in
// parallel without changing a single byte.
#pragma once

#include <cstdint>
#include <random>

namespace sfm_pruning {

// Purposes of the random streams; part of the derived seed so that streams never collide.
enum class SyntheticStream : uint64_t {
  kLayout = 1,      // scene geometry: camera jitter, point positions
  kAppearance = 2,  // base descriptors
  kView = 3,        // per-view pixel noise, descriptor noise, dropout, clutter
  kPair = 4,        // per-pair injected wrong matches
  kParameters = 5,  // a family scene's drawn parameters (a: what is drawn, b: the family)
};

// SplitMix64 finaliser: a bijective mix whose outputs for consecutive inputs are uncorrelated.
inline uint64_t MixSeedBits(uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// A generator for stream `stream` of the object identified by (a, b) under the user's seed.
inline std::mt19937_64 MakeSyntheticRng(uint64_t seed, SyntheticStream stream, uint64_t a = 0, uint64_t b = 0) {
  uint64_t s = MixSeedBits(seed);
  s = MixSeedBits(s ^ static_cast<uint64_t>(stream));
  s = MixSeedBits(s ^ a);
  s = MixSeedBits(s ^ b);
  return std::mt19937_64(s);
}

}  // namespace sfm_pruning
