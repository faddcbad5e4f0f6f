#include "io/output_file.hpp"

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdarg>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/c_locale.hpp"
#include "base/error.hpp"

namespace eg2d {

namespace {

// The final target of a chain of symbolic links (the path itself if it is
// none); a relative link is resolved against the link's own directory.
std::string follow_links(const std::string &path) {
    std::string p = path;
    for (int hops = 0; hops < 40; ++hops) {
        struct stat st;
        if (lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
        std::vector<char> buf(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 255) + 1);
        const ssize_t n = readlink(p.c_str(), buf.data(), buf.size() - 1);
        if (n < 0) return p;
        std::string next(buf.data(), static_cast<std::size_t>(n));
        if (!next.empty() && next[0] != '/') {
            const std::size_t slash = p.rfind('/');
            if (slash != std::string::npos) next = p.substr(0, slash + 1) + next;
        }
        p = next;
    }
    return p;  // a loop: opening it reports ELOOP
}

const char *kind_name(mode_t m) {
    if (S_ISDIR(m)) return "a directory";
    if (S_ISSOCK(m)) return "a socket";
    if (S_ISBLK(m)) return "a block device";
    return "not a regular file";
}

}  // namespace

OutputFile::OutputFile(const std::string &path) : path_(path) {
    if (path.empty()) fail(Failure::Argument, "path is empty");
    target_ = follow_links(path);
    struct stat st;
    if (stat(target_.c_str(), &st) == 0) {
        if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) {
            kind_ = Kind::Stream;
        } else if (!S_ISREG(st.st_mode)) {
            fail(Failure::Io, format("%s: is %s: not written, and not replaced", path_.c_str(), kind_name(st.st_mode)));
        } else {
            kind_ = st.st_nlink > 1 ? Kind::Linked : Kind::Regular;
            old_.mode = static_cast<unsigned>(st.st_mode & 07777);
            old_.uid = static_cast<long>(st.st_uid);
            old_.gid = static_cast<long>(st.st_gid);
        }
    }
    // The temporary: beside the target (a stream's bytes are staged in the
    // system's temporary directory, since /dev cannot take them).
    std::string base = target_;
    if (kind_ == Kind::Stream) {
        const char *tmp = std::getenv("TMPDIR");
        base = std::string(tmp && *tmp ? tmp : "/tmp") + "/eg2d-stream";
    }
    std::vector<char> name(base.begin(), base.end());
    const char suffix[] = ".eg2d-tmp-XXXXXX";
    name.insert(name.end(), suffix, suffix + sizeof suffix);
    const int fd = mkstemp(name.data());
    if (fd < 0) fail_errno("cannot create a file in its directory", errno);
    temp_.assign(name.data());
    // mkstemp makes the file 0600: give it the existing file's permissions,
    // or those a plain fopen would.
    const mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, kind_ == Kind::Regular ? static_cast<mode_t>(old_.mode) : (0666 & ~mask));
    f_ = fdopen(fd, "wb");
    if (!f_) {
        const int err = errno;
        close(fd);
        std::remove(temp_.c_str());
        fail_errno("cannot open", err);
    }
}

OutputFile::~OutputFile() {
    if (f_) std::fclose(f_);
    if (!committed_) std::remove(temp_.c_str());
}

void OutputFile::fail_errno(const char *what, int err) const {
    fail(Failure::Io, format("%s: %s: %s", path_.c_str(), what, std::strerror(err)));
}

void OutputFile::write(const void *data, std::size_t bytes) {
    if (bytes && std::fwrite(data, 1, bytes, f_) != bytes) fail_errno("write failed", errno);
}

void OutputFile::print(const char *fmt, ...) {
    const CLocaleScope c;  // every text format's numbers: the same bytes whatever the host's locale
    va_list args;
    va_start(args, fmt);
    const int n = std::vfprintf(f_, fmt, args);
    const int err = errno;
    va_end(args);
    if (n < 0) fail_errno("write failed", err);
}

void OutputFile::real(double v, char after) {
    if (std::isnan(v)) v = 0.0;
    else if (std::isinf(v)) v = v > 0 ? DBL_MAX : -DBL_MAX;
    print("%.17g%c", v, after);
}

void OutputFile::close_stream() {
    std::FILE *f = f_;
    f_ = nullptr;
    if (std::fclose(f) != 0) fail_errno("close failed", errno);
}

void OutputFile::stream_into_target(int flags) {
    const int in = open(temp_.c_str(), O_RDONLY);
    if (in < 0) fail_errno("cannot reread the finished file", errno);
    const int out = open(target_.c_str(), flags);
    if (out < 0) {
        const int err = errno;
        close(in);
        if (err == ENXIO) fail(Failure::Io, format("%s: a FIFO with no reader: not written", path_.c_str()));
        fail_errno("cannot open", err);
    }
    if (flags & O_NONBLOCK) fcntl(out, F_SETFL, fcntl(out, F_GETFL) & ~O_NONBLOCK);  // a reader is there: block
    char buf[65536];
    for (;;) {
        const ssize_t n = read(in, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        for (ssize_t done = 0; done < n;) {
            const ssize_t w = ::write(out, buf + done, static_cast<std::size_t>(n - done));
            if (w < 0 && errno == EINTR) continue;
            if (w < 0) {
                const int err = errno;
                close(in);
                close(out);
                fail_errno("write failed", err);
            }
            done += w;
        }
    }
    close(in);
    if (close(out) != 0 && errno != EINTR) fail_errno("close failed", errno);
}

void OutputFile::commit() {
    if (f_) {
        if (std::fflush(f_) != 0) fail_errno("write failed", errno);
        if (fsync(fileno(f_)) != 0 && errno != EINVAL) fail_errno("sync failed", errno);
        close_stream();
    }
    switch (kind_) {
    case Kind::Stream:
        stream_into_target(O_WRONLY | O_NONBLOCK);
        std::remove(temp_.c_str());
        break;
    case Kind::Linked:  // keep the other names: the bytes go into the same inode
        stream_into_target(O_WRONLY | O_TRUNC);
        std::remove(temp_.c_str());
        break;
    case Kind::Regular:
        // The owner and group of the file it replaces, where allowed (root,
        // or the group of a file one owns); the mode was set at creation.
        if (chown(temp_.c_str(), static_cast<uid_t>(old_.uid), static_cast<gid_t>(old_.gid)) != 0) {
            // EPERM: the new file stays the writer's, as with any editor's save
        }
        [[fallthrough]];
    case Kind::New:
        if (std::rename(temp_.c_str(), target_.c_str()) != 0)
            fail_errno("cannot rename the finished file into place", errno);
        break;
    }
    committed_ = true;
}

MadeDirectories::~MadeDirectories() {
    if (keep_) return;
    for (auto it = made_.rbegin(); it != made_.rend(); ++it) rmdir(it->c_str());
}

void MadeDirectories::make(const std::string &path) {
    if (mkdir(path.c_str(), 0777) == 0) {
        made_.push_back(path);
        return;
    }
    const int err = errno;
    struct stat st;
    if (err == EEXIST && stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) return;
    fail(Failure::Io, format("%s: cannot make the directory: %s", path.c_str(),
                             err == EEXIST ? "a file that is not a directory is in the way" : std::strerror(err)));
}

}  // namespace eg2d
