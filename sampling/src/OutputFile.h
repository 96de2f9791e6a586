#pragma once
// A file written at known offsets into a temporary beside its target, renamed into place on
// commit(); removed on destruction unless committed. Private to sampling/.

#include <core/Expected.h>

#include <cstdint>
#include <filesystem>
#include <string>

namespace sdfwb::sampling::detail {

class OutputFile {
public:
    static Expected<OutputFile> create(const std::filesystem::path& target);
    OutputFile(OutputFile&& other) noexcept;
    OutputFile& operator=(OutputFile&&) = delete;
    OutputFile(const OutputFile&) = delete;
    ~OutputFile();

    // Allocates the file's final size on disk up front (one extent allocation instead of one per
    // written range at writeback); a file system that cannot is left as it is.
    void reserve(std::uint64_t bytes);
    Expected<void> writeAt(std::uint64_t offset, const void* data, std::size_t size);
    // The same, past the page cache (O_DIRECT) for the whole kDirectAlignment blocks of the range
    // when the data lies in memory at its file offset modulo a block: the disk reads the bytes
    // where they are, so the CPU copies nothing (the sampler's mapped GL buffers are page-aligned).
    // The partial blocks at either end, data placed otherwise, or a file system that refuses
    // direct I/O go through writeAt().
    static constexpr std::size_t kDirectAlignment = 4096;
    static bool directWritable(std::uint64_t offset, const void* data, std::uint64_t size) {
        return size > 0 && offset % kDirectAlignment == 0 && size % kDirectAlignment == 0 &&
               reinterpret_cast<std::uintptr_t>(data) % kDirectAlignment == 0;
    }
    Expected<void> writeDirectAt(std::uint64_t offset, const void* data, std::size_t size);
    // Whether files in `folder` lie in memory (tmpfs, ramfs): writing one costs the CPU a copy and
    // no wait for a disk.
    static bool inMemory(const std::filesystem::path& folder);
    // fsync, close, rename over the target.
    Expected<void> commit();
    const std::filesystem::path& target() const { return m_target; }

private:
    OutputFile(std::filesystem::path target, std::string temporary, int fd)
        : m_target(std::move(target)), m_temporary(std::move(temporary)), m_fd(fd) {}
    std::filesystem::path m_target;
    std::string m_temporary;
    int m_fd = -1;
    int m_directFd = -2; // -2: not opened yet, -1: direct I/O unavailable
    bool m_committed = false;
    std::uint64_t m_unflushed = 0; // bytes written since the disk was last asked to start writing
};

// A read-only file with positional reads; errors name the file. fromBytes() serves the same
// reads from memory (SampleReader::openBytes), so the format readers have one code path.
class InputFile {
public:
    static Expected<InputFile> open(const std::filesystem::path& path);
    static InputFile fromBytes(std::string name, std::string bytes);
    InputFile(InputFile&& other) noexcept;
    InputFile(const InputFile&) = delete;
    ~InputFile();
    std::uint64_t size() const { return m_size; }
    const std::string& name() const { return m_name; }
    // Reads exactly `size` bytes at `offset` or fails ("file.npz: truncated at byte 1234").
    Expected<void> readAt(std::uint64_t offset, void* data, std::size_t size) const;

private:
    InputFile(std::string name, int fd, std::uint64_t size) : m_name(std::move(name)), m_fd(fd), m_size(size) {}
    std::string m_name;
    int m_fd = -1; // -1 when the bytes are in memory
    std::uint64_t m_size = 0;
    std::string m_bytes; // fromBytes()
};

} // namespace sdfwb::sampling::detail
