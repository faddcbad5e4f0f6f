#include "view_lines.hpp"

#include <algorithm>
#include <cmath>

namespace eg2dtool {

namespace {

// A point is left out when the line drawn without it passes within this
// many pixels of it: the drawing moves by less than that.
constexpr double kSkip = 0.3;
// At most this many points are left out in a row (bounds the work per point).
constexpr std::size_t kRun = 32;

// The part t in [t0, t1] of the segment a + t (b - a) inside the window
// (Liang-Barsky); false when none is. t0 stays exactly 0 (t1 exactly 1)
// when a (b) is inside, which is how a clipped line knows it goes on.
bool clip(const View &v, double ax, double ay, double bx, double by, double &t0, double &t1) {
    const double dx = bx - ax, dy = by - ay;
    const double p[4] = {-dx, dx, -dy, dy}, q[4] = {ax - v.xmin, v.xmax - ax, ay - v.ymin, v.ymax - ay};
    t0 = 0.0;
    t1 = 1.0;
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0.0) {
            if (q[k] < 0.0) return false;  // parallel to this edge, outside it
            continue;
        }
        const double t = q[k] / p[k];
        if (p[k] < 0.0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
    }
    return t0 <= t1;
}

// The distance from (x, y) to the segment from (ax, ay) to (bx, by).
double to_segment(double x, double y, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay, d2 = dx * dx + dy * dy;
    const double t = d2 > 0 ? std::min(1.0, std::max(0.0, ((x - ax) * dx + (y - ay) * dy) / d2)) : 0.0;
    return std::hypot(x - ax - t * dx, y - ay - t * dy);
}

// One polyline being built. The points after the last one kept wait in
// `skipped` while a straight segment from that point to the newest stands
// for all of them within kSkip pixels; the newest is kept when the next
// would not, and at the end, so a line's true ends are never lost.
struct Builder {
    std::vector<Polyline> &out;
    double skip;
    Polyline line{kGridLine, {}};
    std::vector<double> skipped;

    void start(LineKind kind, double x, double y) {
        finish();
        line = {kind, {x, y}};
    }
    void add(double x, double y) {
        const double kx = line.xy[line.xy.size() - 2], ky = line.xy.back();
        bool stands = skipped.size() < 2 * kRun;
        for (std::size_t k = 0; stands && k < skipped.size(); k += 2)
            stands = to_segment(skipped[k], skipped[k + 1], kx, ky, x, y) < skip;
        if (!stands) {
            line.xy.insert(line.xy.end(), skipped.end() - 2, skipped.end());
            skipped.clear();
        }
        skipped.push_back(x);
        skipped.push_back(y);
    }
    void finish() {
        if (!skipped.empty()) line.xy.insert(line.xy.end(), skipped.end() - 2, skipped.end());
        skipped.clear();
        if (line.xy.size() >= 4) out.push_back(std::move(line));
        line.xy.clear();
    }
};

}  // namespace

View fitted_view(const std::string &name, double x0, double y0, double x1, double y1, int width, int height) {
    const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
    double w = x1 - x0, h = y1 - y0;
    if (w * height < h * width) w = h * width / height;
    else h = w * height / width;
    return {name, cx - 0.5 * w, cy - 0.5 * h, cx + 0.5 * w, cy + 0.5 * h, width, height};
}

std::vector<Polyline> view_lines(const GridLines &g, const View &v) {
    std::vector<Polyline> out;
    Builder b{out, kSkip * v.pixel(), {kGridLine, {}}, {}};
    for (const LineRef &l : g.lines) {
        bool open = false;  // the line being built ends at this segment's start
        for (int k = 0; k + 1 < l.count; ++k) {
            const std::size_t a = l.first + k * l.stride, e = a + l.stride;
            double t0, t1;
            if (!clip(v, g.x[a], g.y[a], g.x[e], g.y[e], t0, t1)) {
                open = false;
                continue;
            }
            const double dx = g.x[e] - g.x[a], dy = g.y[e] - g.y[a];
            if (!open || t0 > 0.0) b.start(l.kind, g.x[a] + t0 * dx, g.y[a] + t0 * dy);
            b.add(g.x[a] + t1 * dx, g.y[a] + t1 * dy);
            open = t1 == 1.0;
        }
        b.finish();
    }
    return out;
}

const LineStyle &line_style(LineKind kind) {
    static const LineStyle styles[] = {
        {"grid", {0x44, 0x44, 0x44}, 0.5},
        {"boundary", {0x00, 0x00, 0x00}, 1.5},
        {"wall", {0xc0, 0x10, 0x10}, 1.5},
    };
    return styles[kind];
}

}  // namespace eg2dtool
