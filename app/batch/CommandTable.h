#pragma once
// What CommandLine.cpp (CLI11: each command's options) and BatchDispatch.cpp (the overview, the
// dispatch of `--batch`, job files) share: the one table of batch commands.

#include <string>
#include <vector>

namespace sdfwb::app::detail {

using Arguments = std::vector<std::string>;

// Run does the work; Check stops where the work would start (checkCommandLine, checkJobFile).
enum class Mode { Run, Check };

struct BatchCommandEntry {
    const char* name;
    int (*run)(const Arguments& arguments, Mode mode);
};

// The entry named `name`, or null.
const BatchCommandEntry* findBatchCommand(const std::string& name);
// "render, animate, sample, merge, ..." (grade's old name "eval" is accepted, not offered).
std::string batchCommandNames();

} // namespace sdfwb::app::detail
