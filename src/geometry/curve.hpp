// A plane curve r(t) = (x(t), y(t)) on t in [0, 1], and its arc-length view.
// Polylines, splines, NACA sections and user callbacks are Curves; the
// point distributions and eg2d_set_side_curve see only this interface.
#pragma once
#include <memory>
#include <vector>

namespace eg2d {

class Curve {
public:
    virtual ~Curve() = default;
    // The point at parameter t in [0, 1]. May throw (a callback's NaN).
    virtual void eval(double t, double &x, double &y) const = 0;
    // dr/dt at t, where t lies in the smooth piece [lo, hi] (between two
    // breaks). Default: fourth-order finite differences kept inside [lo, hi],
    // so a kink at a break never enters a difference.
    virtual void derivative(double t, double lo, double hi, double &dx, double &dy) const;
    // The round-off in |dr/dt| on the piece [lo, hi] of a curve whose points
    // are about r_max from the origin: the differences' (about eps r_max /
    // their step), far above eps |r'| when the piece is much shorter than
    // r_max. A curve whose derivative is exact overrides it with 0.
    virtual double speed_round_off(double lo, double hi, double r_max) const;
    // Parameters in (0, 1) where the curve may have a kink or a jump in
    // curvature (polyline vertices, spline knots, an airfoil's leading edge).
    virtual std::vector<double> breaks() const { return {}; }
};

// The curves eg2d builds (each in its own file). Points are checked finite;
// every factory throws Argument with the offending index.
// Straight segments, t proportional to arc length (polyline.cpp).
std::shared_ptr<Curve> make_polyline(const double *x, const double *y, int n);
// The cubic spline through the points, t proportional to cumulative chord
// length; periodic when the first and last points coincide, else not-a-knot
// (spline.cpp). corner_at_ends keeps a closed curve's first point as a corner
// (an airfoil's sharp trailing edge) instead of making it periodic.
std::shared_ptr<Curve> make_spline(const double *x, const double *y, int n, bool corner_at_ends);
// NACA 4-digit section "MPTT", chord 1 from (0,0) to (1,0), running from the
// trailing edge along the lower surface to the leading edge (t = 1/2) and back
// along the upper surface (naca.cpp). closed_te: thickness coefficient
// -0.1036, a sharp trailing edge (the curve is closed); else -0.1015.
std::shared_ptr<Curve> make_naca4(const char *digits, bool closed_te);
// An airfoil from a Selig or Lednicer coordinate file (airfoil_file.cpp), as a
// spline oriented like make_naca4. Throws Io (file) or Argument (contents).
std::shared_ptr<Curve> read_airfoil(const char *path);

// Arc length of a curve (the grid-generation lecture notes eq 2.11): s(t) = (1/L) int_0^t |r'(u)| du.
// The integral is tabulated once on panels of 5-point Gauss-Legendre
// quadrature, split until halving a panel changes its length by less than
// 1e-14 L, or, where the curve's points cannot resolve that (a callback's
// piece much shorter than its distance from the origin), by less than the
// speed's round-off over the panel (Curve::speed_round_off); s -> t is then
// solved by safeguarded
// Newton on one panel. The normalized arc length of a returned parameter is
// exact to about 1e-12 (1e-11 for callbacks, whose speed comes from finite
// differences; for a callback's curve of length L about r_max from the
// origin, to about 1e-16 r_max / L more).
class ArcLength {
public:
    // Throws Argument for a curve with a non-finite point or zero length.
    explicit ArcLength(std::shared_ptr<const Curve> curve);

    double length() const { return cumulative_.back(); }
    // The parameter t whose normalized arc length is s in [0, 1].
    double parameter(double s) const;
    // The point at normalized arc length s.
    void point(double s, double &x, double &y) const;
    const Curve &curve() const { return *curve_; }

private:
    double speed(double t, std::size_t panel) const;
    double integrate(double a, double b, std::size_t panel) const;  // 5-point Gauss on [a, b]
    // Splits [a, b] until its length is known to tol or to the speed's
    // round-off (noise per unit t); false when the panels run out.
    bool refine(double a, double b, double whole, std::size_t piece, int depth, double tol, double noise);
    // The panels of the whole curve (false: as refine()).
    bool tabulate(double tol, double r_max, bool with_round_off);

    std::shared_ptr<const Curve> curve_;
    std::vector<double> knots_;       // 0, the breaks, 1
    std::vector<double> t_;           // panel ends, t_[0] = 0 ... t_.back() = 1
    std::vector<std::size_t> piece_;  // knot interval of each panel
    std::vector<double> cumulative_;  // length from 0 to t_[k]
};

}  // namespace eg2d
