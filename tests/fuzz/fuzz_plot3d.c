/* libFuzzer harness of eg2d_read_plot3d: the bytes are the file. Asks the
 * size, reads the arrays, reads the last block too, and gives a block that
 * fits to eg2d_set_coordinates as a start grid. The reader must accept or
 * refuse with EG2D_ERR_IO (or EG2D_ERR_MEMORY), never crash or overrun. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "eg2d.h"
#include "fuzz_file.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void read_block(const char *path, int block) {
    int format = -1, nblocks = -1, ni = -1, nj = -1, rc;
    double *x, *y;
    rc = eg2d_read_plot3d(path, block, &format, &nblocks, &ni, &nj, NULL, NULL);
    if (rc != EG2D_OK) {
        fuzz_reader_failed("eg2d_read_plot3d", rc);
        return;
    }
    /* A block the file holds cannot be larger than the file. */
    if (ni < 1 || nj < 1 || nblocks < 1 || block >= nblocks || format < 0) abort();
    x = malloc(sizeof(double) * (size_t)ni * (size_t)nj);
    y = malloc(sizeof(double) * (size_t)ni * (size_t)nj);
    if (!x || !y) abort();
    rc = eg2d_read_plot3d_into(path, block, ni * nj, NULL, NULL, NULL, NULL, x, y);
    if (rc != EG2D_OK) abort(); /* the same file read twice */
    /* one node short of the block: refused, nothing written past the arrays */
    if (eg2d_read_plot3d_into(path, block, ni * nj - 1, NULL, NULL, NULL, NULL, x, y) != EG2D_ERR_ARGUMENT) abort();
    if (block == 0 && nblocks > 1) read_block(path, nblocks - 1);
    {
        eg2d_grid *g = NULL;
        if (eg2d_create(ni, nj, &g) == EG2D_OK) {
            rc = eg2d_set_coordinates(g, x, y);
            if (rc != EG2D_OK && rc != EG2D_ERR_ARGUMENT && rc != EG2D_ERR_BOUNDARY) abort();
            eg2d_destroy(g);
        }
    }
    free(x);
    free(y);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    read_block(fuzz_write_file(data, size), 0);
    return 0;
}
