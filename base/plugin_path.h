#pragma once
// Where gonio looks for a plugin it opens with dlopen: the path in the environment variable
// `override` when it is set, else `file` in the folder of the running executable, so that
// build/bin/gonio finds build/bin/libgonio_*.so wherever it is called from.

#include <string>

namespace gonio {

std::string PluginPath(const char* override, const char* file);

}  // namespace gonio
