// The job model's one JSON form: every request and report survives a round trip, malformed
// requests are refused naming the key, and the CLI's options make the same requests as JSON.
#include <jobs/JobJson.h>
#include <jobs/Jobs.h>
#include <jobs/Manifest.h>
#include <jobs/Protocol.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <unistd.h>

using namespace sdfwb;
using namespace sdfwb::jobs;
using namespace sdfwb::values;

namespace {

// A frame whose every field differs from its default, with floats that have no short decimal.
values::FrameRequest unusualFrame() {
    values::FrameRequest f;
    f.sdf = {"Torus",
             "map",
             "float map(vec3 p) { return length(p) - 0.1; }\n",
             {{"radius", {0.1f}}, {"offset", {1.0f / 3.0f, -2.0f, 1e-7f}}}};
    f.width = 333;
    f.height = 77;
    f.time = 1.0f / 3.0f;
    f.shading.mode = shaders::ShadingMode::Gooch;
    f.shading.ambientOcclusion = true;
    f.shading.background = {0.1f, 0.2f, 0.30000001f};
    f.shading.lightDirection = {0.0f, 1.0f, 1e-7f};
    f.shading.curvatureScale = 7.25f;
    f.shading.matcap = "jade";
    f.shading.markers = {{0.1f, -0.2f, 0.3f}, {1.0f / 7.0f, 0.0f, -1.0f}};
    f.trace.maxSteps = 999;
    f.trace.stepFactor = 0.7f;
    f.trace.epsilonScale = 0.125f;
    f.trace.boxMargin = 0.2f;
    f.trace.overRelaxation = 1.6f;
    f.trace.cones = values::TraceSettings::Cones::On;
    f.trace.tracer = values::TraceSettings::Tracer::Compute;
    f.camera.position = {3.0f, -2.0f, 1.0e-3f};
    f.camera.target = {0.1f, 0.2f, 0.3f};
    f.camera.up = {0.0f, 0.0f, 1.0f};
    f.camera.fovYDegrees = 55.5f;
    f.camera.nearPlane = 0.02f;
    f.camera.farPlane = 50.0f;
    f.plane.enabled = true;
    f.plane.normal = {1.0f, 2.0f, 3.0f};
    f.plane.offset = -0.25f;
    f.plane.contourSpacing = 0.03f;
    f.plane.rampDistance = 2.0f;
    f.plane.clipSurface = false;
    f.plane.lipschitzOverlay = false;
    return f;
}

std::vector<values::Request> unusualRequests() {
    values::RenderRequest render{unusualFrame(), "/tmp/out.exr"};
    values::AnimateRequest animate{unusualFrame(), "clip.mp4", 2.5f, 24, true, {{"radius", {0.7f}}, {"hollow", {1.0f}}}};
    values::SampleRequest sample;
    sample.sdf = {"a/b c.glsl", "scene", "", {}};
    sample.pattern = "metropolis_curvature";
    sample.count = 12345678901ull;
    sample.output = "s.npz";
    sample.format = "npz";
    sample.seed = 0xFFFFFFFFFFFFFFFFull; // the largest seed survives (no double in between)
    sample.time = 2.0f;
    sample.shardIndex = 3;
    sample.shardCount = 8;
    sample.chunkSize = 4096;
    sample.gradientStep = 1e-4f;
    sample.surfaceTolerance = 3e-6f;
    sample.family.sweeps = {{"radius", {0.1f}, {0.9f}, 5}, {"offset", {0.0f, 0.0f, 0.0f}, {1.0f / 3.0f, 1.0f, 2.0f}, 3}};
    values::AuditRequest audit;
    audit.sdf = {"Sphere", "", "float sdf(vec3 p) { return length(p) - 0.5; }", {}};
    audit.samples = 4096;
    audit.seed = 9;
    audit.time = 0.5f;
    audit.truncationReach = 1.5f;
    audit.plane = values::PlaneSpec{{0.0f, 1.0f, 0.0f}, 0.1f};
    audit.resolution = 64;
    audit.family.randomize = 77;
    values::MergeRequest merge{"all.ply", "ply", {"p0.ply", "p1.ply", "with \"quotes\" and \\.ply"}};
    values::BenchRequest bench{"report", 3, true, true};
    values::ParamsRequest params{{"family.glsl", "shape", "", {}}};
    values::MeshRequest mesh;
    mesh.sdf = {"Torus", "map", "", {{"radius", {0.25f}}}};
    mesh.output = "t.glb";
    mesh.resolution = 333;
    mesh.refine = 3;
    mesh.boundsMin = {-1.5f, -0.25f, -1.0f / 3.0f};
    mesh.boundsMax = {1.5f, 0.25f, 2.0f};
    mesh.time = 0.5f;
    mesh.lipschitz = 1.7f;
    mesh.errorSamples = 1234;
    mesh.seed = 77;
    values::EvalRequest eval;
    eval.sdf = {"Sphere", "", "", {}};
    eval.mesh = "prediction.obj";
    eval.points = 5000;
    eval.tau = 0.005f;
    eval.occupancyResolution = 0;
    eval.seed = 3;
    values::RunRequest run{"a b/shapes.csv", "status.jsonl", 12.5, 2, 5, {}, true, "/opt/sdfwb", "/usr/bin/python3"};
    values::RunRequest one{"m.jsonl", "", 0.0, 0, 1, {12345678901ull, 0, 7}, false, "", ""};
    values::ListRequest list{"my report.json"};
    return {render, animate, sample, audit, merge, values::ListRequest{}, list, bench, params, mesh, eval, run, one};
}

} // namespace

TEST(JobJson, EveryRequestKindSurvivesARoundTrip) {
    for (const values::Request& request : unusualRequests()) {
        for (int indent : {-1, 2}) {
            const std::string json = toJson(request, indent);
            auto back = requestFromJson(json);
            ASSERT_TRUE(back) << kindName(request) << ": " << back.error().message << "\n" << json;
            EXPECT_EQ(back->index(), request.index()) << json;
            EXPECT_TRUE(*back == request) << kindName(request) << " differs after the round trip:\n" << json;
            EXPECT_EQ(toJson(*back, indent), json);
        }
    }
}

TEST(JobJson, DefaultsFillAbsentKeysAndFloatsAreWrittenShort) {
    auto request = requestFromJson(R"({"kind": "render", "sdf": "Torus", "output": "t.png"})");
    ASSERT_TRUE(request) << request.error().message;
    values::RenderRequest expected;
    expected.frame.sdf.sdf = "Torus";
    expected.output = "t.png";
    EXPECT_TRUE(std::get<values::RenderRequest>(*request) == expected);
    const std::string json = toJson(*request);
    EXPECT_EQ(json.rfind(R"({"kind":"render")", 0), 0u) << json;       // the kind leads
    EXPECT_NE(json.find(R"("near":0.01)"), std::string::npos) << json; // not 0.009999999776482582
}

TEST(JobJson, MalformedRequestsAreRefusedNamingTheKey) {
    struct Case {
        const char* json;
        const char* expected;
    };
    const Case cases[] = {
        {R"({"sdf": "Torus"})", "missing \"kind\""},
        {R"({"kind": "paint"})", "unknown kind 'paint'"},
        {R"({"kind": "render", "widht": 3})", "'widht': unknown key"},
        {R"({"kind": "render", "shading": {"mode": "plaid"}})", "'shading.mode': expected a shading mode"},
        {R"({"kind": "render", "shading": {"markers": [[1, 2]]}})", "'shading.markers[0]': expected [x, y, z]"},
        {R"({"kind": "render", "trace": {"max_steps": 2.5}})", "'trace.max_steps': expected an integer"},
        {R"({"kind": "render", "trace": {"max_steps": 99999999999}})", "'trace.max_steps': expected an integer in range"},
        {R"({"kind": "render", "trace": {"tracer": "vertex"}})", "'trace.tracer': expected auto, fragment or compute"},
        {R"({"kind": "sample", "n": -1})", "'n': expected a non-negative integer"},
        {R"({"kind": "audit", "plane": [0, 0, 1]})", "'plane': expected [nx, ny, nz, offset]"},
        {R"({"kind": "merge", "parts": "a.ply"})", "'parts': expected an array"},
        {R"({"kind": "render", "camera": {"fov": "wide"}})", "'camera.fov': expected a number"},
        {R"({"kind": "render", "plane": {"enabled": 1}})", "'plane.enabled': expected true or false"},
        {R"([1, 2])", "expected a JSON object"},
        {R"({"kind": "render", )", "not valid JSON"},
        {R"({"kind": "sample", "surface_tolerance": 1e1000})", "not valid JSON"}, // a number beyond double
        {R"({"kind": "render", "params": [1]})", "'params': expected an object of parameter values"},
        {R"({"kind": "render", "params": {"radius": "big"}})", "'params.radius': expected a finite number"},
        {R"({"kind": "render", "params": {"radius": [1, 2, 3, 4, 5]}})", "'params.radius': expected a finite number"},
        {R"({"kind": "render", "params": {"2radius": 1}})", "'params.2radius': expected a parameter name"},
        {R"({"kind": "sample", "sweep": ["radius=1:2"]})", "'sweep[0]': 'radius=1:2': expected NAME=FROM:TO:COUNT"},
        {R"({"kind": "render", "camera": {"position": [1e39, 0, 0]}})", "'camera.position': expected [x, y, z] (finite)"},
    };
    for (const Case& c : cases) {
        auto request = requestFromJson(c.json);
        ASSERT_FALSE(request) << c.json;
        EXPECT_NE(request.error().message.find(c.expected), std::string::npos)
            << c.json << " -> " << request.error().message << " (expected " << c.expected << ")";
    }
}

TEST(JobJson, ReportsSurviveARoundTrip) {
    values::RenderReport render{
        {"/x/Torus.glsl", "sdf", {}, {"below float32 precision"}}, "a.png", 640, 360, "gooch", 12.5, 0.75, "llvmpipe"};
    auto r = reportFromJson<values::RenderReport>(toJson(render));
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_TRUE(*r == render);
    values::SampleReport sample;
    sample.output = "s.bin";
    sample.entry = "scene"; // the header's four keys travel in every report of one SDF
    sample.count = 1ull << 40;
    sample.rows = 5;
    sample.badRows = 2;
    sample.time = 0.1f;
    sample.samplesPerSecond = 1.5e7;
    sample.instances = {{"s_00000.bin", {{"radius", {0.1f}}, {"offset", {0.0f, 1.0f / 3.0f, 2.0f}}}, 5, 1, 0.25},
                        {"s_00001.bin", {{"radius", {0.9f}}, {"offset", {1.0f, 2.0f, 3.0f}}}, 5, 1, 0.5}};
    sample.index = "s_index.json";
    sample.warnings = {"parameter 'radius' = 2 lies outside its @range 0.1 0.9"};
    auto s = reportFromJson<values::SampleReport>(toJson(sample));
    ASSERT_TRUE(s) << s.error().message;
    EXPECT_TRUE(*s == sample);
    values::AuditJobReport family;
    family.sdf = "blend.glsl";
    family.entry = "map";
    family.truncationReach = 3.0f;
    using values::Finding;
    family.family = {
        {{{"stretch", {0.5f}}}, Finding::Conservative, "L <= 1", {}, 1.0f, 1.01f, 1e-3f, 0.4},
        {{{"stretch", {2.0f}}}, Finding::NonConservative, "L = 2", {Finding::NonConservative}, 2.0f, 2.1f, 0.3f, 0.2}};
    auto f = reportFromJson<values::AuditJobReport>(toJson(family));
    ASSERT_TRUE(f) << f.error().message;
    EXPECT_EQ(f->family, family.family);
    EXPECT_FALSE(f->volume);
    // Findings travel by their names (values::kFindingNames), and a name no finding has is
    // refused at its key.
    for (const auto& [finding, name] : values::kFindingNames) EXPECT_EQ(valueNamed(values::kFindingNames, name), finding);
    std::string misnamed = toJson(family);
    misnamed.replace(misnamed.find(R"("non-conservative")"), 18, R"("non-conservatory")");
    auto refusedFinding = reportFromJson<values::AuditJobReport>(misnamed);
    ASSERT_FALSE(refusedFinding);
    EXPECT_NE(refusedFinding.error().message.find("'family[1].verdict'"), std::string::npos) << refusedFinding.error().message;
    values::ListReport list{
        {{"Torus", "Geometry", "exact", "/d/Torus.glsl", "iq", "MIT", "", false}}, {"bad.glsl: no metadata"}, "/d"};
    auto l = reportFromJson<values::ListReport>(toJson(list));
    ASSERT_TRUE(l) << l.error().message;
    EXPECT_TRUE(*l == list);
    values::RunReport run;
    run.manifest = "shapes.csv";
    run.status = "shapes.csv.status-1-of-4.jsonl";
    run.rank = 1;
    run.worldSize = 4;
    run.items = 9;
    run.selected = 2;
    run.done = 1;
    run.failed = 1;
    run.seconds = 2.5;
    run.shapesPerHour = 1440.0;
    run.bytesWritten = 1ull << 33;
    run.results = {{1, 3, "sample", "torus", "out/t.npz", "00ff00ff00ff00ff", values::ItemStatus::Done, 1.25, 1ull << 33, 100, 2,
                    0, "", "2026-11-24T05:00:00Z"},
                   {5, 8, "deepsdf", "b.glsl", "out/b.npz", "0123456789abcdef", values::ItemStatus::Timeout, 30.0, 0, 0, 0, 137,
                    "killed after \"30 s\"", "2026-11-24T05:00:31Z"}};
    auto rr = reportFromJson<values::RunReport>(toJson(run));
    ASSERT_TRUE(rr) << rr.error().message;
    EXPECT_TRUE(*rr == run);
    auto line = reportFromJson<values::RunItemReport>(toJson(run.results[1], -1));
    ASSERT_TRUE(line) << line.error().message;
    EXPECT_TRUE(*line == run.results[1]);
    EXPECT_EQ(toJson(run.results[1], -1).find('\n'), std::string::npos); // one status-file line
    // Item statuses travel by their names (values::kItemStatusNames): a status file's line with a
    // status no item has is refused at its key.
    for (const auto& [status, name] : values::kItemStatusNames) EXPECT_EQ(valueNamed(values::kItemStatusNames, name), status);
    std::string unknownStatus = toJson(run.results[1], -1);
    unknownStatus.replace(unknownStatus.find(R"("timeout")"), 9, R"("timedout")");
    auto refusedStatus = reportFromJson<values::RunItemReport>(unknownStatus);
    ASSERT_FALSE(refusedStatus);
    EXPECT_NE(refusedStatus.error().message.find("'status'"), std::string::npos) << refusedStatus.error().message;
    // A probe's events and outcome travel by their names (MarchEvent's one table): every event
    // survives, and a name no event has is refused at its key.
    values::ProbeReport probe;
    probe.outcome = values::MarchEvent::OutOfSteps;
    for (const auto& [event, name] : values::kMarchEventNames) {
        values::ProbeStep step;
        step.event = event;
        step.t = 0.5f;
        probe.events.push_back(step);
        EXPECT_EQ(parseMarchEvent(name), event);
    }
    const std::string probeJson = toJson(probe);
    EXPECT_NE(probeJson.find(R"("refine undone")"), std::string::npos) << probeJson;
    auto pr = reportFromJson<values::ProbeReport>(probeJson);
    ASSERT_TRUE(pr) << pr.error().message;
    EXPECT_TRUE(*pr == probe);
    std::string renamed = probeJson;
    renamed.replace(renamed.find(R"("missed the box")"), 16, R"("missed the bus")");
    auto refused = reportFromJson<values::ProbeReport>(renamed);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("'events[9].event'"), std::string::npos) << refused.error().message;
    // Reports grow: a key this build does not know is skipped, not refused.
    auto grown =
        reportFromJson<values::MergeReport>(R"({"output": "m.bin", "rows": 7, "parts": 2, "seconds": 0.5, "new_figure": 1})");
    ASSERT_TRUE(grown) << grown.error().message;
    EXPECT_EQ(grown->rows, 7u);
}

TEST(JobJson, AuditReportsKeepEveryFindingAndFigure) {
    values::AuditJobReport volume;
    volume.sdf = "broken.glsl";
    volume.entry = "map";
    volume.truncationReach = 2.0f;
    values::AuditReport a;
    a.verdict = values::Finding::Discontinuous;
    a.reason = "f jumps";
    a.flags.push_back(
        {values::Finding::Discontinuous, "jumps of 0.2", 0.2f, 0.4f, 0.0f, 0.01, 37, {{0.1f, 0.2f, 0.3f}, {-1.0f, 0.0f, 0.5f}}});
    a.flags.push_back({values::Finding::Truncated, "plateau at 0.3", 0.3f, 0.0f, 0.25f, 0.5, 0, {}});
    a.lipschitz = 1.25f;
    a.truncationDistance = 0.3f;
    a.scales = {{0.02f, 1.0f, 1.1f, 1.2f, 3.0f}};
    a.convergence = {{1000, 1.2f, 0.01f, 0.5}};
    a.samples = 100000;
    volume.volume = a;
    const std::string json = toJson(volume);
    EXPECT_NE(json.find("\"jump_max\": 0.4"), std::string::npos) << json; // the flag's named figures
    auto back = reportFromJson<values::AuditJobReport>(json);
    ASSERT_TRUE(back) << back.error().message;
    ASSERT_TRUE(back->volume);
    EXPECT_FALSE(back->readout);
    EXPECT_EQ(back->volume->flags.size(), 2u);
    EXPECT_EQ(back->volume->flags[0].examples.size(), 2u);
    EXPECT_EQ(back->volume->flags[0].count, 37u);
    EXPECT_EQ(toJson(*back), json);

    values::AuditJobReport plane;
    plane.sdf = "Sphere";
    plane.plane = values::PlaneSpec{{0.0f, 0.0f, 1.0f}, 0.5f};
    values::PlaneReadout readout;
    readout.resolution = 64;
    readout.histogram = {1, 2, 3};
    readout.flags = a.flags;
    plane.readout = readout;
    const std::string planeJson = toJson(plane);
    auto planeBack = reportFromJson<values::AuditJobReport>(planeJson);
    ASSERT_TRUE(planeBack) << planeBack.error().message;
    ASSERT_TRUE(planeBack->readout);
    EXPECT_FALSE(planeBack->volume);
    EXPECT_EQ(planeBack->readout->histogram, readout.histogram);
    EXPECT_FALSE(planeBack->readout->truncationDistance);
    EXPECT_EQ(toJson(*planeBack), planeJson);
}

// The library names the request's key ('fps'), as a JSON or Python caller wrote it; the CLI says
// --fps (tests/app check its messages).
// The list job adds the dataset report's measured types and render times to the entries of the
// same name (the workbench's dataset browser shows them), and says why a report could not be used.
TEST(Jobs, TheListCarriesTheDatasetReportsMeasurements) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("sdfwb-list-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const std::filesystem::path good = folder / "report.json", bad = folder / "bad.json";
    std::FILE* file = std::fopen(good.c_str(), "w");
    ASSERT_NE(file, nullptr);
    std::fputs(R"({"machine": "test machine", "date": "2026-11-26", "sdfs": [
        {"name": "Torus", "measured_type": "exact", "render_ms": 12.5}, {"name": "Nothing", "measured_type": "nan"}]})",
               file);
    std::fclose(file);
    file = std::fopen(bad.c_str(), "w");
    std::fputs("{\"sdfs\": 3", file);
    std::fclose(file);

    auto listed = run(values::ListRequest{good.string()}, {});
    ASSERT_TRUE(listed) << listed.error.message;
    EXPECT_EQ(listed->report, good.string());
    EXPECT_EQ(listed->measuredOn, "test machine");
    EXPECT_EQ(listed->measuredDate, "2026-11-26");
    int measured = 0;
    for (const values::ListItem& item : listed->items) {
        if (item.name == "Torus") {
            EXPECT_EQ(item.measuredType, "exact");
            ASSERT_TRUE(item.renderMilliseconds.has_value());
            EXPECT_DOUBLE_EQ(*item.renderMilliseconds, 12.5);
        }
        measured += !item.measuredType.empty();
    }
    EXPECT_EQ(measured, 1) << "only the entry the report names is measured";
    auto back = reportFromJson<values::ListReport>(toJson(*listed));
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_TRUE(*back == *listed);

    auto broken = run(values::ListRequest{bad.string()}, {});
    ASSERT_TRUE(broken) << "a bad report does not stop the list";
    EXPECT_TRUE(broken->report.empty());
    ASSERT_FALSE(broken->problems.empty());
    EXPECT_NE(broken->problems.back().find("bad.json: not a JSON object"), std::string::npos) << broken->problems.back();
    for (const values::ListItem& item : broken->items) EXPECT_TRUE(item.measuredType.empty());
    std::filesystem::remove_all(folder);
}

TEST(Jobs, ValidationNamesTheArgumentBeforeAnyWork) {
    values::AnimateRequest animate;
    animate.frame.sdf.sdf = "Torus";
    animate.output = "clip.mp4";
    animate.framesPerSecond = 0;
    auto error = validate(animate);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->failure, Failure::Usage);
    EXPECT_NE(error->message.find("'fps'"), std::string::npos) << error->message;

    values::RenderRequest render;
    render.frame.sdf.sdf = "Torus";
    render.output = "picture.xyz";
    error = validate(render);
    ASSERT_TRUE(error);
    EXPECT_NE(error->message.find("unsupported image type '.xyz'"), std::string::npos) << error->message;
    render.output = "picture.png";
    render.frame.plane.enabled = true;
    render.frame.plane.normal = glm::vec3(0.0f);
    error = validate(render);
    ASSERT_TRUE(error);
    EXPECT_NE(error->message.find("'plane'"), std::string::npos) << error->message;
    render.frame.plane.normal = {0.0f, 0.0f, 1.0f};
    render.frame.sdf.sdf = "No Such Shape";
    error = validate(render);
    ASSERT_TRUE(error);
    EXPECT_NE(error->message.find("'sdf'"), std::string::npos) << error->message;
    render.frame.sdf.sdf = "Torus";
    render.frame.sdf.entry = "sdfwb_sdf";
    error = validate(render);
    ASSERT_TRUE(error);
    EXPECT_NE(error->message.find("reserved"), std::string::npos) << error->message;
    render.frame.sdf.entry = "";
    EXPECT_FALSE(validate(render)) << validate(render)->message;

    // Source text with no file is valid: the workbench's untitled buffer, Python's strings.
    values::AuditRequest audit;
    audit.sdf.source = "float sdf(vec3 p) { return length(p) - 0.5; }";
    EXPECT_FALSE(validate(audit));
    audit.samples = 10;
    error = validate(audit);
    ASSERT_TRUE(error);
    EXPECT_NE(error->message.find("'samples'"), std::string::npos) << error->message;
}

TEST(Jobs, OpenSdfUsesTheGivenTextNotTheFile) {
    values::SdfInput input{"Torus", "", "float sdf(vec3 p) { return length(p) - 0.25; }\n", {}};
    auto opened = openSdf(input, "test");
    ASSERT_TRUE(opened) << opened.error.message;
    EXPECT_NE(opened->label.find("Torus.glsl"), std::string::npos) << opened->label; // labelled by the file
    EXPECT_NE(opened->prepared.source.text.find("0.25"), std::string::npos);         // but the given text
    opened = openSdf(values::SdfInput{"", "nothere", "float sdf(vec3 p) { return 1.0; }", {}}, "render");
    ASSERT_FALSE(opened);
    EXPECT_EQ(opened.error.failure, Failure::Work);
    EXPECT_FALSE(opened.error.diagnostics.empty());
    EXPECT_NE(opened.error.message.find("nothing written"), std::string::npos) << opened.error.message;
}

namespace {

// What `sdfwb ARGUMENTS` prints on stdout.
std::string standardOutput(const std::string& arguments) {
    const std::string command = "env -u DISPLAY " + std::string(SDFWB_BINARY) + " " + arguments + " 2>/dev/null";
    std::string output;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return output;
    std::array<char, 4096> buffer;
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) output.append(buffer.data(), n);
    pclose(pipe);
    return output;
}

} // namespace

// The CLI's options and the JSON form make the same request: what --print-request prints reads
// back as the request the options describe, field by field.
TEST(JobJson, CommandLineOptionsMakeTheSameRequestAsJson) {
    values::RenderRequest render;
    render.frame.sdf = {"Torus", "map", "", {}};
    render.output = "/tmp/x.png";
    render.frame.width = 320;
    render.frame.height = 200;
    render.frame.time = 1.5f;
    render.frame.shading.mode = shaders::ShadingMode::Gooch;
    render.frame.shading.ambientOcclusion = true;
    render.frame.shading.matcap = "jade";
    render.frame.camera.position = {3.0f, 2.0f, 1.0f};
    render.frame.camera.target = {0.1f, 0.0f, 0.0f};
    render.frame.camera.fovYDegrees = 50.0f;
    render.frame.trace.maxSteps = 300;
    render.frame.trace.stepFactor = 0.8f;
    render.frame.trace.overRelaxation = 1.5f;
    render.frame.plane.enabled = true;
    render.frame.plane.normal = {0.0f, 1.0f, 0.0f};
    render.frame.plane.offset = 0.25f;
    render.frame.plane.clipSurface = false;
    render.frame.plane.contourSpacing = 0.05f;
    auto parsed = requestFromJson(standardOutput(
        "--batch render --sdf Torus --entry map --output /tmp/x.png --size 320x200 --time 1.5 --shading gooch --ao --matcap jade "
        "--camera 3,2,1 --target 0.1,0,0 --fov 50 --max-steps 300 --step-factor 0.8 --relaxation 1.5 --plane 0,1,0,0.25 "
        "--plane-no-clip --contour-spacing 0.05 --print-request"));
    ASSERT_TRUE(parsed) << parsed.error().message;
    EXPECT_TRUE(*parsed == values::Request(render)) << toJson(*parsed, 2) << "\nexpected\n" << toJson(render, 2);

    values::AnimateRequest animate;
    animate.frame.sdf.sdf = "Sphere";
    animate.output = "/tmp/x.mp4";
    animate.seconds = 0.5f;
    animate.framesPerSecond = 12;
    animate.turntable = true;
    parsed = requestFromJson(
        standardOutput("--batch animate --sdf Sphere --output /tmp/x.mp4 --seconds 0.5 --fps 12 --turntable --print-request"));
    ASSERT_TRUE(parsed) << parsed.error().message;
    EXPECT_TRUE(*parsed == values::Request(animate)) << toJson(*parsed, 2);

    values::SampleRequest sample;
    sample.sdf.sdf = "Sphere";
    sample.pattern = "near";
    sample.count = 1000;
    sample.output = "/tmp/x.npz";
    sample.seed = 7;
    sample.time = 0.5f;
    sample.shardIndex = 1;
    sample.shardCount = 4;
    sample.chunkSize = 512;
    sample.gradientStep = 1e-4f;
    sample.surfaceTolerance = 1e-6f;
    parsed = requestFromJson(
        standardOutput("--batch sample --sdf Sphere --pattern near -n 1000 --output /tmp/x.npz --seed 7 --time 0.5 "
                       "--shard 1/4 --chunk 512 --gradient-step 1e-4 --surface-tolerance 1e-6 --print-request"));
    ASSERT_TRUE(parsed) << parsed.error().message;
    EXPECT_TRUE(*parsed == values::Request(sample)) << toJson(*parsed, 2);

    values::AuditRequest audit;
    audit.sdf = {"Sphere", "sdf", "", {}};
    audit.samples = 1000;
    audit.seed = 3;
    audit.truncationReach = 2.0f;
    audit.plane = values::PlaneSpec{{1.0f, 0.0f, 0.0f}, 0.5f};
    audit.resolution = 64;
    parsed = requestFromJson(standardOutput("--batch audit --sdf Sphere --entry sdf --samples 1000 --seed 3 --probe-distance 2 "
                                            "--plane 1,0,0,0.5 --resolution 64 --print-request"));
    ASSERT_TRUE(parsed) << parsed.error().message;
    EXPECT_TRUE(*parsed == values::Request(audit)) << toJson(*parsed, 2);

    values::RunRequest run;
    run.manifest = "shapes.jsonl";
    run.status = "/tmp/s.jsonl";
    run.itemTimeout = 90.0;
    run.rank = 3;
    run.worldSize = 4;
    run.list = true;
    parsed = requestFromJson(standardOutput("--batch run shapes.jsonl --status /tmp/s.jsonl --item-timeout 90 --rank 3 "
                                            "--world-size 4 --list --print-request"));
    ASSERT_TRUE(parsed) << parsed.error().message;
    EXPECT_TRUE(*parsed == values::Request(run)) << toJson(*parsed, 2);

    // And back: the printed JSON, given to `--batch request`, prints the same request again.
    const std::string printed = toJson(values::Request(audit), 2);
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("sdfwb-jobs-" + std::to_string(::getpid()) + ".json");
    {
        FILE* out = std::fopen(file.c_str(), "w");
        ASSERT_TRUE(out);
        std::fputs(printed.c_str(), out);
        std::fclose(out);
    }
    EXPECT_EQ(standardOutput("--batch request " + file.string() + " --print-request"), printed + "\n");
    std::filesystem::remove(file);
}

namespace {

void writeText(const std::filesystem::path& path, const std::string& text) {
    FILE* out = std::fopen(path.c_str(), "w");
    ASSERT_TRUE(out);
    std::fputs(text.c_str(), out);
    std::fclose(out);
}

} // namespace

TEST(Manifest, CsvAndJsonLinesMakeTheSameItemsWithPathsFromTheManifestsFolder) {
    const auto folder = std::filesystem::temp_directory_path() / ("sdfwb-manifest-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    writeText(folder / "mine.glsl", "uniform float radius = 0.5;\nfloat map(vec3 p) { return length(p) - radius; }\n");
    // Quoted cells with commas and a doubled quote, a comment, a blank line, spaces, CRLF endings.
    writeText(folder / "shapes.csv", "sdf, pattern ,n,seed,params,output,near_widths,entry\r\n"
                                     "# a comment\r\n"
                                     "mine.glsl,near,100,7,\"radius=0.3;offset=1,2,3\",out/a.npz,\"0.005:0.8,0.05:0.2\",map\r\n"
                                     "\r\n"
                                     "Sphere,rand,5,,,\"b \"\"quoted\"\".ply\",,\r\n"
                                     "torus,,,,,c.npz,,\r\n");
    writeText(folder / "shapes.jsonl",
              "{\"sdf\": \"mine.glsl\", \"pattern\": \"near\", \"n\": 100, \"seed\": 7, \"params\": {\"radius\": 0.3, "
              "\"offset\": [1, 2, 3]}, \"output\": \"out/a.npz\", \"near_widths\": \"0.005:0.8,0.05:0.2\", \"entry\": \"map\"}\n"
              "{\"sdf\": \"Sphere\", \"pattern\": \"rand\", \"n\": 5, \"output\": \"b \\\"quoted\\\".ply\"}\n"
              "{\"recipe\": \"occnet\", \"sdf\": \"torus\", \"output\": \"c.npz\", \"padding\": 0.2}\n");
    auto csv = readManifest((folder / "shapes.csv").string());
    EXPECT_FALSE(csv) << "the third row has no pattern and no n";
    if (!csv) {
        EXPECT_NE(csv.error().message.find("shapes.csv:6: missing \"pattern\""), std::string::npos) << csv.error().message;
    }
    writeText(folder / "shapes.csv", "sdf, pattern ,n,seed,params,output,near_widths,entry,recipe,padding\r\n"
                                     "# a comment\r\n"
                                     "mine.glsl,near,100,7,\"radius=0.3;offset=1,2,3\",out/a.npz,\"0.005:0.8,0.05:0.2\",map,,\r\n"
                                     "\r\n"
                                     "Sphere,rand,5,,,\"b \"\"quoted\"\".ply\",,,,\r\n"
                                     "torus,,,,,c.npz,,,occnet,0.2\r\n");
    csv = readManifest((folder / "shapes.csv").string());
    auto jsonl = readManifest((folder / "shapes.jsonl").string());
    ASSERT_TRUE(csv) << csv.error().message;
    ASSERT_TRUE(jsonl) << jsonl.error().message;
    ASSERT_EQ(csv->size(), 3u);
    ASSERT_EQ(jsonl->size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ((*csv)[i].index, i);
        EXPECT_EQ((*csv)[i].kind, (*jsonl)[i].kind);
        EXPECT_EQ((*csv)[i].output, (*jsonl)[i].output);
        if ((*csv)[i].kind == "sample") { // a recipe's JSON keeps its key order; a request's is canonical
            EXPECT_EQ((*csv)[i].childInput, (*jsonl)[i].childInput);
            EXPECT_EQ((*csv)[i].key, (*jsonl)[i].key);
        }
    }
    EXPECT_EQ((*csv)[0].line, 3);
    EXPECT_EQ((*csv)[1].line, 5);
    EXPECT_EQ((*csv)[2].line, 6);
    EXPECT_EQ((*jsonl)[2].line, 3);
    EXPECT_EQ((*csv)[0].sdf, (folder / "mine.glsl").string()); // beside the manifest
    EXPECT_EQ((*csv)[1].sdf, "Sphere");                        // a dataset name stays a name
    EXPECT_EQ((*csv)[0].output, (folder / "out/a.npz").string());
    EXPECT_EQ((*csv)[1].output, (folder / "b \"quoted\".ply").string());
    EXPECT_EQ((*csv)[2].kind, "occnet");
    auto request = requestFromJson((*csv)[0].childInput);
    ASSERT_TRUE(request) << request.error().message;
    const auto& sample = std::get<values::SampleRequest>(*request);
    EXPECT_EQ(sample.sdf.entry, "map");
    EXPECT_EQ(sample.seed, 7u);
    ASSERT_EQ(sample.sdf.params.size(), 2u);
    EXPECT_EQ(sample.sdf.params[1].value, (std::vector<float>{1.0f, 2.0f, 3.0f}));
    EXPECT_EQ(sample.nearWidths, "0.005:0.8,0.05:0.2");
    // Another seed is another item: its key changes, the others' do not.
    writeText(folder / "other.jsonl", "{\"sdf\": \"mine.glsl\", \"pattern\": \"near\", \"n\": 100, \"seed\": 8, \"params\": "
                                      "{\"radius\": 0.3, \"offset\": [1, 2, 3]}, \"output\": \"out/a.npz\", \"near_widths\": "
                                      "\"0.005:0.8,0.05:0.2\", \"entry\": \"map\"}\n");
    auto other = readManifest((folder / "other.jsonl").string());
    ASSERT_TRUE(other) << other.error().message;
    EXPECT_NE((*other)[0].key, (*jsonl)[0].key);
    std::filesystem::remove_all(folder);
}

// The worker protocol (jobs/Protocol.h): every message reads back as it was written, a report
// pretty-printed over many lines travels on one, and lines that are not messages are skipped.
TEST(WorkerProtocol, MessagesReadBackAsTheyWereWritten) {
    const WorkerMessage progress = readWorkerMessage(progressMessage(3, 40));
    EXPECT_EQ(progress.kind, WorkerMessage::Kind::Progress);
    EXPECT_EQ(progress.done, 3u);
    EXPECT_EQ(progress.total, 40u);
    JobError error{Failure::Usage, "--size: expected WxH, got 'x'", {}, {}};
    error.diagnostics.push_back({"scene.glsl", 12, 7, shaders::Severity::Error, "'q' : undeclared identifier"});
    error.diagnostics.push_back({"scene.glsl", 3, 0, shaders::Severity::Warning, "unused \"r\"\nsecond line"});
    const WorkerMessage failed = readWorkerMessage(errorMessage(error));
    ASSERT_EQ(failed.kind, WorkerMessage::Kind::Error);
    EXPECT_EQ(failed.error.failure, Failure::Usage);
    EXPECT_EQ(failed.error.message, error.message);
    ASSERT_EQ(failed.error.diagnostics.size(), 2u);
    EXPECT_EQ(failed.error.diagnostics[0].file, "scene.glsl");
    EXPECT_EQ(failed.error.diagnostics[0].line, 12);
    EXPECT_EQ(failed.error.diagnostics[0].column, 7);
    EXPECT_EQ(failed.error.diagnostics[1].severity, shaders::Severity::Warning);
    EXPECT_EQ(failed.error.diagnostics[1].message, "unused \"r\"\nsecond line");
    for (Failure kind : {Failure::Work, Failure::NoGl, Failure::Cancelled})
        EXPECT_EQ(readWorkerMessage(errorMessage({kind, "m", {}, {}})).error.failure, kind);
    values::ListReport list;
    values::ListItem torus;
    torus.name = "Torus";
    torus.category = "Geometry";
    list.items.push_back(torus);
    const std::string pretty = toJson(list, 2);
    ASSERT_NE(pretty.find('\n'), std::string::npos);
    const std::string line = reportMessage(pretty);
    EXPECT_EQ(line.find('\n'), std::string::npos);
    const WorkerMessage report = readWorkerMessage(line);
    ASSERT_EQ(report.kind, WorkerMessage::Kind::Report);
    auto back = reportFromJson<values::ListReport>(report.report);
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_EQ(*back, list);
    const WorkerMessage end = readWorkerMessage(endMessage(130));
    EXPECT_EQ(end.kind, WorkerMessage::Kind::End);
    EXPECT_EQ(end.exitCode, 130);
    for (const char* other : {"", "progress 3 40", "end 0", "{\"progress\":[1]}", "{\"end\":0,\"x\":1}", "{bad", "[1,2]"})
        EXPECT_EQ(readWorkerMessage(other).kind, WorkerMessage::Kind::Other) << other;
}

// `sdfwb --batch request - --protocol --each-line` answers each request line in the protocol: a
// report and {"end":0}; a request it cannot read, a usage error and {"end":2}; an SDF whose
// parameter annotations are broken, a work error with the diagnostic's file and line.
TEST(WorkerProtocol, TheCommandLineAnswersEveryRequestInTheProtocol) {
    const std::filesystem::path input = std::filesystem::temp_directory_path() / ("sdfwb-protocol-" + std::to_string(::getpid()));
    {
        std::FILE* file = std::fopen(input.c_str(), "w");
        ASSERT_NE(file, nullptr);
        std::fputs("{\"kind\":\"list\"}\n{\"kind\":\"bogus\"}\n", file);
        std::fputs("{\"kind\":\"params\",\"sdf\":\"bad.glsl\",\"source\":\"uniform float r; // @range 1 0\\n"
                   "float sdf(vec3 p) { return length(p) - r; }\"}\n",
                   file);
        std::fclose(file);
    }
    const std::string output = standardOutput("--batch request - --protocol --each-line --quiet < " + input.string());
    std::filesystem::remove(input);
    std::vector<WorkerMessage> messages;
    std::size_t start = 0;
    for (std::size_t end; (end = output.find('\n', start)) != std::string::npos; start = end + 1) {
        WorkerMessage message = readWorkerMessage(output.substr(start, end - start));
        EXPECT_NE(message.kind, WorkerMessage::Kind::Other) << output.substr(start, end - start);
        messages.push_back(std::move(message));
    }
    ASSERT_EQ(messages.size(), 6u) << output;
    EXPECT_EQ(messages[0].kind, WorkerMessage::Kind::Report);
    auto list = reportFromJson<values::ListReport>(messages[0].report);
    ASSERT_TRUE(list) << list.error().message;
    EXPECT_EQ(list->items.size(), 78u);
    EXPECT_EQ(messages[1].kind, WorkerMessage::Kind::End);
    EXPECT_EQ(messages[1].exitCode, 0);
    ASSERT_EQ(messages[2].kind, WorkerMessage::Kind::Error);
    EXPECT_EQ(messages[2].error.failure, Failure::Usage);
    EXPECT_NE(messages[2].error.message.find("bogus"), std::string::npos);
    EXPECT_EQ(messages[3].exitCode, 2);
    ASSERT_EQ(messages[4].kind, WorkerMessage::Kind::Error) << output;
    EXPECT_EQ(messages[4].error.failure, Failure::Work);
    ASSERT_FALSE(messages[4].error.diagnostics.empty()) << messages[4].error.message;
    EXPECT_EQ(messages[4].error.diagnostics[0].line, 1);
    EXPECT_EQ(messages[5].kind, WorkerMessage::Kind::End);
    EXPECT_EQ(messages[5].exitCode, 1);
}

// `--batch grade` grades a mesh; `eval`, its old name, still works and makes the same request,
// whose JSON kind is "grade" ("eval" is read too).
TEST(JobJson, GradeIsTheMeshGradersNameAndEvalItsAlias) {
    const std::string args = " --sdf torus --mesh /tmp/m.ply --tau 0.02 --print-request";
    const std::string graded = standardOutput("--batch grade" + args), old = standardOutput("--batch eval" + args);
    ASSERT_FALSE(graded.empty());
    EXPECT_EQ(graded, old);
    EXPECT_NE(graded.find("\"kind\": \"grade\""), std::string::npos) << graded;
    auto fromOld = requestFromJson(R"({"kind": "eval", "sdf": "torus", "mesh": "/tmp/m.ply"})");
    ASSERT_TRUE(fromOld) << fromOld.error().message;
    EXPECT_TRUE(std::holds_alternative<values::EvalRequest>(*fromOld));
    const std::string help = standardOutput("--help");
    EXPECT_NE(help.find("  grade "), std::string::npos);
}

// A library's usage error names the request's key. A JSON request's failure keeps its keys, on
// stderr and in the worker protocol alike: its writer wrote 'fps', not --fps (the command line's
// options name their own: tests/app/test_cli.cpp, FailuresNameTheOptionsThatSetTheirKeys).
TEST(Jobs, AJsonRequestsFailureNamesItsOwnKeys) {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / ("sdfwb-keys-" + std::to_string(::getpid()));
    auto stderrOf = [&](const std::string& request, const std::string& flags) {
        std::FILE* out = std::fopen(file.c_str(), "w");
        std::fputs(request.c_str(), out);
        std::fclose(out);
        const std::string command =
            "env -u DISPLAY " + std::string(SDFWB_BINARY) + " --batch request " + file.string() + " " + flags + " 2>&1";
        std::string output;
        FILE* pipe = popen(command.c_str(), "r");
        std::array<char, 4096> buffer;
        while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) output.append(buffer.data(), n);
        pclose(pipe);
        return output;
    };
    const std::string animate = R"({"kind": "animate", "sdf": "Sphere", "output": "/tmp/x.mp4", "fps": 0})";
    EXPECT_EQ(stderrOf(animate, ""), "sdfwb: 'fps': must be 1..240\n");
    const std::string render = R"({"kind": "render", "sdf": "Sphere", "output": "/tmp/x.png", "width": 0})";
    EXPECT_EQ(stderrOf(render, ""), "sdfwb: 'width', 'height': expected WxH with integers from 1 to 16384, got '0x720'\n");
    const std::string sample = R"({"kind": "sample", "sdf": "Sphere", "pattern": "rand", "n": 10, "output": "/tmp/x.npz",
                                   "shard_index": 3, "shard_count": 2})";
    EXPECT_EQ(stderrOf(sample, "").find("--shard"), std::string::npos) << stderrOf(sample, "");
    EXPECT_NE(stderrOf(sample, "").find("'shard_index', 'shard_count': "), std::string::npos) << stderrOf(sample, "");
    const std::string viaProtocol = stderrOf(animate, "--protocol");
    EXPECT_NE(viaProtocol.find("'fps': must be 1..240"), std::string::npos) << viaProtocol;
    EXPECT_EQ(viaProtocol.find("--fps"), std::string::npos) << viaProtocol;
    std::filesystem::remove(file);
}
