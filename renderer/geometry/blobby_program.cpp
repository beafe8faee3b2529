#include "renderer/geometry/blobby_program.h"

#include <Imath/ImathBoxAlgo.h>

#include <cmath>

namespace gonio {

namespace {

using Op = BlobbyInstruction::Op;
using Kind = BlobbyLeaf::Kind;

// Reads the code array one instruction at a time, checking every index as it goes.
class BlobbyDecoder {
  public:
    BlobbyDecoder(const std::vector<int>& code, const std::vector<float>& floats,
                  const std::vector<std::string>& strings, std::vector<std::string>* notes)
        : code_(code), floats_(floats), strings_(strings), notes_(notes) {}

    // Fills `program`; false with error() set on the first bad instruction.
    bool Decode(BlobbyProgram* program) {
        if (code_.empty()) return Fail(0, "the code array is empty");
        while (pos_ < code_.size()) {
            start_ = pos_;
            const int opcode = code_[pos_++];
            BlobbyInstruction instruction;
            if (!(opcode >= 1000 ? DecodeLeaf(opcode, program, &instruction)
                                 : DecodeOperation(opcode, *program, &instruction)))
                return false;
            program->instructions.push_back(std::move(instruction));
        }
        return true;
    }

    const std::string& error() const { return error_; }

  private:
    bool Fail(size_t at, const std::string& message) {
        error_ = "code[" + std::to_string(at) + "]: " + message;
        return false;
    }

    // The next code word, an operand of the instruction that starts at start_.
    bool Next(const char* what, int* value) {
        if (pos_ >= code_.size())
            return Fail(start_, std::string("the code array ends before the ") + what);
        *value = code_[pos_++];
        return true;
    }

    // A float index whose `count` floats all lie inside the float array.
    bool FloatBlock(const char* what, int count, int* first) {
        if (!Next("float index", first)) return false;
        if (*first < 0 || static_cast<size_t>(*first) + count > floats_.size())
            return Fail(pos_ - 1, std::string("the ") + what + "'s " + std::to_string(count) +
                                      " floats start at " + std::to_string(*first) +
                                      ", but the float array has " +
                                      std::to_string(floats_.size()));
        for (int k = 0; k < count; ++k)
            if (!std::isfinite(floats_[*first + k]))
                return Fail(pos_ - 1, std::string("the ") + what + "'s float " +
                                          std::to_string(*first + k) + " is not finite");
        return true;
    }

    bool StringIndex(const char* what, int* index) {
        if (!Next("string index", index)) return false;
        if (*index < 0 || static_cast<size_t>(*index) >= strings_.size())
            return Fail(pos_ - 1, std::string("the ") + what + "'s string index " +
                                      std::to_string(*index) + " is outside the string array (" +
                                      std::to_string(strings_.size()) + " strings)");
        return true;
    }

    M44f Matrix(int first) const {
        const float* m = floats_.data() + first;
        return M44f(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8], m[9], m[10], m[11], m[12],
                    m[13], m[14], m[15]);
    }

    // The leaf's matrix and its inverse; a singular matrix has no field to speak of.
    bool SetMatrix(const char* what, int first, BlobbyLeaf* leaf) {
        leaf->objectFromBlob = Matrix(first);
        const float det = leaf->objectFromBlob.determinant();
        if (!(std::fabs(det) > 1e-30f) || !std::isfinite(det))
            return Fail(start_, std::string("the ") + what + "'s matrix is singular");
        leaf->blobFromObject = leaf->objectFromBlob.inverse();
        return true;
    }

    bool DecodeLeaf(int opcode, BlobbyProgram* program, BlobbyInstruction* instruction) {
        BlobbyLeaf leaf;
        int f = 0, s = 0;
        switch (opcode) {
            case 1000:
                if (!FloatBlock("constant", 1, &f)) return false;
                leaf.kind = Kind::Constant;
                leaf.constant = floats_[f];
                break;
            case 1001:
                if (!FloatBlock("ellipsoid", 16, &f) || !SetMatrix("ellipsoid", f, &leaf))
                    return false;
                leaf.kind = Kind::Ellipsoid;
                // The field is 0 outside the unit sphere of blob space.
                leaf.support = Imath::transform(Box3f(V3f(-1), V3f(1)), leaf.objectFromBlob);
                break;
            case 1002: {
                if (!FloatBlock("segment blob", 23, &f) || !SetMatrix("segment blob", f + 7, &leaf))
                    return false;
                const float* q = floats_.data() + f;
                leaf.kind = Kind::Segment;
                leaf.end0 = V3f(q[0], q[1], q[2]);
                leaf.end1 = V3f(q[3], q[4], q[5]);
                leaf.radius = q[6];
                if (!(leaf.radius > 0))
                    return Fail(start_, "the segment blob's radius must be > 0");
                Box3f blob(leaf.end0);
                blob.extendBy(leaf.end1);
                blob.min -= V3f(leaf.radius);
                blob.max += V3f(leaf.radius);
                leaf.support = Imath::transform(blob, leaf.objectFromBlob);
                break;
            }
            case 1003:
                if (!StringIndex("repelling plane", &s) || !FloatBlock("repelling plane", 4, &f))
                    return false;
                leaf.kind = Kind::Plane;
                leaf.name = strings_[s];
                leaf.A = floats_[f], leaf.B = floats_[f + 1];
                leaf.C = floats_[f + 2], leaf.D = floats_[f + 3];
                if (!(leaf.A > 0 && leaf.C > 0))
                    return Fail(start_, "the repelling plane's A and C must be > 0");
                break;
            case 1004: {
                int nf = 0, ns = 0, sf = 0;
                if (!StringIndex("implicit field plugin", &s) || !Next("float count", &nf) ||
                    !FloatBlock("implicit field plugin", std::max(nf, 0), &f) ||
                    !Next("string count", &ns) || !Next("string index", &sf))
                    return false;
                if (nf < 0 || ns < 0 || sf < 0 || static_cast<size_t>(sf) + ns > strings_.size())
                    return Fail(start_,
                                "the implicit field plugin's counts or string index are "
                                "outside the arrays");
                leaf.kind = Kind::Plugin;
                leaf.name = strings_[s];
                notes_->push_back("implicit field plugins (opcode 1004, \"" + leaf.name +
                                  "\") are not supported: the leaf's field is 0");
                break;
            }
            default:
                return Fail(start_, "unknown opcode " + std::to_string(opcode) +
                                        " (primitive fields are 1000-1004)");
        }
        instruction->op = Op::Leaf;
        instruction->leaf = static_cast<int>(program->leaves.size());
        program->leaves.push_back(std::move(leaf));
        return true;
    }

    // An operand must name an earlier instruction: this is what rules out cycles.
    bool Operand(const BlobbyProgram& program, BlobbyInstruction* instruction) {
        int a = 0;
        if (!Next("operand", &a)) return false;
        const int self = static_cast<int>(program.instructions.size());
        if (a < 0 || a >= self)
            return Fail(pos_ - 1, "instruction " + std::to_string(self) + " uses instruction " +
                                      std::to_string(a) +
                                      ", which is not an earlier one (an operation may only use "
                                      "earlier instructions: no forward references or cycles)");
        instruction->operands.push_back(a);
        return true;
    }

    bool DecodeOperation(int opcode, const BlobbyProgram& program, BlobbyInstruction* instruction) {
        static const Op kOps[] = {Op::Add,      Op::Multiply, Op::Maximum, Op::Minimum,
                                  Op::Subtract, Op::Divide,   Op::Negate,  Op::Identity};
        if (opcode < 0 || opcode > 7)
            return Fail(start_, "unknown opcode " + std::to_string(opcode) +
                                    " (operations are 0-7, primitive fields 1000-1004)");
        instruction->op = kOps[opcode];
        int count = 0;
        if (opcode <= 3) {
            if (!Next("operand count", &count)) return false;
            if (count < 1 || static_cast<size_t>(count) > code_.size() - pos_)
                return Fail(pos_ - 1, "operand count " + std::to_string(count) +
                                          " must be at least 1 and fit in the code array");
        } else {
            count = opcode <= 5 ? 2 : 1;
        }
        for (int k = 0; k < count; ++k)
            if (!Operand(program, instruction)) return false;
        return true;
    }

    const std::vector<int>& code_;
    const std::vector<float>& floats_;
    const std::vector<std::string>& strings_;
    std::vector<std::string>* notes_;
    size_t pos_ = 0, start_ = 0;
    std::string error_;
};

}  // namespace

GeometryResult<BlobbyProgram> DecodeBlobby(int nleaf, const std::vector<int>& code,
                                           const std::vector<float>& floats,
                                           const std::vector<std::string>& strings,
                                           std::vector<std::string>* notes) {
    BlobbyProgram program;
    BlobbyDecoder decoder(code, floats, strings, notes);
    if (!decoder.Decode(&program)) return GeometryResult<BlobbyProgram>::Error(decoder.error());
    // Pixar's own published examples miscount nleaf, so a mismatch only warns; primitive
    // variables are checked against the leaves the code really has.
    if (static_cast<size_t>(nleaf) != program.leaves.size())
        notes->push_back("nleaf is " + std::to_string(nleaf) + " but the code has " +
                         std::to_string(program.leaves.size()) +
                         " primitive fields: the code's count is used");
    return program;
}

}  // namespace gonio
