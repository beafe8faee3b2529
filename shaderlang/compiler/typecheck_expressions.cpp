// The type checker's expressions and calls (typecheck.h): identifiers, tuples, operators,
// assignments, casts, and overload resolution of user functions and built-ins.

#include <cmath>

#include "shaderlang/compiler/typecheck.h"
#include "shaderlang/compiler/uniform_random.h"
#include "shaderlang/runtime/builtin_table.h"
#include "shaderlang/runtime/global_vars.h"

namespace gonio::sl {

namespace {

bool IsNumeric(const TypeSpec& t) {
    return !t.IsArray() &&
           (t.base == BaseType::Float || t.IsTriple() || t.base == BaseType::Matrix);
}

std::string OperatorName(int op) {
    switch (op) {
        case kOpEq:
            return "==";
        case kOpNe:
            return "!=";
        case kOpLe:
            return "<=";
        case kOpGe:
            return ">=";
        case kOpAnd:
            return "&&";
        case kOpOr:
            return "||";
        default:
            return std::string(1, char(op));
    }
}

bool IsTexture(const std::string& name) {
    return name == "texture" || name == "environment" || name == "shadow";
}

// The cost of passing `a` for a parameter of type `want` (TypeChecker::ConversionCost), -1 when
// it cannot be passed: an output parameter takes its own type or, by reference, another
// point-like type.
int ArgumentCost(const TypeSpec& want, bool output, const Node* a) {
    int c = TypeChecker::ConversionCost(want, a->type, a->kind == NodeKind::Tuple);
    if (output && c != 0 && !(want.IsPointLike() && a->type.IsPointLike())) return -1;
    return c;
}

// "float, point, ...": the types of a call's arguments, for error messages.
std::string ArgumentTypes(const std::vector<Node*>& args) {
    std::string types;
    for (const Node* a : args) types += (types.empty() ? "" : ", ") + ToString(a->type);
    return types;
}

}  // namespace

void TypeChecker::CheckExpr(Node* e, Context& ctx, const TypeSpec* expected) {
    e->type = MakeType(BaseType::Float);
    switch (e->kind) {
        case NodeKind::Number:
            break;
        case NodeKind::String:
            e->type = MakeType(BaseType::String);
            break;
        case NodeKind::Identifier:
            CheckIdentifier(e, ctx);
            break;
        case NodeKind::Tuple:
            CheckTuple(e, ctx, expected);
            break;
        case NodeKind::InitList:
            Error(e, "a {...} list can only initialise an array");
            e->hasError = true;
            break;
        case NodeKind::Unary: {
            Node* a = e->Operand();
            CheckExpr(a, ctx);
            e->varying = a->varying;
            e->type = a->type;
            if (a->hasError) {
                e->hasError = true;
            } else if (e->op == '!') {
                if (!a->boolean) Error(e, "'!' needs a comparison");
                e->boolean = true;
            } else if (!NotBoolean(a)) {
                e->hasError = true;
            } else if (!IsNumeric(a->type)) {
                Error(e, "cannot negate a " + ToString(a->type));
                e->hasError = true;
            }
            break;
        }
        case NodeKind::Binary:
            CheckBinary(e, ctx);
            break;
        case NodeKind::Assign:
            CheckAssign(e, ctx);
            break;
        case NodeKind::Ternary: {
            Node* a = e->Then();
            Node* b = e->Else();
            CheckCondition(e->Condition(), ctx);
            CheckExpr(a, ctx, expected);
            CheckExpr(b, ctx, expected);
            e->varying = e->Condition()->varying || a->varying || b->varying;
            if (a->hasError || b->hasError || !NotBoolean(a) || !NotBoolean(b)) {
                e->hasError = true;
                break;
            }
            if (ConversionCost(a->type, b->type, b->kind == NodeKind::Tuple) >= 0) {
                e->type = a->type;
            } else if (ConversionCost(b->type, a->type, a->kind == NodeKind::Tuple) >= 0) {
                e->type = b->type;
            } else {
                Error(e, "the branches of ?: have different types, " + ToString(a->type) + " and " +
                             ToString(b->type));
                e->hasError = true;
                break;
            }
            Coerce(a, e->type, "in ?:");
            Coerce(b, e->type, "in ?:");
            break;
        }
        case NodeKind::Call:
            CheckCall(e, ctx, expected);
            break;
        case NodeKind::Index: {
            Node* array = e->Array();
            Node* index = e->Subscript();
            CheckExpr(array, ctx);
            CheckExpr(index, ctx);
            e->varying = array->varying || index->varying;
            if (array->hasError || index->hasError) {
                e->hasError = true;
                break;
            }
            if (!array->type.IsArray()) {
                Error(e, "'" + (array->kind == NodeKind::Identifier ? array->name : "value") +
                             "' is not an array");
                e->hasError = true;
                break;
            }
            if (index->type != MakeType(BaseType::Float) || index->boolean) {
                Error(index, "an array index must be a float");
            }
            e->type = MakeType(array->type.base);
            break;
        }
        case NodeKind::Cast:
            CheckCast(e, ctx);
            break;
        default:
            Error(e, "unexpected expression");
            e->hasError = true;
    }
}

void TypeChecker::CheckIdentifier(Node* e, Context& ctx) {
    Symbol* s = symbols_.Find(e->name);
    if (!s) {
        for (int type = 0; type < 5; ++type) {
            if (FindGlobal(e->name, ShaderType(type)) >= 0) {
                Error(e, "'" + e->name + "' is not available in " + ToString(shaderType_) +
                             " shaders");
                e->hasError = true;
                return;
            }
        }
        Error(e, "unknown variable '" + e->name + "'");
        e->hasError = true;
        return;
    }
    if (ctx.functionDepth > 0 && s->functionDepth < ctx.functionDepth &&
        (s->kind == SymbolKind::Local || s->kind == SymbolKind::Param ||
         s->kind == SymbolKind::Formal)) {
        Error(e, "'" + e->name + "' belongs to an enclosing scope: declare it extern");
        e->hasError = true;
        return;
    }
    auto ext = externs_.find(s);
    if (ext != externs_.end()) s = ext->second;
    e->symbol = s;
    e->type = s->type;
    e->varying = s->detail == Detail::Varying;
    if (ctx.function && e->varying && (s->kind == SymbolKind::Global || ext != externs_.end())) {
        ctx.function->varying = true;  // the function's result depends on varying state
    }
}

void TypeChecker::CheckTuple(Node* e, Context& ctx, const TypeSpec* expected) {
    for (Node* k : e->Elements()) {
        CheckExpr(k, ctx);
        e->varying = e->varying || k->varying;
        if (k->hasError) {
            e->hasError = true;
        } else if (!NotBoolean(k) || k->type != MakeType(BaseType::Float)) {
            if (!k->boolean)
                Error(k, "the elements of (a, b, c) must be floats, not " + ToString(k->type));
            e->hasError = true;
        }
    }
    int count = int(e->Elements().size());
    if (expected && expected->IsTriple() && !expected->IsArray() &&
        count == (expected->base == BaseType::Color ? colorComponents_ : 3)) {
        e->type = *expected;
    } else if (count == 3) {
        e->type = MakeType(BaseType::Point);
    } else if (count == 16) {
        e->type = MakeType(BaseType::Matrix);
    } else if (count == colorComponents_) {
        e->type = MakeType(BaseType::Color);
    } else {
        Error(e, "a tuple has 3 (point, vector, normal, color), " +
                     std::to_string(colorComponents_) + " (color) or 16 (matrix) elements, not " +
                     std::to_string(count));
        e->hasError = true;
    }
}

void TypeChecker::CheckBinary(Node* e, Context& ctx) {
    Node* a = e->Lhs();
    Node* b = e->Rhs();
    CheckExpr(a, ctx);
    CheckExpr(b, ctx);
    e->varying = a->varying || b->varying;
    if (a->hasError || b->hasError) {
        e->hasError = true;
        return;
    }
    const int op = e->op;
    const std::string opName = "'" + OperatorName(op) + "'";
    auto fail = [&](const std::string& message) {
        Error(e, message);
        e->hasError = true;
    };
    if (op == kOpAnd || op == kOpOr) {
        for (Node* k : {a, b}) {
            if (!k->boolean && k->type != MakeType(BaseType::Float)) {
                return fail(opName + " needs comparisons, not " + ToString(k->type));
            }
        }
        e->boolean = true;
        return;
    }
    if (!NotBoolean(a) || !NotBoolean(b)) {
        e->hasError = true;
        return;
    }
    const TypeSpec ta = a->type, tb = b->type;
    if (ta.IsArray() || tb.IsArray()) return fail("cannot apply " + opName + " to arrays");
    if (op == '<' || op == '>' || op == kOpLe || op == kOpGe) {
        if (ta.base != BaseType::Float || tb.base != BaseType::Float) {
            return fail(opName + " compares floats, not " + ToString(ta) + " and " + ToString(tb));
        }
        e->boolean = true;
        return;
    }
    if (op == kOpEq || op == kOpNe) {
        bool strings = ta.base == BaseType::String && tb.base == BaseType::String;
        if (!strings && (ConversionCost(ta, tb, b->kind == NodeKind::Tuple) < 0 &&
                         ConversionCost(tb, ta, a->kind == NodeKind::Tuple) < 0)) {
            return fail("cannot compare " + ToString(ta) + " with " + ToString(tb));
        }
        if (ConversionCost(ta, tb, false) < 0 && !strings) Coerce(a, tb, "in " + opName);
        e->boolean = true;
        return;
    }
    if (ta.base == BaseType::String || tb.base == BaseType::String) {
        return fail("cannot apply " + opName + " to strings");
    }
    if (op == '.' || op == '^') {
        bool ok = op == '.' ? ((ta.IsPointLike() && tb.IsPointLike()) ||
                               (ta.base == BaseType::Color && tb.base == BaseType::Color))
                            : (ta.IsPointLike() && tb.IsPointLike());
        if (!ok) {
            return fail(std::string(op == '.' ? "the dot product '.'" : "the cross product '^'") +
                        " needs two " + (op == '.' ? "vectors or two colors" : "vectors") +
                        ", not " + ToString(ta) + " and " + ToString(tb));
        }
        e->type = op == '.' ? MakeType(BaseType::Float) : MakeType(BaseType::Vector);
        return;
    }
    // + - * /: per component, with floats promoted; matrices multiply and divide.
    bool ma = ta.base == BaseType::Matrix, mb = tb.base == BaseType::Matrix;
    if (ma || mb) {
        bool other = ma ? tb.base == BaseType::Float || mb : ta.base == BaseType::Float || ma;
        if (!other)
            return fail("cannot apply " + opName + " to " + ToString(ta) + " and " + ToString(tb));
        e->type = MakeType(BaseType::Matrix);
        return;
    }
    if (ta.base == BaseType::Float) {
        e->type = tb;
    } else if (tb.base == BaseType::Float || ta.base == tb.base ||
               (ta.IsPointLike() && tb.IsPointLike())) {
        e->type = ta;
    } else if (a->kind == NodeKind::Tuple && tb.IsTriple()) {
        e->type = tb;
        Coerce(a, tb, "in " + opName);
    } else if (b->kind == NodeKind::Tuple && ta.IsTriple()) {
        e->type = ta;
        Coerce(b, ta, "in " + opName);
    } else {
        return fail("cannot apply " + opName + " to " + ToString(ta) + " and " + ToString(tb) +
                    (ta.base == BaseType::Color || tb.base == BaseType::Color
                         ? " (points and colors do not mix)"
                         : ""));
    }
}

bool TypeChecker::CheckLvalue(Node* target, Context& ctx, bool varyingValue) {
    Node* var = target->kind == NodeKind::Index ? target->Array() : target;
    if (var->kind != NodeKind::Identifier) {
        Error(target, "can only assign to a variable or an array element");
        return false;
    }
    Symbol* s = var->symbol;
    if (!s) return false;
    if (s->kind == SymbolKind::Constant || s->readOnly) {
        if (s->kind == SymbolKind::Formal) {
            Error(target, "cannot assign to '" + s->name + "': it is not an output parameter");
        } else {
            Error(target,
                  "cannot assign to '" + s->name + "'" +
                      (s->kind == SymbolKind::Global ? std::string(": it is read-only in ") +
                                                           ToString(shaderType_) + " shaders"
                                                     : ""));
        }
        return false;
    }
    if (s->detail == Detail::Uniform) {
        if (varyingValue) {
            Error(target, "cannot assign a varying value to uniform '" + s->name + "'");
            return false;
        }
        if (ctx.varyingConditions > 0 && s->functionDepth == ctx.functionDepth) {
            Error(target, "cannot assign to uniform '" + s->name +
                              "' under a varying condition (it would differ between points)");
            return false;
        }
    }
    return true;
}

void TypeChecker::UniformRandomIn(Node* value) {
    if (symbols_.FindFunctions("random").empty()) MakeRandomUniform(value);
}

void TypeChecker::CheckAssign(Node* e, Context& ctx) {
    Node* target = e->Target();
    Node* value = e->Value();
    CheckExpr(target, ctx);
    if (!target->hasError && !target->varying) UniformRandomIn(value);
    CheckExpr(value, ctx, &target->type);
    e->type = target->type;
    e->varying = target->varying;
    if (target->hasError || value->hasError) {
        e->hasError = true;
        return;
    }
    if (e->op == '=') {
        if (Coerce(value, target->type,
                   "in the assignment to " + std::string(target->kind == NodeKind::Identifier
                                                             ? "'" + target->name + "'"
                                                             : "an array element"))) {
            CheckLvalue(target, ctx, value->varying);
        }
        return;
    }
    // a op= b is a = a op b: check the operation, then the store.
    if (!NotBoolean(value)) return;
    const TypeSpec ta = target->type, tb = value->type;
    bool ok = IsNumeric(ta) && IsNumeric(tb) &&
              (tb.base == BaseType::Float || ta.base == tb.base ||
               (ta.IsPointLike() && tb.IsPointLike()) ||
               (value->kind == NodeKind::Tuple && ta.IsTriple()) ||
               (ta.base == BaseType::Matrix && (e->op == '*' || e->op == '/')));
    if (ta.base == BaseType::Matrix && tb.base != BaseType::Matrix && tb.base != BaseType::Float)
        ok = false;
    if (!ok) {
        Error(e, "cannot apply '" + OperatorName(e->op) + "=' to " + ToString(ta) + " and " +
                     ToString(tb));
        e->hasError = true;
        return;
    }
    if (value->kind == NodeKind::Tuple) Coerce(value, ta, "in the assignment");
    CheckLvalue(target, ctx, value->varying || target->varying);
}

void TypeChecker::CheckCast(Node* e, Context& ctx) {
    Node* operand = e->Operand();
    const TypeSpec to = e->declType;
    CheckExpr(operand, ctx, &to);
    e->type = to;
    e->varying = operand->varying;
    if (operand->hasError) {
        e->hasError = true;
        return;
    }
    if (!NotBoolean(operand)) {
        e->hasError = true;
        return;
    }
    const TypeSpec from = operand->type;
    bool tuple = operand->kind == NodeKind::Tuple;
    bool ok = from.base == to.base ||
              (from.base == BaseType::Float && to.base != BaseType::String) ||
              (from.IsTriple() && to.IsTriple());
    if (to.base == BaseType::Float && from.base != BaseType::Float) ok = false;
    if (!ok || from.IsArray()) {
        Error(e, "cannot cast " + ToString(from) + " to " + ToString(to));
        e->hasError = true;
        return;
    }
    if (!tuple && !ColorTripleConversion(from, to, e)) {
        e->hasError = true;
        return;
    }
    if (tuple) Coerce(operand, to, "in the cast");
    if (!e->name.empty() && !(to.IsTriple() || to.base == BaseType::Matrix)) {
        Error(e, "only points, vectors, normals, colors and matrices take a space name");
        e->hasError = true;
    }
}

void TypeChecker::CheckCall(Node* e, Context& ctx, const TypeSpec* expected) {
    // texture("name"[channel], ...): the [channel] after the name selects the first channel.
    std::vector<Node*>& args = e->Arguments();
    if (IsTexture(e->name) && !args.empty() && args[0]->kind == NodeKind::Index) {
        Node* index = args[0];
        CheckExpr(index->Array(), ctx);
        if (index->Array()->type == MakeType(BaseType::String)) {
            Node* option = tree_.Make(NodeKind::String, index->loc);
            option->name = "firstchannel";
            args[0] = index->Array();
            args.push_back(option);
            args.push_back(index->Subscript());
        }
    }
    bool hasError = false;
    for (Node* a : args) {
        CheckExpr(a, ctx);
        hasError = hasError || a->hasError;
        e->varying = e->varying || a->varying;
    }
    if (hasError) {
        e->hasError = true;
        return;
    }
    for (Node* a : args) {
        if (!NotBoolean(a)) {
            e->hasError = true;
            return;
        }
    }
    std::vector<Node*> functions = symbols_.FindFunctions(e->name);
    if (functions.empty() && e->name == "arraylength") {
        CheckArrayLength(e);
        return;
    }
    if (!functions.empty()) {
        if (CheckUserCall(e, functions)) {
            if (e->hasError) return;
            for (size_t i = 0; i < args.size(); ++i) {
                Node* formal = e->function->Formals()[i];
                if (formal->output) CheckLvalue(args[i], ctx, e->varying);
            }
            return;
        }
    }
    if (!CheckBuiltinCall(e, ctx, expected)) e->hasError = true;
}

// arraylength(a) (RSL 2, PRMan and Pixie): arrays have fixed lengths here, so it is a constant,
// the code generator's (an unsized formal's is its argument's, known where the call is inlined).
void TypeChecker::CheckArrayLength(Node* e) {
    const std::vector<Node*>& args = e->Arguments();
    if (args.size() != 1 || !args[0]->type.IsArray()) {
        Error(e, "arraylength() takes one array, not (" + ArgumentTypes(args) + ")");
        e->hasError = true;
        return;
    }
    e->type = MakeType(BaseType::Float);
    e->varying = false;
}

bool TypeChecker::CheckUserCall(Node* e, const std::vector<Node*>& candidates) {
    const std::vector<Node*>& args = e->Arguments();
    Node* best = nullptr;
    int bestCost = 1 << 30;
    for (Node* f : candidates) {
        const std::vector<Node*>& formals = f->Formals();
        if (formals.size() != args.size()) continue;
        int cost = 0;
        for (size_t i = 0; i < formals.size() && cost >= 0; ++i) {
            int c = ArgumentCost(formals[i]->declType, formals[i]->output, args[i]);
            cost = c < 0 ? -1 : cost + c;
        }
        if (cost >= 0 && cost < bestCost) {
            best = f;
            bestCost = cost;
        }
    }
    if (!best) {
        // Fall back to the built-ins of the same name before reporting.
        if (!BuiltinRowsNamed(e->name).empty()) return false;
        Error(e, "no version of function '" + e->name + "' takes (" + ArgumentTypes(args) + ")");
        e->hasError = true;
        return true;
    }
    e->function = best;
    e->type = best->declType;
    for (size_t i = 0; i < args.size(); ++i) {
        Coerce(args[i], best->Formals()[i]->declType, "in the call of '" + e->name + "'");
    }
    e->varying =
        e->varying || best->varying || (best->hasDetail && best->detail == Detail::Varying);
    if (best->hasDetail && best->detail == Detail::Uniform) e->varying = false;
    return true;
}

bool TypeChecker::CheckBuiltinCall(Node* e, Context& ctx, const TypeSpec* expected) {
    const std::vector<Node*>& args = e->Arguments();
    const std::vector<int>& rows = BuiltinRowsNamed(e->name);
    if (rows.empty()) {
        Error(e, "unknown function '" + e->name + "'");
        return false;
    }
    int best = -1;
    int bestCost = 1 << 30;
    for (int row : rows) {
        const BuiltinSignature& sig = BuiltinSignatureOf(row);
        const std::vector<BuiltinParameter>& params = sig.parameters;
        if (params.size() > args.size() || (!sig.varargs && params.size() != args.size())) {
            continue;
        }
        int cost = 0;
        for (size_t i = 0; i < params.size() && cost >= 0; ++i) {
            const BuiltinParameter& param = params[i];
            const Node* a = args[i];
            if (param.array) {
                if (!a->type.IsArray() || a->type.base != param.type.base) cost = -1;
                continue;
            }
            int c = ArgumentCost(param.type, param.output, a);
            cost = c < 0 ? -1 : cost + c * 4;
        }
        if (cost < 0) continue;
        if (expected && expected->base != BaseType::Void && sig.result.base != expected->base) {
            cost += ConversionCost(*expected, sig.result, false) >= 0 ? 1 : 2;
        }
        if (cost < bestCost) {
            bestCost = cost;
            best = row;
        }
    }
    if (best < 0) {
        std::string candidates;
        for (size_t k = 0; k < rows.size() && k < 4; ++k) {
            const BuiltinSignature& sig = BuiltinSignatureOf(rows[k]);
            std::string params;
            for (const BuiltinParameter& param : sig.parameters) {
                params += std::string(params.empty() ? "" : ", ") +
                          (param.output ? "output " : "") + ToString(param.type.base) +
                          (param.array ? "[]" : "");
            }
            if (sig.varargs) params += std::string(params.empty() ? "" : ", ") + "...";
            candidates +=
                std::string(candidates.empty() ? "" : "; ") + e->name + "(" + params + ")";
        }
        Error(e, "no version of '" + e->name + "' takes (" + ArgumentTypes(args) + "); it takes " +
                     candidates + (rows.size() > 4 ? " ..." : ""));
        return false;
    }
    const BuiltinInfo& info = BuiltinTable()[size_t(best)];
    const std::vector<BuiltinParameter>& params = BuiltinSignatureOf(best).parameters;
    e->builtin = best;
    e->type = BuiltinSignatureOf(best).result;
    if (info.flags & (kVaryingResult | kReadsGlobals | kUsesLights | kNeedsDerivatives)) {
        e->varying = true;
        // A function that calls random() differs between points even without varying
        // arguments, as one that reads a varying global does (CheckIdentifier).
        if (ctx.function) ctx.function->varying = true;
    }
    for (size_t i = 0; i < params.size(); ++i) {
        if (params[i].output) {
            CheckLvalue(args[i], ctx, e->varying);
        } else if (!params[i].array) {
            Coerce(args[i], params[i].type,
                   "argument " + std::to_string(i + 1) + " of '" + e->name + "'");
        }
    }
    if (info.flags & (kOutputOptions | kOutputPairs))
        CheckOutputOptions(e, info.flags, params.size(), ctx);
    return true;
}

// Output options among a call's options (IsOutputOption): occlusion's ("environmentcolor", c)
// writes the colour variable c, texture3d's ("name", v) any numeric variable v. With
// kOutputPairs the options come in pairs, so only every second argument names one.
void TypeChecker::CheckOutputOptions(Node* e, unsigned flags, size_t first, Context& ctx) {
    const std::vector<Node*>& args = e->Arguments();
    const bool pairs = flags & kOutputPairs;
    for (size_t a = first; a + 1 < args.size(); a += pairs ? 2 : 1) {
        const Node* name = args[a];
        if (name->kind != NodeKind::String || !IsOutputOption(flags, name->name)) continue;
        Node* target = args[a + 1];
        const bool typeOk = pairs ? target->type.base != BaseType::String && !target->type.IsArray()
                                  : target->type.base == BaseType::Color;
        if (target->kind != NodeKind::Identifier || !typeOk) {
            Error(target, "the value of option \"" + name->name + "\" of '" + e->name + "' is a " +
                              (pairs ? "float, color or point-like" : "color") +
                              " variable it writes");
            continue;
        }
        CheckLvalue(target, ctx, true);
    }
}

}  // namespace gonio::sl
