// Sampling from the workbench: the dialog (run, cancel) and the sample-cloud preview.
// Under a real X server (Xvfb) with real input events; helpers in GuiTestSupport.h.

#include "GuiTestSupport.h"

#include <QListWidget>

using namespace sdfwb;
using namespace sdfwb::guitest;

namespace {

// Opens the sampling dialog as a user does (Ctrl+Shift+M on the window); null when it did not show.
widgets::SamplingDialog* openSamplingDialog(app::MainWindow& window) {
    if (!activate(window)) return nullptr;
    QTest::keyClick(&window, Qt::Key_M, Qt::ControlModifier | Qt::ShiftModifier);
    if (!waitFor([&] { return window.sampling()->dialog() && window.sampling()->dialog()->isVisible(); })) return nullptr;
    return window.sampling()->dialog();
}

// Replaces a field's text by typing, as a user does.
void retype(QLineEdit* field, const QString& text) {
    field->selectAll();
    QTest::keyClicks(field, text);
}

// How the last run the sampling controller started ended.
struct RunOutcome {
    bool done = false, ok = false;
    explicit RunOutcome(app::SamplingController* sampling) {
        QObject::connect(sampling, &app::SamplingController::finished, [this](bool success, const QString&) {
            done = true;
            ok = success;
        });
    }
    // Clicks Sample and waits for the run to end.
    bool run(widgets::SamplingDialog* dialog) {
        done = false;
        QTest::mouseClick(dialog->findChild<QPushButton*>("start"), Qt::LeftButton);
        return waitFor([this] { return done; }, 60000);
    }
};

} // namespace

TEST(SamplingDialog, SamplesTheOpenSdfAndCancelsCleanly) {
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(window.openFile(datasetFile("Geometry/Torus.glsl")));
    app::SamplingController* sampling = window.sampling();
    sampling->setExecutable(SDFWB_BINARY);
    sampling->showDialog();
    widgets::SamplingDialog* dialog = sampling->dialog();
    ASSERT_NE(dialog, nullptr);

    QString output = QDir::temp().filePath("sdfwb-gui-samples.npz");
    QFile::remove(output);
    values::SampleRequest settings;
    settings.pattern = "near";
    settings.count = 20000;
    settings.output = output.toStdString();
    dialog->setRequest(settings);
    bool done = false, ok = false;
    QObject::connect(sampling, &app::SamplingController::finished, [&](bool success, const QString&) {
        done = true;
        ok = success;
    });
    dialog->findChild<QPushButton*>("start")->click();
    ASSERT_TRUE(waitFor([&] { return done; }, 60000));
    EXPECT_TRUE(ok) << dialog->findChild<QLabel*>("message")->text().toStdString();
    EXPECT_TRUE(QFile::exists(output));
    EXPECT_TRUE(dialog->findChild<QLabel*>("message")->text().contains("20000 samples"));
    dialog->grab().save(QDir::temp().filePath("sdfwb-gui-sampling-dialog.png"));

    // A long run, cancelled: no file.
    QString cancelled = QDir::temp().filePath("sdfwb-gui-cancelled.npz");
    QFile::remove(cancelled);
    settings.pattern = "metropolis";
    settings.count = 400000000;
    settings.output = cancelled.toStdString();
    dialog->setRequest(settings);
    done = false;
    quint64 written = 0;
    QObject::connect(sampling, &app::SamplingController::progress, [&](quint64 d, quint64) { written = d; });
    dialog->findChild<QPushButton*>("start")->click();
    // Cancel once the child has written samples (its output is open), while it still runs.
    ASSERT_TRUE(waitFor([&] { return written > 0; }, 60000)) << "no progress from the sampling child";
    ASSERT_TRUE(sampling->isRunning()) << "the job ended before Cancel";
    dialog->findChild<QPushButton*>("cancel")->click();
    ASSERT_TRUE(waitFor([&] { return done; }, 30000));
    EXPECT_FALSE(ok);
    EXPECT_TRUE(dialog->findChild<QLabel*>("message")->text().contains("Cancelled"));
    EXPECT_FALSE(QFile::exists(cancelled));
    QFile::remove(output);
}

// A job's diagnostics reach the Problems panel: a sampler file of the user's that does not compile
// (the editor's checks never see it) lists its file:line there, named by the job; a run that
// succeeds clears the rows; clicking a row opens the sampler at its line.
TEST(SamplingDialog, ASamplersCompileErrorReachesTheProblemsPanelAndOpensTheSampler) {
    QTemporaryDir folder;
    const QString sampler = folder.filePath("my_sampler.glsl");
    auto writeSampler = [&](const char* body) {
        QFile file(sampler);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(body);
    };
    const char* broken = "// Uniform points in the box, with a missing semicolon on line 4.\n"
                         "bool samplePosition(uint index, out vec3 position) {\n"
                         "    uint state = index * 747796405u + 2891336453u;\n"
                         "    position = vec3(float(state % 1000u) / 500.0 - 1.0)\n"
                         "    return true;\n"
                         "}\n";
    writeSampler(broken);
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    const int documentRows = window.problems()->count();
    app::SamplingController* sampling = window.sampling();
    sampling->setExecutable(SDFWB_BINARY);
    RunOutcome outcome(sampling);
    widgets::SamplingDialog* dialog = openSamplingDialog(window);
    ASSERT_NE(dialog, nullptr);
    retype(dialog->findChild<QLineEdit*>("count"), "1000");
    retype(dialog->findChild<QLineEdit*>("output"), folder.filePath("out.npz"));
    auto runWith = [&](const QString& pattern) {
        retype(dialog->findChild<QComboBox*>("pattern")->lineEdit(), pattern);
        return outcome.run(dialog);
    };

    ASSERT_TRUE(runWith(sampler));
    EXPECT_FALSE(outcome.ok);
    ASSERT_EQ(window.problems()->count(), documentRows + 1);
    const QString row = window.problems()->rowText(documentRows);
    EXPECT_TRUE(row.startsWith("Sampling job: ")) << row.toStdString();
    EXPECT_TRUE(row.contains("my_sampler.glsl:5"))
        << row.toStdString(); // the statement the semicolon ends is reported where it runs on
    EXPECT_TRUE(window.findChild<QDockWidget*>("ProblemsDock")->isVisible());

    ASSERT_TRUE(runWith("rand"));
    EXPECT_TRUE(outcome.ok) << dialog->findChild<QLabel*>("message")->text().toStdString();
    EXPECT_EQ(window.problems()->count(), documentRows) << "a run that succeeds clears its job's rows";

    ASSERT_TRUE(runWith(sampler));
    ASSERT_EQ(window.problems()->count(), documentRows + 1);
    dialog->close();
    auto* list = window.problems()->findChild<QListWidget*>();
    ASSERT_NE(list, nullptr);
    const QRect rect = list->visualItemRect(list->item(documentRows));
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, rect.center());
    ASSERT_TRUE(waitFor([&] { return window.document()->path() == QFileInfo(sampler).absoluteFilePath(); }))
        << window.document()->path().toStdString();
    int line = 0, column = 0;
    window.editor()->getCursorPosition(&line, &column);
    EXPECT_EQ(line + 1, 5);
    if (QString path = screenshotPath("job_problems.png"); !path.isEmpty()) windowShot(window).save(path);
}

// A failure that names the request's keys speaks the dialog's language: the fields' labels for the
// keys, the fields marked and the first focused; the marks go with the next run.
TEST(SamplingDialog, AFailureNamesAndMarksTheFieldsAtFault) {
    QTemporaryDir folder;
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    app::SamplingController* sampling = window.sampling();
    sampling->setExecutable(SDFWB_BINARY);
    RunOutcome outcome(sampling);
    widgets::SamplingDialog* dialog = openSamplingDialog(window);
    ASSERT_NE(dialog, nullptr);
    auto* count = dialog->findChild<QLineEdit*>("count");
    auto* output = dialog->findChild<QLineEdit*>("output");
    auto* message = dialog->findChild<QLabel*>("message");
    retype(dialog->findChild<QComboBox*>("pattern")->lineEdit(), "rand");
    retype(count, "0");
    retype(output, "/nonexistent-sdfwb-folder/out.npz");
    ASSERT_TRUE(outcome.run(dialog));
    EXPECT_FALSE(outcome.ok);
    EXPECT_EQ(message->text().toStdString(), "Samples (N): the sample count must be at least 1");
    EXPECT_TRUE(count->property("fault").toBool());
    EXPECT_FALSE(output->property("fault").toBool());
    EXPECT_EQ(dialog->focusWidget(), count) << "the field at fault takes the focus";
    if (QString path = screenshotPath("sampling_field_fault.png"); !path.isEmpty()) dialog->grab().save(path);

    retype(count, "1000");
    ASSERT_TRUE(outcome.run(dialog));
    EXPECT_FALSE(outcome.ok);
    EXPECT_EQ(message->text().toStdString(),
              "Output file: '/nonexistent-sdfwb-folder/out.npz': folder '/nonexistent-sdfwb-folder' does not exist");
    EXPECT_FALSE(count->property("fault").toBool()) << "the last failure's mark stays";
    EXPECT_TRUE(output->property("fault").toBool());

    retype(output, folder.filePath("out.npz"));
    ASSERT_TRUE(outcome.run(dialog));
    EXPECT_TRUE(outcome.ok) << message->text().toStdString();
    EXPECT_FALSE(output->property("fault").toBool());
    EXPECT_TRUE(QFile::exists(folder.filePath("out.npz")));
}

// The sampling dialog's Preview draws the run's first points in the viewport, coloured by
// gradient, and its point size spin box (arrow keys) grows them; a sample file with NaN rows
// shows its cloud with the bad rows counted, not drawn.
TEST(SampleCloud, PreviewDrawsTheRunAndAFileShowsItsCloudCountingNaNRows) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    window.sampling()->setExecutable(SDFWB_BINARY);
    // Gooch shading: under normals shading the front points' gradient colours match the surface.
    window.findChild<QAction*>("shading_gooch")->trigger();
    const QImage plain = frameOf(window);
    widgets::SamplingDialog* dialog = openSamplingDialog(window);
    ASSERT_NE(dialog, nullptr);
    retype(dialog->findChild<QLineEdit*>("count"), "20000");
    auto* pattern = dialog->findChild<QComboBox*>("pattern");
    retype(pattern->lineEdit(), "surface");
    QTest::mouseClick(dialog->findChild<QPushButton*>("preview"), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return window.viewport()->pointCloudSize() > 0; }, 60000))
        << dialog->findChild<QLabel*>("message")->text().toStdString();
    EXPECT_EQ(window.viewport()->pointCloudSize(), 20000u) << "surface points on a torus all hit";
    const QImage small = frameOf(window);
    EXPECT_GT(meanDifference(plain, small), 1.0) << "the points are drawn";
    auto* size = dialog->findChild<QSpinBox*>("pointSize");
    const float before = window.viewport()->pointSize();
    for (int i = 0; i < 3; ++i) QTest::keyClick(size, Qt::Key_Up);
    EXPECT_FLOAT_EQ(window.viewport()->pointSize(), before + 3.0f);
    const QImage large = frameOf(window);
    EXPECT_GT(changedPixels(plain, large), changedPixels(plain, small) * 6 / 5) << "larger points cover more";
    dialog->close();
    if (QString path = screenshotPath("sample_cloud.png"); !path.isEmpty()) windowShot(window).save(path);

    // A file of 1000 rows, 37 of them NaN (as surface/near write misses).
    QTemporaryDir folder;
    sampling::SampleSet set;
    for (int i = 0; i < 1000; ++i) {
        const float angle = float(i) * 0.01f, nan = std::nanf("");
        const bool bad = i % 27 == 0;
        set.positions.insert(set.positions.end(), {bad ? nan : 0.5f * std::cos(angle), bad ? nan : 0.0f, 0.5f * std::sin(angle)});
        set.distances.push_back(bad ? nan : 0.0f);
        set.gradients.insert(set.gradients.end(), {std::cos(angle), 0.0f, std::sin(angle)});
    }
    const QString file = folder.filePath("cloud.npz");
    ASSERT_TRUE(sampling::writeSamples(file.toStdString(), sampling::SampleFormat::Npz, set, {}));
    auto loaded = window.clouds()->show(file);
    ASSERT_TRUE(loaded);
    EXPECT_EQ(loaded->rows, 1000u);
    EXPECT_EQ(loaded->badRows, 38u);
    EXPECT_EQ(loaded->drawn, 962u);
    EXPECT_EQ(window.viewport()->pointCloudSize(), 962u);
    EXPECT_TRUE(window.statusBar()->currentMessage().contains("38 NaN")) << window.statusBar()->currentMessage().toStdString();
    // A file that is not samples leaves the cloud as it was.
    const QString broken = folder.filePath("broken.npz");
    {
        QFile f(broken);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("not a zip");
    }
    EXPECT_FALSE(window.clouds()->show(broken));
    EXPECT_TRUE(window.statusBar()->currentMessage().contains("broken.npz"));
    EXPECT_EQ(window.viewport()->pointCloudSize(), 962u);
    window.clouds()->hide();
    EXPECT_EQ(window.viewport()->pointCloudSize(), 0u);
}
