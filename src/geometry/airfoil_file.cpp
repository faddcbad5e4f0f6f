// Airfoil coordinate files as the UIUC database and others hand them out:
//  Selig:    x y pairs round the section from the trailing edge (any
//            direction and start are accepted: airfoil_outline.cpp);
//  Lednicer: a line "NU NL" (point counts), then the upper surface from
//            leading to trailing edge, then the lower one (airfoil_lednicer.cpp).
// Lines before the first point are the header (the first is the name); a
// line is a point by its content (exactly two numbers), so a file without a
// name line loses nothing. Blank lines, CRLF, tabs and commas are allowed;
// text after the last point is ignored; text between points is refused.
// The points become one spline oriented like make_naca4.
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "base/regular_file.hpp"
#include "geometry/airfoil_lednicer.hpp"
#include "geometry/airfoil_lines.hpp"
#include "geometry/airfoil_outline.hpp"
#include "geometry/curve.hpp"

namespace eg2d {

namespace {

// The points of the file and their line numbers. Text after a point is kept
// pending: it is the file's trailing notes unless another point follows.
struct Points {
    std::vector<OutlinePoint> pts;
    std::vector<std::size_t> lines;
};

Points read_points(std::FILE *f, const char *path) {
    Points r;
    AirfoilLines lines(f, path);
    AirfoilLine line;
    std::size_t text_line = 0;  // the first text line after a point
    std::string text;
    while (lines.next(line)) {
        if (line.kind == LineKind::Blank) continue;
        if (line.kind == LineKind::Text) {
            if (!r.pts.empty() && text_line == 0) text_line = line.number, text = quoted(line.text);
            continue;
        }
        if (text_line != 0)
            fail(Failure::Argument,
                 format("airfoil file \"%s\", line %zu: %s is not a pair of numbers (points before it at line %zu "
                        "and after it at line %zu)",
                        path, text_line, text.c_str(), r.lines.back(), line.number));
        if (!std::isfinite(line.x) || !std::isfinite(line.y))
            fail(Failure::Argument, format("airfoil file \"%s\", line %zu: non-finite coordinate in %s", path,
                                           line.number, quoted(line.text).c_str()));
        r.pts.push_back({line.x, line.y});
        r.lines.push_back(line.number);
    }
    if (std::ferror(f)) fail(Failure::Io, format("cannot read airfoil file \"%s\": %s", path, std::strerror(errno)));
    return r;
}

}  // namespace

std::shared_ptr<Curve> read_airfoil(const char *path) {
    require_regular_file(path);
    const std::unique_ptr<std::FILE, int (*)(std::FILE *)> file(std::fopen(path, "r"), std::fclose);
    if (!file) fail(Failure::Io, format("cannot open airfoil file \"%s\": %s", path, std::strerror(errno)));
    const Points r = read_points(file.get(), path);
    if (r.pts.size() < 4)
        fail(Failure::Argument, format("airfoil file \"%s\": %zu points, need at least 4", path, r.pts.size()));
    const bool lednicer = lednicer_counts(r.pts);
    // Neither counts nor a point: a name made of two numbers, or a stray line.
    if (!lednicer && first_off_outline(r.pts))
        fail(Failure::Argument, format("airfoil file \"%s\", line %zu: (%.15g, %.15g) lies far off the outline the other "
                                       "points draw, and is not Lednicer's counts (whole numbers > 1 before a surface "
                                       "from the leading edge): make it a name line with a word, or remove it",
                                       path, r.lines[0], r.pts[0].x, r.pts[0].y));
    const Outline o = normalise_outline(lednicer ? lednicer_outline(r.pts, r.lines, path) : r.pts, path);
    return make_spline(o.x.data(), o.y.data(), static_cast<int>(o.x.size()), true);
}

}  // namespace eg2d
