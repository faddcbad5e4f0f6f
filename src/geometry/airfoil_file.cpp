// Airfoil coordinate files in the two formats of the UIUC airfoil database:
//  Selig:    a name line, then x y pairs from the trailing edge over the upper
//            surface to the leading edge and back along the lower surface;
//  Lednicer: a name line, a line "NU NL" (point counts, both > 1), then the
//            upper surface from leading to trailing edge, then the lower one.
// Both become one spline from the trailing edge along the lower surface to
// the leading edge and back along the upper (the orientation of make_naca4).
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "base/c_locale.hpp"
#include "base/error.hpp"
#include "base/regular_file.hpp"
#include "geometry/curve.hpp"

namespace eg2d {

namespace {

struct Pair { double x, y; };

// Parses "x y" (blank or comma separated); false for a line without two numbers.
bool parse_pair(const std::string &line, Pair &p) {
    const char *s = line.c_str();
    char *end;
    errno = 0;
    p.x = strtod_c(s, &end);
    if (end == s) return false;
    s = end;
    while (*s == ' ' || *s == '\t' || *s == ',') ++s;
    p.y = strtod_c(s, &end);
    if (end == s) return false;
    for (s = end; *s; ++s)
        if (!std::isspace(static_cast<unsigned char>(*s))) return false;
    return errno == 0;
}

bool blank(const std::string &line) {
    for (char c : line)
        if (!std::isspace(static_cast<unsigned char>(c))) return false;
    return true;
}

}  // namespace

std::shared_ptr<Curve> read_airfoil(const char *path) {
    require_regular_file(path);
    const std::unique_ptr<std::FILE, int (*)(std::FILE *)> file(std::fopen(path, "r"), std::fclose);
    std::FILE *f = file.get();
    if (!f) fail(Failure::Io, format("cannot open airfoil file \"%s\": %s", path, std::strerror(errno)));
    // Line by line: what is kept is the points (a file of blank lines or
    // names costs nothing), never the file's lines. Line 1 is the name.
    std::vector<Pair> pts;
    std::size_t first_line = 0, number = 0;
    std::string line;
    bool more = true;
    while (more) {
        const int c = std::fgetc(f);
        if (c != '\n' && c != EOF) {
            if (c != '\r') line.push_back(static_cast<char>(c));
            continue;
        }
        more = c != EOF;
        if (c == EOF && line.empty()) break;
        ++number;
        if (number == 1 || blank(line)) {
            line.clear();
            continue;
        }
        Pair p;
        if (!parse_pair(line, p))
            fail(Failure::Argument,
                 format("airfoil file \"%s\", line %zu: \"%s\" is not a pair of numbers", path, number, line.c_str()));
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            fail(Failure::Argument, format("airfoil file \"%s\", line %zu: non-finite coordinate", path, number));
        if (pts.empty()) first_line = number;
        pts.push_back(p);
        line.clear();
    }
    if (pts.size() < 4) fail(Failure::Argument, format("airfoil file \"%s\": %zu points, need at least 4", path, pts.size()));
    std::vector<double> x, y;
    const Pair head = pts[0];
    const bool lednicer = head.x > 1.5 && head.y > 1.5 && head.x == std::floor(head.x) && head.y == std::floor(head.y);
    if (lednicer) {
        // Compared as doubles first: a count beyond size_t is undefined to convert
        // (UBSan, found by fuzz_airfoil), and size_t sums could wrap.
        if (head.x + head.y != static_cast<double>(pts.size() - 1))
            fail(Failure::Argument, format("Lednicer file \"%s\" (line %zu): announces %.15g + %.15g points but has %zu",
                                           path, first_line, head.x, head.y, pts.size() - 1));
        const std::size_t nu = static_cast<std::size_t>(head.x), nl = static_cast<std::size_t>(head.y);
        for (std::size_t k = nu + nl; k > nu; --k) { x.push_back(pts[k].x); y.push_back(pts[k].y); }  // lower, TE -> LE
        for (std::size_t k = 1; k <= nu; ++k) {  // upper, LE -> TE (its LE point is the lower's)
            if (k == 1 && pts[k].x == x.back() && pts[k].y == y.back()) continue;
            x.push_back(pts[k].x);
            y.push_back(pts[k].y);
        }
    } else {  // Selig: reverse, so the lower surface comes first
        for (std::size_t k = pts.size(); k-- > 0;) { x.push_back(pts[k].x); y.push_back(pts[k].y); }
    }
    return make_spline(x.data(), y.data(), static_cast<int>(x.size()), true);
}

}  // namespace eg2d
