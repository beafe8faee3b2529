#include "imageio/pixel_conversion.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace gonio {

namespace {

float SampleAsFloat(const PixelBuffer& pixels, size_t i) {
    switch (pixels.type) {
        case PixelType::UInt8:
            return static_cast<const uint8_t*>(pixels.data)[i] * (1.0f / 255.0f);
        case PixelType::UInt16:
            return static_cast<const uint16_t*>(pixels.data)[i] * (1.0f / 65535.0f);
        default:
            return static_cast<const float*>(pixels.data)[i];
    }
}

template <typename T>
void StoreCodes(const PixelBuffer& pixels, size_t count, float max, unsigned char* bytes) {
    T* out = reinterpret_cast<T*>(bytes);
    for (size_t i = 0; i < count; ++i)
        out[i] = T(std::clamp(SampleAsFloat(pixels, i) * max + 0.5f, 0.0f, max));
}

size_t SampleBytes(PixelType type) {
    return type == PixelType::UInt8 ? 1 : type == PixelType::UInt16 ? 2 : 4;
}

}  // namespace

std::vector<unsigned char> ConvertPixels(const PixelBuffer& pixels, size_t count, PixelType to) {
    if (to == PixelType::Half) to = PixelType::Float;
    std::vector<unsigned char> bytes(count * SampleBytes(to));
    if (to == pixels.type) {
        std::memcpy(bytes.data(), pixels.data, bytes.size());
    } else if (to == PixelType::UInt8) {
        StoreCodes<uint8_t>(pixels, count, 255.0f, bytes.data());
    } else if (to == PixelType::UInt16) {
        StoreCodes<uint16_t>(pixels, count, 65535.0f, bytes.data());
    } else {
        float* out = reinterpret_cast<float*>(bytes.data());
        for (size_t i = 0; i < count; ++i) out[i] = SampleAsFloat(pixels, i);
    }
    return bytes;
}

}  // namespace gonio
