// Plot3D writers: Fortran-unformatted binary and ASCII, 2D or 3D (one
// k-plane, z = 0, or two, z = 0 and the span), single- or multi-grid header
// (layout in plot3d.hpp); a set of blocks as a multi-grid file.
#include <cstdint>
#include <vector>

#include "base/error.hpp"
#include "eg2d.h"
#include "io/formats.hpp"
#include "io/plot3d.hpp"

namespace eg2d {

namespace {
// One Fortran record: length, payload, length; in the requested byte order.
class RecordWriter {
public:
    RecordWriter(OutputFile &out, bool big_endian, bool markers)
        : out_(out), swap_(big_endian != plot3d::host_big_endian()), markers_(markers) {}
    void ints(std::vector<std::int32_t> v) {
        put_marker(v.size() * 4);
        if (swap_) plot3d::swap_items(v.data(), v.size(), 4);
        out_.write(v.data(), v.size() * 4);
        put_marker(v.size() * 4);
    }
    void begin(std::size_t bytes) { put_marker(bytes); bytes_ = bytes; }
    template <class Real>
    void reals(const std::vector<double> &v) {
        std::vector<Real> buf(v.begin(), v.end());
        if (swap_) plot3d::swap_items(buf.data(), buf.size(), sizeof(Real));
        out_.write(buf.data(), buf.size() * sizeof(Real));
    }
    void end() { put_marker(bytes_); }

private:
    void put_marker(std::size_t bytes) {
        if (!markers_) return;
        if (bytes > 0x7fffffffu)
            fail(Failure::Argument, format("%s: a record of %zu bytes does not fit Plot3D's 4-byte record marker",
                                           out_.path().c_str(), bytes));
        std::int32_t m = static_cast<std::int32_t>(bytes);
        if (swap_) plot3d::swap_items(&m, 1, 4);
        out_.write(&m, 4);
    }
    OutputFile &out_;
    bool swap_, markers_;
    std::size_t bytes_ = 0;
};

// EG2D_PLOT3D_EXTRUDED: the 3-D form with two k-planes, z = 0 and z = span
// (one layer of cells, what 3-D tools such as OpenFOAM's plot3dToFoam
// without -2D need); EG2D_PLOT3D_3D alone: one k-plane, z = 0.
int k_planes(int flags) { return (flags & EG2D_PLOT3D_EXTRUDED) ? 2 : (flags & EG2D_PLOT3D_3D) ? 1 : 0; }

std::vector<std::int32_t> dimensions(const std::vector<const Grid *> &grids, int planes) {
    std::vector<std::int32_t> d;
    for (const Grid *g : grids) {
        d.push_back(g->ni());
        d.push_back(g->nj());
        if (planes > 0) d.push_back(planes);
    }
    return d;
}

// x, y, z of every k-plane in turn (Fortran order: i fastest, then j, then k).
std::vector<std::vector<double>> columns(const Grid &g, double span, int planes) {
    const std::size_t n = g.size();
    if (planes == 0) return {g.x, g.y};
    std::vector<std::vector<double>> c(3);
    for (int k = 0; k < planes; ++k) {
        c[0].insert(c[0].end(), g.x.begin(), g.x.end());
        c[1].insert(c[1].end(), g.y.begin(), g.y.end());
        c[2].insert(c[2].end(), n, k == 0 ? 0.0 : span);
    }
    return c;
}
}  // namespace

// A multi-grid file (the block count first) when asked or when there are
// several grids: every block's dimensions in one record, then each block's
// coordinates in a record of its own.
void write_plot3d_blocks(const BlocksRequest &r, OutputFile &out) {
    const bool single = r.flags & EG2D_PLOT3D_SINGLE;
    const int planes = k_planes(r.flags);
    RecordWriter rec(out, r.flags & EG2D_PLOT3D_BIG_ENDIAN, !(r.flags & EG2D_PLOT3D_NO_MARKERS));
    if ((r.flags & EG2D_PLOT3D_MULTI) || r.grids.size() > 1) rec.ints({static_cast<std::int32_t>(r.grids.size())});
    rec.ints(dimensions(r.grids, planes));
    for (const Grid *g : r.grids) {
        const std::vector<std::vector<double>> c = columns(*g, r.settings.span, planes);
        const std::size_t real = single ? 4 : 8;
        rec.begin(c[0].size() * real * c.size());
        for (const std::vector<double> &v : c) {
            if (single) rec.reals<float>(v);
            else rec.reals<double>(v);
        }
        rec.end();
    }
}

void write_plot3d_ascii_blocks(const BlocksRequest &r, OutputFile &out) {
    const int planes = k_planes(r.flags);
    if ((r.flags & EG2D_PLOT3D_MULTI) || r.grids.size() > 1) out.print("%zu\n", r.grids.size());
    for (std::int32_t d : dimensions(r.grids, planes)) out.print("%d ", d);
    out.print("\n");
    for (const Grid *g : r.grids)
        for (const std::vector<double> &v : columns(*g, r.settings.span, planes))
            for (std::size_t k = 0; k < v.size(); ++k) out.real(v[k], (k % 4 == 3 || k + 1 == v.size()) ? '\n' : ' ');
}

void write_plot3d(const WriteRequest &r, OutputFile &out) {
    write_plot3d_blocks(BlocksRequest{{&r.grid}, r.settings, r.flags}, out);
}

void write_plot3d_ascii(const WriteRequest &r, OutputFile &out) {
    write_plot3d_ascii_blocks(BlocksRequest{{&r.grid}, r.settings, r.flags}, out);
}

}  // namespace eg2d
