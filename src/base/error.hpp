// The core's failure type. The numerics throw eg2d::Error with a Failure kind
// and a precise message; only src/api translates it into an EG2D_ERR_* code.
#pragma once
#include <stdexcept>
#include <string>

namespace eg2d {

enum class Failure {
    Argument,
    Memory,
    Boundary,
    State,
    NotConverged,
    Diverged,
    Folded,
    Io,
    Unsupported,
    Interrupted,
};

class Error : public std::runtime_error {
public:
    Error(Failure failure, const std::string &message)
        : std::runtime_error(message), failure_(failure) {}
    Failure failure() const noexcept { return failure_; }

private:
    Failure failure_;
};

// printf-style formatting for messages ("corner JMIN/IMAX: (1, 0) vs (1.2, 0)").
std::string format(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

[[noreturn]] inline void fail(Failure failure, const std::string &message) {
    throw Error(failure, message);
}

}  // namespace eg2d
