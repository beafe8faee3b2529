#pragma once
// The type checker: resolves names, types every expression, picks built-in and user-function
// overloads (on argument and expected return types) and enforces RSL's rules (RISpec §11-§13):
// no varying value into a uniform variable, no uniform assignment under a varying condition,
// points and colours do not mix, comparison results only as conditions, shader parameters have
// defaults. Every error is reported (`file.sl:LINE:COL: error: ...`), never just the first.

#include "base/diagnostics.h"
#include "shaderlang/compiler/ast.h"
#include "shaderlang/compiler/symtab.h"
#include "shaderlang/shading_system.h"

namespace gonio::sl {

class TypeChecker {
  public:
    TypeChecker(SyntaxTree& tree, Diagnostics& diagnostics, int colorComponents);

    // Checks the file; returns its shader definition, or nullptr if there is none. Errors()
    // says whether the tree may be compiled.
    Node* Check();
    int Errors() const { return errors_; }
    ShaderType Type() const { return shaderType_; }
    // The globals' symbols of the shader, by GlobalId (null where the type has none).
    const std::vector<Symbol*>& Globals() const { return globals_; }

    // Whether `from` converts implicitly to `to` (float to triple or matrix, point-likes to
    // each other, a tuple literal to any triple, colours and point-likes to each other at a
    // higher cost); -1 if not, else a cost (0 exact).
    static int ConversionCost(const TypeSpec& to, const TypeSpec& from, bool fromTuple);

  private:
    struct Context {
        Node* function = nullptr;  // enclosing FunctionDef
        int functionDepth = 0;
        int loops = 0;
        int varyingConditions = 0;
        bool inIlluminance = false;
    };

    void Error(const Node* at, const std::string& message);
    void CheckFunctionDef(Node* f, Context ctx);
    void CheckShader(Node* shader);
    void CheckStatement(Node* s, Context& ctx);
    void CheckBlock(Node* block, Context& ctx, bool newScope = true);
    void CheckDeclaration(Node* decl, Context& ctx, SymbolKind kind);
    void CheckCondition(Node* cond, Context& ctx);
    void CheckLightLoop(Node* s, Context& ctx);
    // Types an expression; `expected` (may be null) is the type the context wants, which picks
    // among overloads on return type and types tuple literals.
    void CheckExpr(Node* e, Context& ctx, const TypeSpec* expected = nullptr);
    void CheckIdentifier(Node* e, Context& ctx);
    void CheckBinary(Node* e, Context& ctx);
    void CheckAssign(Node* e, Context& ctx);
    void CheckCast(Node* e, Context& ctx);
    void CheckTuple(Node* e, Context& ctx, const TypeSpec* expected);
    void CheckCall(Node* e, Context& ctx, const TypeSpec* expected);
    bool CheckUserCall(Node* e, const std::vector<Node*>& candidates);
    bool CheckBuiltinCall(Node* e, Context& ctx, const TypeSpec* expected);
    void CheckOutputOptions(Node* e, unsigned flags, size_t first, Context& ctx);
    // Checks that `value` (already typed) may be stored in a `to`; types tuples to `to`.
    bool Coerce(Node* value, const TypeSpec& to, const std::string& what);
    bool SizeFromDefault(Node* decl, SymbolKind kind);
    void CheckArrayLength(Node* e);
    // A colour ↔ point-like conversion copies 3 components: false (with an error at `at`) when
    // colours have another number.
    bool ColorTripleConversion(const TypeSpec& from, const TypeSpec& to, const Node* at);
    bool CheckLvalue(Node* target, Context& ctx, bool varyingValue);
    // A value stored in a uniform variable: its random() calls draw one value per run
    // (uniform_random.h), unless a user function is named random.
    void UniformRandomIn(Node* value);
    bool NotBoolean(Node* e);

    SyntaxTree& tree_;
    Diagnostics& diagnostics_;
    int colorComponents_;
    int errors_ = 0;
    ShaderType shaderType_ = ShaderType::Surface;
    SymbolTable symbols_;
    std::vector<Symbol*> globals_;
    int paramCount_ = 0;
    std::unordered_map<Symbol*, Symbol*> externs_;  // extern alias -> the outer variable
};

// A type of `base`, an array of `length` when length > 0.
inline TypeSpec MakeType(BaseType base, int length = 0) {
    TypeSpec t;
    t.base = base;
    t.arrayLength = length;
    return t;
}

}  // namespace gonio::sl
