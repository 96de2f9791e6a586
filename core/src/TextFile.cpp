#include <core/TextFile.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace sdfwb {
namespace fs = std::filesystem;

Expected<std::string> readTextFile(const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return makeError(path.string() + ": no such file");
    if (fs::is_directory(path, ec)) return makeError(path.string() + ": is a directory, not a file");
    std::ifstream stream(path, std::ios::binary);
    if (!stream) return makeError(path.string() + ": cannot open: " + std::strerror(errno));
    std::ostringstream buffer;
    buffer << stream.rdbuf();
    if (stream.bad()) return makeError(path.string() + ": read failed");
    return buffer.str();
}

Expected<void> writeFileAtomically(const fs::path& path, std::string_view bytes) {
    fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    std::string pattern = (folder / ("." + path.filename().string() + ".XXXXXX")).string();
    int fd = ::mkstemp(pattern.data());
    if (fd < 0)
        return makeError(path.string() + ": cannot create a temporary file in " + folder.string() + ": " + std::strerror(errno));
    auto fail = [&](const char* what) {
        int code = errno;
        ::close(fd);
        ::unlink(pattern.c_str());
        return makeError(path.string() + ": " + what + ": " + std::strerror(code));
    };
    const char* data = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        ssize_t written = ::write(fd, data, left);
        if (written < 0) {
            if (errno == EINTR) continue;
            return fail("write failed");
        }
        data += written;
        left -= std::size_t(written);
    }
    if (::fsync(fd) != 0) return fail("fsync failed");
    ::fchmod(fd, 0644);
    if (::close(fd) != 0) {
        int code = errno;
        ::unlink(pattern.c_str());
        return makeError(path.string() + ": close failed: " + std::strerror(code));
    }
    if (::rename(pattern.c_str(), path.c_str()) != 0) {
        int code = errno;
        ::unlink(pattern.c_str());
        return makeError(path.string() + ": rename failed: " + std::strerror(code));
    }
    return {};
}

} // namespace sdfwb
