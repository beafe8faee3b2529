#pragma once
// How much memory this machine has, so that a request too large for it (an image, a photon
// count) is refused with its size instead of aborting in the allocator.

#include <string>

namespace gonio {

// Physical memory in bytes (sysconf); 0 when the system does not say.
double PhysicalMemoryBytes();

// "1.5 GiB", "320 MiB": a size for a message.
std::string ByteSize(double bytes);

}  // namespace gonio
