#pragma once
// Running the program of a `Procedural "RunProgram"` (RISpec 3.2 §5.7.1 and App. C.3): the
// renderer writes one request, "detail datablock\n", to the program's standard input; the
// program answers with RIB on its standard output, ended by the byte 0377. Here every request
// gets a program of its own: its standard input is closed after the request, so a program that
// loops over requests until the end of its input (as the protocol asks) exits. The end of its
// output without 0377 is accepted as the end of the answer; a program that neither answers nor
// exits within the time-out is killed.

#include <string>

namespace gonio {

struct ProgramRun {
    bool ok = false;
    std::string rib;    // what the program wrote before 0377 (or its end)
    std::string error;  // why not ok: cannot start, killed after the time-out, exit status
};

// Runs `command` through /bin/sh (so the program may be a script with arguments), writes
// `request` to its standard input and collects its answer. `timeoutSeconds` <= 0: no limit.
ProgramRun RunProceduralProgram(const std::string& command, const std::string& request,
                                double timeoutSeconds);

}  // namespace gonio
