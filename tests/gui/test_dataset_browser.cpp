// The dataset browser (listing, opening, thumbnails, measured types, templates, read-only shipped files) and the log dock.
// Under a real X server (Xvfb) with real input events; helpers in GuiTestSupport.h.

#include "GuiTestSupport.h"

using namespace sdfwb;
using namespace sdfwb::guitest;

TEST(DatasetBrowser, ListsTheDatasetAndOpensAnEntry) {
    app::MainWindow window;
    window.show();
    // Every dataset file with a metadata block (dataset/<Category>/<Name>.glsl; dataset/lib holds
    // includes), counted here from the folder.
    int files = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(SDFWB_SOURCE_DIR "/dataset"))
        if (entry.path().extension() == ".glsl" && entry.path().parent_path().filename() != "lib") ++files;
    EXPECT_GE(files, 63);
    EXPECT_EQ(window.datasetBrowser()->count(), files);
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    ASSERT_TRUE(window.datasetBrowser()->activate("menger sponge"));
    EXPECT_TRUE(window.document()->path().endsWith("Fractal/MengerSponge.glsl"));
    ASSERT_TRUE(waitFor([&] { return applied; }));
    EXPECT_FALSE(window.datasetBrowser()->activate("no such shape"));
}

// Thumbnails are rendered once per file content (an edit renders a new one, an unchanged file
// none), the browser shows the report's measured type, "New SDF from template" opens the
// template, and a shipped file typed into is saved only under a new name: the shipped file keeps
// its bytes, and saving onto it is refused.
TEST(DatasetBrowser, ThumbnailsMeasuredTypesTemplateAndReadOnlyShippedFiles) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    QTemporaryDir cache, mine;
    window.thumbnails()->setExecutable(SDFWB_BINARY);
    window.thumbnails()->setCacheFolder(cache.path());
    const QStringList three = {datasetFile("Geometry/Sphere.glsl"), datasetFile("Geometry/Torus.glsl"),
                               datasetFile("Geometry/Box.glsl")};
    window.thumbnails()->request(three);
    ASSERT_TRUE(waitFor([&] { return window.datasetBrowser()->thumbnailCount() >= 3; }, 60000));
    EXPECT_EQ(window.thumbnails()->rendered(), 3);
    const QImage torus(window.datasetBrowser()->thumbnailOf(three[1]));
    ASSERT_EQ(torus.size(), QSize(96, 96));
    EXPECT_GT(foreground(torus, kBackground), 96 * 96 / 10) << "the thumbnail shows the shape";
    window.thumbnails()->request(three);
    EXPECT_EQ(window.thumbnails()->rendered(), 3) << "cached: nothing rendered again";
    // An SDF of the user's: edited, it gets a new thumbnail.
    const QString own = mine.filePath("own.glsl");
    auto write = [](const QString& path, const QByteArray& text) {
        QFile f(path);
        return f.open(QIODevice::WriteOnly) && f.write(text) == text.size();
    };
    ASSERT_TRUE(write(own, "float sdf(vec3 p) { return length(p) - 0.5; }\n"));
    window.thumbnails()->request({own});
    ASSERT_TRUE(waitFor([&] { return window.thumbnails()->rendered() == 4; }, 60000));
    const QString first = window.thumbnails()->cachedThumbnail(own);
    ASSERT_TRUE(write(own, "float sdf(vec3 p) { return length(p) - 0.9; }\n"));
    EXPECT_TRUE(window.thumbnails()->cachedThumbnail(own).isEmpty()) << "the old thumbnail is not this content's";
    window.thumbnails()->request({own});
    ASSERT_TRUE(waitFor([&] { return window.thumbnails()->rendered() == 5; }, 60000));
    EXPECT_NE(window.thumbnails()->cachedThumbnail(own), first);
    EXPECT_GT(foreground(QImage(window.thumbnails()->cachedThumbnail(own)), kBackground), foreground(QImage(first), kBackground))
        << "the larger sphere covers more";

    // Measured types and render times come from the dataset report (the layout
    // scripts/dataset_report.py writes): two entries measured, the rest shown as declared.
    const QString reportPath = mine.filePath("report.json");
    ASSERT_TRUE(write(reportPath, R"({"machine": "test machine", "date": "2026-11-24", "sdfs": [
        {"name": "Torus", "measured_type": "exact", "render_ms": 12.5},
        {"name": "Snail", "measured_type": "truncated", "render_ms": 242.6}]})"));
    window.loadDatasetItems(reportPath);
    int measuredRows = 0, declaredRows = 0;
    QTreeWidget* tree = window.datasetBrowser()->tree();
    for (int c = 0; c < tree->topLevelItemCount(); ++c)
        for (int i = 0; i < tree->topLevelItem(c)->childCount(); ++i) {
            QTreeWidgetItem* item = tree->topLevelItem(c)->child(i);
            if (item->text(0) == "Torus") {
                EXPECT_EQ(item->text(1), "exact");
                EXPECT_EQ(item->text(2), "12.5");
                ++measuredRows;
            } else if (item->text(0) == "Snail") {
                EXPECT_EQ(item->text(1), "truncated (declared conservative)") << "a disagreement is shown";
                EXPECT_EQ(item->text(2), "242.6");
                ++measuredRows;
            } else {
                EXPECT_TRUE(item->text(1).endsWith("(declared)")) << item->text(0).toStdString();
                EXPECT_TRUE(item->text(2).isEmpty());
                ++declaredRows;
            }
        }
    EXPECT_EQ(measuredRows, 2);
    EXPECT_EQ(declaredRows, window.datasetBrowser()->count() - 2);
    EXPECT_TRUE(window.datasetBrowser()->findChild<QLabel*>("reportNote")->text().contains("test machine"));

    // New SDF from template, by its button.
    window.findChild<QDockWidget*>("DatasetDock")->raise();
    QTest::mouseClick(window.datasetBrowser()->findChild<QPushButton*>("newFromTemplate"), Qt::LeftButton);
    EXPECT_TRUE(window.editor()->text().contains("name: New Shape"));
    EXPECT_TRUE(window.document()->path().isEmpty());
    if (QString path = screenshotPath("dataset_browser.png"); !path.isEmpty()) {
        window.thumbnails()->request(window.datasetBrowser()->paths());
        waitFor([&] { return window.datasetBrowser()->thumbnailCount() == window.datasetBrowser()->count(); }, 240000);
        windowShot(window).save(path);
    }
    window.files()->setPrompt([](const QString&) { return app::FileController::Answer::No; });

    // A shipped file: typed into, Ctrl+S asks for a new name in the user's folder.
    const QString shipped = datasetFile("Geometry/Torus.glsl");
    QFile original(shipped);
    ASSERT_TRUE(original.open(QIODevice::ReadOnly));
    const QByteArray bytes = original.readAll();
    original.close();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    EXPECT_TRUE(window.windowTitle().contains("read-only"));
    window.editor()->setFocus();
    window.editor()->setCursorPosition(0, 0);
    QTest::keyClicks(window.editor(), "// ---"); // no word characters: no completion popup
    QTest::keyClick(window.editor(), Qt::Key_Return);
    ASSERT_TRUE(window.editor()->isModified());
    QString suggested;
    const QString target = mine.filePath("MyTorus.glsl");
    window.setSavePathChooser([&](const QString& path) {
        suggested = path;
        return target;
    });
    ASSERT_TRUE(activate(window));
    QTest::keyClick(window.editor(), Qt::Key_S, Qt::ControlModifier);
    ASSERT_TRUE(waitFor([&] { return QFile::exists(target); }, 5000)) << "Save asked for a new name";
    EXPECT_TRUE(suggested.endsWith("sdfwb/Torus.glsl")) << suggested.toStdString();
    EXPECT_FALSE(app::FileController::isShipped(suggested));
    QFile after(shipped);
    ASSERT_TRUE(after.open(QIODevice::ReadOnly));
    EXPECT_EQ(after.readAll(), bytes) << "the shipped file is untouched";
    QFile saved(target);
    ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
    EXPECT_TRUE(saved.readAll().startsWith("// ---\n"));
    EXPECT_EQ(window.document()->path(), QFileInfo(target).absoluteFilePath());
    EXPECT_FALSE(window.files()->saveAs(shipped)) << "never onto a shipped file";
    QFile again(shipped);
    ASSERT_TRUE(again.open(QIODevice::ReadOnly));
    EXPECT_EQ(again.readAll(), bytes);
}

// The Log dock shows the log file's lines: the GL context, compile times, the first full frame's
// time, and an error (a file that cannot be opened) in both the dock and the file.
TEST(LogDock, ShowsTheLogFileLines) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Box.glsl"));
    ASSERT_TRUE(waitFor([&] { return window.logPanel()->text().contains("first full frame"); }));
    const QString text = window.logPanel()->text();
    EXPECT_TRUE(text.contains("viewport context:")) << "GL vendor, renderer and version";
    EXPECT_TRUE(text.contains("compiled ")) << "shader compile times";
    EXPECT_FALSE(window.openFile("/nonexistent/broken.glsl"));
    ASSERT_TRUE(waitFor([&] { return window.logPanel()->text().contains("broken.glsl"); }));
    QFile file(window.logFilePath());
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QString logged = QString::fromUtf8(file.readAll());
    EXPECT_TRUE(logged.contains("[error] app:") && logged.contains("broken.glsl"));
    EXPECT_TRUE(logged.contains("first full frame"));
    // The filter: errors only.
    auto* level = window.logPanel()->findChild<QComboBox*>("logLevel");
    level->setFocus();
    QTest::keyClick(level, Qt::Key_Down);
    QTest::keyClick(level, Qt::Key_Down);
    EXPECT_EQ(level->currentIndex(), 2);
    EXPECT_FALSE(window.logPanel()->text().contains("compiled "));
    EXPECT_TRUE(window.logPanel()->text().contains("broken.glsl"));
    window.findChild<QDockWidget*>("LogDock")->raise();
    if (QString path = screenshotPath("log_dock.png"); !path.isEmpty()) windowShot(window).save(path);
}
