#pragma once
// The worker protocol: how `sdfwb --batch request - --protocol [--each-line]` answers the process
// that started it (the workbench, for every job kind). Requests go in as JSON, one per line with
// --each-line (JobJson.h); every message out is one JSON object with one key, on one line of
// stdout:
//   {"progress":[done,total]}
//   {"error":{"kind":"work","message":"...","diagnostics":[{"file":"a.glsl","line":3,"column":5,
//             "severity":"error","message":"..."}],
//             "keys":[{"path":"trace.max_steps","at":0,"length":11}]}}   kinds: usage, work, no-gl, cancelled;
//                     "keys" (only when there are any): where the message names request keys, in
//                     bytes, so the reader can word them its own way (core/KeyedText.h)
//   {"report":{...}}    the report of the request's kind, in JobJson.h's form
//   {"end":0}           the request is done, with the exit code its command would have
// Anything else on stdout or stderr is not part of the protocol (log lines); a reader skips it.

#include <jobs/Jobs.h>

#include <cstdint>
#include <string>

namespace sdfwb::jobs {

std::string progressMessage(std::uint64_t done, std::uint64_t total);
std::string errorMessage(const JobError& error);
std::string reportMessage(const std::string& reportJson); // reportJson: one of JobJson.h's toJson
std::string endMessage(int exitCode);

struct WorkerMessage {
    enum class Kind { Progress, Error, Report, End, Other } kind = Kind::Other;
    std::uint64_t done = 0, total = 0; // Progress
    JobError error;                    // Error
    std::string report;                // Report: the report's JSON, for reportFromJson
    int exitCode = 0;                  // End
};

// One line of the child's output; Other for a line that is not a protocol message.
WorkerMessage readWorkerMessage(const std::string& line);

// "usage", "work", "no-gl", "cancelled".
const char* failureName(Failure failure);

} // namespace sdfwb::jobs
