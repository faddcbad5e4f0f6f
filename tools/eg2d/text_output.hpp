// Text files the command writes itself (the run's history and control
// functions), by the rules eg2d_write follows for the library's formats
// (eg2d.h): a new or plain file is written whole and renamed into place; an
// existing symbolic link is kept and its target replaced; a file with other
// hard links is rewritten in place; a FIFO or character device is streamed
// into (a FIFO with no reader fails at once). Failures throw
// Failure(EXIT_IO) naming the path and the system's reason.
#pragma once

#include <string>

namespace eg2dtool {

// `text` as the whole file `path` (a file of the staging directory: new).
void write_text_file(const std::string &path, const std::string &text);

// `text` into what `path` already is (a link, a hard-linked file, a FIFO or a
// character device), as eg2d_write would write there.
void write_text_in_place(const std::string &path, const std::string &text);

}  // namespace eg2dtool
