// The one exception the tool throws: a message for the user and its exit code.
#pragma once

#include <stdexcept>
#include <string>

#include "exit_codes.hpp"

namespace eg2dtool {

class Failure : public std::runtime_error {
public:
    Failure(int exit_code, const std::string &message) : std::runtime_error(message), code_(exit_code) {}
    int exit_code() const { return code_; }

private:
    int code_;
};

}  // namespace eg2dtool
