#include "shaderlang/runtime/ray_sampling.h"

#include <algorithm>
#include <cmath>

#include "base/hash.h"
#include "base/math.h"

namespace gonio::sl::builtins {

namespace {

float Uniform01(ShadingContext& context, int p) { return ToUnitFloat(context.NextRandomBits(p)); }

// An orthonormal basis about unit n without a branch on its direction (Duff et al. 2017,
// "Building an Orthonormal Basis, Revisited", JCGT 6(1), Listing 3).
void Basis(const V3& n, V3* b1, V3* b2) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    *b1 = V3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    *b2 = V3(b, sign + n.y * n.y * a, -n.y);
}

const FloatArg* Number(const BuiltinCall& call, int a) {
    return call.argTypes[a].base == BaseType::Float ? &call.args[a] : nullptr;
}

}  // namespace

RayOptions ReadRayOptions(const BuiltinCall& call, int first, const std::string& what) {
    RayOptions o;
    for (int a = first; a + 1 < call.argCount; a += 2) {
        if (call.argTypes[a].base != BaseType::String || !call.strings[a].data) continue;
        const std::string& name = call.strings[a].data[0];
        const int v = a + 1;
        const bool isString = call.argTypes[v].base == BaseType::String && call.strings[v].data;
        const std::string text = isString ? call.strings[v].data[0] : std::string();
        if (name == "maxdist" && Number(call, v)) {
            o.maxdist = Number(call, v);
        } else if (name == "bias" && Number(call, v)) {
            o.bias = Number(call, v);
        } else if (name == "coneangle" && Number(call, v)) {
            o.coneangle = Number(call, v);
        } else if (name == "samplebase" && Number(call, v)) {
            o.samplebase = Number(call, v);
        } else if (name == "samples" && Number(call, v)) {
            o.samples = Number(call, v);
        } else if (name == "samplecone" && Number(call, v)) {
            o.samplecone = Number(call, v);
        } else if (name == "distribution" && isString && (text == "cosine" || text == "uniform")) {
            o.cosine = text == "cosine";
        } else if (name == "environmentmap" && isString) {
            o.environmentMap = text;
        } else if (name == "environmentspace" && isString) {
            o.environmentSpace = text;
        } else if (name == "environmentcolor" && call.argTypes[v].base == BaseType::Color) {
            o.environmentColor = &call.args[v];
        } else if (name == "__outputs" && isString) {
            o.outputs = text;
        } else if (name == "__id") {
            // gather's loop id (compiler/gather_loop.h), read by builtins_gather.cpp.
        } else if (call.context) {
            call.context->RuntimeWarning(
                what + " option " + name,
                what + ": option \"" + name + "\" is not known (or has the wrong type); ignored");
        }
    }
    return o;
}

int SampleCount(const BuiltinCall& call, const FloatArg& samples) {
    for (int p = 0; p < call.n; ++p) {
        if (!call.IsActive(p)) continue;
        const float s = Float(samples, p);
        return std::isfinite(s) ? std::clamp(int(std::lround(s)), 1, 1 << 20) : 1;
    }
    return 1;
}

void ConeDirections(ShadingContext& context, int p, const V3& axis, float angle, bool cosine,
                    int count, std::vector<V3>* out) {
    out->resize(static_cast<size_t>(count));
    V3 b1, b2;
    Basis(axis, &b1, &b2);
    angle = std::clamp(std::isfinite(angle) ? angle : kHalfPiF, 0.0f, kHalfPiF);
    const float sinAngle = std::sin(angle), cosAngle = std::cos(angle);
    const int columns = std::max(1, int(std::sqrt(float(count)))), rows = count / columns;
    for (int k = 0; k < count; ++k) {
        float u1 = Uniform01(context, p), u2 = Uniform01(context, p);
        if (k < columns * rows) {
            u1 = (float(k % columns) + u1) / float(columns);
            u2 = (float(k / columns) + u2) / float(rows);
        }
        const float cosTheta = cosine ? std::sqrt(std::max(0.0f, 1 - u1 * sinAngle * sinAngle))
                                      : 1 - u1 * (1 - cosAngle);
        const float sinTheta = std::sqrt(std::max(0.0f, 1 - cosTheta * cosTheta));
        const float phi = kTwoPiF * u2;
        (*out)[k] = (b1 * std::cos(phi) + b2 * std::sin(phi)) * sinTheta + axis * cosTheta;
    }
}

V3 JitterOrigin(ShadingContext& context, int p, const V3& origin, const V3& axis, float radius) {
    if (!(radius > 0)) return origin;
    V3 b1, b2;
    Basis(axis, &b1, &b2);
    const float r = radius * std::sqrt(Uniform01(context, p));
    const float phi = kTwoPiF * Uniform01(context, p);
    return origin + (b1 * std::cos(phi) + b2 * std::sin(phi)) * r;
}

std::vector<int> MainActivePoints(const BuiltinCall& call) {
    const int main = call.context ? std::clamp(call.context->MainPointCount(), 1, call.n) : call.n;
    std::vector<int> points;
    for (int p = 0; p < main; ++p) {
        bool any = false;
        for (int copy = p; copy < call.n; copy += main) any = any || call.IsActive(copy);
        if (any) points.push_back(p);
    }
    return points;
}

void CopyToNeighbours(const BuiltinCall& call, const FloatArg& out, int p) {
    if (!out.varying || !call.context) return;
    const int main = std::clamp(call.context->MainPointCount(), 1, call.n);
    for (int copy = p + main; copy < call.n; copy += main) {
        if (!call.IsActive(copy)) continue;
        for (int c = 0; c < out.width; ++c) out.At(c, copy) = out.At(c, p);
    }
}

RayBatch::RayBatch(ShadingContext& context, std::string what, SampledRays::Kind kind, Done done)
    : context_(context), what_(std::move(what)), kind_(kind), done_(std::move(done)) {}

void RayBatch::Add(int point, const V3& org, const V3& dir, float maxdist, float bias) {
    for (int c = 0; c < 3; ++c) org_.push_back(org[c]), dir_.push_back(dir[c]);
    point_.push_back(point), maxdist_.push_back(maxdist), bias_.push_back(bias);
    // Bounded chunks: a shaded ray keeps a whole surface point while its hit is shaded.
    constexpr size_t kChunkRays = 8192;
    if (point_.size() >= kChunkRays) Flush();
}

void RayBatch::Flush() {
    const int count = int(point_.size());
    if (count == 0) return;
    // Component-major planes, as every per-point array of the interface is.
    std::vector<float> org(3 * size_t(count)), dir(3 * size_t(count));
    for (int k = 0; k < count; ++k)
        for (int c = 0; c < 3; ++c) {
            org[size_t(c) * count + k] = org_[3 * size_t(k) + c];
            dir[size_t(c) * count + k] = dir_[3 * size_t(k) + c];
        }
    SampledRays rays;
    rays.kind = kind_;
    rays.count = count;
    rays.org = org.data(), rays.dir = dir.data(), rays.point = point_.data();
    rays.maxdist = maxdist_.data(), rays.bias = bias_.data();
    SampledHits hits;
    if (traced_) traced_ = context_.TraceSampledRays(what_, rays, &hits);
    if (!traced_) {
        const int nc = context_.ColorComponents();
        hits.hit.assign(size_t(count), 0), hits.t.assign(size_t(count), 0);
        hits.P.assign(3 * size_t(count), 0), hits.N.assign(3 * size_t(count), 0);
        hits.colour.assign(size_t(nc) * count, 0.0f);
    }
    for (int k = 0; k < count; ++k)
        done_(point_[k], V3(dir_[3 * size_t(k)], dir_[3 * size_t(k) + 1], dir_[3 * size_t(k) + 2]),
              k, hits);
    org_.clear(), dir_.clear(), point_.clear(), maxdist_.clear(), bias_.clear();
}

void SumEnvironment(ShadingContext& context, const RayOptions& options,
                    const std::vector<std::vector<V3>>& dirs, int ncomps, std::vector<float>* sum) {
    if (options.environmentMap.empty()) return;
    const int n = context.PointCount();
    // The inverse of each point's current-from-environmentspace matrix, once per point.
    std::vector<M44> spaceFromCurrent(static_cast<size_t>(n));
    size_t rounds = 0;
    for (int p = 0; p < n && size_t(p) < dirs.size(); ++p) {
        rounds = std::max(rounds, dirs[p].size());
        M44 currentFromSpace;
        if (!dirs[p].empty() &&
            context.CurrentFromSpace(options.environmentSpace, p, &currentFromSpace))
            spaceFromCurrent[p] = currentFromSpace.inverse();
    }
    // One lookup of the whole batch per round: round r looks up each point's r-th direction.
    std::vector<float> planes(3 * size_t(n), 0.0f), colour(size_t(ncomps) * n);
    std::vector<uint8_t> active(static_cast<size_t>(n));
    for (size_t r = 0; r < rounds; ++r) {
        std::fill(active.begin(), active.end(), 0);
        for (int p = 0; p < n && size_t(p) < dirs.size(); ++p) {
            if (dirs[p].size() <= r) continue;
            V3 d;
            spaceFromCurrent[p].multDirMatrix(dirs[p][r], d);
            for (int c = 0; c < 3; ++c) planes[size_t(c) * n + p] = d[c];
            active[p] = 1;
        }
        std::fill(colour.begin(), colour.end(), 0.0f);
        context.Environment(options.environmentMap, 0, ncomps, planes.data(), active.data(),
                            colour.data());
        for (int p = 0; p < n; ++p)
            if (active[p])
                for (int c = 0; c < ncomps; ++c)
                    (*sum)[size_t(c) * n + p] += colour[size_t(c) * n + p];
    }
}

}  // namespace gonio::sl::builtins
