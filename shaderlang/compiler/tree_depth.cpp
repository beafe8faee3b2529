#include "shaderlang/compiler/tree_depth.h"

#include <utility>
#include <vector>

#include "shaderlang/compiler/parser.h"

namespace gonio::sl {

bool CheckTreeDepth(const SyntaxTree& tree, Diagnostics& diagnostics) {
    // Iterative, so that measuring a deep tree cannot overflow the stack itself.
    std::vector<std::pair<const Node*, int>> pending;
    for (const Node* definition : tree.definitions) pending.emplace_back(definition, 1);
    while (!pending.empty()) {
        const auto [node, depth] = pending.back();
        pending.pop_back();
        if (depth > kMaxTreeDepth) {
            diagnostics.Error(ToFileLoc(tree, node->loc),
                              "expressions or statements nested more than " +
                                  std::to_string(kMaxTreeDepth) +
                                  " deep (a very long sum or chain?): split them");
            return false;
        }
        for (const Node* kid : node->kids)
            if (kid) pending.emplace_back(kid, depth + 1);
    }
    return true;
}

}  // namespace gonio::sl
