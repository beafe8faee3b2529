// Opens the OpenImageIO plugin with dlopen (oiio_plugin.h says why it is a plugin).
#include "imageio/oiio_plugin.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>

#include "base/plugin_path.h"

namespace gonio {

namespace {

struct Loaded {
    OiioPlugin* plugin = nullptr;
    std::string error;  // why it could not be opened
};

Loaded Open() {
    const std::string path = PluginPath("GONIO_OIIO_PLUGIN", "libgonio_oiio.so");
    // RTLD_LOCAL: the plugin's OpenImageIO symbols stay out of the executable's namespace.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) return {nullptr, dlerror()};
    auto entry = reinterpret_cast<OiioPluginEntry>(dlsym(handle, kOiioPluginEntry));
    if (!entry) return {nullptr, path + ": no " + kOiioPluginEntry + " in it"};
    return {entry(), ""};
}

}  // namespace

OiioPlugin& LoadOiioPlugin(const std::string& purpose) {
    static std::once_flag once;
    static Loaded loaded;
    std::call_once(once, [] { loaded = Open(); });
    if (!loaded.plugin)
        throw std::runtime_error(purpose +
                                 " needs OpenImageIO, whose plugin could not be loaded (" +
                                 loaded.error + ")");
    return *loaded.plugin;
}

}  // namespace gonio
