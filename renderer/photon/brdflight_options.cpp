#include "renderer/photon/brdflight_options.h"

#include <filesystem>

namespace gonio {
namespace {

std::string ParamName(const std::string& token) {
    const size_t space = token.find_last_of(' ');
    return space == std::string::npos ? token : token.substr(space + 1);
}

}  // namespace

bool IsBrdfLightFrame(const Frame& frame) { return frame.options.user.count("BRDFLight") > 0; }

bool ReadBrdfLightOptions(const Frame& frame, Diagnostics& diagnostics, BrdfLightOptions* out) {
    BrdfLightOptions o;
    bool ok = true;
    const ParamList& params = frame.options.user.at("BRDFLight");
    if (!params.empty()) o.loc = params.front().loc;
    for (const Param& p : params) {
        const std::string name = ParamName(p.token);
        if (p.isString) {
            if (name == "texturename" && !p.strings.empty()) o.textureName = p.strings[0];
            continue;
        }
        if (p.numbers.empty()) continue;
        const double v = p.numbers[0];
        auto require = [&](bool good, const char* expected) {
            if (good) return;
            diagnostics.Error(p.loc, "Option \"BRDFLight\" \"" + name + "\": expected " + expected +
                                         ", got " + std::to_string(v));
            ok = false;
        };
        if (name == "rays") {
            require(v > 0, "a positive number of photon paths");
            o.rays = static_cast<int64_t>(v);
        } else if (name == "area") {
            require(v > 0, "a positive side length of the sampling area");
            o.area = static_cast<float>(v);
        } else if (name == "isotropic") {
            o.isotropic = v != 0;
        } else if (name == "averageazimuth") {
            o.averageAzimuth = v != 0;
        } else if (name == "seed") {
            require(v >= 0, "a non-negative seed");
            o.hasSeed = true;
            o.seed = static_cast<uint64_t>(v);
        } else if (name == "maxdepth") {
            require(v >= 1, "at least 1 bounce");
            o.maxDepth = static_cast<int>(v);
        } else if (name == "periodic") {
            o.periodic = v != 0;
        } else if (name == "thetamin") {
            require(v >= 0 && v < 90, "an angle in [0, 90) degrees");
            o.thetaMin = static_cast<float>(v);
        } else if (name == "thetamax") {
            require(v > 0 && v <= 90, "an angle in (0, 90] degrees");
            o.thetaMax = static_cast<float>(v);
        }
    }
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
