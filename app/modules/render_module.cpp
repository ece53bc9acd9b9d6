// sdf-workbench's headless image commands: render, compare, parity, tradeoff
// (the GL backend through OSMesa, OpenImageIO, PLplot).

#include "app/compare_command.h"
#include "app/module_commands.h"
#include "app/parity_command.h"
#include "app/render_command.h"
#include "app/tradeoff_command.h"

namespace sdfwb::app {

int runCommand(const CommandLine& line) {
    switch (line.command) {
    case Command::Render: return runRender(line.render);
    case Command::Compare: return runCompare(line.compare);
    case Command::Parity: return runParity(line.parity);
    case Command::Tradeoff: return runTradeoff(line.tradeoff);
    default: return refuseCommand(line);
    }
}

}  // namespace sdfwb::app
