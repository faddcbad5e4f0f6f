/* libFuzzer harness of the airfoil reader (Selig and Lednicer coordinate
 * files): the bytes are the file. A curve that reads must have a finite
 * length and give finite points. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "eg2d.h"
#include "fuzz_file.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    eg2d_curve *c = NULL;
    double len, x[17], y[17];
    int k;
    const int rc = eg2d_curve_read_airfoil(fuzz_write_file(data, size), &c);
    if (rc != EG2D_OK) {
        if (c) abort();
        fuzz_reader_failed("eg2d_curve_read_airfoil", rc);
        return 0;
    }
    if (!c || eg2d_curve_length(c, &len) != EG2D_OK || !(len > 0 && isfinite(len))) abort();
    if (eg2d_curve_points(c, 17, EG2D_DIST_UNIFORM, 0, 0, x, y) == EG2D_OK)
        for (k = 0; k < 17; ++k)
            if (!isfinite(x[k]) || !isfinite(y[k])) abort();
    eg2d_curve_destroy(c);
    return 0;
}
