#include "shaderlang/compiler/uniform_random.h"

#include <vector>

#include "shaderlang/compiler/ast.h"

namespace gonio::sl {

void MakeRandomUniform(Node* value) {
    // Iterative, as CheckTreeDepth is: a long sum must not overflow the stack here.
    std::vector<Node*> pending = {value};
    while (!pending.empty()) {
        Node* node = pending.back();
        pending.pop_back();
        if (node->kind == NodeKind::Call && node->name == "random" && node->kids.empty())
            node->name = kUniformRandom;
        for (Node* kid : node->kids)
            if (kid) pending.push_back(kid);
    }
}

}  // namespace gonio::sl
