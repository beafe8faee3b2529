#include "base/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "base/interrupt_cleanup.h"

namespace gonio {

std::string WriteFileAtomically(const std::string& path, const std::string& text) {
    // The pid keeps two processes that write the same file from sharing a temporary name.
    const std::string temporary = path + ".tmp" + std::to_string(::getpid());
    const PendingTemporary pending(temporary);
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file) return std::strerror(errno);
    const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    const int writeErrno = errno;
    const bool flushed = std::fflush(file) == 0;
    const bool closed = std::fclose(file) == 0;
    if (!written || !flushed || !closed) {
        const int error = written ? errno : writeErrno;
        std::remove(temporary.c_str());
        return std::strerror(error);
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const int renameErrno = errno;
        std::remove(temporary.c_str());
        return std::strerror(renameErrno);
    }
    return "";
}

}  // namespace gonio
