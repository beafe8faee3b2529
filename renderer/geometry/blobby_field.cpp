#include "renderer/geometry/blobby_field.h"

#include <Imath/ImathMatrixAlgo.h>

#include <algorithm>
#include <cmath>

namespace gonio {

namespace {

using Op = BlobbyInstruction::Op;
using Kind = BlobbyLeaf::Kind;

// M's 3×3 part times the column vector v: the chain rule through q = P·M, whose Jacobian
// ∂q_j/∂P_i is M[i][j].
V3f LinearTimesColumn(const M44f& m, const V3f& v) {
    return V3f(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
               m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
               m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z);
}

// Application Note #31's field of the squared blob-space distance s = r²: (1 − s)³ for s < 1.
// `gradientS` is ∇s; the result's gradient is f'(s)·∇s.
FieldSample SphereFalloff(float s, const V3f& gradientS) {
    if (s >= 1) return {};
    const float a = 1 - s;
    return {a * a * a, -3 * a * a * gradientS};
}

// Application Note #31, repelling plane: bump(r) is the polynomial of lowest degree with
// bump(0) = bump'(0) = bump''(0) = 0, bump(1) = 1, bump(2) = bump'(2) = bump''(2) = 0, zero
// outside (0, 2): bump = 8r³ − 12r⁴ + 6r⁵ − r⁶. Returns bump and its derivative.
void Bump(float r, float* value, float* slope) {
    if (r <= 0 || r >= 2) {
        *value = *slope = 0;
        return;
    }
    *value = (((6 - r) * r - 12) * r + 8) * r * r * r;
    *slope = (((-6 * r + 30) * r - 48) * r + 24) * r * r;
}

// ease(r) = 3r² − 2r³ on [0, 1] (ease(0) = ease'(0) = 0, ease(1) = 1, ease'(1) = 0).
void Ease(float r, float* value, float* slope) {
    if (r <= 0 || r >= 1) {
        *value = r <= 0 ? 0.f : 1.f;
        *slope = 0;
        return;
    }
    *value = r * r * (3 - 2 * r);
    *slope = 6 * r * (1 - r);
}

// (D·bump(z/C) − B/z)·(1 − ease(z/A)) of the height z, and its derivative in z.
FieldSample Repulsion(const BlobbyLeaf& leaf, float z) {
    constexpr float kZClamp = 1e-6f;  // Application Note #31's ZCLAMP
    if (z >= leaf.A) return {};
    const bool clamped = z <= kZClamp;
    z = std::max(z, kZClamp);
    float bump, bumpSlope, ease, easeSlope;
    Bump(z / leaf.C, &bump, &bumpSlope);
    Ease(z / leaf.A, &ease, &easeSlope);
    const float near = leaf.D * bump - leaf.B / z;
    const float nearSlope = leaf.D * bumpSlope / leaf.C + leaf.B / (z * z);
    const float value = near * (1 - ease);
    const float slope = clamped ? 0.f : nearSlope * (1 - ease) - near * easeSlope / leaf.A;
    return {value, V3f(0, 0, slope)};
}

// The point of the segment [a, b] nearest q.
V3f NearestOnSegment(const V3f& q, const V3f& a, const V3f& b) {
    const V3f ab = b - a;
    const float length2 = ab.length2();
    const float t = length2 > 0 ? std::clamp((q - a).dot(ab) / length2, 0.f, 1.f) : 0.f;
    return a + t * ab;
}

// The smallest singular value of m's 3×3 part: the shortest semi-axis of the unit sphere's
// image.
float SmallestScale(const M44f& m) {
    Imath::M33d aat;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double sum = 0;
            for (int k = 0; k < 3; ++k) sum += double(m[i][k]) * m[j][k];
            aat[i][j] = sum;
        }
    Imath::V3d eigen;
    Imath::M33d vectors;
    Imath::jacobiEigenSolver(aat, eigen, vectors);
    return static_cast<float>(std::sqrt(std::max(0.0, std::min({eigen.x, eigen.y, eigen.z}))));
}

// Combines the operand samples of one operation (RISpec 3.2 §5.6, Table 5.3).
FieldSample Combine(const BlobbyInstruction& in, const std::vector<FieldSample>& at) {
    const FieldSample& first = at[in.operands[0]];
    FieldSample out = first;
    switch (in.op) {
        case Op::Add:
            for (size_t k = 1; k < in.operands.size(); ++k) {
                out.value += at[in.operands[k]].value;
                out.gradient += at[in.operands[k]].gradient;
            }
            break;
        case Op::Multiply:
            for (size_t k = 1; k < in.operands.size(); ++k) {
                const FieldSample& b = at[in.operands[k]];
                out.gradient = out.gradient * b.value + b.gradient * out.value;
                out.value *= b.value;
            }
            break;
        case Op::Maximum:
        case Op::Minimum:
            for (size_t k = 1; k < in.operands.size(); ++k) {
                const FieldSample& b = at[in.operands[k]];
                if (in.op == Op::Maximum ? b.value > out.value : b.value < out.value) out = b;
            }
            break;
        case Op::Subtract:
            out.value -= at[in.operands[1]].value;
            out.gradient -= at[in.operands[1]].gradient;
            break;
        case Op::Divide: {
            // A division by a zero field gives 0, as in Aqsis: there is no surface there.
            const FieldSample& b = at[in.operands[1]];
            if (b.value == 0) return {};
            out.value = first.value / b.value;
            out.gradient =
                (first.gradient * b.value - b.gradient * first.value) / (b.value * b.value);
            break;
        }
        case Op::Negate:
            out.value = -out.value;
            out.gradient = -out.gradient;
            break;
        case Op::Identity:
        case Op::Leaf:
            break;
    }
    return out;
}

// Where an operation sends the weight `w` it received: into `down` at its operands.
void PassWeight(const BlobbyInstruction& in, const std::vector<FieldSample>& at, float w,
                std::vector<float>* down) {
    const std::vector<int>& ops = in.operands;
    switch (in.op) {
        case Op::Add:
        case Op::Multiply: {
            float total = 0;
            for (int a : ops) total += std::max(at[a].value, 0.f);
            for (int a : ops)
                (*down)[a] +=
                    total > 0 ? w * std::max(at[a].value, 0.f) / total : w / float(ops.size());
            break;
        }
        case Op::Maximum:
        case Op::Minimum: {
            int chosen = ops[0];
            for (int a : ops)
                if (in.op == Op::Maximum ? at[a].value > at[chosen].value
                                         : at[a].value < at[chosen].value)
                    chosen = a;
            (*down)[chosen] += w;
            break;
        }
        default:
            (*down)[ops[0]] += w;
            break;
    }
}

}  // namespace

BlobbyField::BlobbyField(BlobbyProgram program) : program_(std::move(program)) {
    const float surfaceRadius = std::sqrt(1 - std::cbrt(kThreshold));
    far_.resize(program_.instructions.size());
    for (size_t i = 0; i < program_.instructions.size(); ++i) {
        const BlobbyInstruction& in = program_.instructions[i];
        if (in.op != Op::Leaf) {
            operations_.push_back(static_cast<int>(i));
            far_[i] = Combine(in, far_);
            continue;
        }
        const BlobbyLeaf& leaf = program_.leaves[in.leaf];
        if (leaf.kind == Kind::Constant) far_[i].value = leaf.constant;
        if (leaf.support.isEmpty()) continue;
        bounds_.extendBy(leaf.support);
        const float scale = SmallestScale(leaf.objectFromBlob) *
                            (leaf.kind == Kind::Segment ? leaf.radius : 1.f) * surfaceRadius;
        smallestFeature_ = smallestFeature_ > 0 ? std::min(smallestFeature_, scale) : scale;
    }
    farValue_ = far_.empty() ? 0.f : far_.back().value;
}

FieldSample BlobbyField::LeafField(const BlobbyLeaf& leaf, const V3f& p) const {
    switch (leaf.kind) {
        case Kind::Constant:
            return {leaf.constant, V3f(0)};
        case Kind::Plane:
            return Repulsion(leaf, p.z);
        case Kind::Plugin:
            return {};
        case Kind::Ellipsoid:
        case Kind::Segment:
            break;
    }
    if (!leaf.support.intersects(p)) return {};
    V3f q;
    leaf.blobFromObject.multVecMatrix(p, q);
    float scale2 = 1;
    if (leaf.kind == Kind::Segment) {
        q -= NearestOnSegment(q, leaf.end0, leaf.end1);
        scale2 = 1 / (leaf.radius * leaf.radius);
    }
    // s = |q|²·scale2; ∂s/∂q = 2·q·scale2 (the nearest point moves along the segment, at right
    // angles to q, so it adds nothing), carried back to P through blobFromObject.
    return SphereFalloff(q.length2() * scale2,
                         LinearTimesColumn(leaf.blobFromObject, 2 * scale2 * q));
}

FieldSample BlobbyField::Evaluate(const V3f& p, std::vector<FieldSample>* scratch) const {
    std::vector<FieldSample>& at = *scratch;
    at.resize(program_.instructions.size());
    for (size_t i = 0; i < at.size(); ++i) {
        const BlobbyInstruction& in = program_.instructions[i];
        at[i] = in.op == Op::Leaf ? LeafField(program_.leaves[in.leaf], p) : Combine(in, at);
    }
    return at.back();
}

void BlobbyField::LeafWeights(const V3f& p, std::vector<FieldSample>* scratch,
                              std::vector<float>* weights) const {
    Evaluate(p, scratch);
    const size_t n = program_.instructions.size();
    // Operands are earlier instructions, so walking backwards visits every instruction after
    // all the operations that use it.
    std::vector<float> down(n, 0.f);
    down[n - 1] = 1;
    weights->assign(program_.leaves.size(), 0.f);
    for (size_t i = n; i-- > 0;) {
        const BlobbyInstruction& in = program_.instructions[i];
        if (down[i] == 0) continue;
        if (in.op == Op::Leaf)
            (*weights)[in.leaf] += down[i];
        else
            PassWeight(in, *scratch, down[i], &down);
    }
}

bool BlobbyField::Localize(const Box3f& box, Local* local) const {
    local->at = far_;
    local->leaves.clear();
    bool touched = false;
    for (size_t i = 0; i < program_.instructions.size(); ++i) {
        const BlobbyInstruction& in = program_.instructions[i];
        if (in.op != Op::Leaf) continue;
        const BlobbyLeaf& leaf = program_.leaves[in.leaf];
        if (leaf.kind == Kind::Plane) local->leaves.push_back(static_cast<int>(i));
        if (leaf.support.isEmpty() || !leaf.support.intersects(box)) continue;
        local->leaves.push_back(static_cast<int>(i));
        touched = true;
    }
    return touched;
}

FieldSample BlobbyField::Evaluate(const V3f& p, Local* local) const {
    std::vector<FieldSample>& at = local->at;
    for (int i : local->leaves)
        at[i] = LeafField(program_.leaves[program_.instructions[i].leaf], p);
    for (int i : operations_) at[i] = Combine(program_.instructions[i], at);
    return at.back();
}

}  // namespace gonio
