/* libFuzzer harness of the eg2d command's case-file reader: the bytes are a
 * case file, read and validated by read_case (what `eg2d run` does before it
 * builds a grid), without solving or writing anything. A Failure (a message
 * with a location and an exit code) is the accepted error; any other
 * exception would reach main's "internal error", so it aborts here. */
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

#include "case_file.hpp"
#include "failure.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    const std::string text(reinterpret_cast<const char *>(data), size);
    // Point and airfoil pieces name files: device files (/dev/zero, a tty)
    // would test the machine, not the parser, so such inputs are skipped.
    if (text.find("/dev") != std::string::npos || text.find("/proc") != std::string::npos) return 0;
    try {
        // a directory that does not exist: relative file names cannot be read
        eg2dtool::read_case(text, "fuzz.toml", "/nonexistent-eg2d-fuzz", 0, 0);
    } catch (const eg2dtool::Failure &f) {
        if (f.exit_code() == 0 || !*f.what()) std::abort();  // an error must say what and fail
    }
    return 0;
}
