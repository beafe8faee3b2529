// The table of every built-in overload, gathered from the families' registration functions.

#include "shaderlang/runtime/builtin_table.h"

#include <cctype>
#include <unordered_map>

#include "shaderlang/runtime/builtins_util.h"

namespace gonio::sl {

namespace {

builtins::BuiltinList MakeTable() {
    builtins::BuiltinList list;
    builtins::AddMathBuiltins(&list);
    builtins::AddNoiseBuiltins(&list);
    builtins::AddGeometricBuiltins(&list);
    builtins::AddColorBuiltins(&list);
    builtins::AddMatrixBuiltins(&list);
    builtins::AddStringBuiltins(&list);
    builtins::AddLightingBuiltins(&list);
    builtins::AddTextureBuiltins(&list);
    builtins::AddMessageBuiltins(&list);
    builtins::AddDerivativeBuiltins(&list);
    builtins::AddBrdfBuiltins(&list);
    builtins::AddRayBuiltins(&list);
    builtins::AddGatherBuiltins(&list);
    builtins::AddPointCloudBuiltins(&list);
    return list;
}

BuiltinSignature ParseSignature(const BuiltinInfo& info) {
    BuiltinSignature sig;
    sig.result = TypeOfCode(info.returnType[0]);
    for (const char* p = info.arguments; *p; ++p) {
        if (*p == '*') {
            sig.varargs = true;
            break;
        }
        BuiltinParameter param;
        param.type = TypeOfCode(*p);
        param.output = std::isupper(static_cast<unsigned char>(*p));
        param.array = p[1] == '[';
        if (param.array) p += 2;
        sig.parameters.push_back(param);
    }
    return sig;
}

struct ParsedTable {
    std::vector<BuiltinSignature> signatures;  // by row
    std::unordered_map<std::string, std::vector<int>> rowsByName;
};

const ParsedTable& Parsed() {
    static const ParsedTable parsed = [] {
        ParsedTable t;
        const std::vector<BuiltinInfo>& table = BuiltinTable();
        for (size_t row = 0; row < table.size(); ++row) {
            t.signatures.push_back(ParseSignature(table[row]));
            t.rowsByName[table[row].name].push_back(int(row));
        }
        return t;
    }();
    return parsed;
}

}  // namespace

const std::vector<BuiltinInfo>& BuiltinTable() {
    static const builtins::BuiltinList list = MakeTable();
    return list.rows;
}

TypeSpec TypeOfCode(char code) {
    TypeSpec t;
    switch (std::tolower(static_cast<unsigned char>(code))) {
        case 'f':
            t.base = BaseType::Float;
            break;
        case 's':
            t.base = BaseType::String;
            break;
        case 'c':
            t.base = BaseType::Color;
            break;
        case 'p':
            t.base = BaseType::Point;
            break;
        case 'v':
            t.base = BaseType::Vector;
            break;
        case 'n':
            t.base = BaseType::Normal;
            break;
        case 'm':
            t.base = BaseType::Matrix;
            break;
        default:
            t.base = BaseType::Void;
            break;
    }
    return t;
}

const BuiltinSignature& BuiltinSignatureOf(int row) { return Parsed().signatures[size_t(row)]; }

const std::vector<int>& BuiltinRowsNamed(const std::string& name) {
    static const std::vector<int> none;
    auto it = Parsed().rowsByName.find(name);
    return it == Parsed().rowsByName.end() ? none : it->second;
}

}  // namespace gonio::sl
