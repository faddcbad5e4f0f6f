#include "channels.h"

#include <math.h>
#include <stdlib.h>

/* Turbo Pascal's round: half away from zero. */
static int pround(double v) { return (int)(v < 0 ? -floor(-v + 0.5) : floor(v + 0.5)); }

int channel_set(eg2d_grid *g, int geom) {
    int NI, NJ, ni, nj, i, j, status;
    double *bx, *by, *tx, *ty, *lx, *ly, *rx, *ry;
    if ((status = eg2d_get_size(g, &NI, &NJ)) != EG2D_OK) return status;
    ni = NI - 1;
    nj = NJ - 1;
    bx = calloc((size_t)NI, sizeof(double));
    by = calloc((size_t)NI, sizeof(double));
    tx = calloc((size_t)NI, sizeof(double));
    ty = calloc((size_t)NI, sizeof(double));
    lx = calloc((size_t)NJ, sizeof(double));
    ly = calloc((size_t)NJ, sizeof(double));
    rx = calloc((size_t)NJ, sizeof(double));
    ry = calloc((size_t)NJ, sizeof(double));
    if (!bx || !by || !tx || !ty || !lx || !ly || !rx || !ry) {
        status = EG2D_ERR_MEMORY;
        goto done;
    }
    for (i = 0; i <= ni; ++i) { /* JMIN is x = i/ni, y = 0 in all three */
        bx[i] = (double)i / ni;
        by[i] = 0.0;
    }
    if (geom == 1) {
        const int ni1 = ni / 2, nj1 = nj / 2, ni2 = ni - ni1, nj2 = nj - nj1;
        for (i = 0; i <= ni1; ++i) { tx[i] = 1.0 + (double)i / ni1; ty[i] = 2.0; }
        for (i = ni1 + 1; i <= ni; ++i) { tx[i] = 2.0; ty[i] = 2.0 - (double)(i - ni1) / ni2; }
        for (j = 1; j <= nj1; ++j) { lx[j] = 0.0; ly[j] = 2.0 * j / nj1; }
        for (j = nj1 + 1; j <= nj - 1; ++j) { lx[j] = (double)(j - nj1) / nj2; ly[j] = 2.0; }
        for (j = 1; j <= nj1; ++j) { rx[j] = 1.0; ry[j] = (double)j / nj1; }
        for (j = nj1 + 1; j <= nj - 1; ++j) { rx[j] = 1.0 + (double)(j - nj1) / nj2; ry[j] = 1.0; }
    } else if (geom == 2) {
        const int nj2 = pround(nj * 2 / 10.0), nj3 = pround(nj * 3 / 10.0), nj5 = pround(nj * 5 / 10.0);
        const int nj6 = pround(nj * 6 / 10.0), nj7 = pround(nj * 7 / 10.0);
        for (i = 0; i <= ni; ++i) { tx[i] = 0.0; ty[i] = 2.0 + (double)i / ni; }
        for (j = 1; j <= nj2; ++j) { lx[j] = 0.0; ly[j] = 2.0 * j / nj2; }
        for (j = nj2 + 1; j <= nj6 - 2; ++j) { lx[j] = 2.0 * (j - nj2) / (nj6 - nj2); ly[j] = 2.0; }
        lx[nj6 - 1] = 1.9; ly[nj6 - 1] = 1.9;
        lx[nj6] = 2.0; ly[nj6] = 2.0;
        lx[nj6 + 1] = 1.9; ly[nj6 + 1] = 2.1;
        for (j = nj6 + 2; j <= nj - 1; ++j) { lx[j] = 2.0 - 2.0 * (j - nj6) / (nj - nj6); ly[j] = 2.0; }
        for (j = 1; j <= nj3; ++j) { rx[j] = 1.0; ry[j] = (double)j / nj3; }
        for (j = nj3 + 1; j <= nj5; ++j) { rx[j] = 1.0 + 2.0 * (j - nj3) / (nj5 - nj3); ry[j] = 1.0; }
        for (j = nj5 + 1; j <= nj7; ++j) { rx[j] = 3.0; ry[j] = 1.0 + 2.0 * (j - nj5) / (nj7 - nj5); }
        for (j = nj7 + 1; j <= nj - 1; ++j) { rx[j] = 3.0 - 3.0 * (j - nj7) / (nj - nj7); ry[j] = 3.0; }
    } else if (geom == 3) {
        const int nj1 = pround(nj / 3.0), nj2 = pround(nj * 2 / 3.0);
        for (i = 0; i <= ni; ++i) { tx[i] = 1.0 + (double)i / ni; ty[i] = 2.0; }
        for (j = 1; j <= nj2; ++j) { lx[j] = 0.0; ly[j] = 2.0 * j / nj2; }
        for (j = nj2 + 1; j <= nj - 1; ++j) { lx[j] = (double)(j - nj2) / (nj - nj2); ly[j] = 2.0; }
        for (j = 1; j <= nj1; ++j) { rx[j] = 1.0; ry[j] = (double)j / nj1; }
        for (j = nj1 + 1; j <= nj2; ++j) { rx[j] = 1.0 + (double)(j - nj1) / (nj2 - nj1); ry[j] = 1.0; }
        for (j = nj2 + 1; j <= nj - 1; ++j) { rx[j] = 2.0; ry[j] = 1.0 + (double)(j - nj2) / (nj - nj2); }
    } else {
        status = EG2D_ERR_ARGUMENT;
        goto done;
    }
    /* The side ends are the corners of JMIN and JMAX. */
    lx[0] = bx[0]; ly[0] = by[0];
    rx[0] = bx[ni]; ry[0] = by[ni];
    lx[nj] = tx[0]; ly[nj] = ty[0];
    rx[nj] = tx[ni]; ry[nj] = ty[ni];
    status = eg2d_set_side(g, EG2D_SIDE_JMIN, bx, by);
    if (status == EG2D_OK) status = eg2d_set_side(g, EG2D_SIDE_JMAX, tx, ty);
    if (status == EG2D_OK) status = eg2d_set_side(g, EG2D_SIDE_IMIN, lx, ly);
    if (status == EG2D_OK) status = eg2d_set_side(g, EG2D_SIDE_IMAX, rx, ry);
done:
    free(bx); free(by); free(tx); free(ty);
    free(lx); free(ly); free(rx); free(ry);
    return status;
}

void channel_sources(int geom, int NI, int NJ, double *P, double *Q) {
    const int ni = NI - 1, nj = NJ - 1;
    int i, j;
#define AT(i, j) ((i) + NI * (j))
    for (i = 0; i < NI * NJ; ++i) P[i] = Q[i] = 0.0;
    if (geom == 1) {
        const int ni1 = ni / 2, nj1 = nj / 2;
        for (j = nj1 - 3; j <= nj1 + 3; ++j) {
            P[AT(1, j)] = -20.0; /* pushes xi to lower i */
            P[AT(2, j)] = -10.0;
            P[AT(ni - 1, j)] = -20.0;
            P[AT(ni - 2, j)] = -10.0;
        }
        for (i = ni1 - 2; i <= ni1 + 2; ++i) {
            Q[AT(i, nj - 1)] = 20.0; /* pushes eta to higher j */
            Q[AT(i, nj - 2)] = 10.0;
        }
    } else if (geom == 2) {
        const int nj2 = pround(nj * 2 / 10.0), nj3 = pround(nj * 3 / 10.0), nj5 = pround(nj * 5 / 10.0);
        const int nj6 = pround(nj * 6 / 10.0), nj7 = pround(nj * 7 / 10.0);
        for (j = nj3 - 1; j <= nj3 + 1; ++j) {
            P[AT(ni - 1, j)] = -20; P[AT(ni - 2, j)] = -10;
            Q[AT(ni - 1, j)] = -20; Q[AT(ni - 2, j)] = -10;
        }
        for (j = nj2 - 1; j <= nj2 + 1; ++j) {
            P[AT(1, j)] = -20; P[AT(2, j)] = -10;
            Q[AT(1, j)] = -20; Q[AT(2, j)] = -10;
        }
        for (j = nj5 - 1; j <= nj5 + 2; ++j) {
            P[AT(ni - 1, j)] = 20; P[AT(ni - 2, j)] = 10;
            Q[AT(ni - 1, j)] = 5; Q[AT(ni - 2, j)] = 5;
        }
        for (j = nj6 - 1; j <= nj6 + 1; ++j) {
            P[AT(1, j)] = 40; P[AT(2, j)] = 20; P[AT(3, j)] = 10;
            Q[AT(1, j)] = 0; Q[AT(2, j)] = 0;
        }
        for (j = nj7 - 2; j <= nj7 + 1; ++j) {
            P[AT(ni - 1, j)] = 20; P[AT(ni - 2, j)] = 10;
            Q[AT(ni - 1, j)] = -5; Q[AT(ni - 2, j)] = -5;
        }
    } else if (geom == 3) {
        const int nj1 = pround(nj / 3.0), nj2 = pround(nj * 2 / 3.0);
        for (j = nj2 - 3; j <= nj2 + 3; ++j) {
            P[AT(1, j)] = -20; P[AT(2, j)] = -10;
        }
        for (j = nj1 - 3; j <= nj1 + 3; ++j) {
            P[AT(ni - 1, j)] = 20; P[AT(ni - 2, j)] = 10;
        }
    }
#undef AT
}
