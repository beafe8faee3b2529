#pragma once
// Shared helpers of the photon tracer tests: trace a RIB world in memory, and bin the photons.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "base/math.h"
#include "brdfsim/photon_map.h"
#include "renderer/photon/photon_tracer.h"
#include "renderer/raytrace/ray_scene.h"
#include "renderer/rib/rib_parser.h"
#include "renderer/scene/scene_builder.h"

namespace gonio::test {

inline std::string ReadRib(const std::string& name) {
    std::ifstream in(std::string(GONIO_RIBS_DIR) + "/" + name);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The frame of a RIB text (options, WorldBegin ... WorldEnd).
inline Frame ParseFrame(const std::string& rib) {
    Diagnostics diagnostics;
    Frame frame;
    bool got = false;
    SceneBuilder builder("test.rib", diagnostics, [&](const Frame& f) {
        frame = f;
        got = true;
    });
    ParseRibString(rib, "test.rib", builder, diagnostics);
    builder.Finish(FileLoc{});
    EXPECT_TRUE(got);
    EXPECT_EQ(diagnostics.ErrorCount(), 0);
    return frame;
}

inline PhotonTraceResult TraceFrame(const Frame& frame, const PhotonTraceSettings& settings) {
    Diagnostics diagnostics;
    const RayScene scene(frame, diagnostics, RayScene::Traversal::kFast);  // as BRDFLight does
    return TracePhotons(frame, scene, BuildMicroBrdfTable(frame, diagnostics), settings);
}

inline PhotonTraceResult TraceRib(const std::string& rib, const PhotonTraceSettings& settings) {
    return TraceFrame(ParseFrame(rib), settings);
}

inline std::string World(const std::string& body) { return "WorldBegin\n" + body + "\nWorldEnd\n"; }

inline std::string Square(double half, double z = 0) {
    std::ostringstream s;
    s << "Polygon \"P\" [" << -half << " " << -half << " " << z << "  " << half << " " << -half
      << " " << z << "  " << half << " " << half << " " << z << "  " << -half << " " << half << " "
      << z << "]\n";
    return s.str();
}

inline PhotonMap ToPhotonMap(const PhotonTraceResult& result) {
    PhotonMap map;
    map.ncomps = result.ncomps;
    map.paths = result.stats.paths;
    map.rows = result.rows;
    return map;
}

inline int Stride(const PhotonTraceResult& r) { return kFirstColour + r.ncomps; }

inline Imath::V3d Direction(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// Per-path means and standard errors of a weighted indicator over the photons of a run:
// X_b = Σ_k w_k 1[photon k in bin b] / N, the estimate of E[w 1_b] per traced path.
struct BinnedEstimate {
    std::vector<double> mean, sigma;  // sigma: standard error of the mean
};

inline BinnedEstimate Bin(const PhotonTraceResult& r, int bins,
                          const std::function<int(const float* row)>& binOf,
                          const std::function<double(const float* row)>& weight) {
    std::vector<double> sum(bins, 0.0), sum2(bins, 0.0);
    const size_t n = r.rows.size() / Stride(r);
    for (size_t i = 0; i < n; ++i) {
        const float* row = r.rows.data() + i * Stride(r);
        const int b = binOf(row);
        if (b < 0) continue;
        const double w = weight(row);
        sum[b] += w;
        sum2[b] += w * w;
    }
    BinnedEstimate e;
    const double paths = static_cast<double>(r.stats.paths);
    for (int b = 0; b < bins; ++b) {
        const double mean = sum[b] / paths;
        e.mean.push_back(mean);
        e.sigma.push_back(std::sqrt(std::max(0.0, sum2[b] / paths - mean * mean) / paths));
    }
    return e;
}

// The upper quantile of χ² with k degrees of freedom at a tail probability whose standard
// normal quantile is z (Wilson-Hilferty, accurate to a few per cent for k >= 10).
inline double ChiSquareQuantile(int k, double z) {
    const double a = 2.0 / (9.0 * k);
    return k * std::pow(1 - a + z * std::sqrt(a), 3);
}

}  // namespace gonio::test
