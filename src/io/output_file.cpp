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

#include "base/error.hpp"

namespace eg2d {

OutputFile::OutputFile(const std::string &path) : path_(path) {
    if (path.empty()) fail(Failure::Argument, "path is empty");
    std::vector<char> name(path.begin(), path.end());
    const char suffix[] = ".eg2d-tmp-XXXXXX";
    name.insert(name.end(), suffix, suffix + sizeof suffix);
    const int fd = mkstemp(name.data());
    if (fd < 0) fail_errno("cannot create a file in its directory", errno);
    temp_.assign(name.data());
    // mkstemp makes the file 0600; give it the permissions a plain fopen would.
    const mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, 0666 & ~mask);
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

void OutputFile::commit() {
    if (f_) {
        if (std::fflush(f_) != 0) fail_errno("write failed", errno);
        if (fsync(fileno(f_)) != 0 && errno != EINVAL) fail_errno("sync failed", errno);
        close_stream();
    }
    if (std::rename(temp_.c_str(), path_.c_str()) != 0) fail_errno("cannot rename the finished file into place", errno);
    committed_ = true;
}

}  // namespace eg2d
