// The workbench's persistent worker (app/gui/JobWorker.h) against the real sdfwb binary: requests
// share one process, the structured error (kind, message, the SDF's diagnostics with their lines)
// crosses the process boundary, a crashed or hung worker is replaced and the caller told, and a
// queued request can be cancelled. Needs no display: QProcess and timers run on QCoreApplication.
#include "JobWorker.h"

#include <gtest/gtest.h>

#include <jobs/JobJson.h>

#include <QCoreApplication>
#include <QSignalSpy>

#include <csignal>
#include <sys/types.h>

using namespace sdfwb;

namespace {

values::AuditRequest planeRequest(const std::string& source, float offset = 0.0f) {
    values::AuditRequest request;
    request.sdf.sdf = "<test>";
    request.sdf.source = source;
    request.plane = values::PlaneSpec{glm::vec3(0.0f, 0.0f, 1.0f), offset};
    request.resolution = 64;
    return request;
}

const char* kSphere = "float sdf(vec3 p) { return length(p) - 0.5; }\n";

struct Outcome {
    bool ok = false, cancelled = false;
    std::string report;
    QString message;
};

// Waits for the channel's next finished signal.
Outcome await(app::JobChannel& channel, int milliseconds = 60000) {
    QSignalSpy spy(&channel, &app::JobChannel::finished);
    EXPECT_TRUE(spy.wait(milliseconds));
    Outcome outcome;
    if (spy.isEmpty()) return outcome;
    const QList<QVariant> arguments = spy.takeFirst();
    outcome.ok = arguments[0].toBool();
    outcome.cancelled = arguments[1].toBool();
    outcome.report = arguments[2].value<std::string>();
    outcome.message = arguments[3].toString();
    return outcome;
}

app::JobWorker* newWorker() {
    auto* worker = new app::JobWorker;
    worker->setExecutable(SDFWB_BINARY);
    return worker;
}

} // namespace

TEST(JobWorker, RequestsShareOneWarmProcess) {
    std::unique_ptr<app::JobWorker> worker(newWorker());
    app::JobChannel channel(worker.get());
    for (float offset : {0.0f, 0.1f, 0.2f}) {
        ASSERT_TRUE(channel.start(planeRequest(kSphere, offset)));
        EXPECT_FALSE(channel.start(planeRequest(kSphere))) << "one request per channel at a time";
        const Outcome outcome = await(channel);
        ASSERT_TRUE(outcome.ok) << outcome.message.toStdString();
        auto report = jobs::reportFromJson<values::AuditJobReport>(outcome.report);
        ASSERT_TRUE(report) << report.error().message;
        ASSERT_TRUE(report->readout.has_value());
        // The plane z = offset through a sphere of radius 0.5: the smallest value is offset - 0.5 at
        // the plane's centre, which the 64 x 64 grid over the box's section misses by under 0.06.
        EXPECT_GE(report->readout->minimum, offset - 0.5f - 1e-4f);
        EXPECT_LT(report->readout->minimum, offset - 0.5f + 0.06f);
    }
    EXPECT_EQ(worker->starts(), 1);
    EXPECT_GT(worker->processId(), 0);
}

TEST(JobWorker, TheStructuredErrorCrossesTheProcessBoundary) {
    std::unique_ptr<app::JobWorker> worker(newWorker());
    app::JobChannel channel(worker.get());
    ASSERT_TRUE(channel.start(planeRequest("float sdf(vec3 p) {\n    float r = 0.5\n    return length(p) - r;\n}\n")));
    const Outcome outcome = await(channel);
    EXPECT_FALSE(outcome.ok);
    EXPECT_FALSE(outcome.cancelled);
    const jobs::JobError& error = channel.error();
    EXPECT_EQ(error.failure, jobs::Failure::Work);
    ASSERT_FALSE(error.diagnostics.empty()) << error.message;
    EXPECT_EQ(error.diagnostics.front().file, "<test>");
    EXPECT_GE(error.diagnostics.front().line, 2); // the missing ';' of line 2 is seen at line 2 or 3
    EXPECT_LE(error.diagnostics.front().line, 3);
    EXPECT_TRUE(outcome.message.contains("<test>:")) << outcome.message.toStdString();
    // A request the child cannot read is a usage error, and the worker answers the next one.
    values::AuditRequest bad = planeRequest(kSphere);
    bad.resolution = -3;
    ASSERT_TRUE(channel.start(bad));
    EXPECT_FALSE(await(channel).ok);
    EXPECT_EQ(channel.error().failure, jobs::Failure::Usage);
    ASSERT_TRUE(channel.start(planeRequest(kSphere)));
    EXPECT_TRUE(await(channel).ok);
    EXPECT_EQ(worker->starts(), 1);
}

TEST(JobWorker, ACrashedWorkerIsReplacedAndTheCallerTold) {
    std::unique_ptr<app::JobWorker> worker(newWorker());
    app::JobChannel channel(worker.get());
    ASSERT_TRUE(channel.start(planeRequest(kSphere)));
    ASSERT_TRUE(await(channel).ok);
    const qint64 first = worker->processId();
    ASSERT_GT(first, 0);
    ASSERT_TRUE(channel.start(planeRequest(kSphere, 0.1f)));
    ::kill(pid_t(first), SIGKILL); // as a driver crash would
    const Outcome crashed = await(channel);
    EXPECT_FALSE(crashed.ok);
    EXPECT_TRUE(crashed.message.contains("crashed")) << crashed.message.toStdString();
    ASSERT_TRUE(channel.start(planeRequest(kSphere, 0.1f)));
    EXPECT_TRUE(await(channel).ok);
    EXPECT_EQ(worker->starts(), 2);
    EXPECT_NE(worker->processId(), first);
}

TEST(JobWorker, AHungWorkerIsStoppedAfterItsTimeout) {
    std::unique_ptr<app::JobWorker> worker(newWorker());
    app::JobChannel channel(worker.get());
    ASSERT_TRUE(channel.start(planeRequest(kSphere)));
    ASSERT_TRUE(await(channel).ok);
    worker->setTimeout(500);
    const qint64 first = worker->processId();
    ::kill(pid_t(first), SIGSTOP); // it can no longer answer: a hang
    ASSERT_TRUE(channel.start(planeRequest(kSphere, 0.1f)));
    const Outcome hung = await(channel);
    EXPECT_FALSE(hung.ok);
    EXPECT_TRUE(hung.message.contains("no answer")) << hung.message.toStdString();
    worker->setTimeout(60000);
    ASSERT_TRUE(channel.start(planeRequest(kSphere, 0.1f)));
    EXPECT_TRUE(await(channel).ok);
    EXPECT_EQ(worker->starts(), 2);
}

TEST(JobWorker, AQueuedRequestIsCancelledAndTheOthersRun) {
    std::unique_ptr<app::JobWorker> worker(newWorker());
    app::JobChannel first(worker.get()), second(worker.get()), third(worker.get());
    QSignalSpy firstDone(&first, &app::JobChannel::finished), secondDone(&second, &app::JobChannel::finished);
    ASSERT_TRUE(first.start(planeRequest(kSphere)));
    ASSERT_TRUE(second.start(planeRequest(kSphere, 0.1f)));
    ASSERT_TRUE(third.start(planeRequest(kSphere, 0.2f)));
    second.cancel(); // queued behind the first: dropped at once
    ASSERT_EQ(secondDone.size(), 1);
    EXPECT_TRUE(secondDone.takeFirst()[1].toBool());
    EXPECT_FALSE(second.isRunning());
    const Outcome last = await(third);
    EXPECT_TRUE(last.ok) << last.message.toStdString();
    ASSERT_EQ(firstDone.size(), 1); // in order: the first ended before the third
    EXPECT_TRUE(firstDone.takeFirst()[0].toBool());
    EXPECT_EQ(worker->starts(), 1);
}

int main(int argc, char** argv) {
    QCoreApplication application(argc, argv);
    qRegisterMetaType<std::string>("std::string");
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
