#pragma once
// After a frame: the Option and Attribute parameters nobody read, reported at their RIB
// locations (pbrt-v4's ReportUnused), so that a misspelt or unsupported parameter does not
// pass unnoticed. Display parameters are reported by the image writer that reads them.

#include "base/diagnostics.h"
#include "renderer/scene/frame.h"

namespace gonio {

void ReportUnusedParameters(const Frame& frame, Diagnostics& diagnostics);

}  // namespace gonio
