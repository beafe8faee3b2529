#pragma once
// The code array of RiBlobby (RISpec 3.2 §5.6, PRMan Application Note #31) decoded into a
// checked program: the primitive fields ("leaves", opcodes ≥ 1000) and the operations that
// combine them. Every index the code holds is checked here, once, so that evaluating the field
// (blobby_field.h) never reads outside the float or string arrays or follows a cycle.
//
// Instructions are numbered in order, from 0; an operation's operands are the numbers of
// earlier instructions, and the last instruction is the blobby's field. Opcodes:
//
//   1000 f        constant: the value flt[f]
//   1001 f        ellipsoid: the unit sphere's field carried by the 4×4 matrix flt[f..f+15]
//   1002 f        segment blob: ends flt[f..f+5], radius flt[f+6], matrix flt[f+7..f+22]
//   1003 s f      repelling plane: depth map str[s], parameters A B C D = flt[f..f+3]
//   1004 s n f m g   implicit field plugin str[s] (PRMan): a leaf of field 0, with a warning
//   0 n a1..an    add          1 n a1..an    multiply
//   2 n a1..an    maximum      3 n a1..an    minimum
//   4 a b         subtract: a − b           5 a b         divide: a / b
//   6 a           negate: −a                7 a           identity: a
//
// RISpec's table gives 4 subtract and 5 divide, Application Note #31 the reverse; gonio follows
// RISpec. Both name the operands "subtrahend, minuend", yet every published example (and
// Aqsis) computes the first operand minus the second, as done here.

#include <Imath/ImathBox.h>
#include <Imath/ImathMatrix.h>

#include <memory>
#include <string>
#include <vector>

#include "renderer/geometry/blobby_depth_map.h"
#include "renderer/geometry/geometry_result.h"
#include "renderer/geometry/shape.h"

namespace gonio {

using Imath::M44f;

// One primitive field. Its index among the leaves (in code order) selects its vertex and
// varying primitive-variable values.
struct BlobbyLeaf {
    enum class Kind { Constant, Ellipsoid, Segment, Plane, Plugin };
    Kind kind = Kind::Constant;
    float constant = 0;   // Constant
    M44f objectFromBlob;  // Ellipsoid, Segment: the leaf's matrix (row vectors, as RIB)
    M44f blobFromObject;  // its inverse
    V3f end0, end1;       // Segment, in blob space
    float radius = 1;     // Segment
    float A = 0, B = 0, C = 1, D = 0;  // Plane: RISpec's repulsion parameters
    std::string name;                  // Plane: the depth map; Plugin: the plugin
    // Plane: the surface its depth map holds; null for the plane z = 0 of object space.
    std::shared_ptr<const BlobbyDepthMap> depthMap;
    Box3f support;  // object-space box outside which the field is 0 (empty: none)
};

struct BlobbyInstruction {
    enum class Op { Leaf, Add, Multiply, Maximum, Minimum, Subtract, Divide, Negate, Identity };
    Op op = Op::Leaf;
    int leaf = -1;              // Leaf: index into BlobbyProgram::leaves
    std::vector<int> operands;  // earlier instruction numbers
};

struct BlobbyProgram {
    std::vector<BlobbyLeaf> leaves;
    std::vector<BlobbyInstruction> instructions;  // the last one is the field
};

// Decodes and checks a Blobby request's arrays. Errors name the code array position, e.g.
// "code[4]: unknown opcode 9". `notes` receives warnings (a plugin leaf, nleaf disagreeing with
// the code's primitive fields). Planes are left without their depth maps (MakeBlobby finds them).
GeometryResult<BlobbyProgram> DecodeBlobby(int nleaf, const std::vector<int>& code,
                                           const std::vector<float>& floats,
                                           const std::vector<std::string>& strings,
                                           std::vector<std::string>* notes);

}  // namespace gonio
