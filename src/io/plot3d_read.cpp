// Plot3D reader. The variant is found by trying each layout against the
// file: binary layouts must account for every byte (and, with Fortran
// record markers, every marker must match its record), ASCII layouts for
// every number. A file that fits none is rejected with what was found.
#include "io/plot3d_read.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "base/error.hpp"
#include "base/regular_file.hpp"
#include "eg2d.h"
#include "io/plot3d.hpp"

namespace eg2d {

namespace {

// The header of a candidate layout: grids, and the dimension count d (2 or 3).
struct Layout {
    bool multi;
    int dims;
};
const Layout kLayouts[] = {{true, 3}, {true, 2}, {false, 3}, {false, 2}};

std::size_t nodes(const Plot3dBlock &b) {
    return static_cast<std::size_t>(b.ni) * static_cast<std::size_t>(b.nj) * static_cast<std::size_t>(b.nk);
}

// A grid has at least 2 x 2 nodes: a file cut short can otherwise pass as a
// 1 x n grid of another layout.
bool plausible(const Plot3dBlock &b) {
    return b.ni >= 2 && b.nj >= 2 && b.nk >= 1 && nodes(b) <= (std::size_t{1} << 40);
}

// A coordinate no grid has, in any unit: what a file of another layout (or a
// cut one) gives when its bytes are read as reals of the wrong size or at the
// wrong offset (an integer read as a single-precision real is subnormal).
bool implausible(double v, std::size_t real) {
    const double a = std::fabs(v);
    if (real == 4) return a > 1e30 || (a != 0.0 && a < 1.1754943508222875e-38);  // FLT_MIN: subnormal
    return a > 1e100 || (a != 0.0 && a < 1e-100);
}

// Whether the file starts with a Fortran record of a Plot3D header (the grid
// count, or 2 or 3 dimensions: 4, 8 or 12 bytes between equal markers), in
// either byte order. Such a file has record markers: it is not read as a
// marker-less file too, which a cut one could otherwise pass as (a 6 x 5 file
// cut to 392 bytes is a valid marker-less 8 x 6 single-precision grid).
bool starts_with_record(const std::vector<unsigned char> &b) {
    for (bool big : {false, true}) {
        auto word = [&](std::size_t at) {
            std::uint32_t w = 0;
            for (int k = 0; k < 4; ++k) w |= static_cast<std::uint32_t>(b[at + (big ? 3 - k : k)]) << (8 * k);
            return w;
        };
        if (b.size() < 8) return false;
        const std::uint32_t n = word(0);
        if ((n == 4 || n == 8 || n == 12) && b.size() >= 8 + n && word(4 + n) == n) return true;
    }
    return false;
}

// The largest file read: far beyond any 2-D grid (1e9 nodes in doubles),
// short of what a device or a runaway file would take.
constexpr long long kMaxFileBytes = 16LL << 30;

// Sequential binary input with optional Fortran record markers.
class BinaryCursor {
public:
    BinaryCursor(const std::vector<unsigned char> &bytes, bool big_endian, bool markers)
        : b_(bytes), swap_(big_endian != plot3d::host_big_endian()), markers_(markers) {}

    // Opens a record of `expected` bytes (0 = any, returned); false if it does not fit.
    bool open(std::size_t &bytes) {
        if (!markers_) return bytes == 0 ? false : fits(bytes);
        std::int32_t m;
        if (!raw(&m, 4)) return false;
        if (m < 0 || (bytes != 0 && static_cast<std::size_t>(m) != bytes)) return false;
        bytes = static_cast<std::size_t>(m);
        record_ = bytes;
        return fits(bytes + 4);
    }
    bool close() {
        if (!markers_) return true;
        std::int32_t m;
        return raw(&m, 4) && static_cast<std::size_t>(m) == record_;
    }
    bool ints(std::int32_t *v, std::size_t n) { return raw_items(v, n, 4); }
    bool reals(double *v, std::size_t n, std::size_t real) {
        if (real == 8) return raw_items(v, n, 8);
        std::vector<float> f(n);
        if (!raw_items(f.data(), n, 4)) return false;
        for (std::size_t k = 0; k < n; ++k) v[k] = f[k];
        return true;
    }
    void skip(std::size_t bytes) { pos_ += bytes; }
    bool at_end() const { return pos_ == b_.size(); }
    std::size_t position() const { return pos_; }
    std::size_t size() const { return b_.size(); }

private:
    bool fits(std::size_t bytes) const { return bytes <= b_.size() - pos_; }
    bool raw(void *p, std::size_t bytes) {
        if (!fits(bytes)) return false;
        std::memcpy(p, b_.data() + pos_, bytes);
        pos_ += bytes;
        if (swap_ && bytes == 4) plot3d::swap_items(p, 1, 4);
        return true;
    }
    bool raw_items(void *p, std::size_t n, std::size_t size) {
        if (n > (b_.size() - pos_) / size) return false;
        std::memcpy(p, b_.data() + pos_, n * size);
        pos_ += n * size;
        if (swap_) plot3d::swap_items(p, n, size);
        return true;
    }
    const std::vector<unsigned char> &b_;
    bool swap_, markers_;
    std::size_t pos_ = 0, record_ = 0;
};

// Tries one binary layout; on success fills file (and block `want`'s data).
bool try_binary(const std::vector<unsigned char> &bytes, bool big_endian, bool markers, Layout layout, int want,
                Plot3dFile &file) {
    BinaryCursor c(bytes, big_endian, markers);
    std::int32_t ngrid = 1;
    std::size_t len = 4;
    if (layout.multi) {
        if (!c.open(len) || !c.ints(&ngrid, 1) || !c.close() || ngrid < 1 || ngrid > (1 << 20)) return false;
    }
    std::vector<std::int32_t> dims(static_cast<std::size_t>(ngrid) * layout.dims);
    len = dims.size() * 4;
    if (!c.open(len) || !c.ints(dims.data(), dims.size()) || !c.close()) return false;
    std::vector<Plot3dBlock> blocks(static_cast<std::size_t>(ngrid));
    std::size_t total_nodes = 0;
    for (std::size_t g = 0; g < blocks.size(); ++g) {
        Plot3dBlock &b = blocks[g];
        b.ni = dims[g * layout.dims];
        b.nj = dims[g * layout.dims + 1];
        b.nk = layout.dims == 3 ? dims[g * layout.dims + 2] : 1;
        if (!plausible(b)) return false;
        total_nodes += nodes(b);
    }
    // The real size follows from the bytes left: every byte must be used.
    const std::size_t framing = markers ? 8 * blocks.size() : 0;
    if (total_nodes == 0 || c.size() - c.position() < framing) return false;
    const std::size_t left = c.size() - c.position() - framing;
    const std::size_t per = total_nodes * static_cast<std::size_t>(layout.dims);
    if (left % per != 0) return false;
    const std::size_t real = left / per;
    if (real != 4 && real != 8) return false;
    for (std::size_t g = 0; g < blocks.size(); ++g) {
        Plot3dBlock &b = blocks[g];
        const std::size_t n = nodes(b), rec = n * layout.dims * real;
        std::size_t got = rec;
        if (!c.open(got)) return false;
        if (static_cast<int>(g) == want) {
            const std::size_t at = c.position();
            b.x.resize(n);
            b.y.resize(n);
            if (!c.reals(b.x.data(), n, real) || !c.reals(b.y.data(), n, real)) return false;
            for (std::size_t k = 0; k < 2 * n; ++k) {
                const double v = k < n ? b.x[k] : b.y[k - n];
                if (!std::isfinite(v))
                    fail(Failure::Io, format("a non-finite coordinate (%s) at byte offset %zu", std::isnan(v) ? "NaN" : "Inf",
                                             at + k * real));
                if (implausible(v, real)) return false;  // not this layout
            }
            c.skip(rec - 2 * n * real);
        } else {
            c.skip(rec);
        }
        if (!c.close()) return false;
    }
    if (!c.at_end()) return false;
    file.format = EG2D_FORMAT_PLOT3D | (layout.multi ? EG2D_PLOT3D_MULTI : 0) |
                  (layout.dims == 3 ? EG2D_PLOT3D_3D : 0) | (real == 4 ? EG2D_PLOT3D_SINGLE : 0) |
                  (big_endian ? EG2D_PLOT3D_BIG_ENDIAN : 0) | (markers ? 0 : EG2D_PLOT3D_NO_MARKERS);
    file.blocks = std::move(blocks);
    return true;
}

bool whole(double v) { return v == std::floor(v) && std::fabs(v) < 2147483647.0; }

bool try_ascii(const std::vector<double> &t, Layout layout, int want, Plot3dFile &file) {
    std::size_t p = 0;
    double ngrid = 1;
    if (layout.multi) {
        if (t.empty() || !whole(t[0]) || t[0] < 1) return false;
        ngrid = t[p++];
    }
    const std::size_t ng = static_cast<std::size_t>(ngrid);
    if (t.size() - p < ng * layout.dims) return false;
    std::vector<Plot3dBlock> blocks(ng);
    std::size_t total = 0;
    for (Plot3dBlock &b : blocks) {
        for (int d = 0; d < layout.dims; ++d)
            if (!whole(t[p + d])) return false;
        b.ni = static_cast<int>(t[p]);
        b.nj = static_cast<int>(t[p + 1]);
        b.nk = layout.dims == 3 ? static_cast<int>(t[p + 2]) : 1;
        p += layout.dims;
        if (!plausible(b)) return false;
        total += nodes(b) * layout.dims;
    }
    if (t.size() - p != total) return false;
    for (std::size_t g = 0; g < ng; ++g) {
        Plot3dBlock &b = blocks[g];
        const std::size_t n = nodes(b);
        if (static_cast<int>(g) == want) {
            b.x.assign(t.begin() + static_cast<std::ptrdiff_t>(p), t.begin() + static_cast<std::ptrdiff_t>(p + n));
            b.y.assign(t.begin() + static_cast<std::ptrdiff_t>(p + n),
                       t.begin() + static_cast<std::ptrdiff_t>(p + 2 * n));
        }
        p += n * layout.dims;
    }
    file.format = EG2D_FORMAT_PLOT3D_ASCII | (layout.multi ? EG2D_PLOT3D_MULTI : 0) |
                  (layout.dims == 3 ? EG2D_PLOT3D_3D : 0);
    file.blocks = std::move(blocks);
    return true;
}

// All whitespace-separated numbers of a text file; false at the first
// token that is not one (a binary file), with its line in `where`.
bool numbers(const std::vector<unsigned char> &bytes, std::vector<double> &out, std::string &where) {
    std::string text(bytes.begin(), bytes.end());
    if (text.find('\0') != std::string::npos) {
        where = "it has NUL bytes (binary) but no Plot3D binary layout fits its size";
        return false;
    }
    const char *s = text.c_str(), *end = s + text.size();
    int line = 1;
    while (s < end) {
        if (*s == '\n') ++line;
        if (std::isspace(static_cast<unsigned char>(*s)) || *s == ',') {
            ++s;
            continue;
        }
        // Fortran may write a D exponent (1.5D+00): read it as E.
        const char *e = s;
        while (e < end && !std::isspace(static_cast<unsigned char>(*e)) && *e != ',') ++e;
        std::string token(s, e);
        for (char &ch : token)
            if (ch == 'D' || ch == 'd') ch = 'E';
        char *stop;
        const double v = std::strtod(token.c_str(), &stop);
        if (stop != token.c_str() + token.size() || !std::isfinite(v)) {
            where = format("line %d: \"%s\" is not a number", line, std::string(s, e).substr(0, 24).c_str());
            return false;
        }
        out.push_back(v);
        s = e;
    }
    return true;
}

}  // namespace

Plot3dFile read_plot3d(const std::string &path, int block) {
    std::vector<unsigned char> bytes = read_regular_file(path, kMaxFileBytes);
    if (bytes.empty()) fail(Failure::Io, format("%s: the file is empty", path.c_str()));
    Plot3dFile file;
    bool found = false;
    try {
        const bool has_markers = starts_with_record(bytes);
        for (bool markers : {true, false})
            for (bool big : {false, true})
                for (Layout l : kLayouts)
                    if (!found && (markers || !has_markers)) found = try_binary(bytes, big, markers, l, block, file);
    } catch (const Error &e) {  // a layout that fits but holds a bad value
        fail(e.failure(), format("%s: %s", path.c_str(), e.what()));
    }
    if (!found) {
        std::vector<double> t;
        std::string where;
        if (!numbers(bytes, t, where))
            fail(Failure::Io, format("%s: not a Plot3D grid file: %s", path.c_str(), where.c_str()));
        for (Layout l : kLayouts)
            if (!found) found = try_ascii(t, l, block, file);
        if (!found)
            fail(Failure::Io, format("%s: not a Plot3D grid file: its %zu numbers fit no 2D/3D, single-/multi-grid "
                                     "layout (truncated?)",
                                     path.c_str(), t.size()));
    }
    if (block >= static_cast<int>(file.blocks.size()))
        fail(Failure::Argument,
             format("block = %d: %s has %zu grid(s)", block, path.c_str(), file.blocks.size()));
    if (block >= 0 && file.blocks[static_cast<std::size_t>(block)].nk != 1)
        fail(Failure::Io, format("%s: grid %d is 3D with nk = %d planes; a 2D grid has nk = 1", path.c_str(), block,
                                 file.blocks[static_cast<std::size_t>(block)].nk));
    return file;
}

}  // namespace eg2d
