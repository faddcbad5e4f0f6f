/* libFuzzer harness of the point-file reader: the bytes are the file. Reads
 * the count, the points (with the exact capacity and one too few), and sets a
 * side of a grid of that many points from the file. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "eg2d.h"
#include "fuzz_file.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    const char *path = fuzz_write_file(data, size);
    int n = -1, m = -1, k, rc;
    double *x, *y;
    rc = eg2d_read_points(path, 0, &n, NULL, NULL);
    if (rc != EG2D_OK) {
        fuzz_reader_failed("eg2d_read_points", rc);
        return 0;
    }
    if (n < 1) abort();
    x = malloc(sizeof(double) * (size_t)n);
    y = malloc(sizeof(double) * (size_t)n);
    if (!x || !y) abort();
    if (eg2d_read_points(path, n, &m, x, y) != EG2D_OK || m != n) abort();
    for (k = 0; k < n; ++k)
        if (!isfinite(x[k]) || !isfinite(y[k])) abort(); /* documented: two finite numbers a line */
    rc = eg2d_read_points(path, n - 1, &m, x, y);
    if (rc != EG2D_ERR_ARGUMENT) abort(); /* more points than the capacity */
    fuzz_reader_failed("eg2d_read_points", rc);
    if (n >= 3) {
        eg2d_grid *g = NULL;
        if (eg2d_create(n, 3, &g) == EG2D_OK) {
            rc = eg2d_set_side_from_file(g, size % 2 ? EG2D_SIDE_JMIN : EG2D_SIDE_IMAX, path);
            /* JMIN has n points: accepted unless a value is out of range; IMAX has 3. */
            if (rc != EG2D_OK && rc != EG2D_ERR_ARGUMENT && rc != EG2D_ERR_BOUNDARY) abort();
            if (size % 2 == 0 && n != 3 && rc != EG2D_ERR_BOUNDARY) abort();
            eg2d_destroy(g);
        }
    }
    free(x);
    free(y);
    return 0;
}
