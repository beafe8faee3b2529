#pragma once
// The reconstruction filter of `PixelFilter "name" xwidth ywidth` (RISpec §4.1.2). Each filter is
// the RenderMan C binding's function of the sample's offset (dx, dy) in pixels from the pixel
// centre; the footprint is the rectangle |dx| <= XRadius(), |dy| <= YRadius() with radius =
// width / 2, and Evaluate returns 0 outside it.

#include <optional>
#include <string>

namespace gonio {

class PixelFilter {
  public:
    // RISpec default: gaussian 2 2.
    PixelFilter() : PixelFilter(Kind::Gaussian, 2.0f, 2.0f) {}

    // Makes the filter RIB calls `name` ("box", "triangle", "gaussian", "catmull-rom", "sinc",
    // "disk", "mitchell"). On an unknown name or a width that is not positive, returns nullopt
    // and says why in `error` (the scene builder then warns and keeps the default).
    static std::optional<PixelFilter> FromRib(const std::string& name, float xwidth, float ywidth,
                                              std::string& error);

    // Filter weight of a sample at offset (dx, dy) pixels from the pixel centre. May be negative
    // (catmull-rom, sinc, mitchell lobes); 0 outside the footprint.
    float Evaluate(float dx, float dy) const;

    // Every filter but the disk is a product of a function of dx and one of dy: then
    // Evaluate(dx, dy) == XWeight(dx) * YWeight(dy), and a film can weight a sample's row and
    // column of pixels once instead of each pixel.
    bool Separable() const { return kind_ != Kind::Disk; }
    float XWeight(float dx) const { return Weight1D(dx, xwidth_); }
    float YWeight(float dy) const { return Weight1D(dy, ywidth_); }

    // Box, triangle, gaussian and disk weigh no sample negatively (catmull-rom, sinc and
    // mitchell have negative lobes).
    bool NeverNegative() const {
        return kind_ == Kind::Box || kind_ == Kind::Triangle || kind_ == Kind::Gaussian ||
               kind_ == Kind::Disk;
    }
    float XRadius() const { return xwidth_ * 0.5f; }
    float YRadius() const { return ywidth_ * 0.5f; }
    const std::string& Name() const;

  private:
    float Weight1D(float d, float width) const;

    enum class Kind { Box, Triangle, Gaussian, CatmullRom, Sinc, Disk, Mitchell };
    PixelFilter(Kind kind, float xwidth, float ywidth)
        : kind_(kind), xwidth_(xwidth), ywidth_(ywidth) {}

    Kind kind_;
    float xwidth_;
    float ywidth_;
};

}  // namespace gonio
