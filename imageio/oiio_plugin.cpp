// Opens the OpenImageIO plugin with dlopen (oiio_plugin.h says why it is a plugin).
#include "imageio/oiio_plugin.h"

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
    std::string error;
    auto entry = reinterpret_cast<OiioPluginEntry>(
        OpenPluginEntry("GONIO_OIIO_PLUGIN", "libgonio_oiio.so", kOiioPluginEntry, &error));
    if (!entry) return {nullptr, error};
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
