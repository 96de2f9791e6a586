#include <core/Log.h>

#include <cstdio>
#include <map>
#include <mutex>

namespace sdfwb::log {
namespace {

struct State {
    std::mutex mutex;
    std::map<int, Sink> sinks;
    int nextId = 1;
    Level minimum = Level::Info;
    bool stderrEnabled = true;
};

State& state() {
    static State instance;
    return instance;
}

} // namespace

const char* levelName(Level level) {
    switch (level) {
    case Level::Debug:
        return "debug";
    case Level::Info:
        return "info";
    case Level::Warning:
        return "warning";
    case Level::Error:
        return "error";
    }
    return "?";
}

int addSink(Sink sink) {
    State& s = state();
    std::lock_guard lock(s.mutex);
    int id = s.nextId++;
    s.sinks.emplace(id, std::move(sink));
    return id;
}

void removeSink(int id) {
    State& s = state();
    std::lock_guard lock(s.mutex);
    s.sinks.erase(id);
}

void setMinimumLevel(Level level) {
    State& s = state();
    std::lock_guard lock(s.mutex);
    s.minimum = level;
}

Level minimumLevel() {
    State& s = state();
    std::lock_guard lock(s.mutex);
    return s.minimum;
}

void setStderrEnabled(bool enabled) {
    State& s = state();
    std::lock_guard lock(s.mutex);
    s.stderrEnabled = enabled;
}

void write(Level level, std::string_view category, std::string_view message) {
    State& s = state();
    std::lock_guard lock(s.mutex);
    if (level < s.minimum) return;
    if (s.stderrEnabled)
        std::fprintf(stderr, "[%s] %.*s: %.*s\n", levelName(level), int(category.size()), category.data(), int(message.size()),
                     message.data());
    for (auto& [id, sink] : s.sinks) sink(level, category, message);
}

} // namespace sdfwb::log
