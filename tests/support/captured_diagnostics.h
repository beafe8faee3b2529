#pragma once
// Diagnostics whose messages go to memory, for the tests that check them word for word.

#include <cstdio>
#include <cstdlib>
#include <string>

#include "base/diagnostics.h"

namespace gonio::test {

class CapturedDiagnostics {
  public:
    CapturedDiagnostics() : file_(open_memstream(&buffer_, &size_)), diagnostics_(file_) {}
    ~CapturedDiagnostics() {
        std::fclose(file_);
        std::free(buffer_);
    }
    CapturedDiagnostics(const CapturedDiagnostics&) = delete;
    CapturedDiagnostics& operator=(const CapturedDiagnostics&) = delete;

    Diagnostics& Get() { return diagnostics_; }
    // Everything reported so far.
    std::string Text() {
        std::fflush(file_);
        return std::string(buffer_, size_);
    }

  private:
    char* buffer_ = nullptr;
    size_t size_ = 0;
    std::FILE* file_;
    Diagnostics diagnostics_;
};

}  // namespace gonio::test
