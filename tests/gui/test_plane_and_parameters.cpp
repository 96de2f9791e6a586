// The cutting plane and its readouts, and the Parameters dock (redraw without recompiling, jobs, the file, the session).
// Under a real X server (Xvfb) with real input events; helpers in GuiTestSupport.h.

#include "GuiTestSupport.h"

using namespace sdfwb;
using namespace sdfwb::guitest;

namespace {

// Shows the window with the dataset's sphere (radius 0.8), turns the plane on along Z and waits for
// its first readouts; `readouts` counts them and every later one.
void openSphereWithReadouts(app::MainWindow& window, int& readouts) {
    window.resize(1000, 640);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Sphere.glsl"));
    window.plane()->setExecutable(SDFWB_BINARY);
    QObject::connect(window.plane(), &app::PlaneController::readoutUpdated, [&readouts] { ++readouts; });
    window.planePanel()->findChild<QPushButton*>("axis_Z")->click();
    ASSERT_TRUE(waitFor([&] { return readouts > 0; }, 30000))
        << window.planePanel()->findChild<QLabel*>("readouts")->text().toStdString();
    EXPECT_NEAR(window.planePanel()->readout().minimum, -0.8f, 0.03f);
}

} // namespace

TEST(CuttingPlane, PanelDrawsThePlaneAndShowsReadouts) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Sphere.glsl"));
    window.plane()->setExecutable(SDFWB_BINARY);
    QImage before = frameOf(window);
    bool readout = false;
    QObject::connect(window.plane(), &app::PlaneController::readoutUpdated, [&] { readout = true; });
    window.planePanel()->findChild<QPushButton*>("axis_Z")->click();
    EXPECT_TRUE(window.viewport()->plane().enabled);
    QImage with = frameOf(window);
    EXPECT_GT(meanDifference(before, with), 2.0) << "the plane must show";
    with.save(QDir::temp().filePath("sdfwb-gui-plane.png"));
    ASSERT_TRUE(waitFor([&] { return readout; }, 30000))
        << window.planePanel()->findChild<QLabel*>("readouts")->text().toStdString();
    const values::PlaneReadout& r = window.planePanel()->readout();
    EXPECT_NEAR(r.minimum, -0.8f, 0.03f);
    EXPECT_NEAR(r.lipschitzMax, 1.0f, 0.01f);
    EXPECT_EQ(r.nanCount, 0u);

    // Ctrl + drag moves the plane along its normal, and the panel follows.
    widgets::ViewportWidget* viewport = window.viewport();
    QPoint start(400, 300), end(400, 250);
    QMouseEvent press(QEvent::MouseButtonPress, start, viewport->mapToGlobal(start), Qt::LeftButton, Qt::LeftButton,
                      Qt::ControlModifier);
    QApplication::sendEvent(viewport, &press);
    QMouseEvent move(QEvent::MouseMove, end, viewport->mapToGlobal(end), Qt::NoButton, Qt::LeftButton, Qt::ControlModifier);
    QApplication::sendEvent(viewport, &move);
    EXPECT_NEAR(viewport->plane().offset, 0.2f, 1e-3f);
    EXPECT_NEAR(window.planePanel()->plane().offset, 0.2f, 1e-3f);
    // The document holds the plane the drag moved to, and the jobs take it from there.
    EXPECT_TRUE(window.document()->plane() == viewport->plane());
    values::AnimateRequest video;
    video.frame.width = 64;
    video.frame.height = 48;
    EXPECT_TRUE(window.exports()->videoRequest(video).frame.plane == viewport->plane());

    window.planePanel()->findChild<QPushButton*>("apply_step_factor")->click();
    EXPECT_NEAR(viewport->trace().stepFactor, r.safeStepFactor, 1e-6f);
    window.grab().save(QDir::temp().filePath("sdfwb-gui-plane-window.png"));
}

// Issue 15: the plane readouts describe the text on screen, not the file on disk.
TEST(CuttingPlane, AnUnsavedEditChangesTheReadouts) {
    app::MainWindow window;
    int readouts = 0;
    ASSERT_NO_FATAL_FAILURE(openSphereWithReadouts(window, readouts));

    const QByteArray onDisk = [] {
        QFile file(datasetFile("Geometry/Sphere.glsl"));
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    }();
    QString text = window.editor()->text();
    text.replace("return length(p) - radius;", "return length(p) - 0.4;");
    const int before = readouts;
    window.editor()->setText(text); // not saved
    ASSERT_TRUE(waitFor([&] { return readouts > before && window.planePanel()->readout().minimum > -0.5f; }, 30000))
        << "readouts still describe the file on disk: minimum " << window.planePanel()->readout().minimum;
    EXPECT_NEAR(window.planePanel()->readout().minimum, -0.4f, 0.03f);
    EXPECT_TRUE(window.editor()->isModified());
    QFile file(datasetFile("Geometry/Sphere.glsl"));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_EQ(file.readAll(), onDisk) << "the file on disk must be untouched";
}

// Parameters as live controls, on a Shadertoy-style map() with annotated uniforms: real key and
// mouse events on the Parameters dock redraw the viewport with no recompile, the document's jobs
// carry the values (and the clip-end keyframe), reset and "Save values as defaults" work.
TEST(Parameters, DockControlsRedrawWithoutRecompilingAndReachJobsAndTheFile) {
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(openAndWait(window, "../tests/params/iq_torus_map.glsl"));
    widgets::ParametersPanel* panel = window.parametersPanel();
    ASSERT_TRUE(waitFor([&] { return panel->values().size() == 4; })) << "the four declared parameters";
    window.findChild<QDockWidget*>("ParametersDock")->raise();
    auto* slider = panel->findChild<QSlider*>("slider_majorRadius");
    auto* number = panel->findChild<QDoubleSpinBox*>("number_majorRadius");
    auto* capped = panel->findChild<QCheckBox*>("param_capped");
    ASSERT_TRUE(slider && number && capped);
    ASSERT_EQ(panel->findChildren<QDoubleSpinBox*>(QRegularExpression("number_offset_\\d")).size(), 3)
        << "a number per component";
    ASSERT_TRUE(waitFor([&] { return !window.viewport()->isInteracting(); }, 5000));
    const QImage before = frameOf(window);
    const std::uint64_t programs = window.viewport()->programsBuilt();

    // Keyboard on the slider: PageDown twice (real key events through the application).
    slider->setFocus();
    for (int i = 0; i < 2; ++i) {
        QKeyEvent press(QEvent::KeyPress, Qt::Key_PageDown, Qt::NoModifier);
        QApplication::sendEvent(slider, &press);
    }
    const float dragged = panel->values()[0].value[0];
    EXPECT_LT(dragged, 0.6f);
    EXPECT_NEAR(number->value(), dragged, 1e-3) << "the number follows the slider";
    ASSERT_TRUE(waitFor([&] { return !window.viewport()->isInteracting(); }, 5000));
    const QImage smaller = frameOf(window);
    EXPECT_GT(meanDifference(before, smaller), 1.0) << "the viewport shows the new radius";
    EXPECT_EQ(window.viewport()->programsBuilt(), programs) << "a parameter change must not recompile";
    values::SdfInput input = window.document()->input();
    ASSERT_EQ(input.params.size(), 4u);
    EXPECT_EQ(input.params[0].name, "majorRadius");
    EXPECT_EQ(input.params[0].value[0], dragged) << "jobs run with the dock's values";

    // Drag on the number: 40 pixels right is 20 steps up.
    QLineEdit* edit = number->findChild<QLineEdit*>();
    ASSERT_TRUE(edit);
    const QPointF start(edit->width() / 2.0, edit->height() / 2.0);
    QMouseEvent press(QEvent::MouseButtonPress, start, edit->mapToGlobal(start), Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(edit, &press);
    const QPointF end = start + QPointF(40.0, 0.0);
    QMouseEvent move(QEvent::MouseMove, end, edit->mapToGlobal(end), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(edit, &move);
    QMouseEvent release(QEvent::MouseButtonRelease, end, edit->mapToGlobal(end), Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(edit, &release);
    EXPECT_NEAR(panel->values()[0].value[0], dragged + 20.0f * float(number->singleStep()), 1e-4);

    // The bool: a click on the checkbox cuts the torus in half.
    capped->click();
    EXPECT_EQ(panel->values()[3].value[0], 1.0f);
    ASSERT_TRUE(waitFor([&] { return !window.viewport()->isInteracting(); }, 5000));
    EXPECT_GT(meanDifference(smaller, frameOf(window)), 1.0);
    EXPECT_EQ(window.viewport()->programsBuilt(), programs);
    if (const char* folder = std::getenv("SDFWB_SCREENSHOT_DIR"))
        window.grab().save(QDir(folder).filePath("parameters_dock.png"));

    // The clip-end keyframe reaches the MP4 request.
    panel->findChild<QPushButton*>("setClipEnd")->click();
    values::AnimateRequest settings;
    settings.output = "/tmp/clip.mp4";
    values::AnimateRequest request = window.exports()->videoRequest(settings);
    ASSERT_EQ(request.paramsEnd.size(), 4u);
    EXPECT_EQ(request.paramsEnd[3].value[0], 1.0f);
    EXPECT_EQ(request.frame.sdf.params[0].value[0], panel->values()[0].value[0]);

    // Reset one row, then write the others into the file's initializers.
    panel->findChild<QPushButton*>("reset_capped")->click();
    EXPECT_EQ(panel->values()[3].value[0], 0.0f);
    const float saved = panel->values()[0].value[0];
    panel->findChild<QPushButton*>("saveParameterDefaults")->click();
    const std::string text = window.editor()->text().toStdString();
    EXPECT_NE(text.find("uniform float majorRadius = " + shaders::glslLiteral(shaders::ParameterType::Float, {saved}) +
                        "; // @range 0.2 0.8"),
              std::string::npos)
        << text;
    EXPECT_TRUE(window.editor()->isModified());
    // After the recompile the new default is the value: the row is at its default.
    ASSERT_TRUE(waitFor([&] { return window.document()->lastGoodSource().parameters[0].defaultValue[0] == saved; }));
    EXPECT_FALSE(panel->findChild<QPushButton*>("reset_majorRadius")->isEnabled());
    EXPECT_EQ(panel->values()[0].value[0], saved);
}

// The cutting-plane readouts follow a parameter (they run on the document's values), and the
// values come back with the session for the same file.
TEST(Parameters, PlaneReadoutsFollowAndTheSessionKeepsTheValues) {
    {
        app::MainWindow window;
        int readouts = 0;
        ASSERT_NO_FATAL_FAILURE(openSphereWithReadouts(window, readouts));
        auto* radius = window.parametersPanel()->findChild<QDoubleSpinBox*>("number_radius");
        ASSERT_TRUE(radius);
        const int before = readouts;
        radius->setValue(0.4);
        ASSERT_TRUE(waitFor([&] { return readouts > before && window.planePanel()->readout().minimum > -0.5f; }, 30000))
            << "the readouts still describe radius 0.8: minimum " << window.planePanel()->readout().minimum;
        EXPECT_NEAR(window.planePanel()->readout().minimum, -0.4f, 0.03f);
        EXPECT_FALSE(window.document()->isModified()) << "a parameter is not an edit of the text";
        window.close(); // saves the session
    }
    app::MainWindow again;
    again.show();
    ASSERT_TRUE(openAndWait(again, "Geometry/Sphere.glsl"));
    ASSERT_TRUE(waitFor([&] { return !again.parametersPanel()->values().empty(); }));
    EXPECT_FLOAT_EQ(again.parametersPanel()->values()[0].value[0], 0.4f);
    EXPECT_FLOAT_EQ(again.document()->input().params[0].value[0], 0.4f);
    again.parametersPanel()->resetAll();
    again.close();
}

// A Fragmentarium fragment opened unmodified: its slider annotations are the dock's controls, with
// the Default preset's values; the status bar says how the file was read; the values drive the
// viewport, and "Save values as defaults" writes them where Fragmentarium reads them (the preset's
// line for a value the preset sets), in its syntax, so the file still opens there.
TEST(Parameters, FragmentariumSlidersAndPresetsAreTheDocksControls) {
    app::MainWindow window;
    window.resize(1000, 640);
    window.show();
    ASSERT_TRUE(openAndWait(window, "../tests/foreign/80_fr_mandelbox.glsl"));
    widgets::ParametersPanel* panel = window.parametersPanel();
    ASSERT_TRUE(waitFor([&] { return panel->values().size() == 6; })) << "six annotated uniforms";
    EXPECT_NE(window.statusBar()->currentMessage().toStdString().find("Fragmentarium"), std::string::npos)
        << window.statusBar()->currentMessage().toStdString();
    window.findChild<QDockWidget*>("ParametersDock")->raise();
    auto* scale = panel->findChild<QSlider*>("slider_Scale");
    auto* scaleNumber = panel->findChild<QDoubleSpinBox*>("number_Scale");
    ASSERT_TRUE(scale && scaleNumber);
    EXPECT_EQ(scaleNumber->value(), -2.5) << "the Default preset's Scale, not the slider's 3.0";
    for (const shaders::Parameter& p : window.document()->lastGoodSource().parameters)
        if (p.name == "Scale") {
            EXPECT_EQ(p.minimum, -3.0f) << "the slider's range";
            EXPECT_EQ(p.maximum, 5.0f);
        }
    ASSERT_TRUE(waitFor([&] { return !window.viewport()->isInteracting(); }, 10000));
    const QImage before = frameOf(window);
    const std::uint64_t programs = window.viewport()->programsBuilt();
    scale->setFocus();
    for (int i = 0; i < 3; ++i) {
        QKeyEvent press(QEvent::KeyPress, Qt::Key_PageUp, Qt::NoModifier);
        QApplication::sendEvent(scale, &press);
    }
    const float moved = float(scaleNumber->value());
    EXPECT_GT(moved, -2.5f);
    ASSERT_TRUE(waitFor([&] { return !window.viewport()->isInteracting(); }, 10000));
    EXPECT_GT(meanDifference(before, frameOf(window)), 0.5) << "the viewport shows the new scale";
    EXPECT_EQ(window.viewport()->programsBuilt(), programs) << "a parameter change must not recompile";
    if (const char* folder = std::getenv("SDFWB_SCREENSHOT_DIR"))
        window.grab().save(QDir(folder).filePath("fragmentarium_parameters.png"));

    panel->findChild<QPushButton*>("saveParameterDefaults")->click();
    const std::string text = window.editor()->text().toStdString();
    const std::string line = "\nScale = " + shaders::formatParameterValue({"Scale", {moved}}).substr(6) + "\n";
    EXPECT_NE(text.find(line), std::string::npos) << "the preset's line takes the value: " << line;
    EXPECT_NE(text.find("uniform float Scale;  slider[-3.0,3.0,5.0]"), std::string::npos) << "the slider keeps its own default";
    ASSERT_TRUE(waitFor([&] {
        const auto& parameters = window.document()->lastGoodSource().parameters;
        return std::any_of(parameters.begin(), parameters.end(),
                           [&](const shaders::Parameter& p) { return p.name == "Scale" && p.defaultValue[0] == moved; });
    }));
    EXPECT_FALSE(panel->findChild<QPushButton*>("reset_Scale")->isEnabled()) << "the saved value is the default now";
}
