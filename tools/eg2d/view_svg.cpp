#include "view_picture.hpp"

#include <algorithm>
#include <cmath>

#include "svg_text.hpp"

namespace eg2dtool {

std::string view_svg(const View &v, const std::vector<Polyline> &lines, const std::string &title) {
    // coordinates to a tenth of a pixel: enough decimals, and no more
    const int digits = std::max(0, static_cast<int>(std::ceil(-std::log10(0.1 * v.pixel()))));
    std::string s;
    append(s, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" "
              "height=\"%d\" viewBox=\"%.*f %.*f %.*f %.*f\">\n",
           v.width, v.height, digits, v.xmin, digits, -v.ymax, digits, v.xmax - v.xmin, digits, v.ymax - v.ymin);
    s += "<title>" + xml_text(title) + "</title>\n<style>";
    for (LineKind k : {kGridLine, kBoundaryLine, kWallLine}) {
        const LineStyle &l = line_style(k);
        append(s, ".%s{fill:none;stroke:#%02x%02x%02x;stroke-width:%.3g;stroke-linejoin:round}", l.name, l.rgb[0],
               l.rgb[1], l.rgb[2], l.width * v.pixel());
    }
    append(s, "</style>\n<rect x=\"%.*f\" y=\"%.*f\" width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n", digits,
           v.xmin, digits, -v.ymax);
    for (const Polyline &p : lines) {
        append(s, "<polyline class=\"%s\" points=\"", line_style(p.kind).name);
        for (std::size_t k = 0; k < p.xy.size(); k += 2)
            append(s, "%s%.*f,%.*f", k ? " " : "", digits, p.xy[k], digits, -p.xy[k + 1]);
        s += "\"/>\n";
    }
    return s + "</svg>\n";
}

}  // namespace eg2dtool
