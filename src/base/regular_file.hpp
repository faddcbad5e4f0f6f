// Reading files the way a long-running host needs: only regular files (a
// directory, a device or a FIFO is refused before anything is read, so
// /dev/zero cannot grow memory and a FIFO cannot block), with memory bounded
// by the file's size as it was when opened. Failures throw Failure::Io
// naming the path and what it is.
#pragma once
#include <string>
#include <vector>

namespace eg2d {

// Throws unless `path` is a regular file (after following links).
void require_regular_file(const std::string &path);

// The whole of a regular file of at most max_bytes.
std::vector<unsigned char> read_regular_file(const std::string &path, long long max_bytes);

}  // namespace eg2d
