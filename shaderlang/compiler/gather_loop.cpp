#include "shaderlang/compiler/gather_loop.h"

#include <atomic>
#include <string>

namespace gonio::sl {

namespace {

// The output variables gather() fills (docs/shading-language.md, gather): each sample's ray
// whether it hit or not, the hit's geometry and its shaded colour only where it hit.
constexpr const char* kRayOutputs[] = {"ray:origin", "ray:direction"};
constexpr const char* kHitOutputs[] = {"ray:length", "primitive:P", "primitive:N", "surface:Ci"};

template <size_t N>
bool IsOneOf(const std::string& name, const char* const (&names)[N]) {
    for (const char* known : names)
        if (name == known) return true;
    return false;
}

Node* Make(ParseState* state, NodeKind kind, const SourceLoc& loc, std::vector<Node*> kids = {}) {
    Node* n = state->tree->Make(kind, loc);
    n->kids = std::move(kids);
    return n;
}

Node* Text(ParseState* state, const SourceLoc& loc, const std::string& text) {
    Node* n = Make(state, NodeKind::String, loc);
    n->name = text;
    return n;
}

Node* Number(ParseState* state, const SourceLoc& loc, float value) {
    Node* n = Make(state, NodeKind::Number, loc);
    n->number = value;
    return n;
}

Node* Call(ParseState* state, const SourceLoc& loc, const char* name, std::vector<Node*> args) {
    Node* n = Make(state, NodeKind::Call, loc, std::move(args));
    n->name = name;
    return n;
}

// target = __gather_value(id, "name");
Node* Output(ParseState* state, int id, const std::string& name, Node* target) {
    const SourceLoc& at = target->loc;
    Node* assign = Make(state, NodeKind::Assign, at,
                        {target, Call(state, at, "__gather_value",
                                      {Number(state, at, float(id)), Text(state, at, name)})});
    assign->op = '=';
    return Make(state, NodeKind::ExprStmt, at, {assign});
}

}  // namespace

Node* MakeGatherLoop(ParseState* state, const SourceLoc& loc, Node* call, Node* hit, Node* miss) {
    // Unique in the process, not only in the file: a light shader's gather runs inside the
    // surface's gather body (diffuse() there runs the lights) with the same context.
    static std::atomic<int> loops{0};
    const int id = loops++;
    std::vector<Node*>& args = call->kids;
    if (args.size() < 5) {
        state->Error(loc, "gather expects (category, P, dir, angle, samples, ...)");
        return nullptr;
    }
    std::vector<Node*> traced(args.begin(), args.begin() + 5);
    std::vector<Node*> rayOutputs, hitOutputs;
    std::string outputs;
    for (size_t a = 5; a < args.size(); a += 2) {
        Node* name = args[a];
        if (name->kind != NodeKind::String || a + 1 >= args.size()) {
            state->Error(name->loc,
                         "gather: each option or output is a \"name\" (a string "
                         "literal) followed by its value or variable");
            return nullptr;
        }
        if (name->name.find(':') == std::string::npos) {
            traced.push_back(name), traced.push_back(args[a + 1]);
            continue;
        }
        const bool ray = IsOneOf(name->name, kRayOutputs);
        if (!ray && !IsOneOf(name->name, kHitOutputs)) {
            state->Error(name->loc, "gather: output \"" + name->name +
                                        "\" is not supported (ray:origin, ray:direction, "
                                        "ray:length, primitive:P, primitive:N, surface:Ci)");
            return nullptr;
        }
        (ray ? rayOutputs : hitOutputs).push_back(Output(state, id, name->name, args[a + 1]));
        outputs += (outputs.empty() ? "" : ",") + name->name;
    }
    for (Node* extra : {Text(state, loc, "__outputs"), Text(state, loc, outputs),
                        Text(state, loc, "__id"), Number(state, loc, float(id))})
        traced.push_back(extra);
    Node* begin = Make(state, NodeKind::ExprStmt, loc, {Call(state, loc, "gather", traced)});

    Node* onHit = Make(state, NodeKind::Block, hit->loc, hitOutputs);
    onHit->kids.push_back(hit);
    Node* branch =
        Make(state, NodeKind::If, loc,
             {Call(state, loc, "__gather_hit", {Number(state, loc, float(id))}), onHit, miss});
    Node* sample = Make(state, NodeKind::Block, loc, rayOutputs);
    sample->kids.push_back(branch);
    Node* loop = Make(state, NodeKind::While, loc,
                      {Call(state, loc, "__gather_next", {Number(state, loc, float(id))}), sample});
    return Make(state, NodeKind::Block, loc, {begin, loop});
}

}  // namespace gonio::sl
