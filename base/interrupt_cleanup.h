#pragma once
// Temporary files are not left behind when SIGINT or SIGTERM stops the program (Ctrl-C during a
// photon map, a grid, an image or a plot being written). Each writer holds a PendingTemporary
// for the temporary name while the file exists; the handler that main installs removes every
// such file, says that the run was interrupted, and ends the program by the signal, so that
// the shell sees the usual status (130 for SIGINT, 143 for SIGTERM).

#include <string>

namespace gonio {

// Installs the SIGINT and SIGTERM handlers (once, from main).
void RemoveTemporariesOnInterrupt();

// Registers `path` for removal on interruption for this object's lifetime. At most 64 names are
// registered at once; a name past that (or longer than 4095 bytes) is not protected.
class PendingTemporary {
  public:
    explicit PendingTemporary(const std::string& path);
    ~PendingTemporary();
    PendingTemporary(const PendingTemporary&) = delete;
    PendingTemporary& operator=(const PendingTemporary&) = delete;

  private:
    int slot_ = -1;
};

}  // namespace gonio
