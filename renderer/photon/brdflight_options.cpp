#include "renderer/photon/brdflight_options.h"

#include <algorithm>
#include <filesystem>
#include <string>

namespace gonio {
namespace {

// Reads the numeric BRDFLight parameter `name` when it is given: false (after an error at its
// location) when it fails `good`, which `expected` describes.
template <typename Good>
bool ReadNumber(const ParamDict& params, const char* name, Good good, const char* expected,
                Diagnostics& diagnostics, double* value) {
    const TypedParam* p = params.Find(name);
    if (!p || p->numbers.empty()) return true;
    *value = p->numbers[0];
    if (good(*value)) return true;
    diagnostics.Error(params.Location(name), std::string("Option \"BRDFLight\" \"") + name +
                                                 "\": expected " + expected + ", got " +
                                                 FormatNumber(*value));
    return false;
}

}  // namespace

bool IsBrdfLightFrame(const Frame& frame) { return frame.options.user.count("BRDFLight") > 0; }

bool ReadBrdfLightOptions(const Frame& frame, Diagnostics& diagnostics, BrdfLightOptions* out) {
    BrdfLightOptions o;
    const ParamDict& params = frame.options.user.at("BRDFLight");
    o.loc = params.FirstLocation();
    o.textureName = params.GetString("texturename", "");
    o.isotropic = params.GetNumber("isotropic", 0) != 0;
    o.averageAzimuth = params.GetNumber("averageazimuth", 0) != 0;
    o.periodic = params.GetNumber("periodic", 0) != 0;
    o.bounces = params.GetNumber("bounces", 0) != 0;
    double rays = double(o.rays), area = o.area, seed = -1, maxDepth = o.maxDepth;
    double thetaMin = o.thetaMin, thetaMax = o.thetaMax;
    bool ok = ReadNumber(
        params, "rays", [](double v) { return v > 0; }, "a positive number of photon paths",
        diagnostics, &rays);
    ok &= ReadNumber(
        params, "area", [](double v) { return v > 0; },
        "a positive side length of the sampling area", diagnostics, &area);
    ok &= ReadNumber(
        params, "seed", [](double v) { return v >= 0; }, "a non-negative seed", diagnostics, &seed);
    ok &= ReadNumber(
        params, "maxdepth", [](double v) { return v >= 1; }, "at least 1 bounce", diagnostics,
        &maxDepth);
    ok &= ReadNumber(
        params, "thetamin", [](double v) { return v >= 0 && v < 90; },
        "an angle in [0, 90) degrees", diagnostics, &thetaMin);
    ok &= ReadNumber(
        params, "thetamax", [](double v) { return v > 0 && v <= 90; },
        "an angle in (0, 90] degrees", diagnostics, &thetaMax);
    o.rays = static_cast<int64_t>(rays);
    o.area = static_cast<float>(area);
    o.hasSeed = params.Has("seed");
    if (o.hasSeed) o.seed = static_cast<uint64_t>(std::max(0.0, seed));
    o.maxDepth = static_cast<int>(maxDepth);
    o.thetaMin = static_cast<float>(thetaMin);
    o.thetaMax = static_cast<float>(thetaMax);
    if (ok && o.thetaMin >= o.thetaMax) {
        diagnostics.Error(o.loc, "Option \"BRDFLight\": expected thetamin (" +
                                     std::to_string(o.thetaMin) + ") below thetamax (" +
                                     std::to_string(o.thetaMax) + ")");
        ok = false;
    }
    if (o.textureName.empty()) {
        std::string stem = std::filesystem::path(frame.sceneFile).stem().string();
        if (stem.empty() || stem == "-") stem = "gonio";
        o.textureName = stem + ".pm";
        diagnostics.NoteOnce(
            "brdflight texturename", o.loc,
            "Option \"BRDFLight\" names no \"texturename\": writing " + o.textureName);
    }
    *out = o;
    return ok;
}

}  // namespace gonio
