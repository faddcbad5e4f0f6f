#include "run_files.hpp"

#include <eg2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "failure.hpp"
#include "svg_text.hpp"

namespace eg2dtool {

namespace {

// A tick step of 1, 2 or 5 times a power of ten giving at most ~8 ticks over span.
double tick_step(double span) {
    const double raw = span / 8, p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= raw) return m * p;
    return 10 * p;
}

}  // namespace

std::string history_csv(const std::vector<HistoryRow> &rows) {
    std::string out = "iteration,residual\n";
    for (const auto &r : rows) append(out, "%d,%.17g\n", r.iteration, r.residual);
    return out;
}

std::string history_svg(const std::vector<HistoryRow> &rows, double tolerance, const std::string &title) {
    constexpr double W = 640, H = 420, left = 72, right = 24, top = 44, bottom = 52;
    // The decades shown: every positive finite residual and the tolerance.
    double lo = tolerance > 0 ? std::log10(tolerance) : 0, hi = lo;
    for (const auto &r : rows)
        if (r.residual > 0 && std::isfinite(r.residual)) {
            lo = std::min(lo, std::log10(r.residual));
            hi = std::max(hi, std::log10(r.residual));
        }
    lo = std::floor(lo);
    hi = std::max(std::ceil(hi), lo + 1);
    const double last = rows.empty() ? 1 : std::max(1, rows.back().iteration);
    auto px = [&](double it) { return left + (W - left - right) * it / last; };
    auto py = [&](double r) {
        const double e = r > 0 && std::isfinite(r) ? std::log10(r) : lo;
        return top + (H - top - bottom) * (hi - std::max(lo, std::min(hi, e))) / (hi - lo);
    };
    std::string out;
    append(out,
           "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n",
           W, H, W, H);
    out += "<title>" + xml_text(title) + ": residual per iteration</title>\n";
    out += "<style>text{font:12px sans-serif}.axis{stroke:#000;fill:none}.grid{stroke:#ddd}"
           ".history{fill:none;stroke:#1f5fbf;stroke-width:1.5}.tolerance{stroke:#c00;stroke-dasharray:6 4}</style>\n"
           "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    // decades (every one, or every few when there are many)
    const int every = static_cast<int>(std::ceil((hi - lo) / 12));
    for (int e = static_cast<int>(lo); e <= static_cast<int>(hi); e += every) {
        const double y = py(std::pow(10.0, e));
        append(out, "<line class=\"grid\" x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>\n", left, y, W - right, y);
        append(out, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">1e%d</text>\n", left - 6, y + 4, e);
    }
    const double step = tick_step(last);
    for (double it = 0; it <= last + 1e-9 * last; it += step) {
        const double x = px(it);
        append(out, "<line class=\"grid\" x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>\n", x, top, x, H - bottom);
        append(out, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%g</text>\n", x, H - bottom + 16, it);
    }
    append(out, "<rect class=\"axis\" x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\"/>\n", left, top,
           W - left - right, H - top - bottom);
    if (tolerance > 0) {
        const double y = py(tolerance);
        append(out, "<line class=\"tolerance\" x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>\n", left, y, W - right, y);
        append(out, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\" fill=\"#c00\">tolerance %.3g</text>\n",
               W - right - 4, y - 4, tolerance);
    }
    if (!rows.empty()) {
        out += "<polyline class=\"history\" points=\"";
        for (std::size_t k = 0; k < rows.size(); ++k)
            append(out, "%s%.2f,%.2f", k ? " " : "", px(rows[k].iteration), py(rows[k].residual));
        out += "\"/>\n";
        if (rows.size() == 1)
            append(out, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"3\" fill=\"#1f5fbf\"/>\n", px(rows[0].iteration),
                   py(rows[0].residual));
    }
    std::string heading =
        rows.empty() ? title + ": no iterations (the start met the tolerance)"
                     : title + ": " + std::to_string(rows.size()) + " iteration" + (rows.size() == 1 ? "" : "s");
    if (!rows.empty()) append(heading, ", residual %.3e", rows.back().residual);
    append(out, "<text x=\"%.1f\" y=\"24\" text-anchor=\"middle\" font-weight=\"bold\">", (left + W - right) / 2);
    out += xml_text(heading) + "</text>\n";
    append(out, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">iteration</text>\n", (left + W - right) / 2, H - 12);
    append(out, "<text x=\"16\" y=\"%.1f\" text-anchor=\"middle\" transform=\"rotate(-90 16 %.1f)\">residual "
                "(docs/NUMERICS.md)</text>\n",
           (top + H - bottom) / 2, (top + H - bottom) / 2);
    out += "</svg>\n";
    return out;
}

std::string controls_csv(const eg2d_grid *grid) {
    int ni = 0, nj = 0;
    eg2d_get_size(grid, &ni, &nj);
    const std::size_t n = static_cast<std::size_t>(ni) * static_cast<std::size_t>(nj);
    std::vector<double> x(n), y(n), P(n), Q(n);
    int status = eg2d_get_coordinates(grid, x.data(), y.data());
    if (status == EG2D_OK) status = eg2d_get_controls(grid, P.data(), Q.data());
    if (status != EG2D_OK) throw Failure(exit_code_for_status(status), eg2d_last_error(grid));
    std::string out = "i,j,x,y,P,Q\n";
    out.reserve(out.size() + n * 100);
    for (int j = 0; j < nj; ++j)
        for (int i = 0; i < ni; ++i) {
            const std::size_t k = static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * static_cast<std::size_t>(j);
            append(out, "%d,%d,%.17g,%.17g,%.17g,%.17g\n", i, j, x[k], y[k], P[k], Q[k]);
        }
    return out;
}

}  // namespace eg2dtool
