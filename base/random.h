#pragma once
// Counter-based random numbers: each value is a hash of (seed, pixel, sample, dimension), so a
// render is the same whatever order the threads visit the pixels in.

#include <cstdint>

#include "base/hash.h"

namespace gonio {

class SampleRandom {
  public:
    SampleRandom(uint64_t seed, int px, int py, int sample)
        : SampleRandom(PixelHash(seed, px, py), sample) {}
    // The same stream from its pixel's part of the hash, computed once for all its samples.
    SampleRandom(uint64_t pixelHash, int sample)
        : state_(HashCombine(pixelHash, uint64_t(sample))) {}
    static uint64_t PixelHash(uint64_t seed, int px, int py) {
        return HashCombine(HashCombine(MixBits(seed), uint64_t(uint32_t(px))),
                           uint64_t(uint32_t(py)));
    }
    float Next() { return ToUnitFloat(MixBits(state_ += kSplitMix64Step)); }
    // Passes over n values unread: the ones after them stay what they would have been.
    void Skip(int n) { state_ += uint64_t(n) * kSplitMix64Step; }
    // A seed for another stream of this pixel sample (the shaders' random()), independent of
    // this one's values: MixBits(SeedKey()), which a caller that may never use it keeps
    // instead (the hash is most of the work).
    uint64_t Seed() const { return MixBits(SeedKey()); }
    uint64_t SeedKey() const { return state_ ^ 0x5eedc0de5eedc0deull; }

  private:
    uint64_t state_;
};

}  // namespace gonio
