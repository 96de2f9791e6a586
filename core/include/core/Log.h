#pragma once
// Logging by category. Messages go to every registered sink (stderr by default, the GUI's log
// dock, a log file). Thread-safe; sinks are called under a lock, so they must not log themselves.

#include <functional>
#include <string>
#include <string_view>

namespace sdfwb::log {

enum class Level { Debug, Info, Warning, Error };

// Categories name the module or concern: "gl", "shaders", "render", "sampling", "app", ...
using Sink = std::function<void(Level level, std::string_view category, std::string_view message)>;

// Adds a sink; returns an id for removeSink(). The stderr sink is installed by default.
int addSink(Sink sink);
void removeSink(int id);

// Messages below this level are dropped. Default Info (Warning when quiet).
void setMinimumLevel(Level level);
Level minimumLevel();

// Writes to stderr only when enabled (default on). The CLI turns it off with --quiet.
void setStderrEnabled(bool enabled);

void write(Level level, std::string_view category, std::string_view message);
inline void debug(std::string_view category, std::string_view message) { write(Level::Debug, category, message); }
inline void info(std::string_view category, std::string_view message) { write(Level::Info, category, message); }
inline void warning(std::string_view category, std::string_view message) { write(Level::Warning, category, message); }
inline void error(std::string_view category, std::string_view message) { write(Level::Error, category, message); }

const char* levelName(Level level);

} // namespace sdfwb::log
