#pragma once
// random() in a uniform context. gonio's random() is varying: each point draws from its own
// stream. RSL compilers (PRMan's, Pixie's) also let a uniform variable take random(), as in
// `uniform color c = color(random(), random(), random());`, and then draw one value per run of
// the shader, shared by all its points. The type checker renames the random() calls of a value
// stored in a uniform variable to the internal built-in `__uniform_random`, which has no varying
// result and draws from the run's own stream (ShadingContext::NextUniformRandomBits).

namespace gonio::sl {

struct Node;

// The internal built-in a uniform random() calls.
inline constexpr const char* kUniformRandom = "__uniform_random";

// Renames every call of random() (the built-in: no arguments) inside the expression `value` to
// kUniformRandom. The caller knows that `value` is stored in a uniform variable and that no user
// function is named random.
void MakeRandomUniform(Node* value);

}  // namespace gonio::sl
