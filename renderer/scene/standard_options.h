#pragma once
// The Option, Attribute and Display parameters renderers understand without a Declare: RISpec
// Tables 4.5 and 4.11, the common PRMan/Aqsis/Pixie extensions that exported RIB uses, our own
// "BRDFLight" option and "brdflight" attribute, and the Display drivers' parameters.

#include <string>

namespace gonio {

// The declaration (e.g. "uniform string") of `token` under `request` ("Option", "Attribute"
// or "Display") `name` ("" for Display), or an empty string when it is not a standard one.
std::string StandardParamDeclaration(const std::string& request, const std::string& name,
                                     const std::string& token);

// Whether `name` is an Option (or Attribute) name that we or other renderers know.
bool IsKnownOptionName(bool isOption, const std::string& name);

}  // namespace gonio
