#include "formula.hpp"

#include <cfenv>

#include <muParser.h>

#include <cmath>
#include <sstream>

#include "failure.hpp"

namespace eg2dtool {

namespace {
// A user's formula may divide by zero or overflow, which is then refused by
// name (not finite): its evaluation runs with the floating-point traps a
// host (or EG2D_FP_TRAPS) set paused, and the flags it raised discarded.
struct Untrapped {
    std::fenv_t env;
    Untrapped() { std::feholdexcept(&env); }
    ~Untrapped() { std::fesetenv(&env); }
};
}  // namespace

std::string fmt(double v) {
    std::ostringstream s;
    s.precision(12);
    s << v;
    return s.str();
}

Formula::Formula(const std::string &text, const std::vector<std::string> &variables, const Constants &constants,
                 const Location &where)
    : parser_(std::make_unique<mu::Parser>()), slots_(new double[variables.size() + 1]()), names_(variables),
      text_(text), where_(where) {
    try {
        parser_->DefineConst("pi", M_PI);
        parser_->DefineConst("e", M_E);
        for (const auto &c : constants) parser_->DefineConst(c.first, c.second);
        for (std::size_t k = 0; k < variables.size(); ++k) parser_->DefineVar(variables[k], &slots_[k]);
        parser_->SetExpr(text);
        const Untrapped untrapped;
        parser_->Eval();  // compiles: reports syntax errors and unknown names now
    } catch (const mu::Parser::exception_type &e) {
        throw Failure(EXIT_CASE, where.str() + ": bad formula \"" + text + "\": " + e.GetMsg());
    }
}

Formula::Formula(Formula &&) noexcept = default;
Formula &Formula::operator=(Formula &&) noexcept = default;
Formula::~Formula() = default;

double Formula::operator()(const std::vector<double> &values) const {
    for (std::size_t k = 0; k < names_.size() && k < values.size(); ++k) slots_[k] = values[k];
    double v;
    try {
        const Untrapped untrapped;
        v = parser_->Eval();
    } catch (const mu::Parser::exception_type &e) {
        throw Failure(EXIT_CASE, where_.str() + ": bad formula \"" + text_ + "\": " + e.GetMsg());
    }
    if (!std::isfinite(v)) {
        std::string at;
        for (std::size_t k = 0; k < names_.size(); ++k) at += (k ? ", " : "") + names_[k] + " = " + fmt(values[k]);
        throw Failure(EXIT_CASE, where_.str() + ": formula \"" + text_ + "\" gives " + fmt(v) + " at " + at);
    }
    return v;
}

double evaluate_constant(const std::string &text, const Constants &constants, const Location &where) {
    Formula f(text, {}, constants, where);
    return f({});
}

}  // namespace eg2dtool
