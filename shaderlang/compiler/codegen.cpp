#include "shaderlang/compiler/codegen.h"

#include <cstdio>

#include "shaderlang/compiler/parser.h"
#include "shaderlang/runtime/builtin_table.h"
#include "shaderlang/runtime/global_vars.h"

namespace gonio::sl {

namespace {

TypeSpec FloatType() {
    TypeSpec t;
    t.base = BaseType::Float;
    return t;
}

}  // namespace

CodeGenerator::CodeGenerator(const SyntaxTree& tree, const TypeChecker& checker,
                             Diagnostics& diagnostics, int colorComponents)
    : tree_(tree),
      checker_(checker),
      diagnostics_(diagnostics),
      colorComponents_(colorComponents) {}

int CodeGenerator::NewReg(const TypeSpec& type, bool varying, const std::string& name,
                          bool temporary) {
    Register r;
    r.type = type;
    r.varying = varying;
    r.isString = type.base == BaseType::String;
    const int elements = type.IsArray() ? type.arrayLength : 1;
    r.width = r.isString ? elements : type.Width(colorComponents_) * elements;
    r.name = name;
    r.temporary = temporary;
    p_->regs.push_back(r);
    return int(p_->regs.size()) - 1;
}

int CodeGenerator::Constant(const std::vector<float>& values, const TypeSpec& type) {
    std::string key = ToString(type);
    char buffer[32];
    for (float v : values) {
        std::snprintf(buffer, sizeof(buffer), " %a", double(v));
        key += buffer;
    }
    auto it = constants_.find(key);
    if (it != constants_.end()) return it->second;
    int r = NewReg(type, false);
    p_->regs[r].constant = true;
    p_->regs[r].constOffset = p_->AddConstant(values, type);
    p_->regs[r].fixedDetail = true;
    constants_[key] = r;
    return r;
}

int CodeGenerator::Constant(float value) { return Constant({value}, FloatType()); }

int CodeGenerator::StringConstant(const std::string& text) {
    std::string key = "\"" + text;
    auto it = constants_.find(key);
    if (it != constants_.end()) return it->second;
    TypeSpec t;
    t.base = BaseType::String;
    int r = NewReg(t, false);
    p_->regs[r].constant = true;
    p_->regs[r].constOffset = p_->AddStringConstant({text});
    p_->regs[r].fixedDetail = true;
    constants_[key] = r;
    return r;
}

// Kernels flagged kReadsGlobals read globals the shader need not name (texture() without
// coordinates reads s and t, the derivative kernels du and dv): they must have registers. du and
// dv only for kernels that take derivatives: the renderer shades neighbour points for shaders
// that read them. Ng is left out on purpose: faceforward(N, I) then falls back to N as its
// reference, which the conformance scenes need while the renderer's Ng can disagree with
// user-supplied N (Bugs_BugThreeLights goes black with Ng as reference).
void CodeGenerator::ImplicitGlobals(unsigned flags) {
    std::vector<const char*> names = {"s", "t"};
    if (flags & kNeedsDerivatives) names.insert(names.end(), {"du", "dv"});
    for (const char* name : names) {
        const int id = FindGlobal(name, checker_.Type());
        if (id >= 0) GlobalReg(id);
    }
}

int CodeGenerator::GlobalReg(int id) {
    if (p_->globals[id] >= 0) return p_->globals[id];
    const GlobalVarInfo& g = GlobalVar(id);
    TypeSpec t;
    t.base = g.type;
    int r = NewReg(t, g.varying, g.name, false);
    p_->regs[r].global = id;
    p_->regs[r].fixedDetail = true;
    p_->globals[id] = r;
    p_->named[g.name] = r;
    return r;
}

void CodeGenerator::SetLoc(const Node* n) {
    FileLoc fl = ToFileLoc(tree_, n->loc);
    std::string key = (fl.file ? *fl.file : std::string("?")) + ":" + std::to_string(fl.line);
    auto it = locIndex_.find(key);
    if (it == locIndex_.end()) {
        it = locIndex_.emplace(key, int(p_->locations.size())).first;
        p_->locations.push_back(key);
    }
    loc_ = it->second;
}

int CodeGenerator::Emit(Op op, std::initializer_list<int> args, int extra, int jump) {
    if (p_->code.size() == kMaxInstructions && ok_) {
        diagnostics_.Error(ToFileLoc(tree_, current_ ? current_->loc : SourceLoc{}),
                           "the shader is larger than " + std::to_string(kMaxInstructions) +
                               " instructions once its functions are inlined (functions that "
                               "call others several times, nested?)");
        ok_ = false;
    }
    Instr in;
    in.op = uint16_t(op);
    in.depth = uint8_t(depth_);
    in.argCount = uint8_t(args.size());
    int k = 0;
    for (int a : args) in.args[k++] = a;
    in.extra = extra;
    in.jump = jump;
    in.loc = loc_;
    in.region = region_;
    p_->code.push_back(in);
    return int(p_->code.size()) - 1;
}

bool CodeGenerator::DepthAvailable(const Node* at, int entries) {
    // Instr::depth is one byte: mask stacks deeper than that are refused (never seen in a
    // real shader; a fuzzer finds them).
    if (depth_ + entries < 250) return true;
    if (ok_) {
        diagnostics_.Error(ToFileLoc(tree_, at->loc), "control flow is nested too deeply");
    }
    ok_ = false;
    return false;
}

int CodeGenerator::PushRegion(int condition, bool alwaysVarying) {
    Region r;
    r.parent = region_;
    r.condition = condition;
    r.alwaysVarying = alwaysVarying;
    p_->regions.push_back(r);
    region_ = int(p_->regions.size()) - 1;
    return region_;
}

bool CodeGenerator::Generate(Node* shader, Program* program) {
    p_ = program;
    p_->locations.push_back("?");
    SetLoc(shader);
    // Parameters: each default is computed by its own code range, which an instance override
    // replaces (see ShaderInstance::Specialize).
    for (Node* formal : shader->Formals()) {
        const Symbol* s = formal->symbol;
        if (!s) continue;
        int reg = NewReg(s->type, s->detail == Detail::Varying, s->name, false);
        p_->regs[reg].param = s->param;
        p_->regs[reg].fixedDetail = s->detail == Detail::Uniform || s->output;
        regOf_[s] = reg;
        p_->named[s->name] = reg;
        ParamCode code;
        code.reg = reg;
        code.initBegin = int(p_->code.size());
        if (Node* init = formal->Initialiser()) {
            SetLoc(init);
            Initialise(reg, init, s->type);
        }
        code.initEnd = int(p_->code.size());
        if (int(p_->params.size()) <= s->param) p_->params.resize(size_t(s->param) + 1);
        p_->params[s->param] = code;
    }
    for (Node* s : shader->Body()->Statements()) {
        if (s->IsDeclaration()) {
            for (Node* d : s->Statements()) Declare(d, true);
        } else {
            Statement(s);
        }
    }
    // Outputs and light-loop globals exist even when the code never names them.
    const ShaderType type = checker_.Type();
    if (type == ShaderType::Surface || type == ShaderType::Volume || type == ShaderType::Imager) {
        GlobalReg(kGlobalCi);
        GlobalReg(kGlobalOi);
    } else if (type == ShaderType::Light) {
        GlobalReg(kGlobalL);
        GlobalReg(kGlobalCl);
        GlobalReg(kGlobalOl);
    } else if (type == ShaderType::Displacement) {
        GlobalReg(kGlobalP);
        GlobalReg(kGlobalN);
    }
    return ok_;
}

void CodeGenerator::Declare(Node* decl, bool topLevel) {
    if (decl->isExtern || !decl->symbol) return;
    const Symbol* s = decl->symbol;
    SetLoc(decl);
    bool declaredUniform = decl->hasDetail && decl->detail == Detail::Uniform;
    int reg = NewReg(s->type, !declaredUniform, s->name, false);
    p_->regs[reg].fixedDetail = declaredUniform;
    if (topLevel) p_->named[s->name] = reg;
    if (Node* init = decl->Initialiser()) Initialise(reg, init, s->type);
    regOf_[s] = reg;  // after the initialiser, which may name an outer variable of that name
}

void CodeGenerator::Initialise(int reg, Node* init, const TypeSpec& type) {
    if (init->kind != NodeKind::InitList) {
        StoreTo(reg, ExprAs(init, type));
        return;
    }
    TypeSpec element = type;
    element.arrayLength = 0;
    const std::vector<Node*>& elements = init->Elements();
    for (size_t k = 0; k < elements.size(); ++k) {
        int v = ExprAs(elements[k], element);
        Emit(Op::IndexWrite, {reg, Constant(float(k)), v});
    }
}

void CodeGenerator::Statement(Node* s) {
    if (!s) return;
    SetLoc(s);
    switch (s->kind) {
        case NodeKind::Block:
            if (s->IsDeclaration()) {
                for (Node* d : s->Statements()) Declare(d, false);
            } else {
                for (Node* k : s->Statements()) Statement(k);
            }
            break;
        case NodeKind::ExprStmt:
            Expr(s->Expression());
            break;
        case NodeKind::If:
            If(s);
            break;
        case NodeKind::While:
        case NodeKind::For:
            Loop(s);
            break;
        case NodeKind::Break:
        case NodeKind::Continue:
        case NodeKind::Return:
            Exit(s);
            break;
        default:
            if (s->IsLightLoop()) LightLoop(s);
            break;  // function definitions are inlined at their calls
    }
}

int CodeGenerator::Condition(Node* e) {
    int c = Expr(e);
    if (e->boolean) return c;
    int b = NewReg(FloatType(), e->varying);
    Emit(Op::Ne, {b, c, Constant(0.0f)});
    return b;
}

void CodeGenerator::If(Node* s) {
    if (!DepthAvailable(s, 2)) return;
    int c = Condition(s->Condition());
    const int outer = depth_, outerRegion = region_;
    const int entry = depth_ + 1;
    p_->maxDepth = std::max(p_->maxDepth, entry + 1);
    int ifAt = Emit(Op::If, {c}, entry);
    PushRegion(c, false);
    depth_ = entry;
    Statement(s->Then());
    depth_ = outer;
    if (s->Else()) {
        int elseAt = Emit(Op::Else, {c}, entry);
        p_->code[ifAt].jump = elseAt;
        depth_ = entry;
        Statement(s->Else());
        depth_ = outer;
        p_->code[elseAt].jump = int(p_->code.size());
    } else {
        p_->code[ifAt].jump = int(p_->code.size());
    }
    region_ = outerRegion;
}

void CodeGenerator::Loop(Node* s) {
    if (!DepthAvailable(s, 3)) return;
    const bool isFor = s->kind == NodeKind::For;
    if (isFor && s->Init()) Expr(s->Init());
    Node* condNode = s->Condition();
    const int outer = depth_, outerRegion = region_;
    const int running = depth_ + 1;
    p_->maxDepth = std::max(p_->maxDepth, running + 2);
    Emit(Op::LoopInit, {}, running);
    const int region = PushRegion(-1, false);
    depth_ = running;
    const int condStart = int(p_->code.size());
    if (condNode) SetLoc(condNode);
    int c = condNode ? Condition(condNode) : Constant(1.0f);
    p_->regions[region].condition = c;
    int testAt = Emit(Op::LoopTest, {c}, running);
    depth_ = running + 1;
    loops_.push_back({running, region});
    Statement(s->Body());
    loops_.pop_back();
    SetLoc(s);
    Emit(Op::LoopNext, {}, running);
    if (isFor && s->Step()) Expr(s->Step());
    Emit(Op::Jump, {}, 0, condStart);
    p_->code[testAt].jump = int(p_->code.size());
    depth_ = outer;
    region_ = outerRegion;
}

void CodeGenerator::Exit(Node* s) {
    if (s->kind == NodeKind::Return) {
        if (functions_.empty()) return;
        // A copy: the return value may call a function, whose inlining pushes onto functions_.
        const FunctionFrame f = functions_.back();
        if (s->Expression() && f.result >= 0) {
            int v = ExprAs(s->Expression(), f.type);
            Emit(Op::Assign, {f.result, v});
        }
        Emit(Op::Exit, {}, f.entry, f.region);
        return;
    }
    const size_t base = functions_.empty() ? 0 : functions_.back().loopBase;
    const int level = s->op;
    if (level < 1 || size_t(level) > loops_.size() - base) return;  // reported by the checker
    const LoopFrame& loop = loops_[loops_.size() - size_t(level)];
    if (s->kind == NodeKind::Break) {
        Emit(Op::Exit, {}, loop.running, loop.region);
    } else {
        // continue: only the innermost `level - 1` loops are left entirely.
        // continue n: the points leave the inner loops and skip the rest of loop n's body,
        // whose entry (running + 1) lies below the inner loops' entries.
        Emit(Op::Exit, {}, loop.running + 1, loop.region);
    }
}

void CodeGenerator::LightLoop(Node* s) {
    if (!DepthAvailable(s, 3)) return;
    const std::vector<Node*> args = s->LightLoopArguments();
    Node* body = s->Body();
    std::vector<int> regs;
    for (Node* a : args) regs.push_back(Expr(a));
    const int outer = depth_, outerRegion = region_;
    const int entry = depth_ + 1;
    p_->maxDepth = std::max(p_->maxDepth, entry + 2);
    if (s->kind == NodeKind::Illuminance) {
        GlobalReg(kGlobalL);
        GlobalReg(kGlobalCl);
        GlobalReg(kGlobalOl);
        bool category = !args.empty() && args[0]->type.base == BaseType::String;
        int cat = category ? regs[0] : -1;
        size_t first = category ? 1 : 0;
        int axis = args.size() - first == 3 ? regs[first + 1] : -1;
        int angle = args.size() - first == 3 ? regs[first + 2] : -1;
        // The position: the lights are evaluated there (the surface's cached lights when it is
        // the surface's P). The surface's N aims lights from all directions when there is no
        // axis (OpIllumNext).
        const int position = regs[first];
        if (axis < 0 && FindGlobal("N", checker_.Type()) >= 0) GlobalReg(kGlobalN);
        Emit(Op::IllumBegin, {cat, axis, angle, position}, entry);
        const int region = PushRegion(-1, true);
        depth_ = entry;
        int nextAt = Emit(Op::IllumNext, {cat, axis, angle}, entry);
        depth_ = entry + 1;
        loops_.push_back({entry, region});
        Statement(body);
        loops_.pop_back();
        Emit(Op::Jump, {}, 0, nextAt);
        p_->code[nextAt].jump = int(p_->code.size());
    } else {
        GlobalReg(kGlobalL);
        GlobalReg(kGlobalPs);
        p_->ambientLight = false;
        int at;
        if (s->kind == NodeKind::Illuminate) {
            at = Emit(Op::Illuminate,
                      {regs[0], regs.size() == 3 ? regs[1] : -1, regs.size() == 3 ? regs[2] : -1},
                      entry);
        } else {
            at = Emit(Op::Solar, {regs.empty() ? -1 : regs[0], regs.empty() ? -1 : regs[1]}, entry);
        }
        PushRegion(-1, true);
        depth_ = entry;
        Statement(body);
        p_->code[at].jump = int(p_->code.size());
    }
    depth_ = outer;
    region_ = outerRegion;
}

int CodeGenerator::ExprAs(Node* e, const TypeSpec& to) { return Convert(Expr(e), to); }

int CodeGenerator::Convert(int reg, const TypeSpec& to) {
    const Register& r = p_->regs[reg];
    if (r.isString || to.base == BaseType::Void || to.IsUnsized()) return reg;
    const int width = to.Width(colorComponents_) * (to.IsArray() ? to.arrayLength : 1);
    if (r.width == width && !(to.base == BaseType::Matrix && r.type.base == BaseType::Float)) {
        return reg;  // point-likes share a layout, so do colours of 3 and triples
    }
    int out = NewReg(to, r.varying);
    Emit(Op::Assign, {out, reg});
    return out;
}

// Stores `value` in `target`. When the value is a temporary that the last instruction just
// computed, that instruction writes the target directly instead (no copy).
void CodeGenerator::StoreTo(int target, int value) {
    Register& v = p_->regs[value];
    const Register& t = p_->regs[target];
    if (!p_->code.empty() && v.temporary && !v.constant && v.width == t.width &&
        v.isString == t.isString && int(p_->code.size()) > 0) {
        Instr& last = p_->code.back();
        const OpInfo& info = OpTable(last.op);
        if ((info.flags & kOpWrites) && last.args[0] == value && last.op != uint16_t(Op::SetComp) &&
            !(t.type.base == BaseType::Matrix && v.type.base != BaseType::Matrix)) {
            last.args[0] = target;
            if (last.op == uint16_t(Op::Call)) p_->callArgs[last.extra + 2] = target;
            v.used = false;
            return;
        }
    }
    Emit(Op::Assign, {target, value});
}

int CodeGenerator::Expr(Node* e) {
    switch (e->kind) {
        case NodeKind::Number:
            return Constant(e->number);
        case NodeKind::String:
            return StringConstant(e->name);
        case NodeKind::Identifier: {
            const Symbol* s = e->symbol;
            if (!s) return Constant(0.0f);
            if (s->kind == SymbolKind::Constant) return Constant(s->constant);
            if (s->kind == SymbolKind::Global) return GlobalReg(s->global);
            auto it = regOf_.find(s);
            if (it != regOf_.end()) return it->second;
            // A variable used before its declaration executed (e.g. an extern of a function
            // inlined where the variable is not visible): give it storage.
            int r = NewReg(s->type, true, s->name, false);
            regOf_[s] = r;
            return r;
        }
        case NodeKind::Tuple:
            return Tuple(e);
        case NodeKind::Unary: {
            Node* operand = e->Operand();
            int a = Expr(operand);
            int d = NewReg(e->type, e->varying);
            Emit(e->op == '!' ? Op::Not : Op::Neg,
                 {d, e->op == '!' && !operand->boolean ? Condition(operand) : a});
            return d;
        }
        case NodeKind::Binary:
            return Binary(e);
        case NodeKind::Assign:
            return Assign(e);
        case NodeKind::Ternary: {
            int c = Condition(e->Condition());
            int a = ExprAs(e->Then(), e->type);
            int b = ExprAs(e->Else(), e->type);
            int d = NewReg(e->type, e->varying);
            Emit(Op::Select, {d, c, a, b});
            return d;
        }
        case NodeKind::Call:
            if (e->function) return InlineCall(e);
            if (e->builtin >= 0) return BuiltinCall(e);
            if (e->name == "arraylength")  // TypeChecker::CheckArrayLength
                return Constant(float(p_->regs[Expr(e->Arguments()[0])].type.arrayLength));
            return Constant(0.0f);
        case NodeKind::Index: {
            int a = Expr(e->Array());
            int i = Expr(e->Subscript());
            int d = NewReg(e->type, e->varying);
            Emit(Op::IndexRead, {d, a, i});
            return d;
        }
        case NodeKind::Cast:
            return Cast(e);
        default:
            return Constant(0.0f);
    }
}

int CodeGenerator::Tuple(Node* e) {
    std::vector<float> values;
    const std::vector<Node*>& elements = e->Elements();
    for (Node* k : elements) {
        if (k->kind != NodeKind::Number) break;
        values.push_back(k->number);
    }
    if (values.size() == elements.size()) return Constant(values, e->type);
    int d = NewReg(e->type, e->varying);
    if (elements.size() == 3) {
        int a = ExprAs(elements[0], FloatType()), b = ExprAs(elements[1], FloatType()),
            c = ExprAs(elements[2], FloatType());
        Emit(Op::Triple, {d, a, b, c});
        return d;
    }
    for (size_t k = 0; k < elements.size(); ++k) {
        int v = ExprAs(elements[k], FloatType());
        Emit(Op::SetComp, {d, v}, int(k));
    }
    return d;
}

int CodeGenerator::Binary(Node* e) {
    Node* an = e->Lhs();
    Node* bn = e->Rhs();
    const int op = e->op;
    if (op == kOpAnd || op == kOpOr) {
        int a = Condition(an), b = Condition(bn);
        int d = NewReg(FloatType(), e->varying);
        Emit(op == kOpAnd ? Op::And : Op::Or, {d, a, b});
        return d;
    }
    int a = Expr(an), b = Expr(bn);
    int d = NewReg(e->type, e->varying);
    const bool strings = an->type.base == BaseType::String;
    switch (op) {
        case '+':
            Emit(Op::Add, {d, a, b});
            break;
        case '-':
            Emit(Op::Sub, {d, a, b});
            break;
        case '*':
            Emit(an->type.base == BaseType::Matrix && bn->type.base == BaseType::Matrix ? Op::MatMul
                                                                                        : Op::Mul,
                 {d, a, b});
            break;
        case '/':
            Emit(bn->type.base == BaseType::Matrix ? Op::MatDiv : Op::Div, {d, a, b});
            break;
        case '.':
            Emit(Op::Dot, {d, a, b});
            break;
        case '^':
            Emit(Op::Cross, {d, a, b});
            break;
        case '<':
            Emit(Op::Lt, {d, a, b});
            break;
        case '>':
            Emit(Op::Gt, {d, a, b});
            break;
        case kOpLe:
            Emit(Op::Le, {d, a, b});
            break;
        case kOpGe:
            Emit(Op::Ge, {d, a, b});
            break;
        case kOpEq:
            Emit(strings ? Op::StrEq : Op::Eq, {d, a, b});
            break;
        case kOpNe:
            Emit(strings ? Op::StrNe : Op::Ne, {d, a, b});
            break;
        default:
            break;
    }
    return d;
}

int CodeGenerator::Assign(Node* e) {
    Node* target = e->Target();
    Node* value = e->Value();
    auto combine = [&](int current) {
        if (e->op == '=') return ExprAs(value, target->type);
        int v = Expr(value);
        int d = NewReg(target->type, target->varying || value->varying);
        Op op = e->op == '+' ? Op::Add : e->op == '-' ? Op::Sub : e->op == '*' ? Op::Mul : Op::Div;
        if (target->type.base == BaseType::Matrix && value->type.base == BaseType::Matrix) {
            op = e->op == '*' ? Op::MatMul : e->op == '/' ? Op::MatDiv : op;
        }
        Emit(op, {d, current, v});
        return d;
    };
    if (target->kind == NodeKind::Index) {
        int array = Expr(target->Array());
        int index = Expr(target->Subscript());
        int current = -1;
        if (e->op != '=') {
            current = NewReg(target->type, target->varying);
            Emit(Op::IndexRead, {current, array, index});
        }
        int v = combine(current);
        Emit(Op::IndexWrite, {array, index, v});
        return v;
    }
    int reg = Expr(target);
    StoreTo(reg, combine(reg));
    return reg;
}

int CodeGenerator::Cast(Node* e) {
    int v = ExprAs(e->Operand(), e->type);
    if (e->name.empty()) return v;
    const TypeSpec& t = e->type;
    int space = StringConstant(e->name);
    int d = NewReg(t, e->varying);
    if (t.base == BaseType::Color) {
        Emit(Op::ColorCast, {d, v, space});
    } else {
        int mode = t.base == BaseType::Point    ? 0
                   : t.base == BaseType::Vector ? 1
                   : t.base == BaseType::Normal ? 2
                                                : 3;
        Emit(Op::SpaceCast, {d, v, space}, mode);
    }
    return d;
}

int CodeGenerator::BuiltinCall(Node* e) {
    const BuiltinInfo& info = BuiltinTable()[e->builtin];
    if (info.flags & kReadsGlobals) ImplicitGlobals(info.flags);
    std::vector<int> args;
    struct WriteBack {
        int array, index, temp;
    };
    std::vector<WriteBack> writeBacks;
    const std::vector<BuiltinParameter>& params = BuiltinSignatureOf(e->builtin).parameters;
    const std::vector<Node*>& callArgs = e->Arguments();
    for (size_t k = 0; k < callArgs.size(); ++k) {
        Node* a = callArgs[k];
        // Arguments past the parameters (a trailing "*") are passed as they are.
        const BuiltinParameter* param = k < params.size() ? &params[k] : nullptr;
        bool output = param && param->output;
        bool array = param && param->array;
        if (output && a->kind == NodeKind::Index) {
            int arr = Expr(a->Array()), idx = Expr(a->Subscript());
            int temp = NewReg(a->type, true, "", false);
            Emit(Op::IndexRead, {temp, arr, idx});
            writeBacks.push_back({arr, idx, temp});
            args.push_back(temp);
        } else if (output || array || !param) {
            args.push_back(Expr(a));
        } else {
            args.push_back(ExprAs(a, param->type));
        }
    }
    int result = -1;
    if (e->type.base != BaseType::Void) result = NewReg(e->type, e->varying);
    int offset = int(p_->callArgs.size());
    p_->callArgs.push_back(e->builtin);
    p_->callArgs.push_back(int(args.size()));
    p_->callArgs.push_back(result);
    p_->callArgs.insert(p_->callArgs.end(), args.begin(), args.end());
    SetLoc(e);
    Emit(Op::Call, {result}, offset);
    for (const WriteBack& w : writeBacks) Emit(Op::IndexWrite, {w.array, w.index, w.temp});
    return result >= 0 ? result : Constant(0.0f);
}

int CodeGenerator::InlineCall(Node* e) {
    if (!ok_) return Constant(0.0f);  // too large already: stop inlining
    current_ = e;
    const Node* f = e->function;
    for (const Node* active : inlining_) {
        if (active == f) {
            diagnostics_.Error(ToFileLoc(tree_, e->loc),
                               "recursive call of '" + f->name + "' (functions are inlined)");
            ok_ = false;
            return Constant(0.0f);
        }
    }
    if (!DepthAvailable(e, 2)) return Constant(0.0f);
    const std::vector<Node*>& formals = f->Formals();
    struct WriteBack {
        int array, index, temp;
    };
    std::vector<WriteBack> writeBacks;
    std::vector<std::pair<const Symbol*, int>> bindings;
    for (size_t k = 0; k < formals.size(); ++k) {
        Node* a = e->Arguments()[k];
        const Symbol* formal = formals[k]->symbol;
        int reg;
        if (formals[k]->output && a->kind == NodeKind::Index) {
            int arr = Expr(a->Array()), idx = Expr(a->Subscript());
            reg = NewReg(a->type, true, "", false);
            Emit(Op::IndexRead, {reg, arr, idx});
            writeBacks.push_back({arr, idx, reg});
        } else if (formals[k]->output) {
            reg = Expr(a);  // by reference
        } else {
            reg = ExprAs(a, formals[k]->declType);
        }
        bindings.emplace_back(formal, reg);
    }
    // Bind after evaluating every argument: f(x, f(y, z)) must see the caller's names.
    std::vector<std::pair<const Symbol*, int>> saved;
    for (auto& [symbol, reg] : bindings) {
        auto it = regOf_.find(symbol);
        saved.emplace_back(symbol, it == regOf_.end() ? -1 : it->second);
        regOf_[symbol] = reg;
    }
    int result = -1;
    if (f->declType.base != BaseType::Void) result = NewReg(f->declType, e->varying, "", false);
    const int outer = depth_, outerRegion = region_;
    const int entry = depth_ + 1;
    p_->maxDepth = std::max(p_->maxDepth, entry + 1);
    SetLoc(e);
    Emit(Op::Enter, {}, entry);
    const int region = PushRegion(-1, false);
    depth_ = entry;
    inlining_.push_back(f);
    functions_.push_back({entry, region, result, f->declType, loops_.size()});
    for (Node* s : f->Body()->Statements()) Statement(s);
    functions_.pop_back();
    inlining_.pop_back();
    depth_ = outer;
    region_ = outerRegion;
    SetLoc(e);
    for (const WriteBack& w : writeBacks) Emit(Op::IndexWrite, {w.array, w.index, w.temp});
    for (auto& [symbol, reg] : saved) {
        if (reg < 0) {
            regOf_.erase(symbol);
        } else {
            regOf_[symbol] = reg;
        }
    }
    return result >= 0 ? result : Constant(0.0f);
}

}  // namespace gonio::sl
