#include "text_output.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "failure.hpp"

namespace eg2dtool {

namespace {

[[noreturn]] void io_error(const std::string &path, const char *what, int err) {
    throw Failure(EXIT_IO, path + ": " + what + ": " + std::strerror(err));
}

// All of `text` to the open descriptor fd (closed here); `path` names it in errors.
void put_all(int fd, const std::string &text, const std::string &path) {
    for (std::size_t done = 0; done < text.size();) {
        const ssize_t w = ::write(fd, text.data() + done, text.size() - done);
        if (w < 0 && errno == EINTR) continue;
        if (w < 0) {
            const int err = errno;
            close(fd);
            io_error(path, "write failed", err);
        }
        done += static_cast<std::size_t>(w);
    }
    if (close(fd) != 0 && errno != EINTR) io_error(path, "close failed", errno);
}

// `text` as a new file beside `target`, renamed over it; `mode` its permissions.
void replace_file(const std::string &target, const std::string &text, mode_t mode, const std::string &path) {
    std::string temp = target + ".eg2d-tmp-XXXXXX";
    const int fd = mkstemp(&temp[0]);
    if (fd < 0) io_error(path, "cannot create a file in its directory", errno);
    fchmod(fd, mode);
    try {
        put_all(fd, text, path);
    } catch (...) {
        std::remove(temp.c_str());
        throw;
    }
    if (std::rename(temp.c_str(), target.c_str()) != 0) {
        const int err = errno;
        std::remove(temp.c_str());
        io_error(path, "cannot rename the finished file into place", err);
    }
}

mode_t default_mode() {
    const mode_t mask = umask(0);
    umask(mask);
    return 0666 & ~mask;
}

}  // namespace

void write_text_file(const std::string &path, const std::string &text) {
    const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
    if (fd < 0) io_error(path, "cannot open", errno);
    put_all(fd, text, path);
}

void write_text_in_place(const std::string &path, const std::string &text) {
    namespace fs = std::filesystem;
    // The end of a chain of symbolic links (relative ones from their own directory).
    fs::path target = path;
    std::error_code ec;
    for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(target, ec)); ++hops) {
        const fs::path next = fs::read_symlink(target, ec);
        if (ec) break;
        target = next.is_absolute() ? next : target.parent_path() / next;
    }
    struct stat st;
    if (stat(target.c_str(), &st) != 0) {  // a dangling link: its target is made
        replace_file(target.string(), text, default_mode(), path);
        return;
    }
    if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) {
        const int fd = open(target.c_str(), O_WRONLY | O_NONBLOCK);
        if (fd < 0 && errno == ENXIO) throw Failure(EXIT_IO, path + ": a FIFO with no reader: not written");
        if (fd < 0) io_error(path, "cannot open", errno);
        fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);  // a reader is there: block
        put_all(fd, text, path);
    } else if (!S_ISREG(st.st_mode)) {
        throw Failure(EXIT_IO, path + ": is not a regular file: not written, and not replaced");
    } else if (st.st_nlink > 1) {  // keep the other names: the bytes go into the same inode
        const int fd = open(target.c_str(), O_WRONLY | O_TRUNC);
        if (fd < 0) io_error(path, "cannot open", errno);
        put_all(fd, text, path);
    } else {  // through a link: the target replaced whole, its mode kept
        replace_file(target.string(), text, st.st_mode & 07777, path);
    }
}

}  // namespace eg2dtool
