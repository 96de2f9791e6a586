// Sample files: exact layouts, round trips, streaming atomically, merging, rejecting corrupt input.

#include <sampling/SampleFile.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace sdfwb::sampling;

namespace fs = std::filesystem;

namespace {

SampleSet makeSamples(std::size_t n, float offset = 0.0f) {
    SampleSet samples;
    samples.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            samples.positions[3 * i + std::size_t(c)] = offset + float(i) + 0.1f * float(c);
            samples.gradients[3 * i + std::size_t(c)] = -offset - float(i) - 0.2f * float(c);
        }
        samples.distances[i] = offset + 0.5f * float(i);
    }
    return samples;
}

SampleMetadata makeMetadata(std::uint64_t first, std::uint64_t total) {
    SampleMetadata m;
    m.sdf = "Torus \xc3\xa9"; // non-ASCII survives
    m.pattern = "rand";
    m.seed = 1234567890123ull;
    m.time = 1.5f;
    m.firstIndex = first;
    m.totalCount = total;
    m.version = "test";
    return m;
}

fs::path temporary(const std::string& name) {
    fs::path path = fs::temp_directory_path() / ("sdfwb-test-" + name);
    fs::remove(path);
    return path;
}

std::string readBytes(const fs::path& path) {
    std::ifstream stream(path, std::ios::binary);
    std::stringstream buffer;
    buffer << stream.rdbuf();
    return buffer.str();
}

void writeBytes(const fs::path& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// No temporary left beside `target` (".NAME.partial-XXXXXX"); other tests running at the same
// time may have their own in the same folder.
bool noPartialFilesFor(const fs::path& target) {
    const std::string prefix = "." + target.filename().string() + ".partial-";
    for (const auto& entry : fs::directory_iterator(target.parent_path()))
        if (entry.path().filename().string().rfind(prefix, 0) == 0) return false;
    return true;
}

} // namespace

TEST(BinFile, LayoutIsTheTableTwoOfThePaper) {
    fs::path path = temporary("layout.bin");
    ASSERT_TRUE(writeSamples(path, SampleFormat::Bin, makeSamples(3), {}).hasValue());
    std::string bytes = readBytes(path);
    ASSERT_EQ(bytes.size(), 4u + 28u * 3u);
    std::uint32_t n = 0;
    std::memcpy(&n, bytes.data(), 4);
    EXPECT_EQ(n, 3u);
    float value = 0.0f;
    std::memcpy(&value, bytes.data() + 4 + 4 * 4, 4); // position[1].y
    EXPECT_FLOAT_EQ(value, 1.1f);
    std::memcpy(&value, bytes.data() + 4 + 36 + 4 * 2, 4); // distance[2]
    EXPECT_FLOAT_EQ(value, 1.0f);
    std::memcpy(&value, bytes.data() + 4 + 48 + 4 * 5, 4); // gradient[1].z
    EXPECT_FLOAT_EQ(value, -1.4f);
    fs::remove(path);
}

TEST(SampleFiles, EveryFormatRoundTripsWithItsMetadata) {
    for (SampleFormat format : {SampleFormat::Bin, SampleFormat::Npz, SampleFormat::Ply}) {
        fs::path path = temporary(std::string("roundtrip.") + formatName(format));
        SampleSet samples = makeSamples(1000);
        ASSERT_TRUE(writeSamples(path, format, samples, makeMetadata(0, 1000)).hasValue()) << formatName(format);
        std::optional<SampleMetadata> metadata;
        auto read = readSamples(path, &metadata);
        ASSERT_TRUE(read.hasValue()) << read.error().message;
        EXPECT_EQ(read->positions, samples.positions) << formatName(format);
        EXPECT_EQ(read->distances, samples.distances) << formatName(format);
        EXPECT_EQ(read->gradients, samples.gradients) << formatName(format);
        if (format == SampleFormat::Bin) {
            EXPECT_FALSE(metadata.has_value());
        } else {
            ASSERT_TRUE(metadata.has_value()) << formatName(format);
            EXPECT_EQ(metadata->sdf, "Torus \xc3\xa9");
            EXPECT_EQ(metadata->pattern, "rand");
            EXPECT_EQ(metadata->seed, 1234567890123ull);
            EXPECT_EQ(metadata->time, 1.5f);
            EXPECT_EQ(metadata->totalCount, 1000u);
        }
        fs::remove(path);
    }
}

TEST(SampleFiles, StreamingInChunksGivesTheSameBytesAsOneWrite) {
    SampleSet samples = makeSamples(1001);
    for (SampleFormat format : {SampleFormat::Bin, SampleFormat::Npz, SampleFormat::Ply}) {
        fs::path whole = temporary(std::string("whole.") + formatName(format));
        fs::path chunked = temporary(std::string("chunked.") + formatName(format));
        ASSERT_TRUE(writeSamples(whole, format, samples, makeMetadata(0, 1001)).hasValue());
        auto writer = SampleWriter::create(chunked, format, 1001, makeMetadata(0, 1001));
        ASSERT_TRUE(writer.hasValue());
        for (std::size_t first = 0; first < 1001; first += 97) {
            std::size_t n = std::min<std::size_t>(97, 1001 - first);
            ASSERT_TRUE((*writer)
                            ->append(&samples.positions[3 * first], &samples.distances[first], &samples.gradients[3 * first], n)
                            .hasValue());
        }
        ASSERT_TRUE((*writer)->commit().hasValue());
        EXPECT_EQ(readBytes(whole), readBytes(chunked)) << formatName(format);
        fs::remove(whole);
        fs::remove(chunked);
    }
}

// The sampler hands .ply its rows interleaved by the shader; every format takes them so and
// writes the same bytes as from three arrays.
TEST(SampleFiles, InterleavedRowsGiveTheSameBytesAsThreeArrays) {
    SampleSet samples = makeSamples(1001);
    std::vector<float> rows(7 * samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
        std::memcpy(&rows[7 * i], &samples.positions[3 * i], 12);
        rows[7 * i + 3] = samples.distances[i];
        std::memcpy(&rows[7 * i + 4], &samples.gradients[3 * i], 12);
    }
    for (SampleFormat format : {SampleFormat::Bin, SampleFormat::Npz, SampleFormat::Ply}) {
        fs::path arrays = temporary(std::string("arrays.") + formatName(format));
        fs::path interleaved = temporary(std::string("interleaved.") + formatName(format));
        ASSERT_TRUE(writeSamples(arrays, format, samples, makeMetadata(0, 1001)).hasValue());
        auto writer = SampleWriter::create(interleaved, format, 1001, makeMetadata(0, 1001));
        ASSERT_TRUE(writer.hasValue());
        EXPECT_EQ((*writer)->takesRows(), format == SampleFormat::Ply);
        for (std::size_t first = 0; first < 1001; first += 300)
            ASSERT_TRUE((*writer)->appendRows(&rows[7 * first], std::min<std::size_t>(300, 1001 - first)).hasValue());
        EXPECT_FALSE((*writer)->appendRows(rows.data(), 1).hasValue()) << "a row past the announced count";
        ASSERT_TRUE((*writer)->commit().hasValue());
        EXPECT_EQ(readBytes(arrays), readBytes(interleaved)) << formatName(format);
        fs::remove(arrays);
        fs::remove(interleaved);
    }
}

TEST(SampleFiles, AnUnfinishedWriterLeavesNoFileAndKeepsTheOldOne) {
    fs::path path = temporary("keep.npz");
    writeBytes(path, "old contents");
    {
        auto writer = SampleWriter::create(path, SampleFormat::Npz, 10, makeMetadata(0, 10));
        ASSERT_TRUE(writer.hasValue());
        SampleSet half = makeSamples(5);
        ASSERT_TRUE((*writer)->append(half.positions.data(), half.distances.data(), half.gradients.data(), 5).hasValue());
        EXPECT_FALSE((*writer)->commit().hasValue()) << "5 of 10 rows must not commit";
    }
    EXPECT_EQ(readBytes(path), "old contents");
    EXPECT_TRUE(noPartialFilesFor(path));
    fs::remove(path);
}

TEST(SampleFiles, LimitsAndFoldersAreCheckedBeforeWriting) {
    auto tooMany = SampleWriter::create(temporary("huge.bin"), SampleFormat::Bin, 5000000000ull, {});
    ASSERT_FALSE(tooMany.hasValue());
    EXPECT_NE(tooMany.error().message.find("limit"), std::string::npos);
    EXPECT_FALSE(fs::exists(temporary("huge.bin")));
    auto noFolder = SampleWriter::create("/nonexistent-folder/x.npz", SampleFormat::Npz, 1, {});
    ASSERT_FALSE(noFolder.hasValue());
    EXPECT_NE(noFolder.error().message.find("/nonexistent-folder"), std::string::npos);
}

TEST(SampleFiles, CorruptFilesAreRejectedWithTheirName) {
    fs::path bin = temporary("corrupt.bin");
    ASSERT_TRUE(writeSamples(bin, SampleFormat::Bin, makeSamples(5), {}).hasValue());
    std::string bytes = readBytes(bin);
    writeBytes(bin, bytes.substr(0, bytes.size() - 1));
    auto truncated = readSamples(bin);
    ASSERT_FALSE(truncated.hasValue());
    EXPECT_NE(truncated.error().message.find(bin.string()), std::string::npos);
    EXPECT_NE(truncated.error().message.find("N = 5"), std::string::npos) << truncated.error().message;
    bytes[3] = char(0x7f); // N ~ 2e9: refused, not allocated
    writeBytes(bin, bytes);
    EXPECT_FALSE(readSamples(bin).hasValue());

    fs::path npz = temporary("corrupt.npz");
    ASSERT_TRUE(writeSamples(npz, SampleFormat::Npz, makeSamples(50), makeMetadata(0, 50)).hasValue());
    std::string zip = readBytes(npz);
    for (std::size_t cut : {std::size_t(10), zip.size() / 2, zip.size() - 5}) {
        writeBytes(npz, zip.substr(0, cut));
        auto read = readSamples(npz);
        EXPECT_FALSE(read.hasValue()) << "cut at " << cut;
        if (!read) { EXPECT_NE(read.error().message.find(npz.string()), std::string::npos); }
    }
    std::string wrongType = zip;
    std::size_t descr = wrongType.find("'descr': '<f4'");
    ASSERT_NE(descr, std::string::npos);
    wrongType[descr + 12] = '8'; // <f8: same header length, wrong dtype
    writeBytes(npz, wrongType);
    auto typed = readSamples(npz);
    ASSERT_FALSE(typed.hasValue());
    EXPECT_NE(typed.error().message.find("<f8"), std::string::npos) << typed.error().message;

    fs::path ply = temporary("corrupt.ply");
    writeBytes(ply, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n");
    auto ascii = readSamples(ply);
    ASSERT_FALSE(ascii.hasValue());
    EXPECT_NE(ascii.error().message.find("ascii"), std::string::npos);
    writeBytes(ply,
               "ply\nformat binary_little_endian 1.0\nelement vertex 1000\nproperty float x\nproperty float y\nproperty float z\n"
               "property float distance\nproperty float gx\nproperty float gy\nproperty float gz\nend_header\nxx");
    auto short_ = readSamples(ply);
    ASSERT_FALSE(short_.hasValue());
    EXPECT_NE(short_.error().message.find("do not fit"), std::string::npos) << short_.error().message;
    fs::remove(bin);
    fs::remove(npz);
    fs::remove(ply);
}

TEST(Merge, ShardsInAnyOrderGiveTheSingleRunsFile) {
    SampleSet all = makeSamples(1000);
    for (SampleFormat format : {SampleFormat::Npz, SampleFormat::Ply}) {
        std::string ext = std::string(".") + formatName(format);
        fs::path single = temporary("single" + ext);
        ASSERT_TRUE(writeSamples(single, format, all, makeMetadata(0, 1000)).hasValue());
        std::vector<fs::path> parts;
        const std::uint64_t cuts[4] = {0, 333, 666, 1000};
        for (int k = 0; k < 3; ++k) {
            SampleSet part;
            std::size_t first = cuts[k], n = cuts[k + 1] - cuts[k];
            part.positions.assign(all.positions.begin() + long(3 * first), all.positions.begin() + long(3 * (first + n)));
            part.distances.assign(all.distances.begin() + long(first), all.distances.begin() + long(first + n));
            part.gradients.assign(all.gradients.begin() + long(3 * first), all.gradients.begin() + long(3 * (first + n)));
            parts.push_back(temporary("part" + std::to_string(k) + ext));
            ASSERT_TRUE(writeSamples(parts.back(), format, part, makeMetadata(first, 1000)).hasValue());
        }
        fs::path merged = temporary("merged" + ext);
        auto report = mergeSampleFiles(merged, format, {parts[2], parts[0], parts[1]});
        ASSERT_TRUE(report.hasValue()) << report.error().message;
        EXPECT_EQ(report->rows, 1000u);
        EXPECT_EQ(readBytes(merged), readBytes(single)) << formatName(format);

        auto missing = mergeSampleFiles(merged, format, {parts[0], parts[2]});
        ASSERT_FALSE(missing.hasValue());
        EXPECT_NE(missing.error().message.find("missing"), std::string::npos) << missing.error().message;
        for (const fs::path& p : parts) fs::remove(p);
        fs::remove(single);
        fs::remove(merged);
    }
}

TEST(SampleFiles, Zip64NpzIsReadByNumpyAndByUs) {
    fs::path path = temporary("zip64.npz");
    SampleSet samples = makeSamples(100);
    SampleWriter::Options options;
    options.forceZip64 = true;
    auto writer = SampleWriter::create(path, SampleFormat::Npz, 100, makeMetadata(0, 100), options);
    ASSERT_TRUE(writer.hasValue());
    ASSERT_TRUE((*writer)->append(samples.positions.data(), samples.distances.data(), samples.gradients.data(), 100).hasValue());
    ASSERT_TRUE((*writer)->commit().hasValue());
    auto read = readSamples(path);
    ASSERT_TRUE(read.hasValue()) << read.error().message;
    EXPECT_EQ(read->gradients, samples.gradients);
    // Debian's Python with NumPy, or SDFWB_TEST_PYTHON's (the GPU machine's has NumPy elsewhere).
    const char* python = std::getenv("SDFWB_TEST_PYTHON");
    std::string check =
        "'" + std::string(python && *python ? python : "/usr/bin/python3") + "' -c \"import numpy as np; z = np.load('" +
        path.string() +
        "', allow_pickle=False); assert z['position'].shape == (100, 3); assert float(z['distance'][99]) == 49.5\"";
    EXPECT_EQ(std::system(check.c_str()), 0) << "numpy could not read the ZIP64 archive";
    fs::remove(path);
}
