#include "renderer/scene/standard_options.h"

namespace gonio {
namespace {

struct StandardParam {
    const char* request;  // "Option", "Attribute" or "Display"
    const char* name;
    const char* token;
    const char* declaration;
};

constexpr StandardParam kStandardParams[] = {
    {"Option", "searchpath", "shader", "uniform string"},
    {"Option", "searchpath", "texture", "uniform string"},
    {"Option", "searchpath", "archive", "uniform string"},
    {"Option", "searchpath", "procedural", "uniform string"},
    {"Option", "searchpath", "display", "uniform string"},
    {"Option", "searchpath", "resource", "uniform string"},
    {"Option", "statistics", "endofframe", "uniform integer"},
    {"Option", "statistics", "filename", "uniform string"},
    {"Option", "statistics", "xmlfilename", "uniform string"},
    {"Option", "limits", "bucketsize", "uniform integer[2]"},
    {"Option", "limits", "gridsize", "uniform integer"},
    {"Option", "limits", "shadertimeout", "uniform float"},
    {"Option", "limits", "proceduraltimeout", "uniform float"},
    {"Option", "limits", "eyesplits", "uniform integer"},
    {"Option", "limits", "texturememory", "uniform integer"},
    {"Option", "limits", "othreshold", "uniform color"},
    {"Option", "limits", "zthreshold", "uniform color"},
    {"Option", "trace", "maxdepth", "uniform integer"},
    {"Option", "pathtrace", "enable", "uniform integer"},
    {"Option", "pathtrace", "maxdepth", "uniform integer"},
    {"Option", "pathtrace", "rrdepth", "uniform integer"},
    {"Option", "render", "bucketorder", "uniform string"},
    {"Option", "BRDFLight", "texturename", "uniform string"},
    {"Option", "BRDFLight", "rays", "uniform integer"},
    {"Option", "BRDFLight", "area", "uniform float"},
    {"Option", "BRDFLight", "isotropic", "uniform integer"},
    {"Option", "BRDFLight", "seed", "uniform integer"},
    {"Option", "BRDFLight", "maxdepth", "uniform integer"},
    {"Option", "BRDFLight", "periodic", "uniform integer"},
    {"Option", "BRDFLight", "thetamin", "uniform float"},
    {"Option", "BRDFLight", "thetamax", "uniform float"},
    {"Option", "BRDFLight", "averageazimuth", "uniform integer"},
    {"Attribute", "identifier", "name", "uniform string"},
    {"Attribute", "light", "shadows", "uniform string"},
    {"Attribute", "light", "nsamples", "uniform integer"},
    {"Attribute", "displacementbound", "sphere", "uniform float"},
    {"Attribute", "displacementbound", "coordinatesystem", "uniform string"},
    {"Attribute", "trimcurve", "sense", "uniform string"},
    {"Attribute", "dice", "binary", "uniform integer"},
    {"Attribute", "sides", "doubleshaded", "uniform integer"},
    {"Attribute", "visibility", "camera", "uniform integer"},
    {"Attribute", "visibility", "trace", "uniform integer"},
    {"Attribute", "visibility", "transmission", "uniform string"},
    {"Attribute", "visibility", "photon", "uniform integer"},
    {"Attribute", "render", "visibility", "uniform integer"},
    {"Attribute", "trace", "bias", "uniform float"},
    {"Attribute", "trace", "maxdiffusedepth", "uniform integer"},
    {"Attribute", "trace", "maxspeculardepth", "uniform integer"},
    {"Attribute", "trace", "displacements", "uniform integer"},
    {"Attribute", "brdflight", "kd", "uniform float"},
    {"Attribute", "brdflight", "ks", "uniform float"},
    {"Attribute", "brdflight", "exponent", "uniform float"},
    {"Option", "spectral", "basis", "uniform string"},
    {"Option", "spectral", "range", "uniform float[2]"},
    {"Option", "spectral", "step", "uniform float"},
    {"Option", "spectral", "bands", "uniform integer"},
    {"Option", "spectral", "vectors", "uniform integer"},
    {"Attribute", "spectral", "color", "uniform string"},
    {"Attribute", "spectral", "opacity", "uniform string"},
    // Display driver parameters (image_writer.h); the request has no name of its own.
    {"Display", "", "compression", "uniform string"},
    {"Display", "", "exrpixeltype", "uniform string"},
};

constexpr const char* kOtherKnownOptions[] = {"hider", "shading", "shutter", "user"};
constexpr const char* kOtherKnownAttributes[] = {"shade", "user",       "stochastic", "grouping",
                                                 "cull",  "irradiance", "photon",     "autobias"};

}  // namespace

std::string StandardParamDeclaration(const std::string& request, const std::string& name,
                                     const std::string& token) {
    for (const StandardParam& p : kStandardParams)
        if (request == p.request && name == p.name && token == p.token) return p.declaration;
    return "";
}

bool IsKnownOptionName(bool isOption, const std::string& name) {
    const char* request = isOption ? "Option" : "Attribute";
    for (const StandardParam& p : kStandardParams)
        if (request == std::string(p.request) && name == p.name) return true;
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
