#pragma once
// Variables and scopes of the type checker. A Symbol is a shader parameter, a global, a local,
// a function formal or PI; user functions are looked up by name among the FunctionDef nodes
// visible at the call.

#include <string>
#include <unordered_map>
#include <vector>

#include "shaderlang/compiler/ast.h"
#include "shaderlang/types.h"

namespace gonio::sl {

enum class SymbolKind : uint8_t { Global, Param, Local, Formal, Constant };

struct Symbol {
    std::string name;
    SymbolKind kind = SymbolKind::Local;
    TypeSpec type;
    Detail detail = Detail::Varying;
    bool output = false;
    bool readOnly = false;
    int global = -1;        // GlobalId for globals
    int param = -1;         // index among the shader's parameters
    float constant = 0;     // PI
    Node* decl = nullptr;   // the VarDecl (null for globals and PI)
    int functionDepth = 0;  // nesting of user functions at the declaration
};

class SymbolTable {
  public:
    void Push() { scopes_.emplace_back(); }
    void Pop() { scopes_.pop_back(); }
    // False if the name is already declared in the innermost scope.
    bool Declare(Symbol* symbol) {
        return scopes_.back().vars.emplace(symbol->name, symbol).second;
    }
    void DeclareFunction(Node* function) {
        scopes_.back().functions[function->name].push_back(function);
    }
    Symbol* Find(const std::string& name) const {
        for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
            auto found = it->vars.find(name);
            if (found != it->vars.end()) return found->second;
        }
        return nullptr;
    }
    // Every visible user function of that name, innermost scope first.
    std::vector<Node*> FindFunctions(const std::string& name) const {
        std::vector<Node*> out;
        for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
            auto found = it->functions.find(name);
            if (found != it->functions.end()) {
                out.insert(out.end(), found->second.begin(), found->second.end());
            }
        }
        return out;
    }
    Symbol* Make() {
        symbols_.push_back(std::make_unique<Symbol>());
        return symbols_.back().get();
    }

  private:
    struct Scope {
        std::unordered_map<std::string, Symbol*> vars;
        std::unordered_map<std::string, std::vector<Node*>> functions;
    };
    std::vector<Scope> scopes_;
    std::vector<std::unique_ptr<Symbol>> symbols_;
};

}  // namespace gonio::sl
