// Latency of the workbench's interactive requests, before and after the persistent worker: a plane
// readout (from the drag's rest: the debounce, then the request) and a march probe (from the
// click). Before: a child process per request (app::BatchProcess, as every plane drag and probe
// click started until the worker). After: app::JobWorker, one warm child. The reference is the
// job's own compute time, jobs::run on the same request in this process with a warm EGL context
// (the SDF opened and its shaders compiled each time, as the child does). Goal (issue 34): latency
// at most 1.5x that compute time plus 20 ms. Medians of --runs (default 9) after one warm-up.
//
//   build/bench/bench_interactive [--runs N] [--sdf NAME,NAME...]

#include <gui/BatchProcess.h>
#include <gui/JobWorker.h>
#include <gui/PlaneController.h>

#include <jobs/JobJson.h>
#include <jobs/Jobs.h>
#include <renderer/HeadlessContext.h>

#include <QCoreApplication>
#include <QDate>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QSysInfo>
#include <QThread>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace sdfwb;

namespace {

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// Milliseconds from start() to finished(), through a BatchProcess or a JobChannel.
template <class Runner> double roundTrip(Runner& runner, const values::Request& request) {
    QEventLoop loop;
    bool ok = false;
    auto connection =
        QObject::connect(&runner, &Runner::finished, &loop, [&](bool good, bool, const std::string&, const QString& message) {
            ok = good;
            if (!good) std::fprintf(stderr, "request failed: %s\n", message.toStdString().c_str());
            loop.quit();
        });
    QElapsedTimer timer;
    timer.start();
    if (!runner.start(request)) return -1.0;
    loop.exec();
    const double ms = double(timer.nsecsElapsed()) / 1e6;
    QObject::disconnect(connection);
    return ok ? ms : -1.0;
}

double computeMs(const values::Request& request) {
    const auto start = std::chrono::steady_clock::now();
    const bool ok = std::visit([](const auto& r) { return bool(jobs::run(r, ProgressSink{})); }, request);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return ok ? ms : -1.0;
}

} // namespace

int main(int argc, char** argv) {
    QCoreApplication application(argc, argv);
    int runs = 9;
    std::string sdfs = "Torus,Mandelbulb"; // a plain shape and a fractal (its shaders compile slower)
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::strcmp(argv[i], "--runs") == 0) runs = std::max(1, std::atoi(argv[i + 1]));
        if (std::strcmp(argv[i], "--sdf") == 0) sdfs = argv[i + 1];
    }
    const QString binary = QCoreApplication::applicationDirPath() + "/../app/sdfwb";

    auto context = renderer::HeadlessContext::create();
    if (!context) {
        std::fprintf(stderr, "no GL context: %s\n", context.error().message.c_str());
        return 3;
    }
    const std::string renderer = (*context)->info().renderer;
    app::BatchProcess process;
    process.setExecutable(binary);
    app::JobWorker worker;
    worker.setExecutable(binary);
    app::JobChannel channel(&worker);

    std::printf("# Interactive request latency: a child per request (before) against the persistent worker (after)\n\n");
    std::printf("Run on %s, %s (%s), %d cores, %s; SDFs %s; medians of %d runs after one warm-up. Made by "
                "`build/bench/bench_interactive > docs/interactive-latency.md`.\n\n",
                QDate::currentDate().toString(Qt::ISODate).toStdString().c_str(),
                QSysInfo::machineHostName().toStdString().c_str(), QSysInfo::prettyProductName().toStdString().c_str(),
                QThread::idealThreadCount(), renderer.c_str(), sdfs.c_str(), runs);
    std::printf("| SDF | request | job's compute ms (in process, warm GL) | child per request ms | worker ms | debounce ms | "
                "latency before ms | latency after ms | goal ms (1.5 x compute + 20) | after / goal |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    int requests = 0;
    for (std::size_t from = 0; from <= sdfs.size();) {
        const std::size_t comma = std::min(sdfs.find(',', from), sdfs.size());
        const std::string sdf = sdfs.substr(from, comma - from);
        from = comma + 1;
        values::AuditRequest plane; // what PlaneController::refresh sends
        plane.sdf.sdf = sdf;
        plane.plane = values::PlaneSpec{glm::vec3(0.0f, 0.0f, 1.0f), 0.1f};
        plane.resolution = 192;
        values::ProbeRequest probe; // what ProbeController::probe sends for a click in a 960x540 view
        probe.frame.sdf.sdf = sdf;
        probe.frame.width = 960;
        probe.frame.height = 540;
        probe.x = 480;
        probe.y = 270;

        struct Case {
            const char* name;
            values::Request request;
            int debounceBefore, debounceAfter;
        };
        const Case cases[] = {
            {"plane readouts (drag's rest)", plane, 250, app::PlaneController::kDebounceMs},
            {"march probe (click)", probe, 0, 0},
        };
        for (const Case& c : cases) {
            std::vector<double> compute, spawned, warm;
            for (int r = 0; r <= runs; ++r) {
                const double a = computeMs(c.request), b = roundTrip(process, c.request), w = roundTrip(channel, c.request);
                if (a < 0 || b < 0 || w < 0) return 1;
                if (r == 0) continue; // warm-up
                compute.push_back(a);
                spawned.push_back(b);
                warm.push_back(w);
            }
            const double before = c.debounceBefore + median(spawned), after = c.debounceAfter + median(warm);
            const double goal = 1.5 * median(compute) + 20.0;
            std::printf("| %s | %s | %.1f | %.1f | %.1f | %d (was %d) | %.1f | %.1f | %.1f | %.2f |\n", sdf.c_str(), c.name,
                        median(compute), median(spawned), median(warm), c.debounceAfter, c.debounceBefore, before, after, goal,
                        after / goal);
        }
        requests += 2 * (runs + 1);
    }
    std::printf("\nWorker processes started: %d, for all %d worker requests. Latency before: the old debounce plus a "
                "child's whole life (process start, EGL context, the SDF opened and compiled, the job, exit); after: the new "
                "debounce plus the worker's answer (the SDF opened and compiled, the job). Where after / goal is above 1 the "
                "goal is not met.\n",
                worker.starts(), requests);
    return 0;
}
