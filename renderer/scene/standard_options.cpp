#include "renderer/scene/standard_options.h"

namespace gonio {
namespace {

struct StandardParam {
    bool isOption;
    const char* name;
    const char* token;
    const char* declaration;
};

constexpr StandardParam kStandardParams[] = {
    {true, "searchpath", "shader", "uniform string"},
    {true, "searchpath", "texture", "uniform string"},
    {true, "searchpath", "archive", "uniform string"},
    {true, "searchpath", "procedural", "uniform string"},
    {true, "searchpath", "display", "uniform string"},
    {true, "searchpath", "resource", "uniform string"},
    {true, "statistics", "endofframe", "uniform integer"},
    {true, "statistics", "filename", "uniform string"},
    {true, "statistics", "xmlfilename", "uniform string"},
    {true, "limits", "bucketsize", "uniform integer[2]"},
    {true, "limits", "gridsize", "uniform integer"},
    {true, "limits", "eyesplits", "uniform integer"},
    {true, "limits", "texturememory", "uniform integer"},
    {true, "limits", "othreshold", "uniform color"},
    {true, "limits", "zthreshold", "uniform color"},
    {true, "trace", "maxdepth", "uniform integer"},
    {true, "render", "bucketorder", "uniform string"},
    {true, "BRDFLight", "texturename", "uniform string"},
    {true, "BRDFLight", "rays", "uniform integer"},
    {true, "BRDFLight", "area", "uniform float"},
    {true, "BRDFLight", "isotropic", "uniform integer"},
    {true, "BRDFLight", "seed", "uniform integer"},
    {true, "BRDFLight", "maxdepth", "uniform integer"},
    {true, "BRDFLight", "periodic", "uniform integer"},
    {true, "BRDFLight", "thetamin", "uniform float"},
    {true, "BRDFLight", "thetamax", "uniform float"},
    {true, "BRDFLight", "averageazimuth", "uniform integer"},
    {false, "identifier", "name", "uniform string"},
    {false, "light", "shadows", "uniform string"},
    {false, "displacementbound", "sphere", "uniform float"},
    {false, "displacementbound", "coordinatesystem", "uniform string"},
    {false, "trimcurve", "sense", "uniform string"},
    {false, "dice", "binary", "uniform integer"},
    {false, "sides", "doubleshaded", "uniform integer"},
    {false, "visibility", "camera", "uniform integer"},
    {false, "visibility", "trace", "uniform integer"},
    {false, "visibility", "transmission", "uniform string"},
    {false, "visibility", "photon", "uniform integer"},
    {false, "render", "visibility", "uniform integer"},
    {false, "trace", "bias", "uniform float"},
    {false, "trace", "maxdiffusedepth", "uniform integer"},
    {false, "trace", "maxspeculardepth", "uniform integer"},
    {false, "trace", "displacements", "uniform integer"},
    {false, "brdflight", "kd", "uniform float"},
    {false, "brdflight", "ks", "uniform float"},
    {false, "brdflight", "exponent", "uniform float"},
};

constexpr const char* kOtherKnownOptions[] = {"hider", "shading", "shutter", "user"};
constexpr const char* kOtherKnownAttributes[] = {"shade", "user",       "stochastic", "grouping",
                                                 "cull",  "irradiance", "photon",     "autobias"};

}  // namespace

std::string StandardParamDeclaration(bool isOption, const std::string& name,
                                     const std::string& token) {
    for (const StandardParam& p : kStandardParams)
        if (p.isOption == isOption && name == p.name && token == p.token) return p.declaration;
    return "";
}

bool IsKnownOptionName(bool isOption, const std::string& name) {
    for (const StandardParam& p : kStandardParams)
        if (p.isOption == isOption && name == p.name) return true;
    if (isOption) {
        for (const char* other : kOtherKnownOptions)
            if (name == other) return true;
    } else {
        for (const char* other : kOtherKnownAttributes)
            if (name == other) return true;
    }
    return false;
}

}  // namespace gonio
