#include "renderer/geometry/subdivision.h"

#include "renderer/geometry/primvar_eval.h"

namespace gonio {
namespace {

// One tag's integer and float arguments.
struct TagArgs {
    const int* ints;
    int intCount;
    const float* floats;
    int floatCount;
};

std::optional<std::string> ApplyTag(const std::string& tag, const TagArgs& a, int faceCount,
                                    int pointCount, SubdivisionCage* cage,
                                    std::vector<std::string>* notes) {
    auto checkVertices = [&]() -> std::optional<std::string> {
        for (int i = 0; i < a.intCount; ++i)
            if (a.ints[i] < 0 || a.ints[i] >= pointCount)
                return "\"" + tag + "\" tag: vertex " + std::to_string(a.ints[i]) +
                       " is out of range (P has " + std::to_string(pointCount) + " values)";
        return std::nullopt;
    };
    if (tag == "interpolateboundary") {
        cage->interpolateBoundary = a.intCount == 0 || a.ints[0] != 0;
    } else if (tag == "hole") {
        for (int i = 0; i < a.intCount; ++i) {
            if (a.ints[i] < 0 || a.ints[i] >= faceCount)
                return "\"hole\" tag: face " + std::to_string(a.ints[i]) + " is out of range";
            cage->holeFaces.push_back(static_cast<uint32_t>(a.ints[i]));
        }
    } else if (tag == "crease") {
        if (a.intCount < 2 || a.floatCount != 1)
            return std::string("\"crease\" tag needs at least 2 vertices and 1 sharpness");
        if (auto bad = checkVertices()) return bad;
        for (int i = 0; i + 1 < a.intCount; ++i) {
            cage->creaseEdges.push_back(static_cast<uint32_t>(a.ints[i]));
            cage->creaseEdges.push_back(static_cast<uint32_t>(a.ints[i + 1]));
            cage->creaseWeights.push_back(a.floats[0]);
        }
    } else if (tag == "corner") {
        if (a.floatCount != 1 && a.floatCount != a.intCount)
            return "\"corner\" tag needs 1 sharpness or one per vertex, got " +
                   std::to_string(a.floatCount);
        if (auto bad = checkVertices()) return bad;
        for (int i = 0; i < a.intCount; ++i) {
            cage->cornerVertices.push_back(static_cast<uint32_t>(a.ints[i]));
            cage->cornerWeights.push_back(a.floats[a.floatCount == 1 ? 0 : i]);
        }
    } else if (notes) {
        notes->push_back("SubdivisionMesh tag \"" + tag + "\" is not supported and was ignored");
    }
    return std::nullopt;
}

}  // namespace

GeometryResult<SubdivisionCage> MakeSubdivisionMesh(
    const std::string& scheme, const std::vector<int>& nverts, const std::vector<int>& vertices,
    const std::vector<std::string>& tags, const std::vector<int>& nargs,
    const std::vector<int>& intargs, const std::vector<float>& floatargs, const PrimVarSet& vars,
    std::vector<std::string>* notes) {
    using Result = GeometryResult<SubdivisionCage>;
    if (scheme != "catmull-clark")
        return Result::Error("subdivision scheme \"" + scheme +
                             "\" is not supported (only \"catmull-clark\")");
    std::string error;
    auto positions = ReadPositions(vars, &error);
    if (!positions) return Result::Error(error);
    const int pointCount = static_cast<int>(positions->size());

    size_t corners = 0;
    for (int n : nverts) {
        if (n < 3)
            return Result::Error("every face needs at least 3 vertices, got " + std::to_string(n));
        corners += n;
    }
    if (corners != vertices.size())
        return Result::Error("the faces have " + std::to_string(corners) + " vertices in all but " +
                             std::to_string(vertices.size()) + " vertex indices were given");
    for (int v : vertices)
        if (v < 0 || v >= pointCount)
            return Result::Error("vertex index " + std::to_string(v) + " is out of range (P has " +
                                 std::to_string(pointCount) + " values)");
    const int faceCount = static_cast<int>(nverts.size());
    const ClassCounts counts{faceCount, pointCount, pointCount, static_cast<int>(corners)};
    if (auto bad = CheckCounts(vars, counts)) return Result::Error(*bad);

    SubdivisionCage cage;
    cage.positions = std::move(*positions);
    cage.faceVertexCounts.assign(nverts.begin(), nverts.end());
    cage.indices.assign(vertices.begin(), vertices.end());

    if (nargs.size() != 2 * tags.size())
        return Result::Error("nargs needs 2 numbers per tag (" + std::to_string(2 * tags.size()) +
                             "), got " + std::to_string(nargs.size()));
    size_t intPos = 0, floatPos = 0;
    for (size_t t = 0; t < tags.size(); ++t) {
        const int ni = nargs[2 * t], nf = nargs[2 * t + 1];
        if (ni < 0 || nf < 0 || intPos + ni > intargs.size() || floatPos + nf > floatargs.size())
            return Result::Error("tag \"" + tags[t] + "\" asks for more arguments than given");
        const TagArgs args{intargs.data() + intPos, ni, floatargs.data() + floatPos, nf};
        if (auto bad = ApplyTag(tags[t], args, faceCount, pointCount, &cage, notes))
            return Result::Error(*bad);
        intPos += ni;
        floatPos += nf;
    }
    if (intPos != intargs.size() || floatPos != floatargs.size())
        return Result::Error("the tags use " + std::to_string(intPos) + " integer and " +
                             std::to_string(floatPos) + " float arguments, but " +
                             std::to_string(intargs.size()) + " and " +
                             std::to_string(floatargs.size()) + " were given");
    for (const PrimVar& var : vars.vars)
        if (!IsPositionVar(var.decl.name)) cage.vars.vars.push_back(var);
    return cage;
}

}  // namespace gonio
