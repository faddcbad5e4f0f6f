#include "output_set.hpp"

#include <eg2d.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <set>

#include "failure.hpp"
#include "progress.hpp"
#include "text_output.hpp"

namespace eg2dtool {

namespace {

// A path the set may not replace: a directory, a socket or a block device
// (a rename would fail, or destroy what is there); a case directory's path
// must be a directory if it exists. `why` ends the message.
void refuse_unreplaceable(const std::string &path, bool directory, const std::string &why) {
    struct stat st;
    if (stat(path.c_str(), &st) != 0) return;  // new (or a dangling link, whose target is made)
    if (directory) {
        if (!S_ISDIR(st.st_mode))
            throw Failure(EXIT_IO, path + ": not a directory, so no case can be written there" + why);
        return;
    }
    if (S_ISDIR(st.st_mode) || S_ISSOCK(st.st_mode) || S_ISBLK(st.st_mode))
        throw Failure(EXIT_IO, path + ": " +
                                   (S_ISDIR(st.st_mode) ? "a directory" : S_ISSOCK(st.st_mode) ? "a socket" : "a block device") +
                                   ", not replaced by an output file" + why);
}

// Where an output path already is something other than a plain file, the
// library writes it by its own rules (eg2d.h, eg2d_write): a symbolic link's
// target is replaced and the link kept, a file with other hard links is
// rewritten in place, a FIFO or character device is streamed into. A rename
// from the stage would replace any of them. An OpenFOAM case that exists is
// updated in place too: its mesh files replaced, each all-or-nothing, and the
// case's own files (system/, 0/) kept, which a rename would lose.
bool written_in_place(bool directory, const struct stat &st) {
    return directory || S_ISLNK(st.st_mode) || S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode) ||
           (S_ISREG(st.st_mode) && st.st_nlink > 1);
}

// `written`: the paths already written in place (a stream cannot be taken back).
void stop_if_interrupted(const std::vector<std::string> &written = {}) {
    if (!Progress::interrupted()) return;
    std::string done;
    for (const auto &p : written) done += (done.empty() ? "" : ", ") + p;
    throw Failure(Progress::interrupt_exit_code(),
                  std::string("interrupted by ") + Progress::interrupt_name() +
                      (done.empty() ? ": no files written" : ": only " + done + " written (in place), no other file"));
}

}  // namespace

void check_before_solving(const std::string &dir, const std::vector<PlannedPath> &paths) {
    if (dir.empty())
        throw Failure(EXIT_USAGE, "-o \"\": an empty output directory name (it would be the filesystem root; "
                                  "-o . is the current directory)");
    eg2d_grid *probe = nullptr;
    if (eg2d_create(3, 3, &probe) == EG2D_OK) {
        const double x[9] = {0, 0.5, 1, 0, 0.5, 1, 0, 0.5, 1}, y[9] = {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1};
        eg2d_set_coordinates(probe, x, y);
        std::set<int> probed;
        for (const auto &p : paths)
            if (p.format >= 0 && probed.insert(p.format).second &&
                eg2d_write(probe, "/dev/null", p.format) == EG2D_ERR_UNSUPPORTED) {
                const std::string why = eg2d_last_error(probe);
                eg2d_destroy(probe);
                throw Failure(EXIT_UNSUPPORTED, p.where + ": " + why + " (checked before solving; no files written)");
            }
        eg2d_destroy(probe);
    }
    // The directory is made only after the solve (a failed run leaves none):
    // here its nearest existing ancestor must be a writable directory.
    std::string d = dir;
    struct stat st;
    while (stat(d.c_str(), &st) != 0) {
        const std::size_t slash = d.find_last_of('/');
        d = slash == std::string::npos ? "." : slash == 0 ? "/" : d.substr(0, slash);
    }
    if (!S_ISDIR(st.st_mode))
        throw Failure(EXIT_IO, d + ": is not a directory, so " + dir + " cannot be made (checked before solving)");
    if (access(d.c_str(), W_OK) != 0)
        throw Failure(EXIT_IO, d + ": not writable, so " + dir + " cannot be written (checked before solving): " +
                                   std::strerror(errno));
    for (const auto &p : paths) refuse_unreplaceable(dir + "/" + p.name, p.directory, " (checked before solving)");
}

void make_directory(const std::string &dir, std::vector<std::string> *made) {
    std::string partial;
    for (std::size_t k = 0; k <= dir.size(); ++k) {
        if ((k == dir.size() || dir[k] == '/') && !partial.empty()) {
            if (mkdir(partial.c_str(), 0777) == 0) {
                if (made) made->push_back(partial);
            } else if (errno != EEXIST) {
                throw Failure(EXIT_IO, partial + ": cannot create the output directory: " + std::strerror(errno));
            }
        }
        if (k < dir.size()) partial += dir[k];
    }
}

OutputSet::OutputSet(const std::string &dir) : dir_(dir) {
    try {
        make_directory(dir_, &made_);
    } catch (...) {
        remove_made();
        throw;
    }
    stage_ = dir_ + "/.eg2d-set-XXXXXX";
    if (!mkdtemp(&stage_[0])) {
        const int err = errno;
        stage_.clear();
        remove_made();
        throw Failure(EXIT_IO, dir_ + ": cannot stage the output files: " + std::strerror(err));
    }
}

OutputSet::~OutputSet() {
    std::error_code ignored;  // a stage holds only what the set wrote
    if (!stage_.empty()) std::filesystem::remove_all(stage_, ignored);
    if (!committed_) remove_made();
}

void OutputSet::remove_made() {
    for (auto d = made_.rbegin(); d != made_.rend(); ++d) rmdir(d->c_str());  // only what stayed empty
}

std::string OutputSet::staged(const std::string &name) const { return stage_ + "/" + name; }

namespace {
// The names in a directory (the stage's top level).
std::set<std::string> names_in(const std::string &dir) {
    std::set<std::string> names;
    std::error_code ignored;
    for (const auto &e : std::filesystem::directory_iterator(dir, ignored)) names.insert(e.path().filename().string());
    return names;
}

// Moves a staged file, or a staged directory's files (merged into the
// directory at `to`, made where missing), into place; appends the files.
void move_into_place(const std::string &from, const std::string &to, std::vector<std::string> &written) {
    struct stat st;
    if (lstat(from.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
        struct stat there;
        if (mkdir(to.c_str(), 0777) != 0 && !(errno == EEXIST && stat(to.c_str(), &there) == 0 && S_ISDIR(there.st_mode)))
            throw Failure(EXIT_IO, to + ": cannot make the directory: " +
                                       (errno == EEXIST ? "a file that is not a directory is in the way" : std::strerror(errno)));
        for (const std::string &n : names_in(from)) move_into_place(from + "/" + n, to + "/" + n, written);
        return;
    }
    if (std::rename(from.c_str(), to.c_str()) != 0)
        throw Failure(EXIT_IO, to + ": cannot move the written file into place: " + std::strerror(errno));
    written.push_back(to);
}
}  // namespace

void OutputSet::add(const std::string &name, bool directory, Writer write) {
    stop_if_interrupted();
    const std::set<std::string> before = names_in(stage_);
    write(staged(name), false);
    std::vector<std::string> companions;
    for (const std::string &n : names_in(stage_))
        if (n != name && !before.count(n)) companions.push_back(n);
    entries_.push_back({name, directory, std::move(write), std::move(companions)});
}

void OutputSet::add_text(const std::string &name, const std::string &text) {
    add(name, false, [text](const std::string &path, bool in_place) {
        if (in_place) write_text_in_place(path, text);
        else write_text_file(path, text);
    });
}

std::vector<std::string> OutputSet::commit() {
    stop_if_interrupted();
    // What a rename cannot replace is refused before any path is touched.
    for (const auto &e : entries_) refuse_unreplaceable(dir_ + "/" + e.name, e.directory, " (no files written)");
    std::vector<std::string> written;
    // Streams (a FIFO, a character device, or a link to one) first: a FIFO
    // with no reader, the likeliest failure here, then leaves every file as it was.
    for (const bool streams : {true, false})
        for (const auto &e : entries_) {
            const std::string path = dir_ + "/" + e.name;
            struct stat st, end;
            if (lstat(path.c_str(), &st) != 0 || !written_in_place(e.directory, st)) continue;
            const bool stream = stat(path.c_str(), &end) == 0 && (S_ISFIFO(end.st_mode) || S_ISCHR(end.st_mode));
            if (stream != streams) continue;
            stop_if_interrupted(written);
            e.write(path, true);
            written.push_back(path);
        }
    stop_if_interrupted(written);
    for (const auto &e : entries_) {
        const std::string path = dir_ + "/" + e.name, from = staged(e.name);
        struct stat st;
        if (lstat(path.c_str(), &st) == 0) {
            if (written_in_place(e.directory, st)) continue;  // its writer wrote its companions too
            if (S_ISREG(st.st_mode)) {  // the file replaced keeps its permission bits (and owner, where permitted)
                chmod(from.c_str(), st.st_mode & 07777);
                if (chown(from.c_str(), st.st_uid, st.st_gid) != 0) {}
            }
        }
        for (const std::string &c : e.companions) move_into_place(staged(c), dir_ + "/" + c, written);
        if (std::rename(from.c_str(), path.c_str()) != 0)
            throw Failure(EXIT_IO, path + ": cannot move the written file into place: " + std::strerror(errno));
        written.push_back(path);
    }
    committed_ = true;
    return written;
}

}  // namespace eg2dtool
