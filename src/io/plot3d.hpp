// Plot3D whole-grid ("xyz") files, shared by the writer and the reader.
// Layout (one grid; the multi-grid form puts a record "ngrid" first and the
// dimensions of all grids in one record):
//   2D:  ni nj        then x(ni*nj) y(ni*nj)
//   3D:  ni nj nk     then x y z (ni*nj*nk each); eg2d writes nk = 1, z = 0
// In Fortran-unformatted files each line above is one record, framed by a
// 4-byte length before and after it.
#pragma once
#include <cstdint>

namespace eg2d {
namespace plot3d {

inline bool host_big_endian() {
    const std::uint16_t one = 1;
    return *reinterpret_cast<const unsigned char *>(&one) == 0;
}

// Reverses the bytes of each n-byte item of p when the file's byte order
// differs from the host's.
inline void swap_items(void *p, std::size_t count, std::size_t n) {
    unsigned char *b = static_cast<unsigned char *>(p);
    for (std::size_t k = 0; k < count; ++k, b += n)
        for (std::size_t a = 0, z = n - 1; a < z; ++a, --z) {
            const unsigned char t = b[a];
            b[a] = b[z];
            b[z] = t;
        }
}

}  // namespace plot3d
}  // namespace eg2d
