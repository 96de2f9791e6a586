// The metadata block and the catalogue.

#include <dataset/Catalogue.h>
#include <dataset/Metadata.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace sdfwb::dataset;

namespace {

const char* const kGood = "/* sdfwb\n"
                          "name: Test Shape\n"
                          "category: Geometry\n"
                          "type: conservative\n"
                          "animated: yes\n"
                          "author: someone\n"
                          "license: CC0-1.0\n"
                          "notes: first line\n"
                          "  second line\n"
                          "*/\n"
                          "float sdf(vec3 p, float t) { return length(p) - 0.5; }\n";

} // namespace

TEST(Metadata, ParsesEveryField) {
    auto metadata = parseMetadata(kGood, "test.glsl");
    ASSERT_TRUE(metadata.hasValue()) << metadata.error().message;
    EXPECT_EQ(metadata->name, "Test Shape");
    EXPECT_EQ(metadata->category, "Geometry");
    EXPECT_EQ(metadata->type, DeclaredType::Conservative);
    EXPECT_TRUE(metadata->animated);
    EXPECT_EQ(metadata->author, "someone");
    EXPECT_EQ(metadata->license, "CC0-1.0");
    EXPECT_EQ(metadata->notes, "first line second line");
}

TEST(Metadata, ErrorsNameFileAndLine) {
    std::string badType = kGood;
    badType.replace(badType.find("conservative"), 12, "exactish");
    auto metadata = parseMetadata(badType, "shape.glsl");
    ASSERT_FALSE(metadata.hasValue());
    EXPECT_EQ(metadata.error().message.rfind("shape.glsl:4: ", 0), 0u) << metadata.error().message;
    EXPECT_NE(metadata.error().message.find("exactish"), std::string::npos);

    std::string missingLicense = kGood;
    missingLicense.erase(missingLicense.find("license:"), std::string("license: CC0-1.0\n").size());
    metadata = parseMetadata(missingLicense, "shape.glsl");
    ASSERT_FALSE(metadata.hasValue());
    EXPECT_NE(metadata.error().message.find("license"), std::string::npos);

    metadata = parseMetadata("float sdf(vec3 p) { return 0.0; }", "bare.glsl");
    ASSERT_FALSE(metadata.hasValue());
    EXPECT_EQ(metadata.error().message.rfind("bare.glsl:1: ", 0), 0u);

    metadata = parseMetadata("/* sdfwb\nname: x\n", "open.glsl");
    ASSERT_FALSE(metadata.hasValue());
    EXPECT_NE(metadata.error().message.find("not closed"), std::string::npos);
}

TEST(Catalogue, ShippedDatasetParsesCleanlyAndLooksUpAnyCase) {
    Catalogue catalogue = Catalogue::scan(std::filesystem::path(SDFWB_SOURCE_DIR) / "dataset");
    EXPECT_TRUE(catalogue.problems().empty()) << catalogue.problems().front();
    ASSERT_GE(catalogue.entries().size(), 3u);
    const Entry* torus = catalogue.find("tORUS");
    ASSERT_NE(torus, nullptr);
    EXPECT_EQ(torus->metadata.name, "Torus");
    EXPECT_EQ(catalogue.find("no such shape"), nullptr);
    EXPECT_NE(catalogue.find(kDefaultSdfName), nullptr);
}

TEST(Catalogue, SdfArgumentErrorsSayWhatWasMissing) {
    Catalogue catalogue = Catalogue::scan(std::filesystem::path(SDFWB_SOURCE_DIR) / "dataset");
    auto missing = resolveSdfArgument("Dodo", catalogue);
    ASSERT_FALSE(missing.hasValue());
    EXPECT_NE(missing.error().message.find("'Dodo'"), std::string::npos);
    auto missingPath = resolveSdfArgument("/nowhere/shape.glsl", catalogue);
    ASSERT_FALSE(missingPath.hasValue());
    EXPECT_NE(missingPath.error().message.find("no such file"), std::string::npos);
    auto byName = resolveSdfArgument("sphere", catalogue);
    ASSERT_TRUE(byName.hasValue());
    EXPECT_EQ(byName->filename(), "Sphere.glsl");
}

TEST(Catalogue, LookupUnderARootAgreesWithTheScanReadingOnlyWhatItMust) {
    const std::filesystem::path root = std::filesystem::path(SDFWB_SOURCE_DIR) / "dataset";
    const Catalogue catalogue = Catalogue::scan(root);
    for (const Entry& entry : catalogue.entries()) {
        auto byRoot = resolveSdfArgument(entry.metadata.name, root);
        ASSERT_TRUE(byRoot.hasValue()) << entry.metadata.name;
        EXPECT_EQ(*byRoot, *resolveSdfArgument(entry.metadata.name, catalogue)) << entry.metadata.name;
    }
    // A name that is no file's stem falls back to the metadata; a helper under lib/ is no SDF.
    const std::filesystem::path temp = std::filesystem::temp_directory_path() /
                                       ("sdfwb-catalogue-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::remove_all(temp);
    std::filesystem::create_directories(temp / "Things" / "lib");
    const std::string head = "/* sdfwb\nname: Wobbly Cube\ncategory: C\ntype: exact\nanimated: no\nauthor: a\nlicense: l\n*/\n";
    std::ofstream(temp / "Things" / "cube_v2.glsl") << head << "float sdf(vec3 p) { return length(p) - 1.0; }\n";
    std::ofstream(temp / "Things" / "lib" / "helper.glsl") << "float helper(vec3 p) { return p.x; }\n";
    EXPECT_EQ(resolveSdfArgument("CUBE_V2", temp)->filename(), "cube_v2.glsl");
    EXPECT_EQ(resolveSdfArgument("wobbly cube", temp)->filename(), "cube_v2.glsl");
    auto helper = resolveSdfArgument("helper", temp);
    ASSERT_FALSE(helper.hasValue());
    EXPECT_EQ(helper.error().message, resolveSdfArgument("helper", Catalogue::scan(temp)).error().message);
    std::filesystem::remove_all(temp);
}

TEST(Metadata, EntryNamesTheSdfFunction) {
    const std::string head = "/* sdfwb\nname: N\ncategory: C\ntype: exact\nanimated: no\nauthor: a\nlicense: l\n";
    auto parsed = sdfwb::dataset::parseMetadata(head + "entry: map\n*/\n", "e.glsl");
    ASSERT_TRUE(parsed.hasValue()) << parsed.error().message;
    EXPECT_EQ(parsed->entry, "map");
    auto bad = sdfwb::dataset::parseMetadata(head + "entry: not a name\n*/\n", "e.glsl");
    ASSERT_FALSE(bad.hasValue());
    EXPECT_NE(bad.error().message.find("e.glsl:8: entry must be a GLSL function name"), std::string::npos) << bad.error().message;
}
