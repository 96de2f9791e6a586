// The JSON form of requests and reports. Each struct is described once, by a `fields` function
// that names its keys (JobFields.h); the same description writes and reads it.
#include <jobs/JobJson.h>
#include <jobs/Protocol.h>

#include "JobFields.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <concepts>
#include <cstdlib>
#include <limits>
#include <set>
#include <type_traits>

namespace sdfwb::jobs {
namespace {

// Keys in the order the descriptions name them ("kind" first), not sorted.
using json = nlohmann::ordered_json;

using namespace detail; // JobFields.h: the descriptions

// ---- writing ----

struct Writer;
template <class T>
concept Described = requires(Writer& w, T& t) {
    fields(w, t);
};

json encode(bool value) { return value; }
json encode(const std::string& value) { return value; }
json encode(shaders::ShadingMode mode) { return shaders::shadingModeName(mode); }
json encode(values::TraceSettings::Cones cones) { return values::conesName(cones); }
json encode(values::TraceSettings::Tracer tracer) { return values::tracerName(tracer); }
json encode(values::MarchEvent event) { return marchEventName(event); }
json encode(values::Finding finding) { return values::findingName(finding); }
json encode(values::ItemStatus status) { return values::itemStatusName(status); }
// A float as the shortest decimal that reads back as the same float (0.01f is 0.01, not
// 0.009999999776482582): written as that double, it parses back to the same float bits.
json encode(float value) {
    if (!std::isfinite(value)) return nullptr;
    char text[32];
    auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::strtod(std::string(text, end).c_str(), nullptr);
}
// A mesh's provenance as the object its text holds (null for a GLSL SDF).
json encode(const values::MeshSource& source) {
    if (source.json.empty()) return nullptr;
    json parsed = json::parse(source.json, nullptr, false); // no exceptions: text that is no JSON stays text
    return parsed.is_discarded() ? json(source.json) : parsed;
}
json encode(const glm::vec3& v) { return json::array({encode(v.x), encode(v.y), encode(v.z)}); }
// Parameter values as an object, {"radius": 0.3, "offset": [1, 2]}; sweeps as their text form.
json encode(const std::vector<shaders::ParameterValue>& values) {
    json out = json::object();
    for (const shaders::ParameterValue& p : values) {
        if (p.value.size() == 1) {
            out[p.name] = encode(p.value[0]);
        } else {
            json list = json::array();
            for (float x : p.value) list.push_back(encode(x));
            out[p.name] = list;
        }
    }
    return out;
}
json encode(const shaders::ParameterSweep& sweep) { return shaders::formatParameterSweep(sweep); }
json encode(const values::PlaneSpec& p) {
    return json::array({encode(p.normal.x), encode(p.normal.y), encode(p.normal.z), encode(p.offset)});
}
template <class T>
requires std::is_arithmetic_v<T> &&(!std::is_same_v<T, float>)json encode(T value) { return value; }
template <class T> json encode(const std::optional<T>& value);
template <class T> json encode(const std::vector<T>& values);
template <Described T> json encode(const T& value);

struct Writer {
    json& out;
    template <class T> void operator()(const char* key, const T& value) { out[key] = encode(value); }
};

template <class T> json encode(const std::optional<T>& value) { return value ? encode(*value) : json(nullptr); }
template <class T> json encode(const std::vector<T>& values) {
    json list = json::array();
    for (const T& value : values) list.push_back(encode(value));
    return list;
}
template <Described T> json encode(const T& value) {
    json out = json::object();
    Writer writer{out};
    fields(writer, const_cast<T&>(value)); // fields() only reads through a Writer
    return out;
}

// ---- reading ----

// Reads keys into a struct; the first error (with its key path) wins. Strict readers refuse keys
// the description does not name.
struct Reader {
    const json& in;
    std::string path;
    bool strict;
    std::string& error;
    std::set<std::string> seen;

    template <class T> void operator()(const char* key, T& value);
    void finish() {
        if (!strict || !error.empty() || !in.is_object()) return;
        for (const auto& [key, item] : in.items())
            if (!seen.count(key)) {
                std::string known;
                for (const std::string& name : seen) known += (known.empty() ? "" : ", ") + name;
                error = "'" + (path.empty() ? key : path + "." + key) + "': unknown key (known here: " + known + ")";
                return;
            }
    }
};

std::string describeValue(const json& value) {
    std::string text = value.dump();
    return text.size() > 40 ? text.substr(0, 37) + "..." : text;
}

bool fail(std::string& error, const std::string& path, const std::string& expected, const json& value) {
    error = "'" + path + "': expected " + expected + ", got " + describeValue(value);
    return false;
}

bool decode(const json& in, bool& value, const std::string& path, bool, std::string& error) {
    if (!in.is_boolean()) return fail(error, path, "true or false", in);
    value = in.get<bool>();
    return true;
}

bool decode(const json& in, values::MeshSource& value, const std::string& path, bool, std::string& error) {
    if (in.is_null()) return value.json.clear(), true;
    if (!in.is_object()) return fail(error, path, "an object or null", in);
    value.json = in.dump();
    return true;
}

bool decode(const json& in, std::string& value, const std::string& path, bool, std::string& error) {
    if (!in.is_string()) return fail(error, path, "a string", in);
    value = in.get<std::string>();
    return true;
}

template <std::integral T> bool decode(const json& in, T& value, const std::string& path, bool, std::string& error) {
    if (!in.is_number_integer()) return fail(error, path, "an integer", in);
    if (in.is_number_unsigned()) {
        const auto n = in.get<std::uint64_t>();
        if (n > std::uint64_t(std::numeric_limits<T>::max())) return fail(error, path, "an integer in range", in);
        value = T(n);
    } else {
        const auto n = in.get<std::int64_t>();
        if (n < std::int64_t(std::numeric_limits<T>::min()) ||
            (n > 0 && std::uint64_t(n) > std::uint64_t(std::numeric_limits<T>::max())))
            return fail(error, path, std::is_signed_v<T> ? "an integer in range" : "a non-negative integer", in);
        value = T(n);
    }
    return true;
}

template <std::floating_point T> bool decode(const json& in, T& value, const std::string& path, bool, std::string& error) {
    if (!in.is_number()) return fail(error, path, "a number", in);
    const T number = T(in.get<double>());
    if (!std::isfinite(number)) return fail(error, path, "a finite number", in); // 1e39 is no float
    value = number;
    return true;
}

bool finiteFloat(const json& in) { return in.is_number() && std::isfinite(float(in.get<double>())); }

bool decode(const json& in, glm::vec3& value, const std::string& path, bool, std::string& error) {
    if (!in.is_array() || in.size() != 3 || !finiteFloat(in[0]) || !finiteFloat(in[1]) || !finiteFloat(in[2]))
        return fail(error, path, "[x, y, z] (finite)", in);
    value = glm::vec3(in[0].get<float>(), in[1].get<float>(), in[2].get<float>());
    return true;
}

bool decode(const json& in, std::vector<shaders::ParameterValue>& values, const std::string& path, bool, std::string& error) {
    if (!in.is_object()) return fail(error, path, "an object of parameter values ({\"radius\": 0.3, \"offset\": [1, 2]})", in);
    values.clear();
    for (const auto& [name, item] : in.items()) {
        shaders::ParameterValue value{name, {}};
        const std::string where = path + "." + name;
        if (item.is_boolean()) {
            value.value.push_back(item.get<bool>() ? 1.0f : 0.0f);
        } else if (finiteFloat(item)) {
            value.value.push_back(item.get<float>());
        } else if (item.is_array() && !item.empty() && item.size() <= 4) {
            for (const json& x : item) {
                if (!finiteFloat(x)) return fail(error, where, "1 to 4 finite numbers", item);
                value.value.push_back(x.get<float>());
            }
        } else {
            return fail(error, where, "a finite number, true/false, or 1 to 4 numbers", item);
        }
        auto checked = shaders::parseParameterValue(shaders::formatParameterValue(value));
        if (!checked || !(*checked == value)) return fail(error, where, "a parameter name (a GLSL identifier)", in);
        values.push_back(std::move(value));
    }
    return true;
}

bool decode(const json& in, shaders::ParameterSweep& value, const std::string& path, bool, std::string& error) {
    if (!in.is_string()) return fail(error, path, "\"NAME=FROM:TO:COUNT\"", in);
    auto sweep = shaders::parseParameterSweep(in.get<std::string>());
    if (!sweep) {
        error = "'" + path + "': " + sweep.error().message;
        return false;
    }
    value = std::move(*sweep);
    return true;
}

bool decode(const json& in, values::PlaneSpec& value, const std::string& path, bool, std::string& error) {
    if (!in.is_array() || in.size() != 4) return fail(error, path, "[nx, ny, nz, offset]", in);
    for (const json& item : in)
        if (!item.is_number()) return fail(error, path, "[nx, ny, nz, offset]", in);
    for (const json& item : in)
        if (!finiteFloat(item)) return fail(error, path, "[nx, ny, nz, offset] (finite)", in);
    value.normal = glm::vec3(in[0].get<float>(), in[1].get<float>(), in[2].get<float>());
    value.offset = in[3].get<float>();
    return true;
}

// An enum written as its name: `parse` reads the name; `expected` says what may stand there.
template <class Enum, class Parse>
bool decodeNamed(const json& in, Enum& value, const std::string& path, std::string& error, Parse parse,
                 const std::string& expected) {
    const std::optional<Enum> named = in.is_string() ? parse(in.get<std::string>()) : std::nullopt;
    if (!named) return fail(error, path, expected, in);
    value = *named;
    return true;
}

bool decode(const json& in, shaders::ShadingMode& value, const std::string& path, bool, std::string& error) {
    return decodeNamed(in, value, path, error, shaders::parseShadingMode, "a shading mode (" + shaders::shadingModeNames() + ")");
}

bool decode(const json& in, values::TraceSettings::Cones& value, const std::string& path, bool, std::string& error) {
    return decodeNamed(in, value, path, error, values::parseCones, "auto, off or on");
}

bool decode(const json& in, values::TraceSettings::Tracer& value, const std::string& path, bool, std::string& error) {
    return decodeNamed(in, value, path, error, values::parseTracer, "auto, fragment or compute");
}

bool decode(const json& in, values::MarchEvent& value, const std::string& path, bool, std::string& error) {
    return decodeNamed(in, value, path, error, values::parseMarchEvent, "a march event (step, hit, left the box, ...)");
}

bool decode(const json& in, values::ItemStatus& value, const std::string& path, bool, std::string& error) {
    return decodeNamed(
        in, value, path, error, [](const std::string& name) { return valueNamed(values::kItemStatusNames, name); },
        "an item status (pending, done, skipped, failed, timeout or cancelled)");
}

bool decode(const json& in, values::Finding& value, const std::string& path, bool, std::string& error) {
    return decodeNamed(
        in, value, path, error, [](const std::string& name) { return valueNamed(values::kFindingNames, name); },
        "an audit finding (exact, conservative, non-conservative, truncated, ...)");
}

template <class T> bool decode(const json& in, std::optional<T>& value, const std::string& path, bool strict, std::string& error);
template <class T> bool decode(const json& in, std::vector<T>& values, const std::string& path, bool strict, std::string& error);
template <Described T> bool decode(const json& in, T& value, const std::string& path, bool strict, std::string& error);

template <class T>
bool decode(const json& in, std::optional<T>& value, const std::string& path, bool strict, std::string& error) {
    if (in.is_null()) {
        value.reset();
        return true;
    }
    T inner{};
    if (!decode(in, inner, path, strict, error)) return false;
    value = std::move(inner);
    return true;
}

template <class T> bool decode(const json& in, std::vector<T>& values, const std::string& path, bool strict, std::string& error) {
    if (!in.is_array()) return fail(error, path, "an array", in);
    values.clear();
    for (std::size_t i = 0; i < in.size(); ++i) {
        T value{};
        if (!decode(in[i], value, path + "[" + std::to_string(i) + "]", strict, error)) return false;
        values.push_back(std::move(value));
    }
    return true;
}

template <Described T> bool decode(const json& in, T& value, const std::string& path, bool strict, std::string& error) {
    if (!in.is_object()) return fail(error, path, "an object", in);
    Reader reader{in, path, strict, error, {}};
    fields(reader, value);
    reader.finish();
    return error.empty();
}

template <class T> void Reader::operator()(const char* key, T& value) {
    seen.insert(key);
    if (!error.empty()) return;
    auto it = in.find(key);
    if (it == in.end()) return;
    decode(*it, value, path.empty() ? std::string(key) : path + "." + key, strict, error);
}

// Reads the top-level object `in` into `value`, ignoring `skip` (the request's "kind").
template <class T> Expected<T> readObject(const json& in, bool strict, const char* what) {
    T value{};
    std::string error;
    if (!in.is_object()) return makeError(std::string(what) + ": expected a JSON object");
    json body = in;
    body.erase("kind");
    Reader reader{body, "", strict, error, {}};
    fields(reader, value);
    reader.finish();
    if (!error.empty()) return makeError(std::string(what) + ": " + error);
    return value;
}

std::optional<json> parse(const std::string& text, std::string& error) {
    try {
        return json::parse(text);
    } catch (const json::exception& e) { // parse_error, and out_of_range for a number like 1e1000
        error = std::string("not valid JSON: ") + e.what();
        return std::nullopt;
    }
}

std::string dump(const json& value, int indent) { return value.dump(indent, ' ', false, json::error_handler_t::replace); }

} // namespace

std::string toJson(const values::Request& request, int indent) {
    json out = {{"kind", kindName(request)}};
    std::visit([&](const auto& r) { out.update(encode(r)); }, request);
    return dump(out, indent);
}

Expected<values::Request> requestFromJson(const std::string& text) {
    std::string error;
    auto in = parse(text, error);
    if (!in) return makeError("request: " + error);
    if (!in->is_object()) return makeError("request: expected a JSON object with a \"kind\"");
    auto kind = in->find("kind");
    if (kind == in->end() || !kind->is_string()) return makeError("request: missing \"kind\" (" + values::jobKindNames() + ")");
    const std::string name = kind->get<std::string>();
    // The kind's request type from the one table (values/JobKinds.h), its former name included.
    return values::withJobKind(
        name,
        [&]<class T>(T*) -> Expected<values::Request> {
            auto value = readObject<T>(*in, true, (name + " request").c_str());
            if (!value) return value.error();
            return values::Request(std::move(*value));
        },
        Expected<values::Request>(makeError("request: unknown kind '" + name + "' (" + values::jobKindNames() + ")")));
}

namespace {

json encodeAudit(const values::AuditJobReport& report) {
    json out = {{"sdf", report.sdf}, {"entry", report.entry}};
    out["parameters"] = encode(report.parameters);
    out["mesh_source"] = encode(report.meshSource);
    out["warnings"] = encode(report.warnings);
    if (!report.family.empty()) {
        out["truncation_reach"] = report.truncationReach;
        out["family"] = encode(report.family);
    } else if (report.readout) {
        out["plane"] = encode(report.plane.value_or(values::PlaneSpec{}));
        out.update(encode(*report.readout));
        out["histogram_bin_width"] = 0.05;
    } else if (report.volume) {
        out["truncation_reach"] = report.truncationReach;
        out.update(encode(*report.volume));
    }
    // The figures particular to each flag's kind, by name (namedFigures), next to the generic ones.
    if (out.contains("flags")) {
        const auto& flags = report.readout ? report.readout->flags : report.volume->flags;
        for (std::size_t i = 0; i < flags.size(); ++i)
            for (const auto& [name, value] : values::namedFigures(flags[i])) out["flags"][i][name] = value;
    }
    return out;
}

} // namespace

std::string toJson(const values::RenderReport& report, int indent) { return dump(encode(report), indent); }
std::string toJson(const values::AnimateReport& report, int indent) { return dump(encode(report), indent); }
std::string toJson(const values::SampleReport& report, int indent) { return dump(encode(report), indent); }
std::string toJson(const values::MergeReport& report, int indent) { return dump(encode(report), indent); }
std::string toJson(const values::ListReport& report, int indent) { return dump(encode(report), indent); }

Expected<void> addDatasetMeasurements(const std::string& reportText, values::ListReport& report) {
    const json root = json::parse(reportText, nullptr, false);
    if (root.is_discarded() || !root.is_object()) return makeError("not a JSON object");
    auto text = [](const json& object, const char* key) {
        const auto it = object.find(key);
        return it != object.end() && it->is_string() ? it->get<std::string>() : std::string();
    };
    report.measuredOn = text(root, "machine");
    report.measuredDate = text(root, "date");
    const auto sdfs = root.find("sdfs");
    if (sdfs == root.end() || !sdfs->is_array()) return makeError("no \"sdfs\" array");
    for (const json& entry : *sdfs) {
        if (!entry.is_object()) continue;
        const std::string name = text(entry, "name");
        for (values::ListItem& item : report.items) {
            if (item.name != name) continue;
            item.measuredType = text(entry, "measured_type");
            if (const auto ms = entry.find("render_ms"); ms != entry.end() && ms->is_number())
                item.renderMilliseconds = ms->get<double>();
        }
    }
    return {};
}
std::string toJson(const values::BenchReport& report, int indent) { return dump(encode(report), indent); }
std::string toJson(const values::ParamsReport& report, int indent) { return dump(encode(report), indent); }
std::string toJson(const values::MeshReport& report, int indent) { return dump(encode(report), indent); }
std::string toJson(const values::EvalReport& report, int indent) { return dump(encode(report), indent); }
std::string toJson(const values::RunReport& report, int indent) { return dump(encode(report), indent); }
std::string toJson(const values::ProbeReport& report, int indent) { return dump(encode(report), indent); }
std::string toJson(const values::RunItemReport& report, int indent) { return dump(encode(report), indent); }
std::string toJson(const values::AuditJobReport& report, int indent) { return dump(encodeAudit(report), indent); }

template <class T> Expected<T> reportFromJson(const std::string& text) {
    std::string error;
    auto in = parse(text, error);
    if (!in) return makeError("report: " + error);
    return readObject<T>(*in, false, "report");
}

template <> Expected<values::AuditJobReport> reportFromJson<values::AuditJobReport>(const std::string& text) {
    std::string error;
    auto in = parse(text, error);
    if (!in) return makeError("report: " + error);
    if (!in->is_object()) return makeError("report: expected a JSON object");
    values::AuditJobReport report;
    auto read = [&](const char* key, auto& value) {
        if (auto it = in->find(key); it != in->end() && error.empty()) decode(*it, value, key, false, error);
    };
    read("sdf", report.sdf);
    read("entry", report.entry);
    read("parameters", report.parameters);
    read("mesh_source", report.meshSource);
    read("warnings", report.warnings);
    if (in->contains("family")) {
        read(in->contains("truncation_reach") ? "truncation_reach" : "probe_distance", report.truncationReach);
        read("family", report.family);
    } else if (in->contains("plane")) {
        read("plane", report.plane);
        auto readout = readObject<values::PlaneReadout>(*in, false, "report");
        if (!readout) return readout.error();
        report.readout = std::move(*readout);
    } else {
        read(in->contains("truncation_reach") ? "truncation_reach" : "probe_distance", report.truncationReach);
        auto volume = readObject<values::AuditReport>(*in, false, "report");
        if (!volume) return volume.error();
        report.volume = std::move(*volume);
    }
    if (!error.empty()) return makeError("report: " + error);
    return report;
}

template Expected<values::RenderReport> reportFromJson<values::RenderReport>(const std::string&);
template Expected<values::AnimateReport> reportFromJson<values::AnimateReport>(const std::string&);
template Expected<values::SampleReport> reportFromJson<values::SampleReport>(const std::string&);
template Expected<values::MergeReport> reportFromJson<values::MergeReport>(const std::string&);
template Expected<values::ListReport> reportFromJson<values::ListReport>(const std::string&);
template Expected<values::BenchReport> reportFromJson<values::BenchReport>(const std::string&);
template Expected<values::ParamsReport> reportFromJson<values::ParamsReport>(const std::string&);
template Expected<values::MeshReport> reportFromJson<values::MeshReport>(const std::string&);
template Expected<values::EvalReport> reportFromJson<values::EvalReport>(const std::string&);
template Expected<values::RunReport> reportFromJson<values::RunReport>(const std::string&);
template Expected<values::ProbeReport> reportFromJson<values::ProbeReport>(const std::string&);
template Expected<values::RunItemReport> reportFromJson<values::RunItemReport>(const std::string&);

// The worker protocol (Protocol.h).
const char* failureName(Failure failure) {
    switch (failure) {
    case Failure::Usage:
        return "usage";
    case Failure::Work:
        return "work";
    case Failure::NoGl:
        return "no-gl";
    case Failure::Cancelled:
        return "cancelled";
    }
    return "work";
}

std::string progressMessage(std::uint64_t done, std::uint64_t total) {
    return json{{"progress", json::array({done, total})}}.dump();
}

std::string errorMessage(const JobError& error) {
    json diagnostics = json::array();
    for (const shaders::Diagnostic& d : error.diagnostics)
        diagnostics.push_back({{"file", d.file},
                               {"line", d.line},
                               {"column", d.column},
                               {"severity", shaders::severityName(d.severity)},
                               {"message", d.message}});
    json body{{"kind", failureName(error.failure)}, {"message", error.message}, {"diagnostics", diagnostics}};
    if (!error.keys.empty()) { // where the message names request keys, for the reader's own words
        json keys = json::array();
        for (const KeyMention& k : error.keys) keys.push_back({{"path", k.path}, {"at", k.offset}, {"length", k.length}});
        body["keys"] = keys;
    }
    return json{{"error", body}}.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string reportMessage(const std::string& reportJson) {
    std::string line = "{\"report\":";
    for (char c : reportJson)
        if (c != '\n') line += c; // the report's own JSON, on one line (newlines in it lie between tokens)
    return line + "}";
}

std::string endMessage(int exitCode) { return json{{"end", exitCode}}.dump(); }

WorkerMessage readWorkerMessage(const std::string& line) {
    WorkerMessage message;
    if (line.empty() || line.front() != '{') return message;
    const json in = json::parse(line, nullptr, false);
    if (!in.is_object() || in.size() != 1) return message;
    const std::string key = in.begin().key(); // (items()' proxy would dangle here: ASan saw it)
    const json& value = in.begin().value();
    if (key == "progress" && value.is_array() && value.size() == 2 && value[0].is_number_unsigned() &&
        value[1].is_number_unsigned()) {
        message.kind = WorkerMessage::Kind::Progress;
        message.done = value[0].get<std::uint64_t>();
        message.total = value[1].get<std::uint64_t>();
    } else if (key == "end" && value.is_number_integer()) {
        message.kind = WorkerMessage::Kind::End;
        message.exitCode = value.get<int>();
    } else if (key == "report" && value.is_object()) {
        message.kind = WorkerMessage::Kind::Report;
        message.report = value.dump();
    } else if (key == "error" && value.is_object()) {
        message.kind = WorkerMessage::Kind::Error;
        const std::string kind = value.value("kind", std::string("work"));
        for (Failure f : {Failure::Usage, Failure::Work, Failure::NoGl, Failure::Cancelled})
            if (kind == failureName(f)) message.error.failure = f;
        message.error.message = value.value("message", std::string());
        if (const auto it = value.find("diagnostics"); it != value.end() && it->is_array())
            for (const json& d : *it) {
                if (!d.is_object()) continue;
                shaders::Diagnostic diagnostic;
                diagnostic.file = d.value("file", std::string());
                diagnostic.line = d.value("line", 0);
                diagnostic.column = d.value("column", 0);
                const std::string severity = d.value("severity", std::string("error"));
                diagnostic.severity = severity == "warning" ? shaders::Severity::Warning
                                      : severity == "note"  ? shaders::Severity::Note
                                                            : shaders::Severity::Error;
                diagnostic.message = d.value("message", std::string());
                message.error.diagnostics.push_back(std::move(diagnostic));
            }
        if (const auto it = value.find("keys"); it != value.end() && it->is_array())
            for (const json& k : *it)
                if (k.is_object() && k.value("at", json()).is_number_unsigned() && k.value("length", json()).is_number_unsigned())
                    message.error.keys.push_back(
                        {k["at"].get<std::size_t>(), k["length"].get<std::size_t>(), k.value("path", std::string())});
    }
    return message;
}

} // namespace sdfwb::jobs
