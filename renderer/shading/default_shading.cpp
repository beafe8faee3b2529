#include <cmath>

#include "renderer/shading/surface_shading.h"

namespace gonio {
namespace {

class DefaultWorker : public ShadingWorker {
  public:
    explicit DefaultWorker(int ncomps) : ncomps_(ncomps) {}

    void Shade(const ShadingBatch& batch, float* Ci, float* Oi) override {
        for (size_t i = 0; i < batch.points.size(); ++i) {
            const SurfacePoint& sp = *batch.points[i];
            const float facing = std::fabs(sp.N.dot(batch.incident[i].normalized()));
            for (int c = 0; c < ncomps_; ++c) {
                Oi[i * ncomps_ + c] = sp.Os[c];
                Ci[i * ncomps_ + c] = sp.Os[c] * sp.Cs[c] * (0.2f + 0.8f * facing * facing);
            }
        }
    }

  private:
    int ncomps_;
};

class DefaultShading : public SurfaceShading {
  public:
    explicit DefaultShading(int ncomps) : ncomps_(ncomps) {}
    std::unique_ptr<ShadingWorker> MakeWorker() const override {
        return std::make_unique<DefaultWorker>(ncomps_);
    }

  private:
    int ncomps_;
};

}  // namespace

std::unique_ptr<SurfaceShading> MakeDefaultSurfaceShading(int colorComponents) {
    return std::make_unique<DefaultShading>(colorComponents);
}

}  // namespace gonio
