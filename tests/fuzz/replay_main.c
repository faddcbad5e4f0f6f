/* main() for a fuzz harness built without libFuzzer (libgit2's habit): runs
 * LLVMFuzzerTestOneInput once on each file named, or on each file of each
 * directory named, so the seed corpus replays as an ordinary test under any
 * compiler, sanitizer or valgrind. */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int run_file(const char *path) {
    FILE *f = fopen(path, "rb");
    uint8_t *buf = NULL;
    long n;
    if (!f) {
        fprintf(stderr, "replay: cannot open %s\n", path);
        return 1;
    }
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = malloc(n > 0 ? (size_t)n : 1);
    if (!buf || (n > 0 && fread(buf, 1, (size_t)n, f) != (size_t)n)) {
        fprintf(stderr, "replay: cannot read %s\n", path);
        fclose(f);
        free(buf);
        return 1;
    }
    fclose(f);
    LLVMFuzzerTestOneInput(buf, (size_t)n);
    free(buf);
    return 0;
}

int main(int argc, char **argv) {
    int a, files = 0, errors = 0;
    for (a = 1; a < argc; ++a) {
        struct stat st;
        if (stat(argv[a], &st) != 0) {
            fprintf(stderr, "replay: no such file or directory: %s\n", argv[a]);
            return 1;
        }
        if (S_ISDIR(st.st_mode)) {
            struct dirent **entries;
            const int n = scandir(argv[a], &entries, NULL, alphasort);
            int k;
            for (k = 0; k < n; ++k) {
                char path[4096];
                if (entries[k]->d_name[0] != '.') {
                    snprintf(path, sizeof path, "%s/%s", argv[a], entries[k]->d_name);
                    errors += run_file(path);
                    ++files;
                }
                free(entries[k]);
            }
            free(entries);
        } else {
            errors += run_file(argv[a]);
            ++files;
        }
    }
    printf("replay: %d inputs, %d unreadable\n", files, errors);
    return errors != 0 || files == 0;
}
