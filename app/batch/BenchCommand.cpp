// `sdfwb --batch bench`: runs the measurements of bench/ (sdfwb::bench) and writes the report.
#include "BatchCommands.h"

namespace sdfwb::app {

int runBench(const BenchCommand&, const OutputOptions&) {
    printError("--batch bench: not built yet");
    return kExitFailure;
}

} // namespace sdfwb::app
