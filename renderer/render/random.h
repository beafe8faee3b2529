#pragma once
// Counter-based random numbers: each value is a hash of (seed, pixel, sample, dimension), so a
// render is the same whatever order the threads visit the pixels in.

#include <cstdint>

namespace gonio {

// SplitMix64's finaliser: a bijective mix with good avalanche.
inline uint64_t Mix64(uint64_t x) {
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    return x;
}

inline uint64_t HashCombine(uint64_t a, uint64_t b) {
    return Mix64(a ^ (b + 0x9e3779b97f4a7c15ull + (a << 6) + (a >> 2)));
}

// A uniform float in [0, 1) from 24 random bits.
inline float ToUnitFloat(uint64_t bits) { return (bits >> 40) * (1.0f / 16777216.0f); }

class SampleRandom {
  public:
    SampleRandom(uint64_t seed, int px, int py, int sample)
        : state_(HashCombine(
              HashCombine(HashCombine(Mix64(seed), uint64_t(uint32_t(px))), uint64_t(uint32_t(py))),
              uint64_t(sample))) {}
    float Next() { return ToUnitFloat(Mix64(state_ += 0x9e3779b97f4a7c15ull)); }
    // A seed for another stream of this pixel sample (the shaders' random()), independent of
    // this one's values.
    uint64_t Seed() const { return Mix64(state_ ^ 0x5eedc0de5eedc0deull); }

  private:
    uint64_t state_;
};

}  // namespace gonio
