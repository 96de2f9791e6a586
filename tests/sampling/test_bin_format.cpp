// The paper's .bin layout, byte for byte, and clean rejection of corrupt files.

#include <sampling/BinFormat.h>

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

using namespace sdfwb::sampling;

namespace {

SampleSet makeSamples(std::size_t n) {
    SampleSet samples;
    samples.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            samples.positions[3 * i + std::size_t(c)] = float(i) + 0.1f * float(c);
            samples.gradients[3 * i + std::size_t(c)] = -float(i) - 0.2f * float(c);
        }
        samples.distances[i] = 0.5f * float(i);
    }
    return samples;
}

} // namespace

TEST(BinFormat, LayoutIsHeaderThenPositionsDistancesGradients) {
    SampleSet samples = makeSamples(3);
    auto bytes = encodeBin(samples);
    ASSERT_TRUE(bytes.hasValue());
    ASSERT_EQ(bytes->size(), 4u + 28u * 3u);
    std::uint32_t n = 0;
    std::memcpy(&n, bytes->data(), 4);
    EXPECT_EQ(n, 3u);
    float value = 0.0f;
    std::memcpy(&value, bytes->data() + 4 + 4 * 4, 4);  // position[1].y
    EXPECT_FLOAT_EQ(value, 1.1f);
    std::memcpy(&value, bytes->data() + 4 + 36 + 4 * 2, 4);  // distance[2]
    EXPECT_FLOAT_EQ(value, 1.0f);
    std::memcpy(&value, bytes->data() + 4 + 48 + 4 * 5, 4);  // gradient[1].z
    EXPECT_FLOAT_EQ(value, -1.4f);
}

TEST(BinFormat, RoundTripThroughAFile) {
    SampleSet samples = makeSamples(100);
    auto path = std::filesystem::temp_directory_path() / "sdfwb-test-roundtrip.bin";
    ASSERT_TRUE(writeBin(path, samples).hasValue());
    EXPECT_EQ(std::filesystem::file_size(path), 4u + 28u * 100u);
    auto read = readBin(path);
    ASSERT_TRUE(read.hasValue()) << read.error().message;
    EXPECT_EQ(read->positions, samples.positions);
    EXPECT_EQ(read->distances, samples.distances);
    EXPECT_EQ(read->gradients, samples.gradients);
    std::filesystem::remove(path);
}

TEST(BinFormat, CorruptFilesAreRejectedWithTheirName) {
    auto tooShort = decodeBin("ab", "short.bin");
    ASSERT_FALSE(tooShort.hasValue());
    EXPECT_NE(tooShort.error().message.find("short.bin"), std::string::npos);

    auto bytes = encodeBin(makeSamples(5));
    ASSERT_TRUE(bytes.hasValue());
    auto truncated = decodeBin(bytes->substr(0, bytes->size() - 1), "cut.bin");
    ASSERT_FALSE(truncated.hasValue());
    EXPECT_NE(truncated.error().message.find("N = 5"), std::string::npos) << truncated.error().message;

    std::string huge = *bytes;
    huge[3] = char(0x7f);  // N ~ 2e9: must be refused, not allocated
    EXPECT_FALSE(decodeBin(huge, "huge.bin").hasValue());
}
