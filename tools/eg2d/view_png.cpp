// PNG pictures through cairo (Debian's libcairo2-dev), when the build found it.
#include "view_picture.hpp"

#include "failure.hpp"

#ifdef EG2D_HAVE_CAIRO
#include <cairo.h>

#include <memory>
#endif

namespace eg2dtool {

#ifdef EG2D_HAVE_CAIRO

bool png_available() { return true; }

std::string view_png(const View &v, const std::vector<Polyline> &lines) {
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, v.width, v.height), cairo_surface_destroy);
    std::unique_ptr<cairo_t, decltype(&cairo_destroy)> owner(cairo_create(surface.get()), cairo_destroy);
    cairo_t *cr = owner.get();
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    // pixels from the plane: the lines are clipped to the window, so these
    // stay inside cairo's fixed-point range however far the grid reaches
    const double scale = 1.0 / v.pixel();
    for (std::size_t k = 0; k < lines.size();) {  // one path per run of lines of one kind
        const LineStyle &style = line_style(lines[k].kind);
        for (const LineKind kind = lines[k].kind; k < lines.size() && lines[k].kind == kind; ++k) {
            const std::vector<double> &xy = lines[k].xy;
            for (std::size_t m = 0; m < xy.size(); m += 2) {
                const double px = (xy[m] - v.xmin) * scale, py = (v.ymax - xy[m + 1]) * scale;
                m ? cairo_line_to(cr, px, py) : cairo_move_to(cr, px, py);
            }
        }
        cairo_set_source_rgb(cr, style.rgb[0] / 255.0, style.rgb[1] / 255.0, style.rgb[2] / 255.0);
        cairo_set_line_width(cr, style.width);
        cairo_stroke(cr);
    }
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS)
        throw Failure(EXIT_INTERNAL, std::string("png: cairo: ") + cairo_status_to_string(cairo_status(cr)));
    std::string bytes;
    auto append = [](void *closure, const unsigned char *data, unsigned int length) {
        static_cast<std::string *>(closure)->append(reinterpret_cast<const char *>(data), length);
        return CAIRO_STATUS_SUCCESS;
    };
    const cairo_status_t st = cairo_surface_write_to_png_stream(surface.get(), append, &bytes);
    if (st != CAIRO_STATUS_SUCCESS) throw Failure(EXIT_INTERNAL, std::string("png: cairo: ") + cairo_status_to_string(st));
    return bytes;
}

#else

bool png_available() { return false; }

std::string view_png(const View &, const std::vector<Polyline> &) {
    throw Failure(EXIT_UNSUPPORTED, "png: this build has no PNG writer: cairo (Debian's libcairo2-dev) was not found "
                                    "when it was configured");
}

#endif

}  // namespace eg2dtool
