// NACA 4-digit sections (Abbott & von Doenhoff, "Theory of Wing Sections",
// 1959, sec. 6.4; the grid-generation lecture notes section 2.4 uses NACA0012):
//   y_t = 5 t (0.2969 sqrt(x) - 0.1260 x - 0.3516 x^2 + 0.2843 x^3 + a4 x^4),
// a4 = -0.1015 (the standard blunt trailing edge) or -0.1036 (closed, sharp);
// camber line y_c = m/p^2 (2 p x - x^2) for x < p, m/(1-p)^2 ((1-2p) + 2 p x - x^2)
// after; surfaces offset by y_t normal to the camber line.
// The parameter: x = (1 - cos phi)/2 on each surface, phi from pi at the
// trailing edge to 0 at the leading edge (lower surface, t in [0, 1/2]) and
// back (upper surface): sqrt(x) = sin(phi/2) is then smooth, so the arc-length
// quadrature converges fast on each surface.
#include <cctype>
#include <cmath>
#include <cstring>

#include "base/error.hpp"
#include "geometry/curve.hpp"

namespace eg2d {

namespace {

constexpr double kPi = 3.14159265358979323846;

class Naca4 final : public Curve {
public:
    Naca4(double m, double p, double t, double a4) : m_(m), p_(p), t_(t), a4_(a4) {}
    void eval(double t, double &x, double &y) const override {
        const bool upper = t >= 0.5;
        const double phi = upper ? kPi * (2 * t - 1) : kPi * (1 - 2 * t);
        const double xc = 0.5 * (1 - std::cos(phi)), rx = std::sin(0.5 * phi);  // rx = sqrt(xc)
        const double yt = 5 * t_ * (0.2969 * rx + xc * (-0.1260 + xc * (-0.3516 + xc * (0.2843 + xc * a4_))));
        double yc = 0.0, slope = 0.0;
        if (m_ > 0.0) {
            if (xc < p_) {
                yc = m_ / (p_ * p_) * (2 * p_ * xc - xc * xc);
                slope = 2 * m_ / (p_ * p_) * (p_ - xc);
            } else {
                yc = m_ / ((1 - p_) * (1 - p_)) * ((1 - 2 * p_) + 2 * p_ * xc - xc * xc);
                slope = 2 * m_ / ((1 - p_) * (1 - p_)) * (p_ - xc);
            }
        }
        const double th = std::atan(slope), sign = upper ? 1.0 : -1.0;
        x = xc - sign * yt * std::sin(th);
        y = yc + sign * yt * std::cos(th);
    }
    std::vector<double> breaks() const override {
        std::vector<double> b{0.5};
        if (m_ > 0.0) {  // the camber line's curvature jumps at x = p
            const double phi = std::acos(1 - 2 * p_);
            b.push_back(0.5 * (1 - phi / kPi));
            b.push_back(0.5 * (1 + phi / kPi));
        }
        return b;
    }

private:
    double m_, p_, t_, a4_;
};

}  // namespace

std::shared_ptr<Curve> make_naca4(const char *digits, bool closed_te) {
    if (std::strlen(digits) != 4 || !std::isdigit(static_cast<unsigned char>(digits[0])) ||
        !std::isdigit(static_cast<unsigned char>(digits[1])) || !std::isdigit(static_cast<unsigned char>(digits[2])) ||
        !std::isdigit(static_cast<unsigned char>(digits[3])))
        fail(Failure::Argument, format("NACA \"%s\": need four digits MPTT, like \"0012\" or \"2412\"", digits));
    const double m = (digits[0] - '0') / 100.0, p = (digits[1] - '0') / 10.0;
    const double t = ((digits[2] - '0') * 10 + (digits[3] - '0')) / 100.0;
    if (t <= 0.0) fail(Failure::Argument, format("NACA \"%s\": zero thickness", digits));
    if ((m > 0.0) != (p > 0.0))
        fail(Failure::Argument,
             format("NACA \"%s\": a cambered section needs both the camber M and its position P nonzero", digits));
    return std::make_shared<Naca4>(m, p, t, closed_te ? -0.1036 : -0.1015);
}

}  // namespace eg2d
