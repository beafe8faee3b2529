// WriteExrFile through the OpenEXR plugin (exr_plugin.h says why it is one), opened on the first
// call. The plugin is looked for as $GONIO_EXR_PLUGIN, else as libgonio_exr.so beside the
// running executable.
#include "imageio/exr_plugin.h"

#include <mutex>

#include "base/plugin_path.h"
#include "imageio/builtin_drivers.h"

namespace gonio {

std::string WriteExrFile(const std::string& path, const ImageFileSpec& spec,
                         const PixelBuffer& pixels) {
    static std::once_flag once;
    static ExrWriter writer = nullptr;
    static std::string error;  // why the plugin could not be opened
    std::call_once(once, [] {
        auto entry = reinterpret_cast<ExrPluginEntry>(
            OpenPluginEntry("GONIO_EXR_PLUGIN", "libgonio_exr.so", kExrPluginEntry, &error));
        if (entry) writer = entry();
    });
    if (!writer) return "OpenEXR files are written by the plugin libgonio_exr.so: " + error;
    return writer(path, spec, pixels);
}

}  // namespace gonio
