#pragma once
// The plugins gonio opens with dlopen (OpenImageIO's, the viewer's): looked for as the path in
// an environment variable when it is set, else beside the running executable, so that
// build/bin/gonio finds build/bin/libgonio_*.so wherever it is called from.

#include <string>

namespace gonio {

std::string PluginPath(const char* override, const char* file);

// Opens the plugin (PluginPath(override, file)) and returns its symbol `entry`, or null with
// the reason in *error. RTLD_LOCAL: the plugin's libraries stay out of the executable's
// namespace.
void* OpenPluginEntry(const char* override, const char* file, const char* entry,
                      std::string* error);

}  // namespace gonio
