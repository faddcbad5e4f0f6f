#include "io/points.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <vector>

#include "base/c_locale.hpp"
#include "base/error.hpp"
#include "base/regular_file.hpp"

namespace eg2d {

namespace {
// Point files are short lines of two numbers. The bounds keep a wrong path
// (a device such as /dev/zero, a binary file) from growing memory until the
// host is killed: it is reported instead.
constexpr std::size_t kMaxLine = 4096;
constexpr std::size_t kMaxPoints = 10000000;

bool separator(char c) { return c == ' ' || c == '\t' || c == ',' || c == '\r'; }

// The next number from s (after separators); false if there is none.
bool number(const char *&s, double &v) {
    while (separator(*s)) ++s;
    if (!*s) return false;
    char *stop;
    v = strtod_c(s, &stop);
    if (stop == s) return false;
    s = stop;
    return true;
}
}  // namespace

Points read_points(const std::string &path) {
    require_regular_file(path);
    std::ifstream in(path);
    if (!in) fail(Failure::Io, format("%s: cannot open: %s", path.c_str(), std::strerror(errno)));
    Points p;
    std::vector<char> buffer(kMaxLine);
    long number_of_line = 0;
    for (;;) {
        in.getline(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        if (in.bad()) break;
        if (in.fail()) {
            if (in.eof() && in.gcount() == 0) break;  // no more lines
            fail(Failure::Io, format("%s:%ld: a line longer than %zu characters: not a point file", path.c_str(),
                                     number_of_line + 1, kMaxLine - 2));
        }
        ++number_of_line;
        if (p.x.size() >= kMaxPoints)
            fail(Failure::Io, format("%s: more than %zu points: not a point file", path.c_str(), kMaxPoints));
        const std::string line(buffer.data());
        const std::size_t hash = line.find('#');
        const std::string text = line.substr(0, hash);
        const char *s = text.c_str();
        while (separator(*s)) ++s;
        if (!*s) continue;
        double x, y;
        const char *start = s;
        if (!number(s, x) || !number(s, y))
            fail(Failure::Io, format("%s:%ld: \"%s\": expected two numbers x y", path.c_str(), number_of_line,
                                     text.c_str()));
        while (separator(*s)) ++s;
        if (*s)
            fail(Failure::Io, format("%s:%ld: \"%s\": unexpected \"%s\" after the two numbers x y", path.c_str(),
                                     number_of_line, text.c_str(), s));
        if (!std::isfinite(x) || !std::isfinite(y))
            fail(Failure::Io, format("%s:%ld: \"%s\": the point is not finite", path.c_str(), number_of_line, start));
        p.x.push_back(x);
        p.y.push_back(y);
        if (in.eof()) break;  // a last line without a newline
    }
    if (in.bad()) fail(Failure::Io, format("%s: read failed: %s", path.c_str(), std::strerror(errno)));
    if (p.x.empty()) fail(Failure::Io, format("%s: no points in the file", path.c_str()));
    return p;
}

}  // namespace eg2d
