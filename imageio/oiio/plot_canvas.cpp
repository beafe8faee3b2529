// Raster plots' canvas on OpenImageIO's ImageBufAlgo (render_line, render_text, resize).
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "imageio/oiio/oiio_parts.h"

namespace gonio {

namespace {

namespace IBA = OIIO::ImageBufAlgo;

constexpr float kBlack[3] = {0, 0, 0};

IBA::TextAlignX OiioAlign(PlotCanvas::Align align) {
    return align == PlotCanvas::Align::Left     ? IBA::TextAlignX::Left
           : align == PlotCanvas::Align::Center ? IBA::TextAlignX::Center
                                                : IBA::TextAlignX::Right;
}

OIIO::ImageSpec RgbSpec(int width, int height) {
    return OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT);
}

class OiioPlotCanvas : public PlotCanvas {
  public:
    OiioPlotCanvas(int width, int height) : image_(RgbSpec(width, height)) {
        IBA::fill(image_, {1.0f, 1.0f, 1.0f});
    }

    void Line(int x0, int y0, int x1, int y1, const float rgb[3], const Box* clip) override {
        const OIIO::ROI roi =
            clip ? OIIO::ROI(clip->x0, clip->x1, clip->y0, clip->y1) : image_.roi();
        IBA::render_line(image_, x0, y0, x1, y1, {rgb, 3}, false, roi);
    }

    std::string Text(int x, int y, const std::string& text, int size, const std::string& font,
                     Align align) override {
        if (IBA::render_text(image_, x, y, text, size, font, kBlack, OiioAlign(align),
                             IBA::TextAlignY::Baseline))
            return "";
        return image_.geterror();
    }

    // Drawn upright into a buffer of its own, then rotated and pasted.
    std::string VerticalText(int x, int y, const std::string& text, int size,
                             const std::string& font) override {
        const OIIO::ROI box = IBA::text_size(text, size, font);
        if (!box.defined()) return "no size for the text";
        OIIO::ImageBuf upright(RgbSpec(box.width() + 4, box.height() + 4));
        IBA::fill(upright, {1.0f, 1.0f, 1.0f});
        IBA::render_text(upright, 2 - box.xbegin, 2 - box.ybegin, text, size, font, kBlack);
        const OIIO::ImageBuf turned = IBA::rotate270(upright);
        IBA::paste(image_, x - turned.spec().width / 2, y - turned.spec().height / 2, 0, 0, turned);
        return "";
    }

    std::vector<float> Downsampled(int width, int height) override {
        const OIIO::ImageBuf small =
            IBA::resize(image_, "box", 0.0f, OIIO::ROI(0, width, 0, height, 0, 1, 0, 3));
        std::vector<float> pixels(size_t(width) * height * 3);
        small.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT,
                         pixels.data());
        return pixels;
    }

  private:
    OIIO::ImageBuf image_;
};

}  // namespace

std::unique_ptr<PlotCanvas> NewOiioPlotCanvas(int width, int height) {
    return std::make_unique<OiioPlotCanvas>(width, height);
}

}  // namespace gonio
