#pragma once
// Parts of sdfwb built as shared modules and loaded the first time they are needed, so that a
// command pays only for the libraries it uses: libsdfwb_media.so (OpenImageIO and FFmpeg: image
// and video files) and libsdfwb_workbench.so (Qt Widgets: the workbench window).

#include <core/Expected.h>

#include <filesystem>
#include <string>

namespace sdfwb::plugins {

// Where the modules are: $SDFWB_PLUGIN_DIR, else <prefix>/lib/sdfwb when sdfwb is installed, else
// the build tree's plugins/ folder.
std::filesystem::path folder();

// The address of `symbol` in module `file` (a name in folder()), loading the module the first
// time (once per process; later calls return the same answer, an error too). The error names the
// file and says why it did not load.
Expected<void*> symbol(const std::string& file, const std::string& symbol);

} // namespace sdfwb::plugins
