// SVG picture of the grid for a browser: the grid lines, the boundary drawn
// thicker, and (EG2D_PARAM_SVG_QUALITY) the cells coloured by a per-cell
// quality metric from blue (the grid's lowest value) to red (its highest),
// with a legend. Physical y points up; SVG's y points down, so y is flipped.
#include <algorithm>
#include <cmath>
#include <limits>

#include "base/error.hpp"
#include "io/formats.hpp"
#include "base/cell.hpp"
#include "quality/quality.hpp"

namespace eg2d {

namespace {
constexpr double kWidth = 800.0, kMargin = 20.0, kLegend = 60.0;

struct Frame {
    double xmin, ymax, scale;
    double px(double x) const { return kMargin + (x - xmin) * scale; }
    double py(double y) const { return kMargin + (ymax - y) * scale; }
};

void colour(double t, int rgb[3]) {
    t = std::min(1.0, std::max(0.0, t));
    rgb[0] = static_cast<int>(std::lround(255 * t));
    rgb[1] = static_cast<int>(std::lround(255 * (1 - std::fabs(2 * t - 1)) * 0.8));
    rgb[2] = static_cast<int>(std::lround(255 * (1 - t)));
}

void line(OutputFile &out, const Grid &g, const Frame &f, bool along_i, int fixed, const char *style) {
    out.print("<polyline class=\"%s\" points=\"", style);
    const int n = along_i ? g.ni() : g.nj();
    for (int m = 0; m < n; ++m) {
        const std::size_t k = along_i ? static_cast<std::size_t>(m) + static_cast<std::size_t>(g.ni()) * fixed
                                      : static_cast<std::size_t>(fixed) + static_cast<std::size_t>(g.ni()) * m;
        out.print("%.3f,%.3f%s", f.px(g.x[k]), f.py(g.y[k]), m + 1 == n ? "" : " ");
    }
    out.print("\"/>\n");
}
}  // namespace

void write_svg(const WriteRequest &r, OutputFile &out) {
    const Grid &g = r.grid;
    const QualityMetric *metric = nullptr;
    if (r.settings.svg_quality >= 0) {
        const int id = static_cast<int>(r.settings.svg_quality);
        metric = find_quality_metric(id);
        if (!metric) fail(Failure::Argument, format("svg_quality = %d: no such quality metric", id));
        if (!metric->cells)
            fail(Failure::Argument, format("svg_quality = %d (%s): a boundary summary with no per-cell values to "
                                           "colour by", id, metric->name));
    }
    const auto [xlo, xhi] = std::minmax_element(g.x.begin(), g.x.end());
    const auto [ylo, yhi] = std::minmax_element(g.y.begin(), g.y.end());
    const double span = std::max(*xhi - *xlo, *yhi - *ylo);
    const Frame f{*xlo, *yhi, span > 0 ? (kWidth - 2 * kMargin) / span : 1.0};
    const double width = 2 * kMargin + (*xhi - *xlo) * f.scale;
    const double height = 2 * kMargin + (*yhi - *ylo) * f.scale + (metric ? kLegend : 0.0);
    out.print("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
              "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.3f %.3f\">\n"
              "<title>eg2d grid %d x %d%s%s</title>\n"
              "<!-- eg2d frame: xmin %.17g ymax %.17g scale %.17g margin %g (pixel = margin + (x - xmin) scale, "
              "margin + (ymax - y) scale): a zoomed view is this file with another viewBox -->\n"
              "<style>.grid{fill:none;stroke:#333;stroke-width:0.6}"
              ".boundary{fill:none;stroke:#000;stroke-width:2.5;stroke-linejoin:round}"
              "text{font:13px sans-serif}</style>\n"
              "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
              std::ceil(width), std::ceil(height), width, height, g.ni(), g.nj(), metric ? ", cells coloured by " : "",
              metric ? metric->name : "", f.xmin, f.ymax, f.scale, kMargin);
    if (metric) {
        std::vector<double> v(cell_count(g));
        metric->cells(g, v.data());
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (double a : v)
            if (std::isfinite(a)) lo = std::min(lo, a), hi = std::max(hi, a);
        if (!(lo <= hi)) lo = hi = 0.0;
        out.print("<g class=\"cells\" stroke=\"none\">\n");
        for (int j = 0; j < g.nj() - 1; ++j)
            for (int i = 0; i < g.ni() - 1; ++i) {
                const double a = v[static_cast<std::size_t>(i) + static_cast<std::size_t>(g.ni() - 1) * j];
                int rgb[3];
                colour(hi > lo ? ((std::isfinite(a) ? a : hi) - lo) / (hi - lo) : 0.0, rgb);
                out.print("<polygon fill=\"rgb(%d,%d,%d)\" points=\"", rgb[0], rgb[1], rgb[2]);
                const int ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
                for (int m = 0; m < 4; ++m) {
                    const std::size_t k = static_cast<std::size_t>(ci[m]) + static_cast<std::size_t>(g.ni()) * cj[m];
                    out.print("%.3f,%.3f%s", f.px(g.x[k]), f.py(g.y[k]), m == 3 ? "" : " ");
                }
                out.print("\"/>\n");
            }
        out.print("</g>\n");
        // Legend: a bar from the lowest to the highest value.
        const double top = height - kLegend + 15, bar = std::min(300.0, width - 2 * kMargin);
        out.print("<defs><linearGradient id=\"scale\">");
        for (int s = 0; s <= 4; ++s) {
            int rgb[3];
            colour(s / 4.0, rgb);
            out.print("<stop offset=\"%d%%\" stop-color=\"rgb(%d,%d,%d)\"/>", 25 * s, rgb[0], rgb[1], rgb[2]);
        }
        out.print("</linearGradient></defs>\n"
                  "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"12\" fill=\"url(#scale)\"/>\n"
                  "<text x=\"%.1f\" y=\"%.1f\">%s: %.4g</text>\n"
                  "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">%.4g</text>\n",
                  kMargin, top, bar, kMargin, top + 28, metric->name, lo, kMargin + bar, top + 28, hi);
    }
    out.print("<g class=\"lines\">\n");
    for (int j = 1; j < g.nj() - 1; ++j) line(out, g, f, true, j, "grid");
    for (int i = 0; i < g.ni(); ++i)
        if (g.connectivity().periodic_i() || (i > 0 && i < g.ni() - 1)) line(out, g, f, false, i, "grid");
    line(out, g, f, true, 0, "boundary");
    line(out, g, f, true, g.nj() - 1, "boundary");
    if (!g.connectivity().periodic_i()) {
        line(out, g, f, false, 0, "boundary");
        line(out, g, f, false, g.ni() - 1, "boundary");
    }
    out.print("</g>\n</svg>\n");
}

}  // namespace eg2d
