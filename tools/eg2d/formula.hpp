// Formulas in case files ("0.75 + 0.25*sin(pi*(0.5 + 2*s))"), evaluated with muParser.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "location.hpp"

namespace mu {
class Parser;
}

namespace eg2dtool {

// A number for a message (12 significant digits).
std::string fmt(double v);

// Named numbers every formula of a case can use ([constants] plus pi and e).
using Constants = std::map<std::string, double>;

class Formula {
public:
    // Compiles `text` in the given variables; a syntax error, an unknown name or a
    // non-finite value at the variables' test point throws Failure(EXIT_CASE) naming `where`.
    Formula(const std::string &text, const std::vector<std::string> &variables, const Constants &constants,
            const Location &where);
    Formula(Formula &&) noexcept;
    Formula &operator=(Formula &&) noexcept;
    ~Formula();

    // The value at the variables (in the order given to the constructor); a NaN or
    // infinite value throws Failure(EXIT_CASE) naming the key and the variables.
    double operator()(const std::vector<double> &values) const;

private:
    std::unique_ptr<mu::Parser> parser_;
    std::unique_ptr<double[]> slots_;
    std::vector<std::string> names_;
    std::string text_;
    Location where_;
};

// A number given as a TOML number or as a formula string of constants ("2*pi").
double evaluate_constant(const std::string &text, const Constants &constants, const Location &where);

}  // namespace eg2dtool
