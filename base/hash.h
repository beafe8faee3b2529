#pragma once
// Integer hashing and counter-based random streams, defined once for every stage: the image
// renderer's sample streams, the shaders' random(), the synthetic photon maps.

#include <cstdint>

namespace gonio {

// SplitMix64's increment (Steele, Lea and Flood 2014): the golden-ratio Weyl step.
constexpr uint64_t kSplitMix64Step = 0x9e3779b97f4a7c15ull;

// SplitMix64's finaliser: a bijective 64-bit mix with good avalanche.
inline uint64_t MixBits(uint64_t x) {
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// The next 64 bits of the SplitMix64 stream whose state is `state`.
inline uint64_t SplitMix64(uint64_t& state) { return MixBits(state += kSplitMix64Step); }

// Combines two hashes into one (boost's hash_combine, widened to 64 bits and mixed).
inline uint64_t HashCombine(uint64_t a, uint64_t b) {
    return MixBits(a ^ (b + kSplitMix64Step + (a << 6) + (a >> 2)));
}

// A uniform float in [0, 1) from the top 24 bits.
inline float ToUnitFloat(uint64_t bits) { return (bits >> 40) * (1.0f / 16777216.0f); }

// A uniform double in [0, 1) from the top 53 bits.
inline double ToUnitDouble(uint64_t bits) { return (bits >> 11) * (1.0 / 9007199254740992.0); }

}  // namespace gonio
