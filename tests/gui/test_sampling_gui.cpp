// Sampling from the workbench: the dialog (run, cancel) and the sample-cloud preview.
// Under a real X server (Xvfb) with real input events; helpers in GuiTestSupport.h.

#include "GuiTestSupport.h"

using namespace sdfwb;
using namespace sdfwb::guitest;

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
    ASSERT_TRUE(activate(window));
    QTest::keyClick(&window, Qt::Key_M, Qt::ControlModifier | Qt::ShiftModifier);
    ASSERT_TRUE(waitFor([&] { return window.sampling()->dialog() && window.sampling()->dialog()->isVisible(); }));
    widgets::SamplingDialog* dialog = window.sampling()->dialog();
    auto* count = dialog->findChild<QLineEdit*>("count");
    count->selectAll();
    QTest::keyClicks(count, "20000");
    auto* pattern = dialog->findChild<QComboBox*>("pattern");
    pattern->lineEdit()->selectAll();
    QTest::keyClicks(pattern->lineEdit(), "surface");
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
