#pragma once
// The syntax tree of a shader source file. One Node type with a kind keeps the grammar actions
// and the passes short; the meaning of `kids` per kind is listed below. Nodes live in an arena
// owned by the parse (SyntaxTree), so Bison's error recovery never leaks.

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
