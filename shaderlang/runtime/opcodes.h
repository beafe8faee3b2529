#pragma once
// The one opcode table (OSL's habit): each row names an opcode, its flags and the function that
// runs it over a batch. Adding an operation is one row here and one function in ops_*.cpp.
//
// Operands: args[0] is the destination of value-producing opcodes. Control opcodes:
//   If c          entry[extra] = entry[extra-1] & c; no point active: go to jump
//   Else c        entry[extra] = entry[extra-1] & !c; no point active: go to jump
//   LoopInit      entry[extra] = entry[extra-1]       (the loop's running points)
//   LoopTest c    entry[extra] &= c; none: go to jump; entry[extra+1] = entry[extra] (the body)
//   LoopNext      entry[extra+1] = entry[extra]      (continue target: continued points resume)
//   Exit          clears the active points of entry[depth] in entries extra..depth (break,
//                 continue, return; jump = the region left, for detail inference)
//   Enter         entry[extra] = entry[extra-1]       (a function body)
//   IllumBegin    category?, axis?, angle?, position (args 0-3, -1 when absent): start the
//                 light loop, lights evaluated at the position; entry[extra] = entry[extra-1]
//   IllumNext     next light whose category matches: L, Cl, Ol loaded, entry[extra+1] =
//                 entry[extra] & lit & cone; no light left: go to jump
//   Illuminate    from, axis?, angle?: L = Ps - from, entry[extra] = entry[extra-1] & cone, lit
//                 |= entry[extra]; none: go to jump
//   Solar         axis?, angle?: L = axis (none: light from all directions, L = 0);
//                 entry[extra] = entry[extra-1]; lit |= entry[extra]
//   Jump          go to jump
// Triple d, a, b, c builds a point, vector, normal or 3-component colour from floats; SetComp
// d, v writes component `extra` of d (longer tuples).
// Pure opcodes that warn (Div by zero, IndexRead out of range) are folded only when they do not.

#include <cstdint>

namespace gonio::sl {

struct ExecState;
struct Instr;

using OpFunction = void (*)(ExecState& x, const Instr& in);

enum OpFlags : unsigned {
    kOpPure = 1u << 0,     // no side effects: foldable when the inputs are constant, removable
                           // when the destination is never read
    kOpControl = 1u << 1,  // changes masks or the program counter
    kOpWrites = 1u << 2,   // args[0] is written
};

//        name           flags                     function
#define GONIO_SL_OPCODES(X)                        \
    X(Assign, kOpPure | kOpWrites, OpAssign)       \
    X(Neg, kOpPure | kOpWrites, OpNeg)             \
    X(Add, kOpPure | kOpWrites, OpAdd)             \
    X(Sub, kOpPure | kOpWrites, OpSub)             \
    X(Mul, kOpPure | kOpWrites, OpMul)             \
    X(Div, kOpPure | kOpWrites, OpDiv)             \
    X(MatMul, kOpPure | kOpWrites, OpMatMul)       \
    X(MatDiv, kOpPure | kOpWrites, OpMatDiv)       \
    X(Dot, kOpPure | kOpWrites, OpDot)             \
    X(Cross, kOpPure | kOpWrites, OpCross)         \
    X(Lt, kOpPure | kOpWrites, OpLt)               \
    X(Le, kOpPure | kOpWrites, OpLe)               \
    X(Gt, kOpPure | kOpWrites, OpGt)               \
    X(Ge, kOpPure | kOpWrites, OpGe)               \
    X(Eq, kOpPure | kOpWrites, OpEq)               \
    X(Ne, kOpPure | kOpWrites, OpNe)               \
    X(StrEq, kOpPure | kOpWrites, OpStrEq)         \
    X(StrNe, kOpPure | kOpWrites, OpStrNe)         \
    X(And, kOpPure | kOpWrites, OpAnd)             \
    X(Or, kOpPure | kOpWrites, OpOr)               \
    X(Not, kOpPure | kOpWrites, OpNot)             \
    X(Select, kOpPure | kOpWrites, OpSelect)       \
    X(SetComp, kOpWrites, OpSetComp)               \
    X(Triple, kOpPure | kOpWrites, OpTriple)       \
    X(IndexRead, kOpPure | kOpWrites, OpIndexRead) \
    X(IndexWrite, 0, OpIndexWrite)                 \
    X(SpaceCast, kOpWrites, OpSpaceCast)           \
    X(ColorCast, kOpPure | kOpWrites, OpColorCast) \
    X(Call, kOpWrites, OpCall)                     \
    X(Jump, kOpControl, OpJump)                    \
    X(If, kOpControl, OpIf)                        \
    X(Else, kOpControl, OpElse)                    \
    X(LoopInit, kOpControl, OpLoopInit)            \
    X(LoopTest, kOpControl, OpLoopTest)            \
    X(LoopNext, kOpControl, OpLoopNext)            \
    X(Exit, kOpControl, OpExit)                    \
    X(Enter, kOpControl, OpEnter)                  \
    X(IllumBegin, kOpControl, OpIllumBegin)        \
    X(IllumNext, kOpControl, OpIllumNext)          \
    X(Illuminate, kOpControl, OpIlluminate)        \
    X(Solar, kOpControl, OpSolar)

enum class Op : uint16_t {
#define GONIO_SL_ENUM(name, flags, fn) name,
    GONIO_SL_OPCODES(GONIO_SL_ENUM)
#undef GONIO_SL_ENUM
        Count
};

struct OpInfo {
    const char* name;
    unsigned flags;
    OpFunction run;
};

const OpInfo& OpTable(Op op);
inline const OpInfo& OpTable(uint16_t op) { return OpTable(Op(op)); }

}  // namespace gonio::sl
