#include "svg_picture.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace eg2dtool {

std::string write_svg_picture(const std::string &path, int ni, int nj, const std::vector<double> &x,
                              const std::vector<double> &y) {
    const double x0 = *std::min_element(x.begin(), x.end()), x1 = *std::max_element(x.begin(), x.end());
    const double y0 = *std::min_element(y.begin(), y.end()), y1 = *std::max_element(y.begin(), y.end());
    const double size = std::max(x1 - x0, y1 - y0) > 0 ? std::max(x1 - x0, y1 - y0) : 1;
    const double scale = 800 / size, margin = 10;
    const double w = (x1 - x0) * scale + 2 * margin, h = (y1 - y0) * scale + 2 * margin;
    const std::string tmp = path + ".tmp";
    std::FILE *f = std::fopen(tmp.c_str(), "w");
    if (!f) return std::strerror(errno);
    auto px = [&](std::size_t k) { return margin + (x[k] - x0) * scale; };
    auto py = [&](std::size_t k) { return margin + (y1 - y[k]) * scale; };  // y up
    std::fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.2f %.2f\">\n"
                    "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
                 w, h, w, h);
    auto polyline = [&](int count, auto index, const char *style) {
        std::fprintf(f, "<polyline fill=\"none\" %s points=\"", style);
        for (int q = 0; q < count; ++q) std::fprintf(f, "%s%.2f,%.2f", q ? " " : "", px(index(q)), py(index(q)));
        std::fprintf(f, "\"/>\n");
    };
    const char *line = "stroke=\"#2060a0\" stroke-width=\"0.6\"", *edge = "stroke=\"black\" stroke-width=\"1.8\"";
    const std::size_t n = static_cast<std::size_t>(ni);
    for (int j = 0; j < nj; ++j)
        polyline(ni, [&](int i) { return static_cast<std::size_t>(i) + n * static_cast<std::size_t>(j); },
                 j == 0 || j == nj - 1 ? edge : line);
    for (int i = 0; i < ni; ++i)
        polyline(nj, [&](int j) { return static_cast<std::size_t>(i) + n * static_cast<std::size_t>(j); },
                 i == 0 || i == ni - 1 ? edge : line);
    std::fprintf(f, "</svg>\n");
    const bool ok = !std::ferror(f);
    if (std::fclose(f) != 0 || !ok) {
        std::remove(tmp.c_str());
        return std::strerror(errno);
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        std::remove(tmp.c_str());
        return reason;
    }
    return "";
}

}  // namespace eg2dtool
