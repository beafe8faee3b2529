#pragma once
// Helpers the geometry builders share: reading positions from P or Pw, checking value counts
// per class, and copying primitive variables onto a TriangleMesh.

#include <optional>
#include <string>
#include <vector>

#include "renderer/geometry/shape.h"

namespace gonio {

// How many values each class of primitive variable must have on one primitive (RISpec §5 and
// rib_checklist.md §1). Constant is always 1.
struct ClassCounts {
    int uniform = 1;
    int varying = 1;
    int vertex = 1;
    int faceVarying = 1;
    int For(ParamClass cls) const;
};

const char* ClassName(ParamClass cls);

// P, Pw and Pz describe the position and never become MeshVars.
bool IsPositionVar(const std::string& name);

// An error message when some variable's value count disagrees with `counts`, else nullopt.
// The scene builder checks this too; the builders check again so that they can never read
// past an array.
std::optional<std::string> CheckCounts(const PrimVarSet& vars, const ClassCounts& counts);

// The control points from "P", or from "Pw" divided by w (RISpec: hpoints are homogeneous).
// nullopt and an error message when neither is present or w is 0.
std::optional<std::vector<V3f>> ReadPositions(const PrimVarSet& vars, std::string* error);

// The homogeneous control points (x·w, y·w, z·w, w) as a NURBS evaluator wants them: "Pw" as
// given, or "P" with w = 1. Empty when neither is present.
std::vector<float> ReadHomogeneousPositions(const PrimVarSet& vars);

// Copies a primitive variable with new values (same declaration and components).
PrimVar WithValues(const PrimVar& var, std::vector<float> values);

// The rate a constant or uniform variable keeps on a mesh (Constant or PerFace); the values
// are used as given.
MeshVar UnchangedMeshVar(const PrimVar& var);

}  // namespace gonio
