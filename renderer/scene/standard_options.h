#pragma once
// The Option and Attribute parameters renderers understand without a Declare: RISpec Tables 4.5
// and 4.11, the common PRMan/Aqsis/Pixie extensions that exported RIB uses, and our own
// "BRDFLight" option and "brdflight" attribute.

#include <string>

namespace gonio {

// The declaration (e.g. "uniform string") of `token` under Option (isOption) or Attribute
// `name`, or an empty string when it is not a standard parameter.
std::string StandardParamDeclaration(bool isOption, const std::string& name,
                                     const std::string& token);

// Whether `name` is an Option (or Attribute) name that we or other renderers know.
bool IsKnownOptionName(bool isOption, const std::string& name);

}  // namespace gonio
