// The files of one run written as one unit, all or nothing: what eg2d run,
// eg2d airfoil and eg2d channel share. Every file goes first into a staging
// directory inside the output directory (DIR/.eg2d-set-XXXXXX); only when
// all are written are they renamed into place, so a full disk, a FIFO with no
// reader, a missing plugin or a signal part-way leaves the old set as it was,
// never a new .xyz beside an old .vts. Paths that already are links,
// hard-linked files, FIFOs or character devices, and existing case
// directories (OpenFOAM), are written where they are by the library's rules
// (eg2d.h, eg2d_write; text_output.hpp for the command's own files) once the
// stage is complete, streams first, then the renames.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace eg2dtool {

// A path of a set known before the solve: NAME inside the output directory,
// the library's format id (-1: a file the command writes itself), whether it
// is a case directory, and what names it in a message ("case.toml:30:1",
// "airfoil: --format cgns").
struct PlannedPath {
    std::string name;
    int format = -1;
    bool directory = false;
    std::string where;
};

// Refuses, before anything is solved, what would fail only afterwards: an
// empty directory name (it would be taken as the filesystem root), a format
// whose writer is absent (the CGNS plugin: a probe grid written to
// /dev/null says so in microseconds), an output directory that cannot be
// made or written, and a path that is a directory, socket or block device
// (or, for a case directory, not a directory). Failure(EXIT_USAGE, EXIT_IO
// or EXIT_UNSUPPORTED) saying "(checked before solving...)".
void check_before_solving(const std::string &dir, const std::vector<PlannedPath> &paths);

// Makes dir and its parents where missing (Failure EXIT_IO when it cannot);
// appends each directory it made to `made`, parents first.
void make_directory(const std::string &dir, std::vector<std::string> *made = nullptr);

class OutputSet {
public:
    // Writes one output at `path`: the staged path first (in_place false),
    // then, for a path written in place, the final one. Throws Failure.
    using Writer = std::function<void(const std::string &path, bool in_place)>;

    // Makes dir (and its parents) and the stage in it.
    explicit OutputSet(const std::string &dir);
    // Removes what is left of the stage, and, when the set was not
    // committed, the directories it made (the output directory as it was).
    ~OutputSet();
    OutputSet(const OutputSet &) = delete;
    OutputSet &operator=(const OutputSet &) = delete;

    // Writes NAME (a file, or a case directory) into the stage now; stops
    // with the signal's Failure when SIGINT or SIGTERM has arrived. What
    // else the writer put in the stage beside NAME (a VTK multiblock's block
    // directory) goes into place with it, file by file, before NAME.
    void add(const std::string &name, bool directory, Writer write);
    // A file the command writes itself, its whole text.
    void add_text(const std::string &name, const std::string &text);
    // Where NAME is staged (a scratch file there is removed with the stage).
    std::string staged(const std::string &name) const;

    // Moves the set into place; returns the paths written, in the order added.
    std::vector<std::string> commit();

private:
    void remove_made();  // the directories the set made, deepest first

    struct Entry {
        std::string name;
        bool directory;
        Writer write;
        std::vector<std::string> companions;  // written beside NAME by its writer
    };
    std::string dir_, stage_;
    std::vector<std::string> made_;
    std::vector<Entry> entries_;
    bool committed_ = false;
};

}  // namespace eg2dtool
