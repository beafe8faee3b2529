#pragma once
// The usual helper for std::visit with one lambda per alternative: a visit that misses an
// alternative does not compile, so a new kind of shape cannot be silently skipped.
//
//   std::visit(Overloaded{[](const TriangleMesh& m) { ... }, [](const PointSet& p) { ... }}, g);

namespace gonio {

template <class... Visitors>
struct Overloaded : Visitors... {
    using Visitors::operator()...;
};
template <class... Visitors>
Overloaded(Visitors...) -> Overloaded<Visitors...>;

}  // namespace gonio
