#pragma once
// The headless commands behind `sdfwb --batch ...`: each runs one typed request (jobs/Requests.h)
// and prints its report, as text or as the report's JSON (--json). No Qt, no widgets: EGL for GL.
// Each returns a process exit code (see ExitCode). One file each under commands/.

#include <core/KeyedText.h>
#include <values/Requests.h>

#include <string>

namespace sdfwb::app {

enum ExitCode : int {
    kExitOk = 0,
    kExitFailure = 1,     // the work failed: the SDF does not compile, a file cannot be written
    kExitUsage = 2,       // bad arguments: unknown option, malformed value, missing file
    kExitNoGl = 3,        // no OpenGL 4.3 context could be created
    kExitCancelled = 130, // interrupted (Ctrl-C); no partial output was left
};

struct OutputOptions {
    bool quiet = false;    // only errors
    bool json = false;     // machine-readable report on stdout
    bool protocol = false; // the worker protocol (jobs/Protocol.h) on stdout: progress, error, report, end
};

int runRender(const values::RenderRequest& request, const OutputOptions& output);
int runAnimate(const values::AnimateRequest& request, const OutputOptions& output);
int runSample(const values::SampleRequest& request, const OutputOptions& output);
int runAudit(const values::AuditRequest& request, const OutputOptions& output);
int runMerge(const values::MergeRequest& request, const OutputOptions& output);
int runList(const values::ListRequest& request, const OutputOptions& output);
int runParams(const values::ParamsRequest& request, const OutputOptions& output);
int runMesh(const values::MeshRequest& request, const OutputOptions& output);
int runEval(const values::EvalRequest& request, const OutputOptions& output);
// Exit 1 when any item failed (the others still ran), 130 when cancelled.
int runRun(const values::RunRequest& request, const OutputOptions& output);
// The march debugger: every step of one pixel's ray.
int runProbe(const values::ProbeRequest& request, const OutputOptions& output);
// Error against run time for the tracer, the samplers, gradients and the audit (jobs/Benchmarks.h).
int runBench(const values::BenchRequest& request, const OutputOptions& output);

// Runs any request with the command of its kind.
int runRequest(const values::Request& request, const OutputOptions& output);

// Prints "sdfwb: <message>" to stderr, or, under the worker protocol, its error message on stdout.
void printError(const std::string& message);
// Under the worker protocol (setProtocolOutput), errors, progress and reports are protocol messages.
void setProtocolOutput(bool on);
// Ends a request under the worker protocol: its error message (unless it succeeded), then
// {"end": exitCode}. Returns exitCode.
int endProtocolRequest(int exitCode);

// While alive, the failures reportFailure prints name the request keys in `terms` (a command's
// options: --size for 'width', 'height'); outside one they keep the request's own terms, as a JSON
// request or job file wrote them. The worker protocol always sends the request's terms.
class ErrorTerms {
public:
    explicit ErrorTerms(KeyTerms terms);
    ~ErrorTerms();
    ErrorTerms(const ErrorTerms&) = delete;
    ErrorTerms& operator=(const ErrorTerms&) = delete;

private:
    KeyTerms m_previous;
};

} // namespace sdfwb::app
