#pragma once
// Code generation: the checked syntax tree to typed three-address register code (program.h).
// User functions are inlined at every call (arguments by reference); divergent control flow
// becomes mask instructions whose stack depth is fixed here.

#include <unordered_map>

#include "base/diagnostics.h"
#include "shaderlang/compiler/ast.h"
#include "shaderlang/compiler/typecheck.h"
#include "shaderlang/runtime/opcodes.h"
#include "shaderlang/runtime/program.h"

namespace gonio::sl {

class CodeGenerator {
  public:
    CodeGenerator(const SyntaxTree& tree, const TypeChecker& checker, Diagnostics& diagnostics,
                  int colorComponents);

    // Generates `shader`'s code into `program`; false after reporting errors (recursion).
    bool Generate(Node* shader, Program* program);

  private:
    struct LoopFrame {
        int running;  // mask entry of the points still looping; the body's entry is running + 1
        int region;
    };
    struct FunctionFrame {
        int entry;  // mask entry of the inlined body
        int region;
        int result;  // register, -1 for void
        TypeSpec type;
        size_t loopBase;  // loops_ index where this function's own loops start
    };

    int NewReg(const TypeSpec& type, bool varying, const std::string& name = "",
               bool temporary = true);
    int Constant(float value);
    int Constant(const std::vector<float>& values, const TypeSpec& type);
    int StringConstant(const std::string& text);
    int GlobalReg(int id);
    void ImplicitGlobals(unsigned flags);
    int Emit(Op op, std::initializer_list<int> args, int extra = 0, int jump = -1);
    void SetLoc(const Node* n);
    int PushRegion(int condition, bool alwaysVarying);
    bool DepthAvailable(const Node* at, int entries);

    void Statement(Node* s);
    void Declare(Node* decl, bool topLevel);
    // Stores a parameter's or variable's initialiser (a value or an InitList) in `reg`.
    void Initialise(int reg, Node* init, const TypeSpec& type);
    void If(Node* s);
    void Loop(Node* s);
    void Exit(Node* s);
    void LightLoop(Node* s);

    int Expr(Node* e);
    int ExprAs(Node* e, const TypeSpec& to);
    int Convert(int reg, const TypeSpec& to);
    int Condition(Node* e);
    void StoreTo(int target, int value);
    int Assign(Node* e);
    int Binary(Node* e);
    int Cast(Node* e);
    int Tuple(Node* e);
    int BuiltinCall(Node* e);
    int InlineCall(Node* e);

    const SyntaxTree& tree_;
    const TypeChecker& checker_;
    Diagnostics& diagnostics_;
    int colorComponents_;
    Program* p_ = nullptr;
    int depth_ = 0;
    int region_ = 0;
    int loc_ = 0;
    bool ok_ = true;
    // Every function call is inlined, so nested calls can multiply the code: past this many
    // instructions generation stops with an error (a real shader has a few thousand).
    static constexpr size_t kMaxInstructions = size_t(1) << 18;
    const Node* current_ = nullptr;  // the call being inlined, for that error
    std::unordered_map<const Symbol*, int> regOf_;
    std::vector<LoopFrame> loops_;
    std::vector<FunctionFrame> functions_;
    std::vector<const Node*> inlining_;
    std::unordered_map<std::string, int> locIndex_;
    std::unordered_map<std::string, int> constants_;
};

}  // namespace gonio::sl
