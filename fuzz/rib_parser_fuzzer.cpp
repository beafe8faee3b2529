// libFuzzer target for the RIB front end: any input must parse (with or without errors) without
// a crash, a hang, or a report from AddressSanitizer or UndefinedBehaviorSanitizer. Each parse
// also goes through RibWriter, so the printer sees every odd value the parser lets through.

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "base/diagnostics.h"
#include "renderer/rib/rib_parser.h"
#include "renderer/rib/rib_writer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::ostringstream printed;
    gonio::RibWriter writer(printed);
    gonio::Diagnostics quiet(nullptr);
    // A name in a folder that does not exist, so that relative ReadArchive names find nothing.
    gonio::ParseRibString(text, "/nonexistent-gonio-fuzz/input.rib", writer, quiet);
    return 0;
}
