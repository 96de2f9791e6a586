// Files and the editor: foreign code and its entry point, save, autosave and recovery, meshes opened as SDFs, reloads, the
// Problems list, find/replace, F5, loop warnings, and pasted Shadertoy shaders. Under a real X server (Xvfb) with real input
// events; helpers in GuiTestSupport.h.

#include "GuiTestSupport.h"

#include <QAbstractItemModel>
#include <QCompleter>

using namespace sdfwb;
using namespace sdfwb::guitest;

// Issue 14: foreign code in the workbench: a Shadertoy map() opens as it is, the entry field picks
// another function, and "show where" rings the audit's example points and moves the plane there.
TEST(ForeignCode, EntryFieldAndShowWhere) {
    QDir folder(QDir::temp().filePath("sdfwb-gui-foreign"));
    folder.mkpath(".");
    const QString file = folder.filePath("toy.glsl");
    {
        QFile out(file);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
        out.write("// Shadertoy style: map() with a material id; the ball jumps by 0.2 across x = 0.2\n"
                  "#define PI 3.14159265\n"
                  "mat2 rot(float a) { return mat2(cos(a), -sin(a), sin(a), cos(a)); }\n"
                  "vec2 map(vec3 p) { return vec2(length(p) - 0.5 + (p.x > 0.2 ? 0.2 : 0.0), 1.0); }\n"
                  "// the paper's snake in small: steeper than a distance, capped at 0.25\n"
                  "float snake(vec3 p) { p.xz *= rot(PI / 8.0); return min(0.25, 1.9 * (length(vec3(p.x, p.y * 1.6, p.z)) - "
                  "0.45)); }\n");
    }
    app::MainWindow window;
    window.resize(1400, 800);
    window.show();
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    ASSERT_TRUE(window.openFile(file));
    ASSERT_TRUE(waitFor([&] { return applied; })) << "map() was not taken as the entry point";
    EXPECT_EQ(window.document()->signature().entry, "map");
    auto* entry = window.findChild<QLineEdit*>("entry");
    ASSERT_TRUE(entry);
    EXPECT_TRUE(entry->placeholderText().contains("map")) << entry->placeholderText().toStdString();
    window.plane()->setExecutable(SDFWB_BINARY);
    int readouts = 0;
    QObject::connect(window.plane(), &app::PlaneController::readoutUpdated, [&] { ++readouts; });
    auto findingsNamed = [&](const char* name) {
        for (const auto& f : window.planePanel()->readout().flags)
            if (std::string(values::findingName(f.finding)) == name) return true;
        return false;
    };
    window.planePanel()->findChild<QPushButton*>("axis_Z")->click();
    ASSERT_TRUE(waitFor([&] { return readouts > 0 && findingsNamed("discontinuous"); }, 30000))
        << window.planePanel()->findChild<QLabel*>("readouts")->text().toStdString();
    auto* findings = window.planePanel()->findChild<QComboBox*>("findings");
    auto* showWhere = window.planePanel()->findChild<QPushButton*>("show_where");
    ASSERT_TRUE(findings && showWhere && showWhere->isEnabled());
    findings->setCurrentIndex(findings->findText("discontinuous"));
    auto showAndCheck = [&](const char* name, const char* screenshot) {
        std::vector<glm::vec3> examples;
        for (const auto& f : window.planePanel()->readout().flags)
            if (std::string(values::findingName(f.finding)) == name) examples = f.examples;
        ASSERT_FALSE(examples.empty());
        const QImage before = window.viewport()->grabFramebuffer();
        const int seen = readouts;
        showWhere->click();
        EXPECT_EQ(window.viewport()->shading().markers, examples);
        const values::CuttingPlane plane = window.viewport()->plane();
        EXPECT_NEAR(glm::dot(glm::normalize(plane.normal), examples.front()), plane.offset, 1e-4f)
            << "the plane goes through the first point";
        EXPECT_NEAR(window.planePanel()->plane().offset, plane.offset, 1e-3f);
        EXPECT_GT(meanDifference(before, window.viewport()->grabFramebuffer()), 0.05) << "the rings show";
        ASSERT_TRUE(waitFor([&] { return readouts > seen; }, 30000)) << "readouts for the moved plane";
        if (auto* dock = qobject_cast<QDockWidget*>(window.planePanel()->parentWidget())) dock->raise();
        if (const char* folder = std::getenv("SDFWB_SCREENSHOT_DIR")) window.grab().save(QDir(folder).filePath(screenshot));
    };
    showAndCheck("discontinuous", "foreign_discontinuity.png");
    for (const auto& e : window.viewport()->shading().markers) EXPECT_NEAR(e.x, 0.2f, 0.03f) << "on the jump";

    // The entry field: typed, Return; the viewport and the readouts follow the new function.
    applied = false;
    entry->setFocus();
    for (QChar c : QString("snake")) {
        QKeyEvent press(QEvent::KeyPress, 0, Qt::NoModifier, QString(c));
        QApplication::sendEvent(entry, &press);
    }
    QKeyEvent enter(QEvent::KeyPress, Qt::Key_Return, Qt::NoModifier);
    QApplication::sendEvent(entry, &enter);
    EXPECT_EQ(entry->text(), "snake");
    ASSERT_TRUE(waitFor([&] { return applied; }));
    EXPECT_EQ(window.document()->signature().entry, "snake");
    values::CuttingPlane throughOrigin = window.viewport()->plane();
    throughOrigin.offset = 0.0f;
    window.planePanel()->setPlane(throughOrigin);
    window.planePanel()->findChild<QPushButton*>("axis_Z")->click(); // emits the panel's plane: z = 0
    ASSERT_TRUE(waitFor([&] { return findingsNamed("truncated") && findingsNamed("non-conservative"); }, 30000))
        << window.planePanel()->findChild<QLabel*>("readouts")->text().toStdString();
    findings->setCurrentIndex(findings->findText("truncated"));
    showAndCheck("truncated", "foreign_truncated.png");

    // Another file gets its own entry point: the field clears and sdf() is found.
    applied = false;
    ASSERT_TRUE(window.openFile(datasetFile("Geometry/Sphere.glsl")));
    ASSERT_TRUE(waitFor([&] { return applied; }));
    EXPECT_TRUE(entry->text().isEmpty());
    EXPECT_EQ(window.document()->signature().entry, "sdf");
}

// Issue 47, point 1: a pasted whole shader's field is the function its own march steps by: the
// entry box says which and why. Two functions of the point alone that the primary ray marches
// equally often are its scene together: their union. When one of them cannot join a union (a
// material written through an out parameter), the file does not open, the error names both, the
// entry box offers them, and picking one (typed, Return) opens it.
TEST(ForeignCode, TheEntryBoxSaysWhatTheMarchChoseAndOffersATie) {
    const std::string caster =
        "void mainImage(out vec4 c, in vec2 f) {\n"
        "    vec3 ro = vec3(0.0, 0.0, 3.0), rd = normalize(vec3((f - 0.5 * iResolution.xy) / iResolution.y, -2.0));\n";
    const QString single =
        writeScratch("marched.glsl", QByteArray::fromStdString("float Map(vec3 p) { return length(p) - 0.5; }\n" + caster +
                                                               "    float t = 0.0;\n"
                                                               "    for (int i = 0; i < 64; i++) t += Map(ro + rd * t);\n"
                                                               "    c = vec4(vec3(t * 0.1), 1.0);\n}\n"));
    const std::string marches = "    float t = 0.0, s = 0.0, id = 0.0;\n"
                                "    for (int i = 0; i < 64; i++) t += Solid(ro + rd * t);\n"
                                "    for (int i = 0; i < 64; i++) s += Water(ro + rd * s);\n"
                                "    c = vec4(vec3(min(t, s) * 0.1), 1.0);\n}\n";
    const QString united =
        writeScratch("united.glsl", QByteArray::fromStdString("float Solid(vec3 p) { return length(p) - 0.5; }\n"
                                                              "float Water(vec3 p) { return p.y + 0.4; }\n" +
                                                              caster + marches));
    std::string tiedMarches = marches;
    tiedMarches.replace(tiedMarches.find("Water(ro + rd * s)"), 18, "Water(ro + rd * s, id)");
    const QString tied = writeScratch(
        "tied.glsl", QByteArray::fromStdString("float Solid(vec3 p) { return length(p) - 0.5; }\n"
                                               "float Water(vec3 p, out float id) { id = 1.0; return p.y + 0.4; }\n" +
                                               caster + tiedMarches));
    app::MainWindow window;
    window.resize(1000, 640);
    window.show();
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    ASSERT_TRUE(window.openFile(single));
    ASSERT_TRUE(waitFor([&] { return applied; })) << "Map() was not found from the march";
    EXPECT_EQ(window.document()->signature().entry, "Map");
    auto* entry = window.findChild<QLineEdit*>("entry");
    ASSERT_TRUE(entry);
    EXPECT_TRUE(entry->placeholderText().contains("Map (called by the march at line 5)"))
        << entry->placeholderText().toStdString();
    EXPECT_EQ(entry->completer(), nullptr);
    applied = false;
    ASSERT_TRUE(window.openFile(united));
    ASSERT_TRUE(waitFor([&] { return applied; })) << "the union did not open";
    EXPECT_TRUE(entry->placeholderText().contains("the union of Solid (called by the march at line 6)"))
        << entry->placeholderText().toStdString();

    bool failed = false;
    QObject::connect(window.document(), &app::SdfDocument::diagnosticsChanged,
                     [&](const std::vector<shaders::Diagnostic>& d) { failed = failed || shaders::hasErrors(d); });
    applied = false;
    ASSERT_TRUE(window.openFile(tied));
    ASSERT_TRUE(waitFor([&] { return failed; })) << "the tie was not reported";
    ASSERT_TRUE(entry->completer());
    QStringList offered;
    for (int row = 0; row < entry->completer()->model()->rowCount(); ++row)
        offered << entry->completer()->model()->index(row, 0).data().toString();
    EXPECT_EQ(offered, (QStringList{"Solid", "Water"}));
    EXPECT_TRUE(entry->placeholderText().contains("Solid, Water")) << entry->placeholderText().toStdString();
    EXPECT_FALSE(applied);

    entry->setFocus();
    for (QChar c : QString("Water")) {
        QKeyEvent press(QEvent::KeyPress, 0, Qt::NoModifier, QString(c));
        QApplication::sendEvent(entry, &press);
    }
    QKeyEvent enter(QEvent::KeyPress, Qt::Key_Return, Qt::NoModifier);
    QApplication::sendEvent(entry, &enter);
    ASSERT_TRUE(waitFor([&] { return applied; })) << "the chosen function did not open";
    EXPECT_EQ(window.document()->signature().entry, "Water");
}

TEST(Files, SaveAutosaveRecoverAndPromptOnClose) {
    QString path = writeScratch("saved.glsl", "float sdf(vec3 p) { return length(p) - 0.5; }\n");
    for (const QString& stale : app::FileController::recoveryFiles()) QFile::remove(stale);
    {
        app::MainWindow window;
        window.show();
        ASSERT_TRUE(window.openFile(path));
        EXPECT_EQ(window.files()->recentFiles().value(0), QFileInfo(path).absoluteFilePath());
        window.editor()->setText("float sdf(vec3 p) { return length(p) - 0.6; }\n");
        EXPECT_TRUE(window.editor()->isModified());
        EXPECT_TRUE(window.windowTitle().contains("*"));
        // Autosave: the recovery file holds the edit; the real file does not change.
        window.files()->autosaveNow();
        ASSERT_TRUE(QFile::exists(window.files()->recoveryPath()));
        EXPECT_TRUE(readAll(window.files()->recoveryPath()).contains("0.6"));
        EXPECT_TRUE(readAll(path).contains("0.5"));
        // Closing asks; Cancel keeps the window and the edit.
        int asked = 0;
        window.files()->setPrompt([&](const QString&) {
            ++asked;
            return app::FileController::Answer::Cancel;
        });
        EXPECT_FALSE(window.close());
        EXPECT_EQ(asked, 1);
        EXPECT_TRUE(window.editor()->isModified());
        // The window goes away without a clean close, as in a crash: the recovery file stays.
    }
    QStringList recovery = app::FileController::recoveryFiles();
    ASSERT_FALSE(recovery.isEmpty());
    {
        app::MainWindow window;
        ASSERT_TRUE(window.files()->restoreRecovery(recovery.first()));
        EXPECT_TRUE(window.editor()->text().contains("0.6"));
        EXPECT_EQ(window.document()->path(), QFileInfo(path).absoluteFilePath());
        EXPECT_TRUE(window.editor()->isModified());
        // Save writes atomically and clears the recovery file; then closing asks nothing.
        ASSERT_TRUE(window.files()->save());
        EXPECT_TRUE(readAll(path).contains("0.6"));
        EXPECT_FALSE(QFile::exists(window.files()->recoveryPath()));
        int asked = 0;
        window.files()->setPrompt([&](const QString&) {
            ++asked;
            return app::FileController::Answer::Cancel;
        });
        EXPECT_TRUE(window.close());
        EXPECT_EQ(asked, 0);
    }
}

// Not a test of its own: the child process of the test below (hence DISABLED_, which the parent
// turns on). It edits, lets the real autosave timer fire, then dies by SIGKILL, as a crash would.
TEST(CrashChild, DISABLED_EditThenDie) {
    QString path = writeScratch("crashed.glsl", "float sdf(vec3 p) { return length(p) - 0.5; }\n");
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(window.openFile(path));
    window.files()->setAutosaveInterval(200);
    window.editor()->setText("float sdf(vec3 p) { return length(p) - 0.25; } // typed before the crash\n");
    QString recovery = window.files()->recoveryPath();
    ASSERT_TRUE(waitFor([&] { return QFile::exists(recovery); }, 5000));
    ::raise(SIGKILL);
}

TEST(Files, RecoversAfterTheProcessIsKilled) {
    for (const QString& stale : app::FileController::recoveryFiles()) QFile::remove(stale);
    QProcess child;
    child.start(QCoreApplication::applicationFilePath(),
                {"--gtest_also_run_disabled_tests", "--gtest_filter=CrashChild.DISABLED_EditThenDie"});
    ASSERT_TRUE(child.waitForFinished(60000));
    EXPECT_EQ(child.exitStatus(), QProcess::CrashExit) << "the child must have been killed";
    QStringList recovery = app::FileController::recoveryFiles();
    ASSERT_EQ(recovery.size(), 1);
    app::MainWindow window;
    ASSERT_TRUE(window.files()->restoreRecovery(recovery.first()));
    EXPECT_TRUE(window.editor()->text().contains("typed before the crash"));
    EXPECT_TRUE(window.document()->path().endsWith("crashed.glsl"));
    window.files()->setPrompt([](const QString&) { return app::FileController::Answer::No; });
    EXPECT_TRUE(window.close());
    EXPECT_TRUE(app::FileController::recoveryFiles().isEmpty()) << "a clean close (discarding) removes the recovery file";
}

// File > Open mesh: a triangle mesh is the document's field. A 6-unit cube far outside the box
// opens scaled into it (unit-cube); the viewport traces it; the plane's readouts, computed by a
// child job from the document's input, see the same scaled field; text over the mesh (an offset
// shell) reaches the viewport and the jobs; and nothing ever writes over the mesh.
TEST(Files, OpenMeshTracesItAndItsJobsSeeTheSameField) {
    QByteArray cube =
        "v 2 2 2\nv 8 2 2\nv 8 8 2\nv 2 8 2\nv 2 2 8\nv 8 2 8\nv 8 8 8\nv 2 8 8\n"
        "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
    const QString path = writeScratch("far_cube.obj", cube);
    app::MainWindow window;
    window.resize(900, 560); // a small viewport keeps the test quick on llvmpipe
    window.show();
    window.plane()->setExecutable(SDFWB_BINARY);
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    int readouts = 0;
    QObject::connect(window.plane(), &app::PlaneController::readoutUpdated, [&] { ++readouts; });
    ASSERT_TRUE(window.openFile(path));
    ASSERT_TRUE(waitFor([&] { return applied; })) << "the mesh never reached the viewport";
    EXPECT_TRUE(window.document()->isMesh());
    EXPECT_EQ(window.document()->meshSign(), "winding");
    EXPECT_EQ(window.document()->meshNormalize(), "unit-cube");
    EXPECT_TRUE(window.windowTitle().contains("mesh: sign winding, normalize unit-cube")) << window.windowTitle().toStdString();
    EXPECT_TRUE(window.editor()->text().contains("sdfwb_meshSdf(p)"));
    const values::SdfInput input = window.document()->input();
    EXPECT_EQ(input.sdf, QFileInfo(path).absoluteFilePath().toStdString());
    EXPECT_EQ(input.normalize, "unit-cube");
    // At whatever resolution the viewport settles on for this field on this machine.
    ASSERT_TRUE(waitFor([&] { return window.viewport()->lastFrameMilliseconds() > 0.0 && !window.viewport()->isInteracting(); }));
    const QImage frame = frameOf(window);
    const double share = double(foreground(frame, kBackground)) / double(frame.width() * frame.height());
    // The cube fills the traced box, so from the default camera it covers most of the frame (91.5 %
    // of a 443x476 viewport): background shows only around its silhouette.
    EXPECT_GT(share, 0.05) << "the scaled cube fills part of the viewport";
    EXPECT_LT(share, 0.97) << "background shows around the cube";
    frame.save(QDir::temp().filePath("sdfwb-gui-mesh.png"));

    // The plane through the middle: the scaled cube is [-1, 1]^3, so the field's minimum there is
    // -1 at the centre (unscaled, the plane would lie outside the cube, all positive).
    window.planePanel()->findChild<QPushButton*>("axis_Z")->click();
    ASSERT_TRUE(waitFor([&] { return readouts > 0; }, 60000))
        << window.planePanel()->findChild<QLabel*>("readouts")->text().toStdString();
    EXPECT_NEAR(window.planePanel()->readout().minimum, -1.0f, 0.03f);
    EXPECT_EQ(window.planePanel()->readout().nanCount, 0u);

    // Text over the mesh: an offset shell 0.25 thicker, in the viewport and in the next readout.
    applied = false;
    const int before = readouts;
    window.editor()->setText("float sdf(vec3 p) { return sdfwb_meshSdf(p) - 0.25; }\n");
    window.document()->checkNow(window.editor()->text());
    ASSERT_TRUE(waitFor([&] { return applied; })) << "the offset shell did not compile";
    ASSERT_TRUE(waitFor([&] { return readouts > before; }, 60000));
    EXPECT_NEAR(window.planePanel()->readout().minimum, -1.25f, 0.03f);

    // Save and Save As write nothing: not over the mesh, and not the text elsewhere.
    EXPECT_FALSE(window.files()->save());
    EXPECT_EQ(readAll(path), cube);
    const QString elsewhere = QDir::temp().filePath("sdfwb-gui-files/far_cube_text.glsl");
    QFile::remove(elsewhere);
    EXPECT_FALSE(window.files()->saveAs(elsewhere));
    EXPECT_FALSE(QFile::exists(elsewhere));
    window.files()->setPrompt([](const QString&) { return app::FileController::Answer::No; });
}

// The document owns the modified flag: typing sets it (and the title's *), undoing back to the
// saved text clears it, Ctrl+S clears it in the document and the editor, and a reload from disk
// leaves it clear.
TEST(Files, TheDocumentOwnsTheModifiedFlag) {
    QString path = writeScratch("flag.glsl", "float sdf(vec3 p) { return length(p) - 0.5; }\n");
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(window.openFile(path));
    EXPECT_FALSE(window.document()->isModified());
    int changes = 0;
    QObject::connect(window.document(), &app::SdfDocument::modifiedChanged, [&] { ++changes; });
    ASSERT_TRUE(activate(window));
    window.editor()->setFocus();
    window.editor()->setCursorPosition(0, 0);
    QTest::keyClicks(window.editor(), "// -");
    QTest::keyClick(window.editor(), Qt::Key_Return);
    EXPECT_TRUE(window.document()->isModified());
    EXPECT_TRUE(window.windowTitle().contains("*"));
    EXPECT_EQ(changes, 1) << "one change of the flag, not one per key";
    for (int i = 0; i < 8 && window.editor()->isModified(); ++i) QTest::keyClick(window.editor(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_FALSE(window.document()->isModified()) << "undone back to the saved text";
    EXPECT_FALSE(window.windowTitle().contains("*"));
    QTest::keyClicks(window.editor(), "// -");
    QTest::keyClick(window.editor(), Qt::Key_Return);
    ASSERT_TRUE(window.document()->isModified());
    QTest::keyClick(window.editor(), Qt::Key_S, Qt::ControlModifier);
    ASSERT_TRUE(waitFor([&] { return readAll(path).startsWith("// -\n"); }, 5000)) << "Ctrl+S saved";
    EXPECT_FALSE(window.document()->isModified());
    EXPECT_FALSE(window.editor()->isModified()) << "the editor's save point moved with it";
    writeScratch("flag.glsl", "float sdf(vec3 p) { return length(p) - 0.3; }\n");
    ASSERT_TRUE(waitFor([&] { return window.editor()->text().contains("0.3"); }, 5000));
    EXPECT_FALSE(window.document()->isModified()) << "a reload from disk is not an edit";
}

TEST(Files, ReloadsWhenTheFileChangesOnDiskAndAsksWhenEdited) {
    QString path = writeScratch("watched.glsl", "float sdf(vec3 p) { return length(p) - 0.5; }\n");
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(window.openFile(path));
    writeScratch("watched.glsl", "float sdf(vec3 p) { return length(p) - 0.3; }\n");
    ASSERT_TRUE(waitFor([&] { return window.editor()->text().contains("0.3"); }, 5000)) << "an unmodified file reloads by itself";
    EXPECT_FALSE(window.editor()->isModified());

    window.editor()->setText("float sdf(vec3 p) { return length(p) - 0.4; } // my edit\n");
    int asked = 0;
    window.files()->setPrompt([&](const QString&) {
        ++asked;
        return app::FileController::Answer::No;
    });
    writeScratch("watched.glsl", "float sdf(vec3 p) { return length(p) - 0.2; }\n");
    ASSERT_TRUE(waitFor([&] { return asked > 0; }, 5000)) << "local edits: ask before reloading";
    EXPECT_TRUE(window.editor()->text().contains("my edit")) << "answered no: the edit stays";
    window.files()->setPrompt([](const QString&) { return app::FileController::Answer::No; });
    window.editor()->setModified(false);
}

TEST(Editor, ProblemsListJumpsToTheLineAndOpensIncludedFiles) {
    QString helper =
        writeScratch("helper.glsl", "// helper\n\nfloat helperDistance(vec3 p) {\n    return length(p) - missingRadius;\n}\n");
    QString main = writeScratch("main.glsl", "#include \"helper.glsl\"\nfloat sdf(vec3 p) {\n    return helperDistance(p);\n}\n");
    app::MainWindow window;
    window.show();
    int updates = 0;
    QObject::connect(window.document(), &app::SdfDocument::diagnosticsChanged, [&] { ++updates; });
    ASSERT_TRUE(window.openFile(main));
    ASSERT_TRUE(waitFor([&] { return updates > 0 && window.problems()->count() > 0; }));
    window.problems()->activate(0);
    EXPECT_EQ(window.document()->path(), QFileInfo(helper).absoluteFilePath()) << "the included file opens";
    int line = 0, column = 0;
    window.editor()->getCursorPosition(&line, &column);
    EXPECT_EQ(line + 1, 4);
    window.grab().save(QDir::temp().filePath("sdfwb-gui-problems.png"));
}

TEST(Editor, FindReplaceGoToAndCompletion) {
    QString path = writeScratch("edit.glsl", "float bump(vec3 p, float height) { return p.y - height; }\n"
                                             "float sdf(vec3 p) {\n    return min(bump(p, 0.1), length(p) - 0.5);\n}\n");
    app::MainWindow window;
    window.show();
    int updates = 0;
    QObject::connect(window.document(), &app::SdfDocument::diagnosticsChanged, [&] { ++updates; });
    ASSERT_TRUE(window.openFile(path));
    ASSERT_TRUE(waitFor([&] { return updates > 0; }));
    EXPECT_TRUE(window.editor()->findNext("length"));
    EXPECT_EQ(window.editor()->selectedText(), "length");
    EXPECT_EQ(window.editor()->replaceAll("0.5", "0.45"), 1);
    EXPECT_TRUE(window.editor()->text().contains("0.45"));
    window.editor()->goToLine(3, 5);
    int line = 0, column = 0;
    window.editor()->getCursorPosition(&line, &column);
    EXPECT_EQ(line, 2);
    EXPECT_EQ(column, 4);
    // Completion knows the file's own functions (with signatures for call tips) and the library's.
    // The file's functions arrive after the diagnostics (they are not on the latency path).
    ASSERT_TRUE(waitFor([&] { return window.editor()->completionEntries().contains("bump(vec3 p, float height)"); }, 10000));
    QStringList names = window.editor()->completionEntries();
    EXPECT_TRUE(names.contains("sdBox(vec3 p, vec3 halfSize)"));
    EXPECT_TRUE(names.contains("smoothstep(edge0, edge1, x)"));
    window.editor()->setModified(false);
}

TEST(Editor, F5ReloadsIncludesFromDisk) {
    QString helper = writeScratch("radius.glsl", "const float kRadius = 0.3;\n");
    QString main =
        writeScratch("uses_radius.glsl", "#include \"radius.glsl\"\nfloat sdf(vec3 p) { return length(p) - kRadius; }\n");
    app::MainWindow window;
    window.show();
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    ASSERT_TRUE(window.openFile(main));
    ASSERT_TRUE(waitFor([&] { return applied; }));
    long small = foreground(frameOf(window), kBackground);
    writeScratch("radius.glsl", "const float kRadius = 0.6;\n");
    applied = false;
    window.files()->reloadAll();
    ASSERT_TRUE(waitFor([&] { return applied; }));
    long large = foreground(frameOf(window), kBackground);
    EXPECT_GT(large, 3 * small) << "F5 re-reads the included file";
}

// On llvmpipe (which ends every loop after 65535 iterations without an error) a loop that runs
// longer is a warning at its line in the editor; elsewhere nothing is said (docs/stability.md).
TEST(Editor, ALoopTheDriverWouldCutShortIsAWarningAtItsLine) {
    app::MainWindow window;
    window.show();
    const QString path = writeScratch("long_loop.glsl", "// 0.5 / 200000 added 200000 times\n"
                                                        "float sdf(vec3 p) {\n"
                                                        "    float s = 0.0;\n"
                                                        "    for (int i = 0; i < 200000; ++i) s += 0.5 / 200000.0;\n"
                                                        "    return length(p) - s;\n"
                                                        "}\n");
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    ASSERT_TRUE(window.openFile(path));
    ASSERT_TRUE(waitFor([&] { return applied; }));
    // The viewport's context is up by now: edit once so the check runs knowing its driver.
    int updates = 0;
    QObject::connect(window.document(), &app::SdfDocument::diagnosticsChanged, [&] { ++updates; });
    window.editor()->setText(window.editor()->text() + "\n// edited\n");
    ASSERT_TRUE(waitFor([&] { return updates > 0; }));
    const bool llvmpipe = window.viewport()->contextDescription().contains("llvmpipe");
    const auto& diagnostics = window.document()->diagnostics();
    const auto warning = std::find_if(diagnostics.begin(), diagnostics.end(),
                                      [](const shaders::Diagnostic& d) { return d.message.find("65535") != std::string::npos; });
    if (llvmpipe) {
        ASSERT_NE(warning, diagnostics.end()) << "no warning on llvmpipe";
        EXPECT_EQ(warning->line, 4);
        EXPECT_EQ(warning->severity, shaders::Severity::Warning);
        EXPECT_GE(window.editor()->diagnosticCount(), 1);
    } else {
        EXPECT_EQ(warning, diagnostics.end()) << "a warning on a driver without the limit";
    }
    EXPECT_TRUE(applied) << "a warning does not keep the SDF from the viewport";
}

// ---- #32: a whole Shadertoy shader, pasted as is ----

// A whole Shadertoy shader opens unmodified and sdfwb traces its map(); View > Shadertoy picture
// (its shortcut, a real key event) runs the file's own mainImage instead: the author's sky
// replaces sdfwb's background, a left drag sets iMouse as Shadertoy does (and moves the author's
// camera in a file that orbits with iMouse) without orbiting sdfwb's camera, and a file without
// mainImage turns the picture off and the action off. SDFWB_SCREENSHOT_DIR keeps
// shadertoy_pasted.png and shadertoy_picture.png for docs/foreign-code.md.
namespace {

// Opens `path` in the window and waits until the document applied it and the viewport drew it at rest.
bool openApplied(app::MainWindow& window, const QString& path) {
    bool applied = false;
    auto connection = QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    const bool ok = window.openFile(path) && waitFor([&] { return applied; });
    QObject::disconnect(connection);
    return ok && waitFor([&] { return window.viewport()->lastFrameMilliseconds() > 0.0 && !window.viewport()->isInteracting(); });
}

bool isBackground(QColor c) {
    return std::abs(c.redF() - kBackground.redF()) < 0.03 && std::abs(c.greenF() - kBackground.greenF()) < 0.03 &&
           std::abs(c.blueF() - kBackground.blueF()) < 0.03;
}

} // namespace

TEST(Shadertoy, PastedShaderTracesItsMapAndShowsItsOwnPicture) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(activate(window));
    const QString corpus = QDir(SDFWB_SOURCE_DIR "/tests/foreign").absolutePath();
    ASSERT_TRUE(openApplied(window, corpus + "/34_st_mouse_lattice.glsl"));
    EXPECT_EQ(window.document()->signature().entry, "map");
    EXPECT_TRUE(window.document()->lastGoodSource().shadertoyMainImage);
    auto* action = window.findChild<QAction*>("shadertoy_picture");
    ASSERT_NE(action, nullptr);
    EXPECT_TRUE(action->isEnabled());
    widgets::ViewportWidget* viewport = window.viewport();
    const QImage traced = fullResolutionFrame(window);
    if (QString path = screenshotPath("shadertoy_pasted.png"); !path.isEmpty()) windowShot(window).save(path);
    EXPECT_TRUE(isBackground(traced.pixelColor(2, 2))) << "sdfwb's tracer: its own background in the corner";

    QTest::keyClick(&window, Qt::Key_Y, Qt::ControlModifier | Qt::ShiftModifier);
    ASSERT_TRUE(viewport->shadertoyPicture()) << "the shortcut turns the picture on";
    EXPECT_TRUE(action->isChecked());
    const QImage picture = frameOf(window);
    EXPECT_FALSE(isBackground(picture.pixelColor(2, 2))) << "the author's picture has the author's background";
    EXPECT_GT(meanDifference(traced, picture), 10.0) << "the picture is not the tracer's frame";
    if (QString path = screenshotPath("shadertoy_picture.png"); !path.isEmpty()) windowShot(window).save(path);

    // A left drag: iMouse follows (pixels from the lower left, zw the press), the camera stays.
    const values::Camera camera = viewport->camera();
    const QPoint from = centreOf(viewport), to = from + QPoint(120, -40);
    QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, from);
    EXPECT_GT(viewport->shadertoyMouse().z, 0.0f) << "pressed: z is positive";
    QMouseEvent drag(QEvent::MouseMove, QPointF(to), viewport->mapToGlobal(QPointF(to)), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QApplication::sendEvent(viewport, &drag);
    const qreal ratio = viewport->devicePixelRatioF();
    EXPECT_NEAR(viewport->shadertoyMouse().x, to.x() * ratio, 1.0);
    EXPECT_NEAR(viewport->shadertoyMouse().y, (viewport->height() - to.y()) * ratio, 1.0);
    EXPECT_NEAR(viewport->shadertoyMouse().z, from.x() * ratio, 1.0);
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, to);
    EXPECT_LT(viewport->shadertoyMouse().z, 0.0f) << "released: z is negative";
    EXPECT_EQ(viewport->camera(), camera) << "a drag in the picture does not orbit sdfwb's camera";
    EXPECT_GT(meanDifference(picture, frameOf(window)), 2.0) << "this file's author orbits with iMouse";

    // A file without mainImage: the tracer comes back, and the action cannot be turned on.
    ASSERT_TRUE(openApplied(window, datasetFile("Geometry/Sphere.glsl")));
    EXPECT_FALSE(viewport->shadertoyPicture());
    EXPECT_FALSE(action->isChecked());
    EXPECT_FALSE(action->isEnabled());
    EXPECT_TRUE(isBackground(frameOf(window).pixelColor(2, 2)));
}

// A pasted shader whose field is never negative (the distance to two thin lines, floored): the
// workbench takes its surface where its own march stops (d < 0.001), says so in the title and the
// Problems panel (at the march's test, also after an edit), and the jobs get the same level.
TEST(Shadertoy, AnUnsignedFieldsSurfaceIsWhereItsMarchStops) {
    const QString folder = QDir::temp().filePath(QString("sdfwb-gui-level-%1").arg(QCoreApplication::applicationPid()));
    QDir().mkpath(folder);
    const QString path = folder + "/lines.glsl";
    {
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write("float segment(vec3 p, vec3 a, vec3 b) {\n"
                   "    vec3 pa = p - a, ba = b - a;\n"
                   "    return length(pa - ba * clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0));\n"
                   "}\n"
                   "float map(vec3 p) {\n"
                   "    return max(min(segment(p, vec3(-0.6, 0.0, 0.0), vec3(0.6, 0.0, 0.0)),\n"
                   "                   segment(p, vec3(0.0, -0.6, 0.1), vec3(0.0, 0.6, 0.1))), 0.0004);\n"
                   "}\n"
                   "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                   "    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;\n"
                   "    vec3 ro = vec3(0.0, 0.0, -3.0), rd = normalize(vec3(uv, 1.5));\n"
                   "    float t = 0.0;\n"
                   "    for (int i = 0; i < 120; i++) {\n"
                   "        float d = map(ro + rd * t);\n"
                   "        if (d < 0.001 || t > 20.0) break;\n"
                   "        t += d;\n"
                   "    }\n"
                   "    fragColor = vec4(vec3(t < 20.0 ? 1.0 : 0.0), 1.0);\n"
                   "}\n");
    }
    app::MainWindow window;
    window.resize(1000, 640);
    window.show();
    ASSERT_TRUE(activate(window));
    ASSERT_TRUE(openApplied(window, path));
    EXPECT_EQ(window.document()->level(), 0.001f);
    EXPECT_TRUE(window.document()->frame().isEmpty()) << "the lines cross the unit box";
    EXPECT_TRUE(window.windowTitle().contains("an unsigned field: its surface taken at f = 0.001"))
        << window.windowTitle().toStdString();
    EXPECT_EQ(window.document()->input().level, 0.001f) << "the jobs run the levelled field";
    auto note = [&] {
        const auto& diagnostics = window.document()->diagnostics();
        return std::find_if(diagnostics.begin(), diagnostics.end(), [](const shaders::Diagnostic& d) {
            return d.message.find("its surface is taken at f = 0.001") != std::string::npos;
        });
    };
    ASSERT_NE(note(), window.document()->diagnostics().end());
    EXPECT_EQ(note()->line, 15) << "the march's test";
    // After an edit the decision is kept, and said again.
    int updates = 0;
    QObject::connect(window.document(), &app::SdfDocument::diagnosticsChanged, [&] { ++updates; });
    window.editor()->setText(window.editor()->text() + "\n// edited\n");
    ASSERT_TRUE(waitFor([&] { return updates > 0; }));
    EXPECT_NE(note(), window.document()->diagnostics().end());
    EXPECT_EQ(window.document()->level(), 0.001f);
    if (QString shot = screenshotPath("unsigned_lines.png"); !shot.isEmpty()) windowShot(window).save(shot);

    ASSERT_TRUE(openApplied(window, datasetFile("Geometry/Sphere.glsl")));
    EXPECT_EQ(window.document()->level(), 0.0f);
    EXPECT_EQ(window.document()->input().level, 0.0f);
    QDir(folder).removeRecursively();
}

// A pasted scene built around its own camera (a ball at z = 5, outside [-1, 1]^3): the workbench
// frames it by its surface's box, so the ball fills the view instead of an empty box; the title
// says so and the jobs get the same frame. A dataset file is shown as it is.
TEST(Shadertoy, ASceneOutsideTheUnitBoxIsFramed) {
    const QString folder = QDir::temp().filePath(QString("sdfwb-gui-frame-%1").arg(QCoreApplication::applicationPid()));
    QDir().mkpath(folder);
    const QString path = folder + "/far_ball.glsl";
    {
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write("float map(vec3 p) { return length(p - vec3(0.0, 0.0, 5.0)) - 1.0; }\n"
                   "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                   "    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;\n"
                   "    vec3 ro = vec3(0.0), rd = normalize(vec3(uv, 1.5));\n"
                   "    float t = 0.0;\n"
                   "    for (int i = 0; i < 100; i++) {\n"
                   "        float d = map(ro + rd * t);\n"
                   "        if (d < 0.001) break;\n"
                   "        t += d;\n"
                   "    }\n"
                   "    fragColor = vec4(vec3(1.0 / (1.0 + t)), 1.0);\n"
                   "}\n");
    }
    app::MainWindow window;
    window.resize(1000, 640);
    window.show();
    ASSERT_TRUE(activate(window));
    ASSERT_TRUE(openApplied(window, path));
    const QString frame = window.document()->frame();
    ASSERT_FALSE(frame.isEmpty()) << "the ball has no surface in [-1, 1]^3";
    const QStringList corners = frame.split(',');
    ASSERT_EQ(corners.size(), 6);
    EXPECT_NEAR(0.5 * (corners[2].toDouble() + corners[5].toDouble()), 5.0, 0.05) << frame.toStdString();
    EXPECT_TRUE(window.windowTitle().contains("framed by the box")) << window.windowTitle().toStdString();
    EXPECT_EQ(window.document()->input().normalize, frame.toStdString()) << "the jobs run the framed field";
    const QImage framed = fullResolutionFrame(window);
    if (QString shot = screenshotPath("framed_scene.png"); !shot.isEmpty()) windowShot(window).save(shot);
    EXPECT_FALSE(isBackground(framed.pixelColor(framed.width() / 2, framed.height() / 2))) << "the ball is drawn";
    EXPECT_TRUE(isBackground(framed.pixelColor(2, 2)));

    ASSERT_TRUE(openApplied(window, datasetFile("Geometry/Sphere.glsl")));
    EXPECT_TRUE(window.document()->frame().isEmpty());
    EXPECT_TRUE(window.document()->input().normalize.empty());
    EXPECT_FALSE(window.windowTitle().contains("framed"));
    QDir(folder).removeRecursively();
}
