#pragma once
// Where the running sdfwb code is installed (core's private helper for Paths.cpp and Plugins.cpp).

#include <filesystem>

namespace sdfwb::paths::detail {

// The install prefix of the file that holds sdfwb's code (the sdfwb binary, or the Python module
// <prefix>/lib/python3/dist-packages/sdfwb/_native*.so); empty in a build tree or anywhere else.
std::filesystem::path installPrefix();

} // namespace sdfwb::paths::detail
