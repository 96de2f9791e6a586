#include "OutputFile.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#ifdef __linux__
#include <linux/magic.h>
#include <sys/vfs.h>
#endif
#include <sys/stat.h>
#include <unistd.h>

namespace sdfwb::sampling::detail {
namespace fs = std::filesystem;

Expected<OutputFile> OutputFile::create(const fs::path& target) {
    fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) return makeError(target.string() + ": folder '" + folder.string() + "' does not exist");
    if (fs::is_directory(target, ec)) return makeError(target.string() + ": is a folder, not a file");
    std::string pattern = (folder / ("." + target.filename().string() + ".partial-XXXXXX")).string();
    int fd = ::mkstemp(pattern.data());
    if (fd < 0)
        return makeError(target.string() + ": cannot create a file in '" + folder.string() + "': " + std::strerror(errno));
    ::fchmod(fd, 0644);
    return OutputFile(target, pattern, fd);
}

OutputFile::OutputFile(OutputFile&& other) noexcept
    : m_target(std::move(other.m_target)), m_temporary(std::move(other.m_temporary)), m_fd(other.m_fd),
      m_directFd(other.m_directFd), m_committed(other.m_committed) {
    other.m_fd = -1;
    other.m_directFd = -1;
    other.m_committed = true;
}

OutputFile::~OutputFile() {
    if (m_fd >= 0) ::close(m_fd);
    if (m_directFd >= 0) ::close(m_directFd);
    if (!m_committed && !m_temporary.empty()) ::unlink(m_temporary.c_str());
}

bool OutputFile::inMemory(const fs::path& folder) {
#ifdef __linux__
    struct statfs system {};
    const fs::path at = folder.empty() ? fs::path(".") : folder;
    return ::statfs(at.c_str(), &system) == 0 && (system.f_type == TMPFS_MAGIC || system.f_type == RAMFS_MAGIC);
#else
    (void)folder;
    return false;
#endif
}

void OutputFile::reserve(std::uint64_t bytes) {
#ifdef __linux__
    // Not in memory (tmpfs): there it allocates and zeroes every page up front that the writes
    // then fill (0.06 s for 560 MB here; the writes alone allocate them anyway), with no extents
    // to gain. The temporary lies beside the target.
    if (inMemory(m_target.parent_path())) return;
    if (bytes > 0) (void)::fallocate(m_fd, 0, 0, off_t(bytes));
#endif
}

namespace {

// Writes all `size` bytes at `offset` (retrying interrupted and partial writes): 0, or the errno.
int writeFully(int fd, std::uint64_t offset, const void* data, std::size_t size) {
    const char* bytes = static_cast<const char*>(data);
    while (size > 0) {
        ssize_t written = ::pwrite(fd, bytes, size, off_t(offset));
        if (written < 0 && errno == EINTR) continue;
        if (written < 0) return errno;
        if (written == 0) return EIO;
        bytes += written;
        offset += std::uint64_t(written);
        size -= std::size_t(written);
    }
    return 0;
}

} // namespace

Expected<void> OutputFile::writeAt(std::uint64_t offset, const void* data, std::size_t size) {
    if (int error = writeFully(m_fd, offset, data, size))
        return makeError(m_target.string() + ": write failed: " + std::strerror(error));
    m_unflushed += size;
#ifdef __linux__
    // Start the disk writing what is already there (asynchronously) every 64 MiB, so commit()'s
    // fsync waits only for the tail instead of the whole file after the last row.
    if (m_unflushed >= (64u << 20)) {
        ::sync_file_range(m_fd, 0, 0, SYNC_FILE_RANGE_WRITE);
        m_unflushed = 0;
    }
#endif
    return {};
}

Expected<void> OutputFile::writeDirectAt(std::uint64_t offset, const void* data, std::size_t size) {
    const std::uint64_t block = kDirectAlignment;
    const auto* bytes = static_cast<const char*>(data);
    if (reinterpret_cast<std::uintptr_t>(bytes) % block == offset % block && !directWritable(offset, data, size)) {
        // The whole blocks directly, the partial ones at either end through the page cache.
        const std::size_t head = std::size_t(std::min<std::uint64_t>(size, (block - offset % block) % block));
        const std::size_t body = (size - head) / block * block;
        if (body == 0) return writeAt(offset, data, size);
        if (head > 0)
            if (auto ok = writeAt(offset, bytes, head); !ok) return ok;
        if (auto ok = writeDirectAt(offset + head, bytes + head, body); !ok) return ok;
        if (head + body < size) return writeAt(offset + head + body, bytes + head + body, size - head - body);
        return {};
    }
#ifdef O_DIRECT
    const bool aligned = directWritable(offset, data, size);
    if (aligned && m_directFd == -2) {
        // SDFWB_DIRECT_IO=0 turns it off, for benchmarks.
        const char* setting = std::getenv("SDFWB_DIRECT_IO");
        m_directFd = setting && setting[0] == '0' ? -1 : ::open(m_temporary.c_str(), O_WRONLY | O_DIRECT | O_CLOEXEC);
    }
    if (aligned && m_directFd >= 0) {
        const int error = writeFully(m_directFd, offset, data, size);
        if (error == 0) return {};
        if (error != EINVAL) return makeError(m_target.string() + ": write failed: " + std::strerror(error));
        ::close(m_directFd); // the file system refused direct I/O after all: write the usual way
        m_directFd = -1;
    }
#endif
    return writeAt(offset, data, size);
}

Expected<void> OutputFile::commit() {
    if (m_directFd >= 0 && ::fsync(m_directFd) != 0)
        return makeError(m_target.string() + ": flushing to disk failed: " + std::strerror(errno));
    if (::fsync(m_fd) != 0) return makeError(m_target.string() + ": flushing to disk failed: " + std::strerror(errno));
    int fd = m_fd;
    m_fd = -1;
    if (::close(fd) != 0) return makeError(m_target.string() + ": close failed: " + std::strerror(errno));
    if (::rename(m_temporary.c_str(), m_target.c_str()) != 0)
        return makeError(m_target.string() + ": cannot move the finished file into place: " + std::strerror(errno));
    m_committed = true;
    return {};
}

Expected<InputFile> InputFile::open(const fs::path& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) return makeError(path.string() + ": is a folder, not a file");
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return makeError(path.string() + ": cannot open: " + std::strerror(errno));
    struct stat status {};
    if (::fstat(fd, &status) != 0) {
        ::close(fd);
        return makeError(path.string() + ": cannot stat: " + std::strerror(errno));
    }
    return InputFile(path.string(), fd, std::uint64_t(status.st_size));
}

InputFile InputFile::fromBytes(std::string name, std::string bytes) {
    InputFile file(std::move(name), -1, bytes.size());
    file.m_bytes = std::move(bytes);
    return file;
}

InputFile::InputFile(InputFile&& other) noexcept
    : m_name(std::move(other.m_name)), m_fd(other.m_fd), m_size(other.m_size), m_bytes(std::move(other.m_bytes)) {
    other.m_fd = -1;
    other.m_size = 0; // a moved-from file reads nothing
}

InputFile::~InputFile() {
    if (m_fd >= 0) ::close(m_fd);
}

Expected<void> InputFile::readAt(std::uint64_t offset, void* data, std::size_t size) const {
    if (offset > m_size || size > m_size - offset)
        return makeError(m_name + ": truncated: needs bytes up to " + std::to_string(offset + size) + " but has " +
                         std::to_string(m_size));
    char* bytes = static_cast<char*>(data);
    if (m_fd < 0) {
        if (size > 0) std::memcpy(bytes, m_bytes.data() + offset, size);
        return {};
    }
    while (size > 0) {
        ssize_t got = ::pread(m_fd, bytes, size, off_t(offset));
        if (got < 0) {
            if (errno == EINTR) continue;
            return makeError(m_name + ": read failed: " + std::strerror(errno));
        }
        if (got == 0) return makeError(m_name + ": unexpected end of file");
        bytes += got;
        offset += std::uint64_t(got);
        size -= std::size_t(got);
    }
    return {};
}

} // namespace sdfwb::sampling::detail
