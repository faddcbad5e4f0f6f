// A file written all-or-nothing, that respects what is at the path:
//  - the bytes go to a temporary in the target's directory, and commit()
//    renames it over the target (atomic on one file system); destroyed
//    without commit(), the temporary is removed and the target is as it was;
//  - a symbolic link is followed (through a chain): its final target is
//    written, the link kept;
//  - an existing regular file keeps its permission bits and, where the
//    process may, its owner and group; one with other hard links is
//    rewritten in place once the temporary is complete (a rename would
//    detach it from its other names);
//  - a FIFO or a character device is written in place (the finished bytes
//    streamed into it; a FIFO without a reader fails rather than blocks);
//  - a directory, a socket or a block device is refused, never replaced.
// Every failure throws Failure::Io with the requested path and strerror.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

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
    // Copies the finished temporary into the target opened with `flags`.
    void stream_into_target(int flags);
    std::string path_, target_, temp_;
    std::FILE *f_ = nullptr;
    bool committed_ = false;
    enum class Kind { New, Regular, Linked, Stream } kind_ = Kind::New;
    struct stat_info {
        unsigned mode = 0;
        long uid = -1, gid = -1;
    } old_;
};

// Directories a writer of several files made (an OpenFOAM case, a VTK
// multiblock's block directory), removed again (when still empty) unless
// keep() is called, so that a failed write leaves the file system as it was:
// with every file an OutputFile, a writer makes its directories, writes
// every file, commits them, then keeps the directories.
class MadeDirectories {
public:
    MadeDirectories() = default;
    ~MadeDirectories();
    MadeDirectories(const MadeDirectories &) = delete;
    MadeDirectories &operator=(const MadeDirectories &) = delete;
    // Makes the directory unless it is one already (its parent must exist);
    // Failure::Io naming it when it cannot, or a file is in the way.
    void make(const std::string &path);
    void keep() { keep_ = true; }

private:
    std::vector<std::string> made_;
    bool keep_ = false;
};

}  // namespace eg2d
