#pragma once
// The predefined (global) variables of the shading language (RISpec §12, Tables 12.1-12.5):
// their types, detail, and which shader types may read or write them.

#include <string>

#include "shaderlang/shading_system.h"
#include "shaderlang/types.h"

namespace gonio::sl {

enum GlobalId : int {
    kGlobalP,
    kGlobalN,
    kGlobalNg,
    kGlobalI,
    kGlobalE,
    kGlobalDPdu,
    kGlobalDPdv,
    kGlobalDPdtime,
    kGlobalU,
    kGlobalV,
    kGlobalDu,
    kGlobalDv,
    kGlobalS,
    kGlobalT,
    kGlobalCs,
    kGlobalOs,
    kGlobalCi,
    kGlobalOi,
    kGlobalL,
    kGlobalCl,
    kGlobalOl,
    kGlobalPs,
    kGlobalNs,
    kGlobalNcomps,
    kGlobalTime,
    kGlobalDtime,
    kGlobalAlpha,
    kGlobalCount
};

struct GlobalVarInfo {
    const char* name;
    BaseType type;
    bool varying;
    unsigned readers;  // bit per ShaderType that can see it
    unsigned writers;  // bit per ShaderType that can assign it
};

// Indexed by GlobalId.
const GlobalVarInfo& GlobalVar(int id);
// The id of a global named `name` visible in shaders of `type`, or -1.
int FindGlobal(const std::string& name, ShaderType type);
inline unsigned ShaderBit(ShaderType type) { return 1u << int(type); }

}  // namespace gonio::sl
