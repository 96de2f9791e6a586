// The GUI tests' main: a QApplication (its surface format set as the workbench's), test-mode
// settings, and jobs run by the real sdfwb binary.
#include "GuiTestSupport.h"

using namespace sdfwb;

int main(int argc, char** argv) {
    QStandardPaths::setTestModeEnabled(true); // no user settings read or written
    // Jobs the window starts on its own (thumbnails, probes) run the real sdfwb, never this binary.
    qputenv("SDFWB_BATCH_EXECUTABLE", SDFWB_BINARY);
    app::setDefaultSurfaceFormat();
    QApplication application(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
