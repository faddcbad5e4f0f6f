/* Reading a fuzzer's bytes as typed values. Every harness takes its choices
 * from one of these; an exhausted input reads as zeros, so every byte string
 * is a valid program. Values come from a table of edge cases (0, -0, NaN,
 * +-Inf, the largest and smallest doubles, ...) or raw from the bytes. */
#ifndef EG2D_FUZZ_INPUT_H
#define EG2D_FUZZ_INPUT_H

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

typedef struct {
    const uint8_t *data;
    size_t size, pos;
} fuzz_input;

static inline int fuzz_done(const fuzz_input *in) { return in->pos >= in->size; }

static inline uint8_t fuzz_u8(fuzz_input *in) { return in->pos < in->size ? in->data[in->pos++] : 0; }

static inline void fuzz_bytes(fuzz_input *in, void *out, size_t n) {
    size_t k;
    for (k = 0; k < n; ++k) ((uint8_t *)out)[k] = fuzz_u8(in);
}

/* An int in [0, n). */
static inline int fuzz_below(fuzz_input *in, int n) { return (int)(fuzz_u8(in) % (unsigned)n); }

/* An int: mostly small, sometimes an edge case or raw 32 bits. */
static inline int fuzz_int(fuzz_input *in) {
    static const int edges[] = {0, 1, -1, 2, 3, 4, 99, 100, 199, 200, 299, 999, INT_MAX, INT_MIN, 65536, 46341};
    const uint8_t sel = fuzz_u8(in);
    if (sel < 128) return (int)(sel % 24) - 4;
    if (sel < 240) return edges[sel % (sizeof edges / sizeof edges[0])];
    {
        uint32_t u;
        fuzz_bytes(in, &u, sizeof u);
        return (int)u;
    }
}

static const double fuzz_edge_doubles[] = {
    0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 1e-8, 1e-12, 1.5, 1.99, 1e4, 1e12,
    NAN, INFINITY, -INFINITY, DBL_MAX, -DBL_MAX, DBL_MIN, 4.9406564584124654e-324, 1e200, 1e-200, 1e100, 1e-100,
    1e154, 1e-154, 0.1, 10.0, 0.999999, 1.000001};

/* A double: an edge case, a small fraction, or raw 64 bits. */
static inline double fuzz_double(fuzz_input *in) {
    const uint8_t sel = fuzz_u8(in);
    const size_t n = sizeof fuzz_edge_doubles / sizeof fuzz_edge_doubles[0];
    if (sel < 2 * n) return fuzz_edge_doubles[sel % n];
    if (sel < 240) return (double)(int8_t)fuzz_u8(in) / 64.0;
    {
        double d;
        fuzz_bytes(in, &d, sizeof d);
        return d;
    }
}

#endif
