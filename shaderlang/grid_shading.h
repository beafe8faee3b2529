#pragma once
// Shading without a scene, as OSL's testshade does: a shader run over a W × H grid of points
// with simple globals, its outputs collected over the whole grid. `gonio shade` is this plus
// printing and an image; tests and benchmarks call it directly.
//
// Point (x, y) has u = s = (x + ½)/W, v = t = (y + ½)/H, P = (u, v, 0), N = Ng = (0, 0, −1),
// I = (0, 0, 1), dPdu = (1, 0, 0), dPdv = (0, 1, 0), du = 1/W, dv = 1/H, E = (0, 0, −1); its
// neighbours for derivatives are the next point along x and along y.

#include <map>
#include <string>
#include <vector>

#include "shaderlang/shading_system.h"
#include "shaderlang/simple_context.h"

namespace gonio::sl {

// One output over the grid: width planes of W·H floats (varying) or width floats (uniform), or
// a string.
struct GridOutput {
    std::vector<float> values;
    int width = 0;
    bool varying = false;
    bool found = false;  // a numeric output of that name exists
    std::string text;    // a string output's value

    // Component `comp` (clamped to the last) at point i; 0 when there is no such output.
    float At(int comp, int i, int total) const;
};

// Runs `instance` over the grid (the lights are those of `context`) and collects the globals,
// parameters or top-level variables `names` (call KeepVariables on the instance first to read
// variables of its body).
std::map<std::string, GridOutput> ShadeGrid(ShaderInstance& instance, int width, int height,
                                            const std::vector<std::string>& names,
                                            SimpleShadingContext& context);

// Sets a parameter from "name=value" text: numbers separated by commas (one number fills a
// whole colour or point, or the diagonal of a matrix), or the text of a string parameter
// (comma-separated for a string array). False with *error saying why.
bool SetParameterFromText(ShaderInstance& instance, const std::string& assignment,
                          std::string* error);

}  // namespace gonio::sl
