#include "shaderlang/runtime/global_vars.h"

namespace gonio::sl {

namespace {

constexpr unsigned kS = 1u << int(ShaderType::Surface);
constexpr unsigned kL = 1u << int(ShaderType::Light);
constexpr unsigned kD = 1u << int(ShaderType::Displacement);
constexpr unsigned kV = 1u << int(ShaderType::Volume);
constexpr unsigned kI = 1u << int(ShaderType::Imager);
constexpr unsigned kAll = kS | kL | kD | kV | kI;

// name, type, varying, readers, writers
const GlobalVarInfo kGlobals[kGlobalCount] = {
    // Surface shaders may write P, as Pixie's allow (displacement inside a surface shader): the
    // new P serves the rest of the shader and its illuminance loops; what the camera sees is
    // not re-traced (docs/shading-language.md, Writing P).
    {"P", BaseType::Point, true, kAll, kS | kD},
    // Light shaders may write N and read I, as Pixie's do: its arealight normalises N (in an
    // area light the sample point's normal, docs/shading-language.md, Area lights); its
    // ambient lights run at the surface points and face N towards I.
    {"N", BaseType::Normal, true, kS | kL | kD, kS | kL | kD},
    {"Ng", BaseType::Normal, true, kS | kL | kD, 0},
    // RISpec 3.2 Table 12.1 lists I among a surface shader's inputs only; Pixie lets surface
    // shaders write it, and its mirror.sl normalises it in place (I = normalize(I)). The write
    // changes the shader's own I (and a Display of "I", which shows the surface's, as for N).
    {"I", BaseType::Vector, true, kS | kL | kD | kV, kS},
    {"E", BaseType::Point, false, kAll, 0},
    {"dPdu", BaseType::Vector, true, kS | kL | kD, 0},
    {"dPdv", BaseType::Vector, true, kS | kL | kD, 0},
    {"dPdtime", BaseType::Vector, true, kS | kD, 0},
    {"u", BaseType::Float, true, kS | kL | kD, 0},
    {"v", BaseType::Float, true, kS | kL | kD, 0},
    {"du", BaseType::Float, true, kS | kL | kD, 0},
    {"dv", BaseType::Float, true, kS | kL | kD, 0},
    // Imagers read s, t as the pixel's place across the image (0 to 1 from the top left, Pixie's
    // compiler lets every shader type read them; docs/shading-language.md, Imager shaders).
    {"s", BaseType::Float, true, kS | kL | kD | kI, 0},
    {"t", BaseType::Float, true, kS | kL | kD | kI, 0},
    {"Cs", BaseType::Color, true, kS, 0},
    {"Os", BaseType::Color, true, kS, 0},
    {"Ci", BaseType::Color, true, kS | kV | kI, kS | kV | kI},
    {"Oi", BaseType::Color, true, kS | kV | kI, kS | kV | kI},
    {"L", BaseType::Vector, true, kS | kL, kL},
    {"Cl", BaseType::Color, true, kS | kL, kL},
    {"Ol", BaseType::Color, true, kS | kL, kL},
    {"Ps", BaseType::Point, true, kL, 0},
    // Ns: the normal of the surface point being lit (PRMan's and Pixie's light shaders read it
    // inside illuminate and solar): the surface's shading normal as the renderer found it.
    {"Ns", BaseType::Normal, true, kL, 0},
    {"ncomps", BaseType::Float, false, kAll, 0},
    {"time", BaseType::Float, false, kAll, 0},
    {"dtime", BaseType::Float, false, kAll, 0},
    // RISpec's Table 12.5 makes alpha uniform, as if each pixel ran alone; an imager here runs
    // over a batch of pixels, each with its own coverage.
    {"alpha", BaseType::Float, true, kI, kI},
};

}  // namespace

const GlobalVarInfo& GlobalVar(int id) { return kGlobals[id]; }

int FindGlobal(const std::string& name, ShaderType type) {
    for (int i = 0; i < kGlobalCount; ++i) {
        if (name == kGlobals[i].name && (kGlobals[i].readers & ShaderBit(type))) return i;
    }
    return -1;
}

}  // namespace gonio::sl
