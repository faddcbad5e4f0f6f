// Point files: plain text, one "x y" per line (spaces, tabs or a comma
// between), '#' starts a comment, blank lines are skipped.
#pragma once
#include <string>
#include <vector>

namespace eg2d {

struct Points {
    std::vector<double> x, y;
};

// Throws Io with the path, the line number and the offending text.
Points read_points(const std::string &path);

}  // namespace eg2d
