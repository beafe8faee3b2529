#include "shaderlang/compiler/typecheck.h"

#include <cmath>

#include "shaderlang/compiler/parser.h"
#include "shaderlang/runtime/global_vars.h"

namespace gonio::sl {

TypeChecker::TypeChecker(SyntaxTree& tree, Diagnostics& diagnostics, int colorComponents)
    : tree_(tree), diagnostics_(diagnostics), colorComponents_(colorComponents) {}

void TypeChecker::Error(const Node* at, const std::string& message) {
    ++errors_;
    diagnostics_.Error(ToFileLoc(tree_, at->loc), message);
}

int TypeChecker::ConversionCost(const TypeSpec& to, const TypeSpec& from, bool fromTuple) {
    if (to.IsArray() || from.IsArray()) {
        // An unsized formal takes an array of any length (its body sees the argument's).
        const bool length =
            to.arrayLength == from.arrayLength || (to.IsUnsized() && from.IsArray());
        return to.base == from.base && length ? 0 : -1;
    }
    if (to.base == from.base) return 0;
    if (from.base == BaseType::Float && (to.IsTriple() || to.base == BaseType::Matrix)) return 1;
    if (to.IsPointLike() && from.IsPointLike()) return 1;
    if (fromTuple && to.IsTriple() && from.IsTriple()) return 1;
    // A colour and a point-like convert to each other component by component, as both peer
    // compilers allow (Pixie's sdrc treats every triple alike; Aqsis's aqsl ranks these casts
    // below those within the point family, as this cost does). Coerce rejects them when colours
    // do not have 3 components.
    if (to.IsTriple() && from.IsTriple()) return 2;
    return -1;
}

bool TypeChecker::ColorTripleConversion(const TypeSpec& from, const TypeSpec& to, const Node* at) {
    const bool colorAndPoint = from.IsTriple() && to.IsTriple() && !from.IsArray() &&
                               (from.base == BaseType::Color) != (to.base == BaseType::Color);
    if (!colorAndPoint || colorComponents_ == 3) return true;
    Error(at, "cannot convert " + ToString(from) + " to " + ToString(to) + ": colors have " +
                  std::to_string(colorComponents_) + " components here (ColorSamples), not 3");
    return false;
}

bool TypeChecker::NotBoolean(Node* e) {
    if (!e->boolean) return true;
    Error(e, "a comparison result can only be used as a condition (if, while, for, ?:, &&, ||, !)");
    e->hasError = true;
    return false;
}

bool TypeChecker::Coerce(Node* value, const TypeSpec& to, const std::string& what) {
    if (value->hasError) return false;
    if (!NotBoolean(value)) return false;
    bool tuple = value->kind == NodeKind::Tuple;
    if (tuple && to.IsTriple()) {
        int count = int(value->Elements().size());
        int want = to.base == BaseType::Color ? colorComponents_ : 3;
        if (count != want) {
            Error(value, what + ": a " + ToString(to) + " has " + std::to_string(want) +
                             " components, not " + std::to_string(count));
            return false;
        }
        value->type = to;
        return true;
    }
    if (ConversionCost(to, value->type, tuple) < 0) {
        Error(value, what + ": cannot convert " + ToString(value->type) + " to " + ToString(to));
        value->hasError = true;
        return false;
    }
    if (!ColorTripleConversion(value->type, to, value)) {
        value->hasError = true;
        return false;
    }
    return true;
}

Node* TypeChecker::Check() {
    symbols_.Push();  // globals and PI
    Node* shader = nullptr;
    for (Node* d : tree_.definitions) {
        if (d->kind == NodeKind::ShaderDef) {
            if (shader) {
                Error(d, "a file holds one shader; '" + shader->name + "' was defined first");
                continue;
            }
            shader = d;
            if (d->op == 5) {
                Error(d, "transformation shaders are not supported (RISpec 3.2 dropped them)");
                continue;
            }
            shaderType_ = ShaderType(d->op);
        }
    }
    if (!shader) {
        if (errors_ == 0) {
            ++errors_;
            diagnostics_.Error(ToFileLoc(tree_, SourceLoc{}), "no shader definition in the file");
        }
        return nullptr;
    }
    globals_.assign(kGlobalCount, nullptr);
    for (int i = 0; i < kGlobalCount; ++i) {
        const GlobalVarInfo& g = GlobalVar(i);
        if (!(g.readers & ShaderBit(shaderType_))) continue;
        Symbol* s = symbols_.Make();
        s->name = g.name;
        s->kind = SymbolKind::Global;
        s->type = MakeType(g.type);
        s->detail = g.varying ? Detail::Varying : Detail::Uniform;
        s->readOnly = !(g.writers & ShaderBit(shaderType_));
        s->global = i;
        symbols_.Declare(s);
        globals_[i] = s;
    }
    Symbol* pi = symbols_.Make();
    pi->name = "PI";
    pi->kind = SymbolKind::Constant;
    pi->type = MakeType(BaseType::Float);
    pi->detail = Detail::Uniform;
    pi->readOnly = true;
    pi->constant = float(M_PI);
    symbols_.Declare(pi);

    // Functions defined before the shader are visible in it (and in later functions).
    for (Node* d : tree_.definitions) {
        if (d->kind == NodeKind::FunctionDef) {
            symbols_.DeclareFunction(d);
            CheckFunctionDef(d, Context{});
        } else if (d == shader && d->op != 5) {
            CheckShader(d);
        }
    }
    return shader;
}

void TypeChecker::CheckFunctionDef(Node* f, Context outer) {
    Context ctx;
    ctx.function = f;
    ctx.functionDepth = outer.functionDepth + 1;
    if (outer.function && outer.function == f) return;
    symbols_.Push();
    for (Node* formal : f->Formals()) {
        Symbol* s = symbols_.Make();
        s->name = formal->name;
        s->kind = SymbolKind::Formal;
        s->type = formal->declType;
        s->detail = formal->hasDetail ? formal->detail : Detail::Varying;
        s->output = formal->output;
        s->readOnly = !formal->output;
        s->decl = formal;
        s->functionDepth = ctx.functionDepth;
        formal->symbol = s;
        if (formal->Initialiser()) Error(formal, "function parameters cannot have default values");
        if (!symbols_.Declare(s))
            Error(formal, "parameter '" + formal->name + "' is declared twice");
    }
    CheckBlock(f->Body(), ctx, false);
    symbols_.Pop();
}

void TypeChecker::CheckShader(Node* shader) {
    Context ctx;
    symbols_.Push();
    for (Node* formal : shader->Formals()) {
        if (!formal->hasDetail) formal->detail = Detail::Uniform;
        if (!formal->Initialiser()) {
            Error(formal, "shader parameter '" + formal->name + "' needs a default value");
        }
        CheckDeclaration(formal, ctx, SymbolKind::Param);
    }
    CheckBlock(shader->Body(), ctx, true);
    symbols_.Pop();
}

// A shader parameter `float k[] = {1, 2}` has its default's length (PRMan's and Pixie's rule);
// a function formal stays unsized and takes its argument's.
bool TypeChecker::SizeFromDefault(Node* decl, SymbolKind kind) {
    if (kind == SymbolKind::Formal) return true;
    const Node* init = decl->Initialiser();
    if (!init || init->kind != NodeKind::InitList) {
        Error(decl, "unsized array parameter '" + decl->name +
                        "' needs a {...} default to give it a length");
        return false;
    }
    decl->declType.arrayLength = int(init->Elements().size());
    return true;
}

void TypeChecker::CheckDeclaration(Node* decl, Context& ctx, SymbolKind kind) {
    if (decl->isExtern) {
        Symbol* outer = symbols_.Find(decl->name);
        if (!outer || outer->kind == SymbolKind::Constant) {
            Error(decl, "extern '" + decl->name + "' names no variable of an enclosing scope");
            return;
        }
        if (outer->type != decl->declType) {
            Error(decl, "extern '" + decl->name + "' is declared " + ToString(decl->declType) +
                            " but the variable is " + ToString(outer->type));
        }
        // Uses resolve to the outer variable itself (codegen finds its register by symbol);
        // the alias only makes the name visible at this function's depth.
        decl->symbol = outer;
        Symbol* alias = symbols_.Make();
        *alias = *outer;
        alias->functionDepth = ctx.functionDepth;
        externs_[alias] = outer;
        if (!symbols_.Declare(alias)) Error(decl, "'" + decl->name + "' is already declared");
        return;
    }
    if (decl->declType.base == BaseType::Void) {
        Error(decl, "variables cannot be void");
        return;
    }
    if (decl->declType.IsUnsized() && !SizeFromDefault(decl, kind)) return;
    Symbol* s = symbols_.Make();
    s->name = decl->name;
    s->kind = kind;
    s->type = decl->declType;
    s->detail = decl->hasDetail ? decl->detail
                                : (kind == SymbolKind::Param ? Detail::Uniform : Detail::Varying);
    s->output = decl->output;
    s->decl = decl;
    s->functionDepth = ctx.functionDepth;
    if (kind == SymbolKind::Param) s->param = paramCount_++;
    if (decl->output && kind == SymbolKind::Local) {
        Error(decl, "only shader and function parameters can be output");
    }
    decl->symbol = s;
    decl->detail = s->detail;
    if (Node* init = decl->Initialiser()) {
        if (s->detail == Detail::Uniform) UniformRandomIn(init);
        if (init->kind == NodeKind::InitList) {
            if (!decl->declType.IsArray()) {
                Error(init, "a {...} initialiser needs an array");
            } else if (int(init->Elements().size()) != decl->declType.arrayLength) {
                Error(init, "array '" + decl->name + "' has " +
                                std::to_string(decl->declType.arrayLength) + " elements, the " +
                                "initialiser " + std::to_string(init->Elements().size()));
            }
            TypeSpec element = decl->declType;
            element.arrayLength = 0;
            for (Node* k : init->Elements()) {
                CheckExpr(k, ctx, &element);
                Coerce(k, element, "in the initialiser of '" + decl->name + "'");
                init->varying = init->varying || k->varying;
            }
            init->type = decl->declType;
        } else {
            CheckExpr(init, ctx, &decl->declType);
            Coerce(init, decl->declType, "in the initialiser of '" + decl->name + "'");
        }
        if (init->varying && s->detail == Detail::Uniform && !init->hasError) {
            Error(init, "cannot initialise uniform '" + decl->name + "' with a varying value");
        }
    }
    if (!symbols_.Declare(s)) Error(decl, "'" + decl->name + "' is already declared in this scope");
}

void TypeChecker::CheckBlock(Node* block, Context& ctx, bool newScope) {
    if (newScope) symbols_.Push();
    for (Node* s : block->Statements()) CheckStatement(s, ctx);
    if (newScope) symbols_.Pop();
}

void TypeChecker::CheckCondition(Node* cond, Context& ctx) {
    CheckExpr(cond, ctx);
    if (cond->hasError || cond->boolean) return;
    if (cond->type.base != BaseType::Float || cond->type.IsArray()) {
        Error(cond, "a condition must be a comparison or a float, not " + ToString(cond->type));
    }
}

void TypeChecker::CheckStatement(Node* s, Context& ctx) {
    if (!s) return;
    switch (s->kind) {
        case NodeKind::Block:
            if (s->IsDeclaration()) {
                for (Node* d : s->Statements()) CheckDeclaration(d, ctx, SymbolKind::Local);
            } else {
                CheckBlock(s, ctx);
            }
            break;
        case NodeKind::FunctionDef:
            symbols_.DeclareFunction(s);
            CheckFunctionDef(s, ctx);
            break;
        case NodeKind::ExprStmt:
            CheckExpr(s->Expression(), ctx);
            break;
        case NodeKind::If: {
            CheckCondition(s->Condition(), ctx);
            int v = s->Condition()->varying ? 1 : 0;
            ctx.varyingConditions += v;
            CheckStatement(s->Then(), ctx);
            CheckStatement(s->Else(), ctx);
            ctx.varyingConditions -= v;
            break;
        }
        case NodeKind::While:
        case NodeKind::For: {
            bool isFor = s->kind == NodeKind::For;
            Node* cond = s->Condition();
            if (isFor && s->Init()) CheckExpr(s->Init(), ctx);
            if (cond) CheckCondition(cond, ctx);
            int v = cond && cond->varying ? 1 : 0;
            ctx.varyingConditions += v;
            ++ctx.loops;
            if (isFor && s->Step()) CheckExpr(s->Step(), ctx);
            CheckStatement(s->Body(), ctx);
            --ctx.loops;
            ctx.varyingConditions -= v;
            break;
        }
        case NodeKind::Break:
        case NodeKind::Continue:
            if (s->op < 1 || s->op > ctx.loops) {
                Error(s,
                      std::string(s->kind == NodeKind::Break ? "break" : "continue") +
                          (s->op > 1 ? " " + std::to_string(s->op) : "") +
                          (ctx.loops ? " leaves more loops than enclose it" : " outside a loop"));
            }
            break;
        case NodeKind::Return: {
            if (!ctx.function) {
                Error(s, "return outside a function");
                break;
            }
            TypeSpec want = ctx.function->declType;
            Node* value = s->Expression();
            if (!value) {
                if (want.base != BaseType::Void)
                    Error(s, "return needs a value of type " + ToString(want));
                break;
            }
            CheckExpr(value, ctx, &want);
            if (want.base == BaseType::Void) {
                Error(value, "a void function cannot return a value");
            } else {
                Coerce(value, want, "in return");
            }
            break;
        }
        case NodeKind::Illuminance:
        case NodeKind::Illuminate:
        case NodeKind::Solar:
            CheckLightLoop(s, ctx);
            break;
        default:
            Error(s, "unexpected statement");
    }
}

void TypeChecker::CheckLightLoop(Node* s, Context& ctx) {
    const std::vector<Node*> args = s->LightLoopArguments();
    const size_t argCount = args.size();
    for (Node* a : args) CheckExpr(a, ctx);
    auto expect = [&](size_t i, BaseType base, const char* what) {
        if (i < args.size() && !args[i]->hasError) Coerce(args[i], MakeType(base), what);
    };
    if (s->kind == NodeKind::Illuminance) {
        if (shaderType_ != ShaderType::Surface && shaderType_ != ShaderType::Volume) {
            Error(s, "illuminance is only allowed in surface and volume shaders");
        }
        if (ctx.inIlluminance) Error(s, "illuminance statements cannot nest");
        bool category = argCount > 0 && args[0]->type.base == BaseType::String;
        size_t first = category ? 1 : 0;
        size_t rest = argCount - first;
        if (rest != 1 && rest != 3) {
            Error(s, "illuminance expects ([category,] P) or ([category,] P, axis, angle)");
        } else {
            expect(first, BaseType::Point, "illuminance position");
            if (rest == 3) {
                expect(first + 1, BaseType::Vector, "illuminance axis");
                expect(first + 2, BaseType::Float, "illuminance angle");
            }
        }
    } else if (s->kind == NodeKind::Illuminate) {
        if (shaderType_ != ShaderType::Light)
            Error(s, "illuminate is only allowed in light shaders");
        if (argCount != 1 && argCount != 3) {
            Error(s, "illuminate expects (from) or (from, axis, angle)");
        } else {
            expect(0, BaseType::Point, "illuminate position");
            if (argCount == 3) {
                expect(1, BaseType::Vector, "illuminate axis");
                expect(2, BaseType::Float, "illuminate angle");
            }
        }
    } else {
        if (shaderType_ != ShaderType::Light) Error(s, "solar is only allowed in light shaders");
        if (argCount != 0 && argCount != 2) {
            Error(s, "solar expects () or (axis, angle)");
        } else if (argCount == 2) {
            expect(0, BaseType::Vector, "solar axis");
            expect(1, BaseType::Float, "solar angle");
        }
    }
    for (Node* a : args) {
        if (a->type.base == BaseType::String && a->varying)
            Error(a, "the category must be uniform");
    }
    Context inner = ctx;
    inner.varyingConditions += 1;
    inner.loops += s->kind == NodeKind::Illuminance ? 1 : 0;
    inner.inIlluminance = inner.inIlluminance || s->kind == NodeKind::Illuminance;
    CheckStatement(s->Body(), inner);
}

}  // namespace gonio::sl
