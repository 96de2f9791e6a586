#pragma once
// SDFs of this source tree for tests: loaded with the shader library and the dataset as include
// roots, and audited (no convergence runs). The audit needs a current GL context.

#include <sampling/FieldAudit.h>
#include <shaders/SdfSource.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace sdfwb::testing {

// `relative` to the source tree, e.g. "tests/stability/steep_sphere.glsl".
inline shaders::PreparedSdf loadSourceSdf(const std::string& relative) {
    const std::filesystem::path root(SDFWB_SOURCE_DIR);
    shaders::IncludeOptions options;
    options.libraryRoots = {root / "shaders" / "lib", root / "dataset"};
    auto sdf = shaders::prepareSdfFile(root / relative, options);
    EXPECT_TRUE(sdf.ok()) << relative;
    return sdf;
}

inline values::AuditReport auditSourceSdf(const std::string& relative, std::uint64_t samples = 20000) {
    sampling::AuditOptions options;
    options.samples = samples;
    options.convergence = false;
    auto report = sampling::auditField(loadSourceSdf(relative), options, {});
    EXPECT_TRUE(report.hasValue()) << relative << ": " << (report ? "" : report.error().message);
    return report ? *report : values::AuditReport{};
}

} // namespace sdfwb::testing
