// The mesh field's values on both engines (shaders/mesh/mesh_field.glsl through the samplers' points
// stage, and meshfield::MeshQuery on the CPU) against float64 references: distances within 1e-5 of
// the bounding box's diagonal of a brute-force scan, each sign method's sign, the caller's order,
// the Morton pass and the CPU engine bit for bit, and the gradient exact or by taps.
#include "MeshSdfTesting.h"

#include <renderer/GlInfo.h>

namespace sdfwb::meshsdftest {
namespace {

TEST_F(MeshSdfTest, GpuDistancesMatchAFloat64BruteForceScanAndEachSignMethodsCpuSign) {
    const meshfield::TriangleMesh mesh = testing::torusMesh(0.6f, 0.25f, 64, 24);
    std::vector<float> points = uniformPoints(4000, 11, 1.2f);
    // points near the surface, where the nearest feature changes
    for (std::size_t k = 0; k < 1000; ++k) {
        const glm::vec3 v = mesh.vertices[(k * 13) % mesh.vertices.size()];
        points.insert(points.end(), {v.x + 3e-3f * float(k % 3), v.y - 2e-3f * float(k % 5), v.z + 1e-3f * float(k % 7)});
    }
    const std::size_t n = points.size() / 3;
    std::vector<double> reference(n);
    for (std::size_t i = 0; i < n; ++i)
        reference[i] = testing::bruteDistance(mesh, dvec3(points[3 * i], points[3 * i + 1], points[3 * i + 2]));
    for (meshfield::SignMethod sign :
         {meshfield::SignMethod::Winding, meshfield::SignMethod::Parity, meshfield::SignMethod::Pseudonormal}) {
        meshfield::MeshFieldOptions options;
        options.sign = sign;
        auto field = meshfield::makeMeshField(mesh, "torus.obj", options);
        ASSERT_TRUE(field.hasValue());
        const double diagonal = glm::length((*field)->bounds.hi - (*field)->bounds.lo);
        for (const char* engine : {"gpu", "cpu"}) {
            EngineScope scope(engine);
            const std::vector<float> gpu = evaluate(shaders::prepareMeshSdf(*field, "torus.obj"), points);
            double worst = 0.0;
            int wrongSign = 0;
            int signed_ = 0;
            for (std::size_t i = 0; i < n; ++i) {
                const dvec3 p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
                worst = std::max(worst, std::abs(std::abs(double(gpu[i])) - reference[i]));
                if (reference[i] < 1e-4) continue; // the sign of a point on the surface is either
                ++signed_;
                if ((gpu[i] < 0.0f) != (*field)->inside(p)) ++wrongSign;
            }
            std::printf(
                "%-4s engine, %-12s |f| vs float64 brute force: largest error %.2e (%.2e of the diagonal); sign differs from the "
                "CPU's at %d of %d points\n",
                engine, meshfield::signName(sign), worst, worst / diagonal, wrongSign, signed_);
            EXPECT_LE(worst, 1e-5 * diagonal) << meshfield::signName(sign) << ' ' << engine;
            EXPECT_EQ(wrongSign, 0) << meshfield::signName(sign) << ' ' << engine;
        }
    }
}

// Issue 46: the GLSL field takes a row's winding sign from the lattice of winding numbers after
// the hierarchy (MeshQuery::signLattice) where the empty ball of the nearest distance holds a
// lattice point: the same signs as the CPU's exact reference, and most far rows served without a
// winding walk on a closed mesh (SDFWB_MESH_COUNT=1 counts them, whatever the driver); open meshes
// only where the boundary's bound allows.
TEST_F(MeshSdfTest, TheGlslFieldTakesFarSignsFromTheLatticeAndKeepsEverySign) {
    const meshfield::TriangleMesh torus = testing::torusMesh(0.6f, 0.25f, 48, 16);
    const std::vector<float> points = uniformPoints(6000, 11, 1.1f);
    const std::size_t n = points.size() / 3;
    EngineScope scope("gpu");
    setenv("SDFWB_MESH_COUNT", "1", 1);
    for (bool open : {false, true}) {
        const meshfield::TriangleMesh mesh = open ? testing::damaged(torus, testing::Damage::RemoveFivePercent) : torus;
        auto field = meshfield::makeMeshField(mesh, "torus.obj", {});
        ASSERT_TRUE(field.hasValue());
        meshfield::QueryCounters counters;
        const std::vector<float> values = evaluate(shaders::prepareMeshSdf(*field, "torus.obj"), points, &counters);
        int wrongSign = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const dvec3 p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
            if ((*field)->distance(p) > 1e-4 && (values[i] < 0.0f) != (*field)->inside(p)) ++wrongSign;
        }
        std::printf("%s torus: %llu of %zu signs from the lattice, %.1f winding nodes and %.1f nearest nodes a row\n",
                    open ? "open" : "closed", (unsigned long long)counters.cachedSigns, n,
                    double(counters.windingNodes) / double(n), double(counters.nearestNodes) / double(n));
        EXPECT_EQ(wrongSign, 0) << (open ? "open" : "closed");
        EXPECT_GE(counters.nearestNodes, n) << "every row walks the nearest hierarchy";
        EXPECT_GT(counters.cachedSigns, open ? n / 10 : n * 8 / 10) << (open ? "open" : "closed");
        EXPECT_LT(counters.cachedSigns, n) << "rows near the surface still walk";
        EXPECT_GT(counters.windingNodes + counters.segmentNodes, 0u) << "rows the lattice cannot sign walk";
    }
    unsetenv("SDFWB_MESH_COUNT");
}

// Rows too near the surface for the lattice ball (near samples) take the crossing sign: the nearest
// lattice point's winding number plus the oriented crossings of the segment to the row (a short
// segment walk instead of a winding walk), bounded by the open boundary's slope there. The same
// signs as the CPU's exact reference, most near rows on a closed mesh served that way, and far
// fewer winding nodes a row; on an open mesh only where the boundary's slope allows. With the
// lattice of 33^3 points (the default) and of 65^3 (a GPU's runs of 4 M rows or more).
TEST_F(MeshSdfTest, TheGlslFieldTakesNearSignsFromSegmentCrossingsAndKeepsEverySign) {
    const meshfield::TriangleMesh torus = testing::torusMesh(0.6f, 0.25f, 48, 16);
    EngineScope scope("gpu");
    setenv("SDFWB_MESH_COUNT", "1", 1);
    for (bool open : {false, true}) {
        const meshfield::TriangleMesh mesh = open ? testing::damaged(torus, testing::Damage::RemoveFivePercent) : torus;
        auto field = meshfield::makeMeshField(mesh, "torus.obj", {});
        ASSERT_TRUE(field.hasValue());
        // Points near the surface: the smooth torus's points (within 0.007 of the mesh's facets)
        // moved by up to 0.004 along each axis.
        std::vector<float> points;
        std::uint32_t state = 7;
        auto uniform = [&state] {
            state = state * 1664525u + 1013904223u;
            return float(state >> 8) / float(1u << 24);
        };
        for (int i = 0; i < 6000; ++i) {
            const float u = 6.2831853f * uniform(), v = 6.2831853f * uniform();
            const glm::vec3 on((0.6f + 0.25f * std::cos(v)) * std::cos(u), (0.6f + 0.25f * std::cos(v)) * std::sin(u),
                               0.25f * std::sin(v));
            const glm::vec3 off = glm::vec3(uniform(), uniform(), uniform()) * 0.008f - 0.004f;
            for (int a = 0; a < 3; ++a) points.push_back(on[a] + off[a]);
        }
        const std::size_t n = points.size() / 3;
        // The lattice of 33^3 points and of 65^3: the finer decides more rows.
        std::uint64_t decidedAt33 = 0; // rows signed without a winding walk
        std::vector<float> valuesAt33;
        for (const char* level : {"5", "6"}) {
            setenv("SDFWB_MESH_SIGN_LEVEL", level, 1);
            meshfield::QueryCounters counters;
            const std::vector<float> values = evaluate(shaders::prepareMeshSdf(*field, "torus.obj"), points, &counters);
            unsetenv("SDFWB_MESH_SIGN_LEVEL");
            int wrongSign = 0, compared = 0;
            for (std::size_t i = 0; i < n; ++i) {
                const dvec3 p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
                if ((*field)->distance(p) <= 1e-5) continue;
                ++compared;
                if ((values[i] < 0.0f) != (*field)->inside(p)) ++wrongSign;
            }
            std::printf(
                "%s torus, near rows, lattice level %s: %llu of %zu signs by crossings (%llu from the lattice), %.1f segment "
                "nodes and %.1f winding nodes a row\n",
                open ? "open" : "closed", level, (unsigned long long)counters.crossedSigns, n,
                (unsigned long long)counters.cachedSigns, double(counters.segmentNodes) / double(n),
                double(counters.windingNodes) / double(n));
            EXPECT_GT(compared, int(n) * 9 / 10);
            EXPECT_EQ(wrongSign, 0) << (open ? "open" : "closed");
            // The damaged torus has holes all over: the boundary's slope bound allows few segments.
            EXPECT_GT(counters.crossedSigns, open ? n / 20 : n * 9 / 10) << (open ? "open" : "closed");
            EXPECT_GT(counters.segmentNodes, counters.crossedSigns) << "each crossing sign walks its segment";
            if (!open) { EXPECT_LT(double(counters.windingNodes) / double(n), 5.0) << "few near rows walk the winding numbers"; }
            const std::uint64_t decided = counters.crossedSigns + counters.cachedSigns;
            if (std::string_view(level) == "5") {
                decidedAt33 = decided;
                valuesAt33 = values;
            } else {
                EXPECT_GE(decided, decidedAt33)
                    << (open ? "open" : "closed") << ": the finer lattice left more rows to the winding walk";
                // Each lattice seeds the nearest walks with its own points' triangles: the same
                // triangle wins either way, so the same values bit for bit.
                EXPECT_EQ(0, std::memcmp(values.data(), valuesAt33.data(), values.size() * sizeof(float)))
                    << (open ? "open" : "closed");
            }
        }
    }
    unsetenv("SDFWB_MESH_COUNT");
}

// The GLSL field evaluates the caller's points grouped by cell (neighbouring invocations walk
// alike) and returns each value to its point: the same values whatever order the points come in.
TEST_F(MeshSdfTest, TheGlslFieldReturnsEachPointsValueInTheCallersOrder) {
    auto field = meshfield::makeMeshField(testing::torusMesh(0.6f, 0.25f, 48, 16), "torus.obj", {});
    ASSERT_TRUE(field.hasValue());
    const shaders::PreparedSdf sdf = shaders::prepareMeshSdf(*field, "torus.obj");
    const std::vector<float> points = uniformPoints(5000, 3, 1.1f);
    std::vector<float> reversed(points.size());
    for (std::size_t i = 0; i < points.size() / 3; ++i)
        std::copy(points.begin() + long(3 * i), points.begin() + long(3 * i + 3), reversed.end() - long(3 * i + 3));
    EngineScope scope("gpu");
    const std::vector<float> forward = evaluate(sdf, points);
    const std::vector<float> backward = evaluate(sdf, reversed);
    ASSERT_EQ(forward.size(), backward.size());
    int differing = 0;
    for (std::size_t i = 0; i < forward.size(); ++i)
        differing += forward[i] == backward[forward.size() - 1 - i] && std::isfinite(forward[i]) ? 0 : 1;
    EXPECT_EQ(differing, 0);
    for (std::size_t i = 0; i < 50; ++i) {
        const dvec3 p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
        EXPECT_NEAR(std::abs(forward[i]), (*field)->distance(p), 1e-5) << i;
    }
}

// The GLSL engine evaluates a mesh's own field with each chunk's rows grouped by cell, on the GPU
// (SDFWB_MESH_MORTON=1, the default on every driver): the sampler's positions, the cells' counts
// and slots, then the values in cell order, written at each row's own place. SDFWB_MESH_MORTON=0
// keeps one pass in the sampler's order. The same rows bit for bit, the gradient exact or by
// taps, in one chunk and in chunks of 700 (the ring, the sort buffer reused).
TEST_F(MeshSdfTest, TheGlslFieldsRowsSortedByCellAreTheOnePassRowsBitForBit) {
    auto field = meshfield::makeMeshField(testing::torusMesh(0.6f, 0.25f, 48, 16), "torus.obj", {});
    ASSERT_TRUE(field.hasValue());
    const shaders::PreparedSdf sdf = shaders::prepareMeshSdf(*field, "torus.obj");
    auto differing = [](const std::vector<float>& a, const std::vector<float>& b) {
        int n = 0;
        for (std::size_t i = 0; i < a.size(); ++i) n += std::memcmp(&a[i], &b[i], sizeof(float)) != 0 ? 1 : 0;
        return n;
    };
    // Metropolis with taps is left out: in one pass its chain and six taps can spend llvmpipe's loop
    // budget (10 NaN rows of 3,000 here), which the sorted passes, a budget each, do not.
    for (const char* pattern : {"rand", "near", "surface", "metropolis"})
        for (bool taps : {false, true})
            for (std::uint32_t chunk : {0u, 700u}) {
                if (taps && std::string_view(pattern) == "metropolis") continue;
                setenv("SDFWB_MESH_MORTON", "0", 1);
                const Rows one = sampleRows(sdf, pattern, 3000, "gpu", taps, chunk);
                setenv("SDFWB_MESH_MORTON", "1", 1);
                const Rows sorted = sampleRows(sdf, pattern, 3000, "gpu", taps, chunk);
                unsetenv("SDFWB_MESH_MORTON");
                EXPECT_FALSE(one.sortedRows);
                EXPECT_TRUE(sorted.sortedRows) << "the rows are sorted by cell";
                EXPECT_FALSE(sorted.positionsOnly) << "one program computes positions and values";
                EXPECT_EQ(differing(one.positions, sorted.positions), 0) << pattern << " taps " << taps << " chunk " << chunk;
                EXPECT_EQ(differing(one.distances, sorted.distances), 0) << pattern << " taps " << taps << " chunk " << chunk;
                EXPECT_EQ(differing(one.gradients, sorted.gradients), 0) << pattern << " taps " << taps << " chunk " << chunk;
                EXPECT_LT(*std::max_element(sorted.distances.begin(), sorted.distances.end()), 2.0f) << pattern;
            }
    EXPECT_TRUE(sampleRows(sdf, "rand", 300, "gpu", false).sortedRows) << "sorted by default on every driver";
    EXPECT_FALSE(sampleRows(sdf, "rand", 300, "cpu", false).sortedRows) << "the CPU engine sorts rows its own way";
}

// The metropolis samplers read only |f| (they declare sdfwb_chainReadsMagnitude): on a mesh's own
// field their chain walks for the nearest distance alone, each state's walk bounded by the last
// state's triangle, and computes no sign; metropolis_curvature's taps take one only nearer the
// surface than their step. On a closed mesh, the same rows bit for bit as the chain on the signed
// field (the sampler without the declaration), on both engines. On llvmpipe the chains run in passes of a few steps
// (SampleCompute): in one pass the signed chains of metropolis_curvature (seven signed walks a
// state) ran out of the driver's loop budget.
TEST_F(MeshSdfTest, TheMetropolisChainsOnAMeshWalkForTheNearestDistanceAloneAndKeepTheSignedChainsRows) {
    auto field = meshfield::makeMeshField(testing::torusMesh(0.6f, 0.25f, 48, 16), "torus.obj", {});
    ASSERT_TRUE(field.hasValue());
    const shaders::PreparedSdf sdf = shaders::prepareMeshSdf(*field, "torus.obj");
    // Whether the CPU engine's program for `sampler` defines `name`.
    auto defines = [&](const shaders::ShaderPiece& sampler, const std::string& name) {
        meshsdftest::EngineScope scope("cpu");
        renderer::SampleCompute compute;
        EXPECT_FALSE(shaders::hasErrors(compute.build(sdf, sampler)));
        const bool defined = compute.source().find("#define " + name + " ") != std::string::npos;
        compute.releaseGl();
        return defined;
    };
    auto same = [](const std::vector<float>& a, const std::vector<float>& b) {
        return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
    };
    for (const char* pattern : {"metropolis", "metropolis_curvature"}) {
        SCOPED_TRACE(pattern);
        const bool curvature = std::string_view(pattern) == "metropolis_curvature";
        auto magnitude = sampling::findSampler(pattern, sampling::samplerFolders());
        ASSERT_TRUE(magnitude.hasValue());
        shaders::ShaderPiece signedChain = *magnitude;
        const std::string declaration = "const bool sdfwb_chainReadsMagnitude = true;";
        const std::size_t at = signedChain.text.find(declaration);
        ASSERT_NE(at, std::string::npos);
        signedChain.text.erase(at, declaration.size());
        EXPECT_TRUE(defines(*magnitude, "SDFWB_CHAIN_MAGNITUDE"));
        EXPECT_FALSE(defines(signedChain, "SDFWB_CHAIN_MAGNITUDE"));
        const std::uint64_t n = curvature ? 1500 : 3000;
        const Rows fast = sampleRows(sdf, *magnitude, n, "gpu");
        const Rows slow = sampleRows(sdf, signedChain, n, "gpu");
        EXPECT_TRUE(same(fast.positions, slow.positions));
        EXPECT_TRUE(same(fast.distances, slow.distances));
        EXPECT_TRUE(same(fast.gradients, slow.gradients));
        // The rows gather near the surface (pi ~ exp(-|f| / 0.01)), and metropolis_curvature's
        // chains reach states both nearer than their taps' step and farther (either kind of tap).
        int near = 0;
        int beyondStep = 0;
        for (float d : fast.distances) {
            near += std::abs(d) < 0.05f ? 1 : 0;
            beyondStep += std::abs(d) > 0.0101f ? 1 : 0;
        }
        EXPECT_GT(near, int(n) * 8 / 10);
        EXPECT_GT(beyondStep, int(n) / 20);
        EXPECT_LT(beyondStep, int(n) * 9 / 10);
        // The CPU engine's positions come from the same chain. Its program takes the sign lattice
        // only where the sampler evaluates the signed field itself (metropolis_curvature's near
        // taps); the signed chain's program keeps it.
        const Rows cpu = sampleRows(sdf, *magnitude, n, "cpu");
        EXPECT_TRUE(cpu.positionsOnly);
        EXPECT_TRUE(same(cpu.positions, fast.positions));
        EXPECT_EQ(defines(*magnitude, "SDFWB_MESH_SIGNS"), curvature);
        EXPECT_TRUE(defines(signedChain, "SDFWB_MESH_SIGNS"));
    }
    auto rand = sampling::findSampler("rand", sampling::samplerFolders());
    ASSERT_TRUE(rand.hasValue());
    EXPECT_FALSE(defines(*rand, "SDFWB_MESH_SIGNS")) << "the CPU engine's rand program places points only";
}

// llvmpipe ends every loop of an invocation once its loops together have run 65,535 iterations,
// without an error. SampleCompute runs the Metropolis chains there in passes of a few steps (a pass
// resumes from the states the last one stored): the same rows bit for bit as one pass wherever one
// pass is not cut, whatever the steps a pass. A chain cut anyway is a NaN row, counted, never a
// sample of a shorter chain: in one pass llvmpipe cuts metropolis_curvature's chains on this mesh.
TEST_F(MeshSdfTest, MetropolisChainsRunInPassesWithTheOnePassRowsAndACutChainIsABadRow) {
    struct PassSteps {
        explicit PassSteps(const char* steps) { setenv("SDFWB_CHAIN_PASS_STEPS", steps, 1); }
        ~PassSteps() { unsetenv("SDFWB_CHAIN_PASS_STEPS"); }
    };
    auto field = meshfield::makeMeshField(testing::torusMesh(0.6f, 0.25f, 48, 16), "torus.obj", {});
    ASSERT_TRUE(field.hasValue());
    const shaders::PreparedSdf sdf = shaders::prepareMeshSdf(*field, "torus.obj");
    auto same = [](const std::vector<float>& a, const std::vector<float>& b) {
        return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
    };
    Rows onePass;
    {
        PassSteps steps("0");
        onePass = sampleRows(sdf, "metropolis", 2000, "gpu");
    }
    for (const char* perPass : {"1", "7", "8", "160", "161"}) {
        SCOPED_TRACE(perPass);
        PassSteps steps(perPass);
        const Rows passes = sampleRows(sdf, "metropolis", 2000, "gpu");
        EXPECT_TRUE(same(passes.positions, onePass.positions));
        EXPECT_TRUE(same(passes.distances, onePass.distances));
    }
    auto curvature = sampling::findSampler("metropolis_curvature", sampling::samplerFolders());
    ASSERT_TRUE(curvature.hasValue());
    for (const char* engine : {"gpu", "cpu"}) {
        SCOPED_TRACE(engine);
        meshsdftest::EngineScope scope(engine);
        PassSteps steps("0");
        renderer::SampleCompute compute;
        EXPECT_FALSE(shaders::hasErrors(compute.build(sdf, *curvature)));
        sampling::SamplingJob job;
        job.count = 1000;
        std::vector<float> positions(3 * job.count), distances(job.count), gradients(3 * job.count);
        auto report = sampling::sampleInto(compute, job, positions.data(), distances.data(), gradients.data(), {});
        ASSERT_TRUE(report.hasValue()) << report.error().message;
        std::uint64_t nanRows = 0;
        for (float d : distances) nanRows += std::isnan(d) ? 1 : 0;
        EXPECT_EQ(report->badRows, nanRows);
        if (renderer::softwareRasteriser())
            EXPECT_GT(report->badRows, job.count / 2) << "llvmpipe cuts these chains in one pass";
        else
            EXPECT_EQ(report->badRows, 0u) << "a GPU's driver cuts no loop";
        compute.releaseGl();
    }
}

TEST_F(MeshSdfTest, TheCpuEngineWritesTheGlslFieldsValuesAtTheSamePositionsBitForBit) {
    const meshfield::TriangleMesh torus = testing::torusMesh(0.6f, 0.25f, 48, 16);
    const std::pair<const char*, meshfield::TriangleMesh> meshes[] = {
        {"closed", torus}, {"5% removed", testing::damaged(torus, testing::Damage::RemoveFivePercent)}};
    for (const auto& [name, mesh] : meshes)
        for (meshfield::SignMethod sign :
             {meshfield::SignMethod::Winding, meshfield::SignMethod::Parity, meshfield::SignMethod::Pseudonormal}) {
            meshfield::MeshFieldOptions options;
            options.sign = sign;
            auto field = meshfield::makeMeshField(mesh, "torus.obj", options);
            ASSERT_TRUE(field.hasValue());
            const shaders::PreparedSdf sdf = shaders::prepareMeshSdf(*field, "torus.obj");
            const double diagonal = glm::length((*field)->bounds.hi - (*field)->bounds.lo);
            // The grid's points lie on the torus's planes of symmetry, where two triangles are exactly
            // equally near: it runs once, and its gradients are not compared (either is right).
            for (const char* pattern : {"rand", "near", "grid"}) {
                const bool grid = std::string(pattern) == "grid";
                if (grid && (sign != meshfield::SignMethod::Winding || std::string(name) != "closed")) continue;
                const std::uint64_t n = 3000;
                const Rows gpu = sampleRows(sdf, pattern, n, "gpu");
                const Rows cpu = sampleRows(sdf, pattern, n, "cpu");
                EXPECT_EQ(gpu.engine, "gpu");
                EXPECT_EQ(cpu.engine, "cpu");
                EXPECT_EQ(0, std::memcmp(gpu.positions.data(), cpu.positions.data(), gpu.positions.size() * sizeof(float)))
                    << name << ' ' << pattern << ": positions differ";
                double worst = 0.0;
                int wrongSign = 0;
                int gradientsApart = 0;
                for (std::size_t i = 0; i < n; ++i) {
                    worst = std::max(worst, double(std::abs(gpu.distances[i] - cpu.distances[i])));
                    if (std::abs(cpu.distances[i]) > 1e-5f && (gpu.distances[i] < 0.0f) != (cpu.distances[i] < 0.0f)) ++wrongSign;
                    const glm::vec3 a(gpu.gradients[3 * i], gpu.gradients[3 * i + 1], gpu.gradients[3 * i + 2]);
                    const glm::vec3 b(cpu.gradients[3 * i], cpu.gradients[3 * i + 1], cpu.gradients[3 * i + 2]);
                    // The GPU's float closest point moves the direction by about its rounding over
                    // |d| (1e-7 / |d|): close to the surface that is the larger term.
                    if (glm::length(a - b) > 1e-3f + 1e-6f / std::abs(cpu.distances[i])) ++gradientsApart;
                }
                std::printf("%-10s %-12s %-4s: largest value difference %.2e (%.2e of the diagonal), signs differing %d, "
                            "exact gradients more than 1e-3 apart %d of %llu\n",
                            name, meshfield::signName(sign), pattern, worst, worst / diagonal, wrongSign, gradientsApart,
                            (unsigned long long)n);
                EXPECT_LE(worst, 1e-6 * diagonal) << name << ' ' << pattern;
                EXPECT_EQ(wrongSign, 0) << name << ' ' << pattern;
                // Only at float ties between two nearest triangles (the medial axis) may the GPU's
                // float walk and the CPU's double walk pick different closest points.
                if (!grid) { EXPECT_LE(gradientsApart, int(n / 500)) << name << ' ' << pattern; }
            }
        }
}

TEST_F(MeshSdfTest, ExplicitGradientStepsGiveSixTapsOnBothEnginesAndTheExactGradientOtherwise) {
    auto field = meshfield::makeMeshField(testing::torusMesh(0.6f, 0.25f, 96, 32), "torus.obj", {});
    ASSERT_TRUE(field.hasValue());
    const shaders::PreparedSdf sdf = shaders::prepareMeshSdf(*field, "torus.obj");
    const std::uint64_t n = 4000;
    const Rows exactGpu = sampleRows(sdf, "rand", n, "gpu");
    const Rows tapsGpu = sampleRows(sdf, "rand", n, "gpu", true);
    const Rows tapsCpu = sampleRows(sdf, "rand", n, "cpu", true);
    int unit = 0;
    int tapsAgree = 0;
    int compared = 0;
    int close = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 e(exactGpu.gradients[3 * i], exactGpu.gradients[3 * i + 1], exactGpu.gradients[3 * i + 2]);
        const glm::vec3 g(tapsGpu.gradients[3 * i], tapsGpu.gradients[3 * i + 1], tapsGpu.gradients[3 * i + 2]);
        const glm::vec3 c(tapsCpu.gradients[3 * i], tapsCpu.gradients[3 * i + 1], tapsCpu.gradients[3 * i + 2]);
        unit += std::abs(glm::length(e) - 1.0f) < 1e-5f ? 1 : 0;
        tapsAgree += glm::length(g - c) < 2e-3f ? 1 : 0;       // float taps of two float-rounded fields
        if (std::abs(glm::length(g) - 1.0f) > 1e-3f) continue; // a stencil across a kink
        ++compared;
        close += glm::length(e - g) < 1e-2f ? 1 : 0;
    }
    std::printf("exact gradients of unit length %d of %llu; GPU and CPU taps within 2e-3 at %d; exact within 1e-2 of the "
                "taps at %d of %d smooth rows\n",
                unit, (unsigned long long)n, tapsAgree, close, compared);
    EXPECT_EQ(unit, int(n));
    EXPECT_GE(tapsAgree, int(n) * 99 / 100);
    EXPECT_GT(compared, int(n) * 9 / 10);
    EXPECT_GE(close, compared * 99 / 100);
    // The taps are not the exact gradient: a step of 1e-3 over a float field moves them.
    EXPECT_NE(0, std::memcmp(exactGpu.gradients.data(), tapsGpu.gradients.data(), n * 3 * sizeof(float)));
}

} // namespace
} // namespace sdfwb::meshsdftest
