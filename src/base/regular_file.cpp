#include "base/regular_file.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/error.hpp"

namespace eg2d {

namespace {
const char *what_it_is(mode_t m) {
    if (S_ISDIR(m)) return "a directory";
    if (S_ISFIFO(m)) return "a FIFO";
    if (S_ISCHR(m) || S_ISBLK(m)) return "a device";
    if (S_ISSOCK(m)) return "a socket";
    return "not a regular file";
}
}  // namespace

void require_regular_file(const std::string &path) {
    struct stat st;
    if (stat(path.c_str(), &st) != 0) fail(Failure::Io, format("%s: cannot open: %s", path.c_str(), std::strerror(errno)));
    if (!S_ISREG(st.st_mode))
        fail(Failure::Io, format("%s: %s, not a regular file: not read", path.c_str(), what_it_is(st.st_mode)));
}

std::vector<unsigned char> read_regular_file(const std::string &path, long long max_bytes) {
    const int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK);
    if (fd < 0) fail(Failure::Io, format("%s: cannot open: %s", path.c_str(), std::strerror(errno)));
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        const mode_t m = st.st_mode;
        close(fd);
        fail(Failure::Io, format("%s: %s, not a regular file: not read", path.c_str(), what_it_is(m)));
    }
    if (st.st_size > max_bytes) {
        close(fd);
        fail(Failure::Io, format("%s: %lld bytes, more than the %lld a grid file may have", path.c_str(),
                                 static_cast<long long>(st.st_size), max_bytes));
    }
    std::vector<unsigned char> bytes(static_cast<std::size_t>(st.st_size));
    std::size_t got = 0;
    while (got < bytes.size()) {
        const ssize_t n = read(fd, bytes.data() + got, bytes.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int err = errno;
            close(fd);
            fail(Failure::Io, n == 0 ? format("%s: the file shrank while it was read", path.c_str())
                                     : format("%s: read failed: %s", path.c_str(), std::strerror(err)));
        }
        got += static_cast<std::size_t>(n);
    }
    close(fd);  // bytes appended since the fstat are not read: the file as it was
    return bytes;
}

}  // namespace eg2d
