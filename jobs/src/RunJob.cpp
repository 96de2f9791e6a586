// `sdfwb --batch run MANIFEST`: every item of a manifest in a child process of its own (sample
// items: this binary's `--batch request -`; recipes: `python3 -m sdfwb recipe -`), with a time
// limit, a status file that makes the run resumable, and rank slicing for Slurm arrays and Dask.
// POSIX only: fork/exec, poll and process groups (a timed-out item is killed with its children).
#include <jobs/Jobs.h>

#include <jobs/JobJson.h>
#include <jobs/Manifest.h>
#include <jobs/Protocol.h>

#include <core/TextFile.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

extern char** environ;

namespace sdfwb::jobs {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string statusPath(const values::RunRequest& request) {
    if (!request.status.empty()) return request.status;
    if (request.worldSize > 1)
        return request.manifest + ".status-" + std::to_string(request.rank) + "-of-" + std::to_string(request.worldSize) +
               ".jsonl";
    return request.manifest + ".status.jsonl";
}

fs::path executable(const values::RunRequest& request) {
    if (!request.executable.empty()) return request.executable;
    std::error_code ec;
    return fs::read_symlink("/proc/self/exe", ec);
}

std::string python(const values::RunRequest& request) {
    if (!request.python.empty()) return request.python;
    if (const char* given = std::getenv("SDFWB_PYTHON"); given && *given) return given;
#ifdef SDFWB_PYTHON
    return SDFWB_PYTHON;
#else
    return "/usr/bin/python3";
#endif
}

// PYTHONPATH for recipe items: the folders next to the sdfwb binary that hold the sdfwb package
// (the build tree's python/, an install's lib/python3/dist-packages), then the caller's.
std::string pythonPath(const fs::path& binary) {
    std::string path;
    std::error_code ec;
    for (const fs::path& folder : {binary.parent_path().parent_path() / "python",
                                   binary.parent_path().parent_path() / "lib" / "python3" / "dist-packages"})
        if (fs::is_regular_file(folder / "sdfwb" / "__init__.py", ec)) path += (path.empty() ? "" : ":") + folder.string();
    if (const char* given = std::getenv("PYTHONPATH"); given && *given) path += (path.empty() ? "" : ":") + std::string(given);
    return path;
}

std::string utcNow() {
    std::time_t now = std::time(nullptr);
    std::tm parts{};
    gmtime_r(&now, &parts);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &parts);
    return text;
}

// The temporary files an interrupted writer may leave beside `output` (sampling's OutputFile and
// sdfwb/recipes.py both name them ".NAME.partial-XXXXXX").
void removePartials(const fs::path& output) {
    std::error_code ec;
    const fs::path folder = output.parent_path().empty() ? fs::path(".") : output.parent_path();
    const std::string prefix = "." + output.filename().string() + ".partial-";
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().filename().string().rfind(prefix, 0) == 0) fs::remove(it->path(), ec);
}

struct ChildOutcome {
    int exitCode = 0; // the item's (from the end message), the process's, or 128 + signal
    bool timedOut = false, cancelled = false, startFailed = false;
    std::string out, err;          // out: the worker's report (or a recipe's stdout); err: stderr
    std::optional<JobError> error; // the worker's error message for the item
    double seconds = 0.0;
};

void closeFd(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
}

// A child process in its own process group, with pipes on stdin, stdout and stderr; it dies with
// this process (PR_SET_PDEATHSIG). Two uses: one input, then its exit (recipes through Python);
// or a worker (`sdfwb --batch request - --protocol --each-line`) that answers each request line in
// the worker protocol (jobs/Protocol.h), so one process start and GL context serve many items.
class Child {
public:
    Child(const std::vector<std::string>& argv, const std::vector<std::string>& environment) {
        int in[2], out[2], err[2];
        if (::pipe2(in, O_CLOEXEC) != 0 || ::pipe2(out, O_CLOEXEC) != 0 || ::pipe2(err, O_CLOEXEC) != 0) {
            m_startError = std::string("cannot create pipes: ") + std::strerror(errno);
            return;
        }
        std::vector<char*> args, env;
        for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        for (const std::string& e : environment) env.push_back(const_cast<char*>(e.c_str()));
        env.push_back(nullptr);
        const pid_t parent = ::getpid();
        const pid_t pid = ::fork();
        if (pid == 0) {
            ::setpgid(0, 0);
            ::prctl(PR_SET_PDEATHSIG, SIGKILL);
            if (::getppid() != parent) ::_exit(127);
            ::dup2(in[0], 0);
            ::dup2(out[1], 1);
            ::dup2(err[1], 2);
            ::signal(SIGPIPE, SIG_DFL);
            ::signal(SIGINT, SIG_DFL);
            ::signal(SIGTERM, SIG_DFL);
            ::execve(args[0], args.data(), env.data());
            const std::string message = std::string("cannot run ") + args[0] + ": " + std::strerror(errno) + "\n";
            [[maybe_unused]] auto written = ::write(2, message.data(), message.size());
            ::_exit(127);
        }
        ::close(in[0]);
        ::close(out[1]);
        ::close(err[1]);
        m_in = in[1];
        m_out = out[0];
        m_err = err[0];
        if (pid < 0) {
            m_startError = std::string("fork failed: ") + std::strerror(errno);
            end();
            return;
        }
        m_pid = pid;
        ::setpgid(pid, pid); // also here: no window where a signal to the group misses the child
        for (int fd : {m_in, m_out, m_err}) ::fcntl(fd, F_SETFL, O_NONBLOCK);
    }
    ~Child() { end(); }
    Child(const Child&) = delete;
    Child& operator=(const Child&) = delete;

    bool running() const { return m_pid > 0; }

    // Writes `input`. With `toExit`, closes stdin after it and waits for the process to end;
    // otherwise reads the worker's protocol messages up to the item's {"end":CODE}. Past `timeout` seconds (0: none) or
    // on a cancel, SIGTERM goes to the group and SIGKILL 3 s later; the process is then gone.
    ChildOutcome exchange(const std::string& input, bool toExit, double timeout, const ProgressSink& sink) {
        ChildOutcome outcome;
        const auto start = Clock::now();
        if (!running()) {
            outcome.startFailed = true;
            outcome.exitCode = 127;
            outcome.err = m_startError.empty() ? "the worker is not running" : m_startError;
            return outcome;
        }
        std::size_t written = 0;
        std::optional<Clock::time_point> killAt; // SIGKILL after the SIGTERM grace
        while (true) {
            pollfd fds[3];
            nfds_t count = 0;
            if (m_out >= 0) fds[count++] = {m_out, POLLIN, 0};
            if (m_err >= 0) fds[count++] = {m_err, POLLIN, 0};
            if (m_in >= 0 && written < input.size()) fds[count++] = {m_in, POLLOUT, 0};
            ::poll(fds, count, count > 0 ? 50 : 0);
            if (m_in >= 0 && written < input.size()) {
                const ssize_t n = ::write(m_in, input.data() + written, input.size() - written);
                if (n > 0) written += std::size_t(n);
                if (n < 0 && errno != EAGAIN && errno != EINTR) closeFd(m_in);
            }
            if (toExit && m_in >= 0 && written == input.size()) closeFd(m_in);
            drain(m_out, m_pending);
            drain(m_err, outcome.err);
            if (outcome.err.size() > 65536) outcome.err.erase(0, outcome.err.size() - 32768);
            if (!toExit && takeMessages(outcome)) {
                drain(m_err, outcome.err); // written before the end message, so already in the pipe
                break;
            }
            int status = 0;
            if (::waitpid(m_pid, &status, WNOHANG) == m_pid) {
                drain(m_out, m_pending);
                drain(m_err, outcome.err);
                m_pid = -1;
                outcome.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
                if (!toExit && outcome.exitCode == 0) outcome.exitCode = 1; // a worker ending mid-item failed it
                if (toExit) outcome.out = std::move(m_pending);
                m_pending.clear();
                end();
                break;
            }
            const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
            if (!killAt && ((timeout > 0.0 && elapsed > timeout) || sink.isCancelled())) {
                (sink.isCancelled() ? outcome.cancelled : outcome.timedOut) = true;
                ::kill(-m_pid, SIGTERM);
                killAt = Clock::now() + std::chrono::seconds(3);
            }
            if (killAt && Clock::now() > *killAt) ::kill(-m_pid, SIGKILL);
        }
        outcome.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        return outcome;
    }

    // Closes stdin (a worker exits at the end of its input), waits up to 2 s, then kills the group.
    void end() {
        closeFd(m_in);
        if (m_pid > 0) {
            const auto deadline = Clock::now() + std::chrono::seconds(2);
            int status = 0;
            while (::waitpid(m_pid, &status, WNOHANG) == 0 && Clock::now() < deadline) ::usleep(5000);
            ::kill(-m_pid, SIGKILL);
            ::waitpid(m_pid, &status, 0);
            m_pid = -1;
        }
        closeFd(m_out);
        closeFd(m_err);
    }

private:
    // Takes the worker's complete lines: the item's report and error, log lines skipped. True once
    // its end message came (its exit code in `outcome`).
    bool takeMessages(ChildOutcome& outcome) {
        for (std::size_t newline = m_pending.find('\n'); newline != std::string::npos; newline = m_pending.find('\n')) {
            WorkerMessage message = readWorkerMessage(m_pending.substr(0, newline));
            m_pending.erase(0, newline + 1);
            if (message.kind == WorkerMessage::Kind::Report) outcome.out = std::move(message.report);
            if (message.kind == WorkerMessage::Kind::Error) outcome.error = std::move(message.error);
            if (message.kind == WorkerMessage::Kind::End) {
                outcome.exitCode = message.exitCode;
                return true;
            }
        }
        return false;
    }

    static void drain(int& fd, std::string& target) {
        char buffer[65536];
        while (fd >= 0) {
            const ssize_t n = ::read(fd, buffer, sizeof buffer);
            if (n > 0) {
                target.append(buffer, std::size_t(n));
            } else if (n == 0) {
                closeFd(fd);
            } else {
                if (errno != EAGAIN && errno != EINTR) closeFd(fd);
                if (errno != EINTR) break;
            }
        }
    }

    pid_t m_pid = -1;
    int m_in = -1, m_out = -1, m_err = -1;
    std::string m_pending; // stdout not yet claimed by an item
    std::string m_startError;
};

// The last three lines of a child's stderr joined by " / ", for the status file (at most 1000 characters).
std::string lastMessage(const std::string& err) {
    std::vector<std::string> lines;
    std::istringstream stream(err);
    std::string line;
    while (std::getline(stream, line))
        // Log lines ("[info] gl: ...") are context, not the failure.
        if (line.find_first_not_of(" \t\r") != std::string::npos && line.rfind("[info]", 0) != 0 && line.rfind("[debug]", 0) != 0)
            lines.push_back(line.substr(0, line.find_last_not_of(" \t\r") + 1));
    std::string text;
    for (std::size_t i = lines.size() > 3 ? lines.size() - 3 : 0; i < lines.size(); ++i)
        text += (text.empty() ? "" : " / ") + lines[i];
    return text.size() > 1000 ? "..." + text.substr(text.size() - 997) : text;
}

// A worker's error for the status file: its message, then its first diagnostics as the CLI prints
// them (at most 1000 characters).
std::string errorText(const JobError& error) {
    std::string text = error.message;
    for (std::size_t k = 0; k < error.diagnostics.size() && k < 3; ++k)
        text += " / " + shaders::formatDiagnostic(error.diagnostics[k]);
    return text.size() > 1000 ? text.substr(0, 997) + "..." : text;
}

Expected<void> appendStatus(const std::string& path, const values::RunItemReport& item) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) return makeError(path + ": cannot open the status file: " + std::strerror(errno));
    const std::string line = toJson(item, -1) + "\n";
    // One write: concurrent runners (Dask tasks) appending to one file do not interleave lines.
    const bool ok = ::write(fd, line.data(), line.size()) == ssize_t(line.size()) && ::fsync(fd) == 0;
    const int code = errno;
    ::close(fd);
    if (!ok) return makeError(path + ": cannot append to the status file: " + std::strerror(code));
    return {};
}

// The last record of each item index; lines that do not read (a torn last line) are ignored.
std::map<std::uint64_t, values::RunItemReport> readStatus(const std::string& path) {
    std::map<std::uint64_t, values::RunItemReport> records;
    std::error_code ec;
    if (!fs::exists(path, ec)) return records;
    auto text = readTextFile(path);
    if (!text) return records;
    std::istringstream lines(*text);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.empty()) continue;
        if (auto record = reportFromJson<values::RunItemReport>(line)) records[record->index] = std::move(*record);
    }
    return records;
}

bool recordedDone(const values::RunItemReport& record, const ManifestItem& item) {
    std::error_code ec;
    return record.status == values::ItemStatus::Done && record.key == item.key && fs::is_regular_file(item.output, ec) &&
           fs::file_size(item.output, ec) == record.bytes;
}

std::vector<ManifestItem> selected(const std::vector<ManifestItem>& items, const values::RunRequest& request) {
    std::vector<ManifestItem> mine;
    for (const ManifestItem& item : items)
        if (request.items.empty() ? item.index % request.worldSize == request.rank
                                  : std::find(request.items.begin(), request.items.end(), item.index) != request.items.end())
            mine.push_back(item);
    return mine;
}

values::RunItemReport itemReport(const ManifestItem& item) {
    values::RunItemReport report;
    report.index = item.index;
    report.line = item.line;
    report.task = item.kind;
    report.sdf = item.sdf;
    report.output = item.output;
    report.key = item.key;
    return report;
}

// How children start: this environment (PYTHONPATH pointing at the sdfwb package next to the
// binary, for recipes), the sdfwb binary, and the Python interpreter.
struct Launcher {
    fs::path binary;
    std::string python;
    std::vector<std::string> environment;
};

Launcher launcher(const values::RunRequest& request) {
    Launcher launch{executable(request), python(request), {}};
    for (char** e = environ; *e; ++e)
        if (std::strncmp(*e, "PYTHONPATH=", 11) != 0 && std::strncmp(*e, "SDFWB_BINARY=", 13) != 0)
            launch.environment.push_back(*e);
    if (std::string path = pythonPath(launch.binary); !path.empty()) launch.environment.push_back("PYTHONPATH=" + path);
    launch.environment.push_back("SDFWB_BINARY=" + launch.binary.string());
    return launch;
}

// Runs one item: sample items on the worker (started, or restarted after a crash or a kill, as
// needed), recipes in a Python child of their own.
values::RunItemReport runItem(const ManifestItem& item, const values::RunRequest& request, const Launcher& launch,
                              std::unique_ptr<Child>& worker, const ProgressSink& sink) {
    values::RunItemReport report = itemReport(item);
    std::error_code ec;
    const fs::path output(item.output);
    if (!output.parent_path().empty()) fs::create_directories(output.parent_path(), ec);
    if (ec) {
        report.status = values::ItemStatus::Failed;
        report.exitCode = 1;
        report.error = item.output + ": cannot create its folder: " + ec.message();
        report.finished = utcNow();
        return report;
    }
    removePartials(output);
    ChildOutcome child;
    if (item.kind == "sample") {
        if (!worker || !worker->running())
            worker = std::make_unique<Child>(std::vector<std::string>{launch.binary.string(), "--batch", "request", "-",
                                                                      "--protocol", "--each-line", "--quiet"},
                                             launch.environment);
        child = worker->exchange(item.childInput + "\n", false, request.itemTimeout, sink);
    } else {
        Child once({launch.python, "-m", "sdfwb", "recipe", "-"}, launch.environment);
        child = once.exchange(item.childInput, true, request.itemTimeout, sink);
    }
    report.seconds = child.seconds;
    report.exitCode = child.exitCode;
    report.finished = utcNow();
    if (child.cancelled) {
        report.status = values::ItemStatus::Cancelled;
        report.error = "cancelled";
    } else if (child.timedOut) {
        report.status = values::ItemStatus::Timeout;
        char text[96];
        std::snprintf(text, sizeof text, "killed after the item timeout of %g s", request.itemTimeout);
        report.error = text;
    } else if (child.startFailed || child.exitCode != 0) {
        report.status = values::ItemStatus::Failed;
        report.error = child.error ? errorText(*child.error) : lastMessage(child.err);
        if (report.error.empty()) report.error = "exit code " + std::to_string(child.exitCode);
    } else if (!fs::is_regular_file(output, ec)) {
        report.status = values::ItemStatus::Failed;
        report.error = "the child succeeded but wrote no " + item.output;
    } else {
        report.status = values::ItemStatus::Done;
        report.bytes = fs::file_size(output, ec);
        // Sample items print their SampleReport; recipes a JSON line with the same rows and bad_rows keys.
        if (auto written = reportFromJson<values::SampleReport>(child.out)) {
            report.rows = written->rows;
            report.badRows = written->badRows;
        }
    }
    if (report.status != values::ItemStatus::Done) removePartials(output);
    return report;
}

// SIGPIPE is ignored while children run: a child that exits before reading its stdin must not
// end the runner.
struct IgnoreSigpipe {
    struct sigaction previous {};
    IgnoreSigpipe() {
        struct sigaction ignore {};
        ignore.sa_handler = SIG_IGN;
        ::sigaction(SIGPIPE, &ignore, &previous);
    }
    ~IgnoreSigpipe() { ::sigaction(SIGPIPE, &previous, nullptr); }
};

} // namespace

std::optional<JobError> validate(const values::RunRequest& request) {
    if (request.manifest.empty()) return usageError("run: no manifest given");
    if (request.worldSize < 1) return usageError(key("world_size") + ": must be at least 1");
    if (request.rank >= request.worldSize)
        return usageError(key("rank") + ": must be below " + key("world_size") + " (" + std::to_string(request.worldSize) +
                          "), got " + std::to_string(request.rank));
    if (!request.items.empty() && request.worldSize > 1)
        return usageError(key("items") + ": names the items to run; it cannot be combined with " + key("world_size"));
    if (!std::isfinite(request.itemTimeout) || request.itemTimeout < 0.0)
        return usageError(key("item_timeout") + ": expected seconds >= 0 (0: no limit)");
    const fs::path binary = executable(request);
    std::error_code ec;
    if (request.executable.empty() && binary.filename() != "sdfwb")
        return usageError("run: this process (" + binary.string() +
                          ") is not sdfwb; give \"executable\": the sdfwb binary's path");
    if (!fs::is_regular_file(binary, ec)) return usageError("run: executable '" + binary.string() + "' does not exist");
    const fs::path status = statusPath(request);
    const fs::path folder = status.parent_path().empty() ? fs::path(".") : status.parent_path();
    if (!fs::is_directory(folder, ec))
        return usageError(key("status") + ": '" + status.string() + "': folder '" + folder.string() + "' does not exist");
    auto items = readManifest(request.manifest);
    if (!items) return usageError(items.error().keyed());
    for (std::uint64_t item : request.items)
        if (item >= items->size())
            return usageError(key("items") + ": " + std::to_string(item) + " is past the manifest's last item (" +
                              std::to_string(items->size() - 1) + ")");
    return std::nullopt;
}

JobResult<values::RunReport> run(const values::RunRequest& request, const ProgressSink& progress,
                                 const std::function<void(const values::RunItemReport&)>& onItem) {
    if (auto error = validate(request)) return *error;
    const auto start = Clock::now();
    auto items = readManifest(request.manifest);
    values::RunReport report;
    report.manifest = request.manifest;
    report.status = statusPath(request);
    report.rank = request.rank;
    report.worldSize = request.worldSize;
    report.items = items->size();
    const std::vector<ManifestItem> mine = selected(*items, request);
    report.selected = mine.size();
    const auto records = readStatus(report.status);
    IgnoreSigpipe ignoreSigpipe;
    const Launcher launch = launcher(request);
    std::unique_ptr<Child> worker; // one sdfwb process for the sample items, until one crashes or hangs
    for (std::size_t k = 0; k < mine.size(); ++k) {
        const ManifestItem& item = mine[k];
        const auto record = records.find(item.index);
        values::RunItemReport result;
        if (record != records.end() && recordedDone(record->second, item)) {
            result = record->second;
            result.status = request.list ? values::ItemStatus::Done : values::ItemStatus::Skipped;
        } else if (request.list) {
            result = record != records.end() && record->second.key == item.key ? record->second : itemReport(item);
        } else {
            result = runItem(item, request, launch, worker, progress);
            if (auto appended = appendStatus(report.status, result); !appended) return workError(appended.error().keyed());
        }
        if (result.status == values::ItemStatus::Done && !request.list) {
            ++report.done;
            report.bytesWritten += result.bytes;
        } else if (result.status == values::ItemStatus::Skipped || (request.list && result.status == values::ItemStatus::Done)) {
            ++report.skipped;
        } else if (result.status != values::ItemStatus::Pending && result.status != values::ItemStatus::Cancelled) {
            ++report.failed;
        }
        report.results.push_back(result);
        if (onItem) onItem(result);
        progress(k + 1, mine.size());
        if (result.status == values::ItemStatus::Cancelled || progress.isCancelled())
            return JobError{Failure::Cancelled,
                            "run: cancelled; " + std::to_string(report.done) + " items were done and recorded in " +
                                report.status,
                            {},
                            {}};
    }
    report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    report.shapesPerHour = report.seconds > 0.0 ? double(report.done) * 3600.0 / report.seconds : 0.0;
    return report;
}

} // namespace sdfwb::jobs
