// Plot3D writers: Fortran-unformatted binary and ASCII, 2D or 3D (one
// k-plane, z = 0), single- or multi-grid header (layout in plot3d.hpp).
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

std::vector<std::int32_t> dimensions(const Grid &g, bool three_d) {
    std::vector<std::int32_t> d{g.ni(), g.nj()};
    if (three_d) d.push_back(1);
    return d;
}
}  // namespace

void write_plot3d(const WriteRequest &r, OutputFile &out) {
    const bool three_d = r.flags & EG2D_PLOT3D_3D, single = r.flags & EG2D_PLOT3D_SINGLE;
    RecordWriter rec(out, r.flags & EG2D_PLOT3D_BIG_ENDIAN, !(r.flags & EG2D_PLOT3D_NO_MARKERS));
    if (r.flags & EG2D_PLOT3D_MULTI) rec.ints({1});
    rec.ints(dimensions(r.grid, three_d));
    const std::size_t n = r.grid.size(), real = single ? 4 : 8;
    rec.begin(n * real * (three_d ? 3 : 2));
    const std::vector<double> zero(three_d ? n : 0, 0.0);
    for (const std::vector<double> *v : {&r.grid.x, &r.grid.y, &zero}) {
        if (v->empty()) continue;
        if (single) rec.reals<float>(*v);
        else rec.reals<double>(*v);
    }
    rec.end();
}

void write_plot3d_ascii(const WriteRequest &r, OutputFile &out) {
    const bool three_d = r.flags & EG2D_PLOT3D_3D;
    if (r.flags & EG2D_PLOT3D_MULTI) out.print("1\n");
    for (std::int32_t d : dimensions(r.grid, three_d)) out.print("%d ", d);
    out.print("\n");
    const std::size_t n = r.grid.size();
    auto column = [&](const std::vector<double> *v) {
        for (std::size_t k = 0; k < n; ++k) out.real(v ? (*v)[k] : 0.0, (k % 4 == 3 || k + 1 == n) ? '\n' : ' ');
    };
    column(&r.grid.x);
    column(&r.grid.y);
    if (three_d) column(nullptr);
}

}  // namespace eg2d
