#pragma once
// The syntax tree of a shader source file. One Node type with a kind keeps the grammar actions
// and the passes short; the meaning of `kids` per kind is listed below, and the passes read them
// through Node's named accessors (only the parser builds `kids` by position). Nodes live in an
// arena owned by the parse (SyntaxTree), so Bison's error recovery never leaks.

#include <cassert>
#include <memory>
#include <string>
#include <vector>

#include "shaderlang/types.h"

namespace gonio::sl {

struct SourceLoc {
    int file = 0;  // index into SyntaxTree::files
    int line = 0;
    int column = 0;
};

enum class NodeKind : uint8_t {
    ShaderDef,    // name, shaderType; kids: [formals (List), body (Block)]
    FunctionDef,  // name, declType/detail = return type; kids: [formals (List), body (Block)]
    List,         // formals: VarDecl kids
    Block,        // statements
    VarDecl,      // name, declType, detail, output, isExtern; kids: [initialiser or null]
    ExprStmt,     // kids: [expr]
    If,           // kids: [cond, then, else or null]
    While,        // kids: [cond, body]
    For,          // kids: [init or null, cond or null, step or null, body]
    Break,        // level
    Continue,     // level
    Return,       // kids: [expr or null]
    Illuminance,  // kids: [args..., body]
    Illuminate,   // kids: [args..., body]
    Solar,        // kids: [args..., body]
    Number,       // number
    String,       // name (the text)
    Identifier,   // name
    Tuple,        // (a, b, c): kids
    InitList,     // {a, b, c}: kids
    Unary,        // op ('-' or '!'); kids: [operand]
    Binary,       // op (token); kids: [lhs, rhs]
    Assign,       // op ('=' or the operator of += -= *= /=); kids: [lvalue, value]
    Ternary,      // kids: [cond, a, b]
    Call,         // name; kids: args
    Index,        // kids: [array, index]
    Cast,         // declType, name = space ("" when none); kids: [operand]
};

// Operators of Binary nodes that are not single characters.
enum BinaryOp : int { kOpEq = 256, kOpNe, kOpLe, kOpGe, kOpAnd, kOpOr };

struct Symbol;

struct Node {
    NodeKind kind;
    SourceLoc loc;
    std::vector<Node*> kids;
    std::string name;
    float number = 0;
    int op = 0;  // operator, break/continue level, shader type
    // Declarations and casts.
    TypeSpec declType;
    Detail detail = Detail::Varying;
    bool hasDetail = false;  // uniform/varying written explicitly
    bool output = false;
    bool isExtern = false;

    // Filled by the type checker.
    TypeSpec type;             // Void for statements
    bool varying = false;      // the value differs between points
    bool boolean = false;      // a relation: only usable as a condition
    Symbol* symbol = nullptr;  // Identifier, VarDecl: the variable
    int builtin = -1;          // Call: the BuiltinTable() row
    Node* function = nullptr;  // Call: the user FunctionDef
    bool hasError = false;     // an error was reported here: no follow-on errors

    // The kids by meaning, for the kinds named (see NodeKind); any other kind is a bug.
    // ShaderDef, FunctionDef: the formal parameters (VarDecls).
    const std::vector<Node*>& Formals() const {
        assert(kind == NodeKind::ShaderDef || kind == NodeKind::FunctionDef);
        return kids[0]->kids;
    }
    // ShaderDef, FunctionDef: the Block; While, For, Illuminance, Illuminate, Solar: the
    // statement run per iteration.
    Node* Body() const {
        switch (kind) {
            case NodeKind::ShaderDef:
            case NodeKind::FunctionDef:
            case NodeKind::While:
                return kids[1];
            case NodeKind::For:
                return kids[3];
            default:
                assert(IsLightLoop());
                return kids.back();
        }
    }
    bool IsLightLoop() const {
        return kind == NodeKind::Illuminance || kind == NodeKind::Illuminate ||
               kind == NodeKind::Solar;
    }
    // Illuminance, Illuminate, Solar: the arguments before the body.
    std::vector<Node*> LightLoopArguments() const {
        assert(IsLightLoop());
        return {kids.begin(), kids.end() - 1};
    }
    const std::vector<Node*>& Statements() const {
        assert(kind == NodeKind::Block);
        return kids;
    }
    // A declaration statement: a Block of VarDecls, declared in the enclosing scope.
    bool IsDeclaration() const {
        return kind == NodeKind::Block && !kids.empty() && kids[0]->kind == NodeKind::VarDecl;
    }
    // VarDecl: the initial (or default) value, null when none.
    Node* Initialiser() const {
        assert(kind == NodeKind::VarDecl);
        return kids[0];
    }
    // ExprStmt: the expression; Return: the value, null when none.
    Node* Expression() const {
        assert(kind == NodeKind::ExprStmt || kind == NodeKind::Return);
        return kids[0];
    }
    // If, While, Ternary; For (null when none).
    Node* Condition() const {
        assert(kind == NodeKind::If || kind == NodeKind::While || kind == NodeKind::For ||
               kind == NodeKind::Ternary);
        return kids[kind == NodeKind::For ? 1 : 0];
    }
    // If: the statements (Else null when none); Ternary: the values.
    Node* Then() const {
        assert(kind == NodeKind::If || kind == NodeKind::Ternary);
        return kids[1];
    }
    Node* Else() const {
        assert(kind == NodeKind::If || kind == NodeKind::Ternary);
        return kids[2];
    }
    // For: the expressions before the first and after each iteration, null when none.
    Node* Init() const {
        assert(kind == NodeKind::For);
        return kids[0];
    }
    Node* Step() const {
        assert(kind == NodeKind::For);
        return kids[2];
    }
    // Tuple, InitList.
    const std::vector<Node*>& Elements() const {
        assert(kind == NodeKind::Tuple || kind == NodeKind::InitList);
        return kids;
    }
    // Unary, Cast.
    Node* Operand() const {
        assert(kind == NodeKind::Unary || kind == NodeKind::Cast);
        return kids[0];
    }
    // Binary.
    Node* Lhs() const {
        assert(kind == NodeKind::Binary);
        return kids[0];
    }
    Node* Rhs() const {
        assert(kind == NodeKind::Binary);
        return kids[1];
    }
    // Assign: the lvalue (Identifier or Index) and the value stored.
    Node* Target() const {
        assert(kind == NodeKind::Assign);
        return kids[0];
    }
    Node* Value() const {
        assert(kind == NodeKind::Assign);
        return kids[1];
    }
    // Index: array[subscript].
    Node* Array() const {
        assert(kind == NodeKind::Index);
        return kids[0];
    }
    Node* Subscript() const {
        assert(kind == NodeKind::Index);
        return kids[1];
    }
    // Call (the type checker rewrites texture("name"[c], ...)'s).
    std::vector<Node*>& Arguments() {
        assert(kind == NodeKind::Call);
        return kids;
    }
    const std::vector<Node*>& Arguments() const {
        assert(kind == NodeKind::Call);
        return kids;
    }
};

// The result of parsing one preprocessed file.
struct SyntaxTree {
    std::vector<std::shared_ptr<const std::string>> files;  // file names by SourceLoc::file
    std::vector<std::unique_ptr<Node>> arena;
    std::vector<Node*> definitions;  // ShaderDef and FunctionDef nodes in order

    Node* Make(NodeKind kind, const SourceLoc& loc) {
        arena.push_back(std::make_unique<Node>());
        Node* n = arena.back().get();
        n->kind = kind;
        n->loc = loc;
        return n;
    }
};

}  // namespace gonio::sl
