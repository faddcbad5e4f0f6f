/* The readers take paths: a harness writes the fuzzer's bytes to one scratch
 * file per process (made once, removed at exit) and hands over its path. */
#ifndef EG2D_FUZZ_FILE_H
#define EG2D_FUZZ_FILE_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char fuzz_file_path[4096];

static void fuzz_file_remove(void) {
    if (fuzz_file_path[0]) unlink(fuzz_file_path);
}

/* Writes data to the scratch file; returns its path (aborts if it cannot:
 * that is the harness's environment failing, not the library). */
static inline const char *fuzz_write_file(const uint8_t *data, size_t size) {
    FILE *f;
    if (!fuzz_file_path[0]) {
        const char *dir = getenv("TMPDIR");
        int fd;
        snprintf(fuzz_file_path, sizeof fuzz_file_path, "%s/eg2d-fuzz-XXXXXX", dir && *dir ? dir : "/tmp");
        fd = mkstemp(fuzz_file_path);
        if (fd < 0) abort();
        close(fd);
        atexit(fuzz_file_remove);
    }
    f = fopen(fuzz_file_path, "wb");
    if (!f || (size && fwrite(data, 1, size, f) != size) || fclose(f) != 0) abort();
    return fuzz_file_path;
}

/* A reader's failure: a documented status and a message naming the call. */
static inline void fuzz_reader_failed(const char *function, int status) {
    const char *m = eg2d_last_error(NULL);
    if (status < 1 || status > 10 || strncmp(m, function, strlen(function)) != 0 || m[strlen(function)] != ':') {
        fprintf(stderr, "%s: status %d, message \"%s\"\n", function, status, m);
        abort();
    }
}

#endif
