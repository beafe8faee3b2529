#include <CLI/CLI.hpp>

#include "base/interrupt_cleanup.h"
#include "commands.h"

int main(int argc, char** argv) {
    gonio::RemoveTemporariesOnInterrupt();
    CLI::App app{"gonio: a RenderMan-style renderer and virtual gonioreflectometer"};
    app.require_subcommand(1);
    int exitCode = 0;
    gonio::AddRenderCommand(app, &exitCode);
    gonio::AddCatribCommand(app, &exitCode);
    gonio::AddBrdfCommand(app, &exitCode);
    gonio::AddShaderCommand(app, &exitCode);
    gonio::AddShadeCommand(app, &exitCode);
    gonio::AddSpectralCommand(app, &exitCode);
    gonio::AddViewCommand(app, &exitCode);
    gonio::AddFarmCommand(app, &exitCode);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int status = app.exit(e);
        return status == 0 ? 0 : 2;  // --help is not an error; a bad command line is a usage error
    }
    return exitCode;
}
