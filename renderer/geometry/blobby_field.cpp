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

// (D·bump(z/C) − B/z)·(1 − ease(z/A)) of the height z above the plane, whose gradient is ∇z:
// the chain rule carries the derivative in z to object space.
FieldSample Repulsion(const BlobbyLeaf& leaf, float z, const V3f& gradientZ) {
    constexpr float kZClamp = 1e-6f;  // Application Note #31's ZCLAMP
    if (!(z < leaf.A)) return {};     // also a height of +inf: no surface under the point
    const bool clamped = z <= kZClamp;
    z = std::max(z, kZClamp);
    float bump, bumpSlope, ease, easeSlope;
    Bump(z / leaf.C, &bump, &bumpSlope);
    Ease(z / leaf.A, &ease, &easeSlope);
    const float near = leaf.D * bump - leaf.B / z;
    const float nearSlope = leaf.D * bumpSlope / leaf.C + leaf.B / (z * z);
    const float value = near * (1 - ease);
    const float slope = clamped ? 0.f : nearSlope * (1 - ease) - near * easeSlope / leaf.A;
    return {value, slope * gradientZ};
}

// The repelling plane's field at p: the height above its depth map's surface, or above z = 0
// of object space when it has no map.
FieldSample PlaneField(const BlobbyLeaf& leaf, const V3f& p) {
    if (!leaf.depthMap) return Repulsion(leaf, p.z, V3f(0, 0, 1));
    const BlobbyDepthMap::Height height = leaf.depthMap->HeightAt(p);
    return Repulsion(leaf, height.value, height.gradient);
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

// a ∘ b for the operations whose operand lists fold left to right: add, multiply (with the
// product rule for the gradient), maximum and minimum (the first operand wins ties).
FieldSample Fold(Op op, const FieldSample& a, const FieldSample& b) {
    switch (op) {
        case Op::Add:
            return {a.value + b.value, a.gradient + b.gradient};
        case Op::Multiply:
            return {a.value * b.value, a.gradient * b.value + b.gradient * a.value};
        case Op::Maximum:
            return b.value > a.value ? b : a;
        case Op::Minimum:
            return b.value < a.value ? b : a;
        default:
            return a;
    }
}

// Combines the operand samples of one operation (RISpec 3.2 §5.6, Table 5.3).
FieldSample Combine(Op op, const std::vector<int>& operands, const std::vector<FieldSample>& at) {
    FieldSample out = at[operands[0]];
    switch (op) {
        case Op::Add:
        case Op::Multiply:
        case Op::Maximum:
        case Op::Minimum:
            for (size_t k = 1; k < operands.size(); ++k) out = Fold(op, out, at[operands[k]]);
            break;
        case Op::Subtract:
            out.value -= at[operands[1]].value;
            out.gradient -= at[operands[1]].gradient;
            break;
        case Op::Divide: {
            // A division by a zero field gives 0, as in Aqsis: there is no surface there.
            const FieldSample& a = at[operands[0]];
            const FieldSample& b = at[operands[1]];
            if (b.value == 0) return {};
            out.value = a.value / b.value;
            out.gradient = (a.gradient * b.value - b.gradient * a.value) / (b.value * b.value);
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

bool Folds(Op op) {
    return op == Op::Add || op == Op::Multiply || op == Op::Maximum || op == Op::Minimum;
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
            far_[i] = Combine(in.op, in.operands, far_);
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
            return PlaneField(leaf, p);
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
        at[i] = in.op == Op::Leaf ? LeafField(program_.leaves[in.leaf], p)
                                  : Combine(in.op, in.operands, at);
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
    local->operations.clear();
    std::vector<uint8_t> varies(program_.instructions.size(), 0);
    bool touched = false;
    for (size_t i = 0; i < program_.instructions.size(); ++i) {
        const BlobbyInstruction& in = program_.instructions[i];
        if (in.op == Op::Leaf) {
            const BlobbyLeaf& leaf = program_.leaves[in.leaf];
            const bool reaches = !leaf.support.isEmpty() && leaf.support.intersects(box);
            touched |= reaches;
            if (reaches || leaf.kind == Kind::Plane) {
                varies[i] = 1;
                local->leaves.push_back(static_cast<int>(i));
            }
            continue;
        }
        LocalOperation op;
        op.instruction = static_cast<int>(i);
        for (int a : in.operands)
            if (varies[a]) op.operands.push_back(a);
        if (op.operands.empty()) continue;  // its far value holds throughout the box
        varies[i] = 1;
        if (!Folds(in.op)) {
            op.operands = in.operands;
        } else if (op.operands.size() < in.operands.size()) {
            std::vector<int> constant;
            for (int a : in.operands)
                if (!varies[a]) constant.push_back(a);
            op.folded = Combine(in.op, constant, far_);
            op.hasFolded = true;
        }
        local->operations.push_back(std::move(op));
    }
    return touched;
}

FieldSample BlobbyField::Evaluate(const V3f& p, Local* local) const {
    std::vector<FieldSample>& at = local->at;
    for (int i : local->leaves)
        at[i] = LeafField(program_.leaves[program_.instructions[i].leaf], p);
    for (const LocalOperation& op : local->operations) {
        const Op kind = program_.instructions[op.instruction].op;
        FieldSample out = Combine(kind, op.operands, at);
        at[op.instruction] = op.hasFolded ? Fold(kind, out, op.folded) : out;
    }
    return at.back();
}

}  // namespace gonio
