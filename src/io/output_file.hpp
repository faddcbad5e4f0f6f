// A file written all-or-nothing: the bytes go to a temporary in the same
// directory (so that the rename is atomic on one file system), and commit()
// renames it over the requested path. Destroyed without commit(), the
// temporary is removed: a failed write never leaves a half-written file
// under the requested name, and an existing file there stays as it was.
// Every failure throws Failure::Io with the requested path and strerror.
#pragma once
#include <cstdio>
#include <string>

namespace eg2d {

class OutputFile {
public:
    explicit OutputFile(const std::string &path);
    ~OutputFile();
    OutputFile(const OutputFile &) = delete;
    OutputFile &operator=(const OutputFile &) = delete;

    void write(const void *data, std::size_t bytes);
    void print(const char *fmt, ...)
#if defined(__GNUC__)
        __attribute__((format(printf, 2, 3)))
#endif
        ;
    // A double with 17 significant digits (round trip); +-inf as +-DBL_MAX
    // and NaN as 0 so that every reader parses it (text formats only).
    void real(double v, char after);

    // Closes the stream but keeps the temporary, for a writer that fills the
    // file by its name (the CGNS plugin).
    void close_stream();
    const std::string &temp_path() const { return temp_; }
    const std::string &path() const { return path_; }

    // Flushes, syncs and renames the temporary to the path.
    void commit();

private:
    [[noreturn]] void fail_errno(const char *what, int err) const;
    std::string path_, temp_;
    std::FILE *f_ = nullptr;
    bool committed_ = false;
};

}  // namespace eg2d
