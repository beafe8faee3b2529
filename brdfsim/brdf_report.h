#pragma once
// What `gonio brdf info` prints: photon-map statistics, and for a .grd its parameters, the grid's
// splats per cell (thesis Table 4.1), memory, albedo at a few incident angles and the
// reciprocity error.

#include <cstdio>
#include <string>
#include <vector>

#include "brdfsim/brdf.h"
#include "brdfsim/grd_file.h"

namespace gonio {

struct PhotonMapSummary {
    std::uint64_t photons = 0, paths = 0;
    int ncomps = 0;
    bool allPhiInZero = true;  // an isotropic (GPIBRDFOpt) map
    double thetaInMin = 1e9, thetaInMax = -1e9;
    std::vector<double> energyPerPath;  // (1/N) Σ β / p_in
};

// Streams the file: maps larger than memory are fine.
PhotonMapSummary SummarizePhotonMap(const std::string& path);
void PrintPhotonMapInfo(const std::string& path, const PhotonMapSummary& summary, std::FILE* out);

// The photons' escaped energy at incidence wIn, (1/N) Σ β/p smoothed over the incoming side by
// the splat kernel with ω integrated out (reflect mode): what ∫ f cos θ dω must equal wherever
// cos θ_out varies little over a splat.
std::vector<double> PhotonEnergyAt(const SplatSet& splats, const Imath::V3f& wIn);

// Mean |f(a→b) − f(b→a)| over mean f, for `pairs` random direction pairs up to 80°.
double ReciprocityError(const Brdf& brdf, int pairs);

void PrintGrdInfo(const std::string& path, const GrdFile& file, std::FILE* out);

// The grid a .pm is given when none is named: about one splat radius per cell.
void DefaultGridFor(double radius, int* rings, int* rects);

}  // namespace gonio
