#pragma once
// RISpec §5.3 SubdivisionMesh as a Catmull-Clark control cage for Embree's subdivision
// geometry. Tags: "hole" (faces), "crease" (a chain of vertices and one sharpness, made into
// one crease edge per consecutive pair), "corner" (vertices with one sharpness each or one for
// all), "interpolateboundary". Other tags are skipped with a note in `notes`.

#include <string>
#include <vector>

#include "renderer/geometry/geometry_result.h"
#include "renderer/geometry/shape.h"

namespace gonio {

// scheme must be "catmull-clark". Vertex and varying variables have one value per "P",
// facevarying one per face corner, uniform one per face.
GeometryResult<SubdivisionCage> MakeSubdivisionMesh(
    const std::string& scheme, const std::vector<int>& nverts, const std::vector<int>& vertices,
    const std::vector<std::string>& tags, const std::vector<int>& nargs,
    const std::vector<int>& intargs, const std::vector<float>& floatargs, const PrimVarSet& vars,
    std::vector<std::string>* notes = nullptr);

}  // namespace gonio
