#pragma once
// The angular (polar) plot of thesis fig. 3.4 and GPBRDFMap: the outgoing hemisphere for one
// light direction, seen from above, θ_out proportional to the distance from the centre, φ_out
// counter-clockwise from +x (to the right). Written with OpenImageIO (TIFF, PNG, EXR, ...).

#include <string>

#include "brdfsim/brdf.h"

namespace gonio {

enum class ColourMap { kNone, kGrey, kViridis, kHeat };

// Parses "none", "grey", "viridis", "heat"; throws std::invalid_argument.
ColourMap ParseColourMap(const std::string& text);

struct AngularMapOptions {
    int size = 256;
    double energyScale = 1.0;  // pixel value = f × energyScale (1 = white / top of the map)
    double thetaLight = 45.0, phiLight = 0.0;  // degrees
    ColourMap colourMap = ColourMap::kNone;    // none: the BRDF's components as RGB (or grey)
    bool scaleBar = false;  // a strip on the right running from 0 to 1/energyScale
};

struct AngularMapResult {
    double maxValue = 0.0;  // largest f on the map (first component)
};

// Throws std::runtime_error when the image cannot be written.
AngularMapResult WriteAngularMap(const Brdf& brdf, const AngularMapOptions& options,
                                 const std::string& path);

}  // namespace gonio
