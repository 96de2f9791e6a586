// A mesh file through the job layer: the same files for every chunk size, every job (render, sample,
// audit, mesh) on a mesh and mesh options refused on GLSL files, and the mesh's provenance in every
// output.
#include "MeshSdfTesting.h"

namespace sdfwb::meshsdftest {
namespace {

TEST_F(MeshSdfTest, FilesFromTheCpuEngineAreTheSameForEveryChunkSize) {
    const fs::path folder = fs::temp_directory_path() / ("sdfwb_meshengine_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    auto field = meshfield::makeMeshField(testing::torusMesh(0.6f, 0.25f, 48, 16), "torus.obj", {});
    ASSERT_TRUE(field.hasValue());
    const shaders::PreparedSdf sdf = shaders::prepareMeshSdf(*field, "torus.obj");
    EngineScope scope("cpu");
    for (const char* extension : {".npz", ".ply"}) {
        std::vector<std::string> contents;
        for (std::uint32_t chunk : {1000u, 1u << 18}) {
            renderer::SampleCompute compute;
            auto sampler = sampling::findSampler("near", sampling::samplerFolders());
            ASSERT_TRUE(sampler.hasValue());
            ASSERT_FALSE(shaders::hasErrors(compute.build(sdf, *sampler)));
            EXPECT_STREQ(compute.meshEngine(), "cpu");
            sampling::SamplingJob job;
            job.count = 9000;
            job.chunkSize = chunk;
            const fs::path path = folder / ("rows_" + std::to_string(chunk) + extension);
            auto report = sampling::sampleToFile(compute, job, path, *sampling::formatFromPath(path), {}, {});
            ASSERT_TRUE(report.hasValue()) << report.error().message;
            EXPECT_EQ(report->badRows, 0u);
            std::ifstream in(path, std::ios::binary);
            contents.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
            compute.releaseGl();
        }
        EXPECT_GT(contents[0].size(), 9000u * 28u) << extension;
        EXPECT_TRUE(contents[0] == contents[1]) << extension << ": the file depends on the chunk size";
    }
    fs::remove_all(folder);
}

TEST_F(MeshSdfTest, AMeshFileIsAnSdfForEveryJobAndMeshOptionsAreRefusedElsewhere) {
    const fs::path folder = fs::temp_directory_path() / ("sdfwb_meshsdf_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    const meshfield::TriangleMesh mesh = testing::torusMesh(0.6f, 0.25f, 48, 16);
    testing::writeObj(folder / "torus.obj", mesh);
    values::SdfInput input;
    input.sdf = (folder / "torus.obj").string();
    input.sign = "pseudonormal";
    input.normalize = "unit-sphere";
    auto opened = jobs::openSdf(input, "sample");
    ASSERT_TRUE(bool(opened)) << opened.error.message;
    ASSERT_TRUE(opened->prepared.mesh);
    EXPECT_EQ(opened->prepared.mesh->options.sign, meshfield::SignMethod::Pseudonormal);
    EXPECT_NEAR(opened->prepared.mesh->transform[0], 1.0 / 0.85, 1e-4); // the farthest vertex is 0.85 out
    EXPECT_EQ(opened->prepared.signature.entry, "sdf");

    // A sample job on the mesh: the torus's inside (scaled by 1/0.85) comes out negative.
    values::SampleRequest sample;
    sample.sdf = input;
    sample.count = 4096;
    sample.pattern = "rand";
    sample.output = (folder / "torus.npz").string();
    ASSERT_FALSE(jobs::validate(sample).has_value());
    auto report = jobs::run(sample, {});
    ASSERT_TRUE(bool(report)) << report.error.message;
    EXPECT_TRUE(fs::exists(folder / "torus.npz"));

    // The user's own text over the mesh: an offset surface, the mesh attached.
    values::SdfInput offset = input;
    offset.source = "float sdf(vec3 p) { return sdfwb_meshSdf(p) - 0.05; }\n";
    auto shell = jobs::openSdf(offset, "sample");
    ASSERT_TRUE(bool(shell)) << shell.error.message;
    const std::vector<float> point = {0.6f / 0.85f, 0.0f, 0.0f}; // the tube's centre, after the scaling
    const std::vector<float> plain = evaluate(opened->prepared, point);
    const std::vector<float> thicker = evaluate(shell->prepared, point);
    // the tube's inscribed 16-gon: r cos(pi/16), scaled
    EXPECT_NEAR(plain[0], -0.25f * std::cos(3.14159265f / 16.0f) / 0.85f, 1e-3f);
    EXPECT_NEAR(thicker[0], plain[0] - 0.05f, 1e-5f);

    values::SdfInput glsl;
    glsl.sdf = "sphere";
    glsl.sign = "parity";
    auto refused = jobs::openSdf(glsl, "sample");
    ASSERT_FALSE(bool(refused));
    EXPECT_NE(refused.error.message.find("'sign'"), std::string::npos) << refused.error.message;
    values::SdfInput badSign = input;
    badSign.sign = "inside";
    values::SampleRequest badRequest = sample;
    badRequest.sdf = badSign;
    auto bad = jobs::validate(badRequest);
    ASSERT_TRUE(bad.has_value());
    EXPECT_NE(bad->message.find("'sign'"), std::string::npos) << bad->message;
    fs::remove_all(folder);
}

// Every output of a job on a mesh says where its field came from (the file, the sign method, the
// normalisation's transform and the file's bounds): each report as "mesh_source", and the files
// themselves (PNG and EXR attributes, MP4 tags, PLY and OBJ comments; samples are tested with
// their formats). A GLSL SDF's reports carry null.
TEST_F(MeshSdfTest, EveryOutputOfAJobOnAMeshCarriesTheMeshsProvenance) {
    const fs::path folder = fs::temp_directory_path() / ("sdfwb_meshsource_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    const meshfield::TriangleMesh mesh = testing::torusMesh(0.6f, 0.25f, 24, 12);
    testing::writeObj(folder / "torus.obj", mesh);
    values::SdfInput input;
    input.sdf = (folder / "torus.obj").string();
    input.sign = "parity";
    input.normalize = "unit-sphere";
    // The provenance a report or file carries, checked against the mesh as written.
    auto checkSource = [&](const std::string& text, const std::string& where) {
        SCOPED_TRACE(where);
        ASSERT_FALSE(text.empty());
        const std::string expected =
            (*meshfield::loadMeshField(input.sdf, {meshfield::SignMethod::Parity, meshfield::Normalization::UnitSphere}))
                ->provenanceJson();
        EXPECT_EQ(text, expected);
        EXPECT_NE(text.find("\"sign\": \"parity\""), std::string::npos) << text;
        EXPECT_NE(text.find("\"normalize\": \"unit-sphere\""), std::string::npos) << text;
        EXPECT_NE(text.find("\"transform\": [1.17647"), std::string::npos) << text; // 1 / 0.85: the farthest vertex
        EXPECT_NE(text.find("\"bounds\": [-0.85"), std::string::npos) << text;
    };
    // The file's bytes hold the JSON text after the key.
    auto fileSource = [](const fs::path& file, const std::string& key) {
        std::ifstream in(file, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::size_t at = bytes.find(key);
        if (at == std::string::npos) return std::string();
        const std::size_t start = bytes.find('{', at);
        const std::size_t end = bytes.find('}', start);
        return bytes.substr(start, end - start + 1);
    };

    values::FrameRequest frame;
    frame.sdf = input;
    frame.width = 48;
    frame.height = 32;
    for (const char* name : {"torus.png", "torus.exr"}) {
        values::RenderRequest render{frame, (folder / name).string()};
        auto report = jobs::run(render, {});
        ASSERT_TRUE(bool(report)) << report.error.message;
        checkSource(report->meshSource.json, std::string("render report, ") + name);
        checkSource(fileSource(folder / name, "sdfwb_mesh_source"), name);
        // Through JSON and back (the workbench reads its child processes' reports this way).
        auto back = jobs::reportFromJson<values::RenderReport>(jobs::toJson(*report));
        ASSERT_TRUE(back.hasValue()) << back.error().message;
        EXPECT_EQ(jobs::toJson(*back), jobs::toJson(*report));
    }
    values::AnimateRequest animate{frame, (folder / "torus.mp4").string(), 0.1f, 30, true, {}};
    auto animated = jobs::run(animate, {});
    ASSERT_TRUE(bool(animated)) << animated.error.message;
    checkSource(animated->meshSource.json, "animate report");
    checkSource(fileSource(folder / "torus.mp4", "sdfwb_mesh_source"), "torus.mp4");
    values::ProbeRequest probe{frame, 24, 16};
    auto probed = jobs::run(probe, {});
    ASSERT_TRUE(bool(probed)) << probed.error.message;
    checkSource(probed->meshSource.json, "probe report");
    for (const char* name : {"shell.ply", "shell.obj"}) {
        values::MeshRequest meshRequest;
        meshRequest.sdf = input;
        meshRequest.output = (folder / name).string();
        meshRequest.resolution = 24;
        meshRequest.lipschitz = 1.0f; // no audit, no error: the files are what is tested here
        meshRequest.errorSamples = 0;
        auto meshed = jobs::run(meshRequest, {});
        ASSERT_TRUE(bool(meshed)) << meshed.error.message;
        checkSource(meshed->meshSource.json, std::string("mesh report, ") + name);
        checkSource(fileSource(folder / name, "sdfwb_mesh_source"), name);
        auto reread = meshing::readMesh(folder / name); // the comment does not disturb readers
        ASSERT_TRUE(reread.hasValue()) << reread.error().message;
        EXPECT_EQ(reread->triangleCount(), meshed->triangles);
    }
    values::EvalRequest eval;
    eval.sdf = input;
    eval.mesh = (folder / "shell.ply").string();
    eval.points = 1000;
    eval.occupancyResolution = 0;
    auto evaluated = jobs::run(eval, {});
    ASSERT_TRUE(bool(evaluated)) << evaluated.error.message;
    checkSource(evaluated->meshSource.json, "eval report");
    values::AuditRequest audit;
    audit.sdf = input;
    audit.samples = 500;
    auto audited = jobs::run(audit, {});
    ASSERT_TRUE(bool(audited)) << audited.error.message;
    checkSource(audited->meshSource.json, "audit report");
    auto auditBack = jobs::reportFromJson<values::AuditJobReport>(jobs::toJson(*audited));
    ASSERT_TRUE(auditBack.hasValue()) << auditBack.error().message;
    EXPECT_EQ(jobs::toJson(*auditBack), jobs::toJson(*audited));
    values::SampleRequest sample;
    sample.sdf = input;
    sample.count = 256;
    sample.pattern = "rand";
    sample.output = (folder / "torus.npz").string();
    auto sampled = jobs::run(sample, {});
    ASSERT_TRUE(bool(sampled)) << sampled.error.message;
    checkSource(sampled->meshSource.json, "sample report");

    // GLSL: no provenance, and null in the JSON.
    values::FrameRequest sphere = frame;
    sphere.sdf = values::SdfInput{};
    sphere.sdf.sdf = "sphere";
    values::RenderRequest glsl{sphere, (folder / "sphere.png").string()};
    auto plain = jobs::run(glsl, {});
    ASSERT_TRUE(bool(plain)) << plain.error.message;
    EXPECT_TRUE(plain->meshSource.json.empty());
    EXPECT_NE(jobs::toJson(*plain, -1).find("\"mesh_source\":null"), std::string::npos) << jobs::toJson(*plain);
    EXPECT_EQ(fileSource(folder / "sphere.png", "sdfwb_mesh_source"), "");
    fs::remove_all(folder);
}

} // namespace
} // namespace sdfwb::meshsdftest
