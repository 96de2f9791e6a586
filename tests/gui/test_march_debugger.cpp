// The march debugger: a clicked pixel's march, and the field under the cursor on the plane.
// Under a real X server (Xvfb) with real input events; helpers in GuiTestSupport.h.

#include "GuiTestSupport.h"

using namespace sdfwb;
using namespace sdfwb::guitest;

// ---- #19: the march debugger, sample clouds, the dataset browser, exports, the log ----

// Tools > Probe pixel from its toolbar button, then clicks in the viewport: the dock shows the
// centre pixel's march ending in a hit on the sphere (table and plot), a corner pixel's miss, and
// the camera does not move. With the cutting plane on, hovering shows f and |grad f| under the
// cursor in the status bar, equal to the sphere's closed form at the position it names.
TEST(MarchDebugger, ClickingAPixelShowsItsMarchAndHoveringThePlaneShowsTheField) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Sphere.glsl"));
    window.probe()->setExecutable(SDFWB_BINARY);
    auto* bar = window.findChild<QToolBar*>("SdfToolBar");
    ASSERT_NE(bar, nullptr);
    QWidget* button = bar->widgetForAction(window.probeAction());
    ASSERT_NE(button, nullptr);
    QTest::mouseClick(button, Qt::LeftButton);
    ASSERT_TRUE(window.viewport()->probeTool());

    widgets::ViewportWidget* viewport = window.viewport();
    const values::Camera camera = viewport->camera();
    int probes = 0;
    QObject::connect(window.probe(), &app::ProbeController::probed, [&] { ++probes; });
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, centreOf(viewport));
    ASSERT_TRUE(waitFor([&] { return probes == 1; }, 30000)) << window.probePanel()->summary().toStdString();
    EXPECT_EQ(viewport->camera(), camera) << "a probe click does not orbit";
    {
        // The cross-hair: a yellow ring of radius 6 around the probed pixel.
        const QImage frame = frameOf(window);
        const QPoint centre = centreOf(viewport);
        int yellow = 0;
        for (int dy = -13; dy <= 13; ++dy)
            for (int dx = -13; dx <= 13; ++dx) {
                const QColor c = frame.pixelColor(centre + QPoint(dx, dy));
                yellow += c.red() > 200 && c.green() > 180 && c.blue() < 90;
            }
        EXPECT_GT(yellow, 20) << "the probed pixel is marked";
    }
    const values::ProbeReport& hit = window.probePanel()->report();
    EXPECT_EQ(hit.outcome, values::MarchEvent::Hit) << hit.reason;
    EXPECT_EQ(hit.x, viewport->width() / 2);
    ASSERT_FALSE(hit.events.empty());
    EXPECT_EQ(hit.events.front().event, values::MarchEvent::Step);
    EXPECT_TRUE(
        std::any_of(hit.events.begin(), hit.events.end(), [](const auto& r) { return r.event == values::MarchEvent::Hit; }));
    EXPECT_EQ(hit.oversteps, 0u) << "an exact field never oversteps";
    ASSERT_TRUE(hit.hitT.has_value());
    // The hit lies on the sphere of radius 0.8: the distance from the camera along the ray.
    const auto& last =
        *std::find_if(hit.events.begin(), hit.events.end(), [](const auto& r) { return r.event == values::MarchEvent::Hit; });
    EXPECT_NEAR(glm::length(last.position), 0.8f, 2e-3f);
    EXPECT_EQ(window.probePanel()->table()->rowCount(), int(hit.events.size()));
    EXPECT_GE(window.probePanel()->plot()->markerCount(), hit.steps);
    // Selecting a row (a click on its cell) rings it in the plot.
    const QRect cell = window.probePanel()->table()->visualItemRect(window.probePanel()->table()->item(1, 1));
    QTest::mouseClick(window.probePanel()->table()->viewport(), Qt::LeftButton, Qt::NoModifier, cell.center());
    EXPECT_EQ(window.probePanel()->table()->currentRow(), 1);
    if (QString path = screenshotPath("march_debugger.png"); !path.isEmpty()) windowShot(window).save(path);

    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, QPoint(2, 2));
    ASSERT_TRUE(waitFor([&] { return probes == 2; }, 30000));
    const values::ProbeReport& miss = window.probePanel()->report();
    EXPECT_TRUE(miss.outcome == values::MarchEvent::MissedBox || miss.outcome == values::MarchEvent::LeftBox)
        << values::marchEventName(miss.outcome);
    EXPECT_TRUE(window.probePanel()->summary().contains(values::marchEventName(miss.outcome)));

    // The probe tool off: a drag orbits again.
    QTest::mouseClick(button, Qt::LeftButton);
    EXPECT_FALSE(viewport->probeTool());

    // The plane readout under the cursor.
    window.planePanel()->findChild<QPushButton*>("axis_Z")->click();
    ASSERT_TRUE(viewport->plane().enabled);
    frameOf(window);
    hover(viewport, centreOf(viewport) + QPoint(40, -25));
    const QString text = window.planeReadout()->text();
    ASSERT_TRUE(text.contains("f = ")) << text.toStdString();
    widgets::ViewportWidget::PlaneValue value;
    ASSERT_TRUE(viewport->planeValueAt(centreOf(viewport) + QPoint(40, -25), value));
    EXPECT_NEAR(value.position.z, 0.0f, 1e-4f) << "on the plane z = 0";
    EXPECT_NEAR(value.value, glm::length(value.position) - 0.8f, 1e-4f);
    EXPECT_NEAR(value.gradientLength, 1.0f, 1e-2f);
    EXPECT_TRUE(text.contains(QString::number(double(value.value), 'g', 5))) << text.toStdString();
    hover(viewport, QPoint(2, 2)); // off the plane (outside the box)
    EXPECT_TRUE(window.planeReadout()->text().isEmpty());
}
