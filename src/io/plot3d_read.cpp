// Plot3D reader. The variant is found by trying each layout against the
// file: binary layouts must account for every byte (and, with Fortran
// record markers, every marker must match its record), ASCII layouts for
// every number. A file that fits none is rejected with what was found.
#include "io/plot3d_read.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "base/c_locale.hpp"
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
        if (n > (b_.size() - pos_) / 4) return false;
        for (std::size_t k = 0; k < n; ++k) {  // each float straight into its double: no copy of the record
            float f = 0.0f;  // raw() fills it: the bound above holds (GCC -O3 cannot see that)
            raw(&f, 4);
            v[k] = f;
        }
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

// Block g of a header of d dimensions per block.
Plot3dBlock block_of(const std::int32_t *dims, std::size_t g, int d) {
    Plot3dBlock b;
    b.ni = dims[g * d];
    b.nj = dims[g * d + 1];
    b.nk = d == 3 ? dims[g * d + 2] : 1;
    return b;
}

// Tries one binary layout; on success fills file (and block `want`'s data).
bool try_binary(const std::vector<unsigned char> &bytes, bool big_endian, bool markers, Layout layout, int want,
                Plot3dFile &file) {
    BinaryCursor c(bytes, big_endian, markers);
    std::int32_t ngrid = 1;
    std::size_t len = 4;
    if (layout.multi) {
        if (!c.open(len) || !c.ints(&ngrid, 1) || !c.close() || ngrid < 1 || ngrid > (1 << 20)) return false;
    }
    // The dimensions are allocated once the file is known to hold them.
    const std::size_t ng = static_cast<std::size_t>(ngrid);
    len = ng * layout.dims * 4;
    if (!c.open(len)) return false;
    std::vector<std::int32_t> dims(ng * layout.dims);
    if (!c.ints(dims.data(), dims.size()) || !c.close()) return false;
    std::size_t total_nodes = 0;
    for (std::size_t g = 0; g < ng; ++g) {
        const Plot3dBlock b = block_of(dims.data(), g, layout.dims);
        if (!plausible(b)) return false;
        total_nodes += nodes(b);
    }
    // The real size follows from the bytes left: every byte must be used.
    const std::size_t framing = markers ? 8 * ng : 0;
    if (total_nodes == 0 || c.size() - c.position() < framing) return false;
    const std::size_t left = c.size() - c.position() - framing;
    const std::size_t per = total_nodes * static_cast<std::size_t>(layout.dims);
    if (left % per != 0) return false;
    const std::size_t real = left / per;
    if (real != 4 && real != 8) return false;
    Plot3dBlock wanted;
    for (std::size_t g = 0; g < ng; ++g) {
        Plot3dBlock b = block_of(dims.data(), g, layout.dims);
        const std::size_t n = nodes(b), rec = n * layout.dims * real;
        std::size_t got = rec;
        if (!c.open(got)) return false;
        if (static_cast<int>(g) == want) {  // the record is in the file: its coordinates are at most 2x its bytes
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
            wanted = std::move(b);
        } else {
            c.skip(rec);
        }
        if (!c.close()) return false;
    }
    if (!c.at_end()) return false;
    file.format = EG2D_FORMAT_PLOT3D | (layout.multi ? EG2D_PLOT3D_MULTI : 0) |
                  (layout.dims == 3 ? EG2D_PLOT3D_3D : 0) | (real == 4 ? EG2D_PLOT3D_SINGLE : 0) |
                  (big_endian ? EG2D_PLOT3D_BIG_ENDIAN : 0) | (markers ? 0 : EG2D_PLOT3D_NO_MARKERS);
    file.nblocks = ngrid;
    file.block = std::move(wanted);
    return true;
}

bool whole(double v) { return v == std::floor(v) && std::fabs(v) < 2147483647.0; }

// The whitespace- (or comma-) separated numbers of a text file, read in two
// passes over its bytes rather than kept: scan() counts them and keeps the
// header's integers, copy() gives one block's coordinates. What grows with
// the file is only the header (4 bytes an integer, each at least 2 of the
// file's) and the block asked for.
class AsciiNumbers {
public:
    explicit AsciiNumbers(const std::vector<unsigned char> &bytes) : b_(bytes) {}

    // False at the first token that is not a number (a binary file), with its line in `where`.
    bool scan(std::string &where) {
        if (std::memchr(b_.data(), 0, b_.size())) {
            where = "it has NUL bytes (binary) but no Plot3D binary layout fits its size";
            return false;
        }
        // The header is at most 1 + 3 ngrid numbers, ngrid the first (multi-grid layouts), else 3.
        std::size_t keep = 3;
        return each([&](std::size_t k, double v) {
            if (k == 0 && whole(v) && v >= 1) keep = std::max(keep, 1 + 3 * static_cast<std::size_t>(v));
            if (k < keep) {
                if (!whole(v) && first_fraction_ == npos) first_fraction_ = k;
                header_.push_back(whole(v) ? static_cast<std::int32_t>(v) : 0);
            }
            count_ = k + 1;
            return true;
        }, &where);
    }
    std::size_t count() const { return count_; }
    // The k-th number, if it is an integer of the header.
    bool integer(std::size_t k, int &v) const {
        if (k >= header_.size() || k >= first_fraction_) return false;
        v = header_[k];
        return true;
    }
    // Numbers [from, from + n) into x, the n after them into y.
    void copy(std::size_t from, std::size_t n, double *x, double *y) const {
        each([&](std::size_t k, double v) {
            if (k >= from + 2 * n) return false;
            if (k >= from) (k < from + n ? x[k - from] : y[k - from - n]) = v;
            return true;
        }, nullptr);
    }

private:
    static constexpr std::size_t npos = static_cast<std::size_t>(-1);
    // f(index, value) for each number until it returns false.
    template <class F>
    bool each(F f, std::string *where) const {
        const char *s = reinterpret_cast<const char *>(b_.data()), *end = s + b_.size();
        int line = 1;
        std::size_t k = 0;
        std::string token;
        while (s < end) {
            if (*s == '\n') ++line;
            if (std::isspace(static_cast<unsigned char>(*s)) || *s == ',') {
                ++s;
                continue;
            }
            // Fortran may write a D exponent (1.5D+00): read it as E.
            const char *e = s;
            while (e < end && !std::isspace(static_cast<unsigned char>(*e)) && *e != ',') ++e;
            token.assign(s, e);
            for (char &ch : token)
                if (ch == 'D' || ch == 'd') ch = 'E';
            char *stop;
            const double v = strtod_c(token.c_str(), &stop);
            if (stop != token.c_str() + token.size() || !std::isfinite(v)) {
                if (where) *where = format("line %d: \"%s\" is not a number", line, std::string(s, e).substr(0, 24).c_str());
                return false;
            }
            if (!f(k++, v)) return true;
            s = e;
        }
        return true;
    }

    const std::vector<unsigned char> &b_;
    std::size_t count_ = 0, first_fraction_ = npos;
    std::vector<std::int32_t> header_;
};

bool try_ascii(const AsciiNumbers &t, Layout layout, int want, Plot3dFile &file) {
    std::size_t p = 0, ng = 1;
    if (layout.multi) {
        int first;
        if (!t.integer(0, first) || first < 1) return false;
        ng = static_cast<std::size_t>(first);
        p = 1;
    }
    if (t.count() - p < ng * layout.dims) return false;
    const std::size_t data = p + ng * layout.dims;  // where the coordinates begin
    std::size_t total = 0, wanted_at = 0;
    Plot3dBlock wanted;
    for (std::size_t g = 0; g < ng; ++g) {
        int v[3] = {0, 0, 1};
        for (int d = 0; d < layout.dims; ++d)
            if (!t.integer(p + d, v[d])) return false;
        Plot3dBlock b;
        b.ni = v[0];
        b.nj = v[1];
        b.nk = v[2];
        p += layout.dims;
        if (!plausible(b)) return false;
        if (static_cast<int>(g) == want) {
            wanted = b;
            wanted_at = data + total;
        }
        total += nodes(b) * layout.dims;
    }
    if (t.count() - p != total) return false;
    if (want >= 0 && static_cast<std::size_t>(want) < ng) {  // the numbers are in the file: 8 bytes for each >= 2
        const std::size_t n = nodes(wanted);
        wanted.x.resize(n);
        wanted.y.resize(n);
        t.copy(wanted_at, n, wanted.x.data(), wanted.y.data());
    }
    file.format = EG2D_FORMAT_PLOT3D_ASCII | (layout.multi ? EG2D_PLOT3D_MULTI : 0) |
                  (layout.dims == 3 ? EG2D_PLOT3D_3D : 0);
    file.nblocks = static_cast<int>(ng);
    file.block = std::move(wanted);
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
        AsciiNumbers t(bytes);
        std::string where;
        if (!t.scan(where))
            fail(Failure::Io, format("%s: not a Plot3D grid file: %s", path.c_str(), where.c_str()));
        for (Layout l : kLayouts)
            if (!found) found = try_ascii(t, l, block, file);
        if (!found)
            fail(Failure::Io, format("%s: not a Plot3D grid file: its %zu numbers fit no 2D/3D, single-/multi-grid "
                                     "layout (truncated?)",
                                     path.c_str(), t.count()));
    }
    if (block >= file.nblocks)
        fail(Failure::Argument, format("block = %d: %s has %d grid(s)", block, path.c_str(), file.nblocks));
    if (block >= 0 && file.block.nk != 1)
        fail(Failure::Io, format("%s: grid %d is 3D with nk = %d planes; a 2D grid has nk = 1", path.c_str(), block,
                                 file.block.nk));
    return file;
}

}  // namespace eg2d
