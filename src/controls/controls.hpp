// The control terms of NUMERICS.md, one file each; this header is what the
// API needs to create them. Every factory checks nothing: src/api validates.
#pragma once
#include <array>
#include <memory>
#include <vector>

#include "controls/control.hpp"

namespace eg2d {

// attraction.cpp: Thompson's line and point attraction (NUMERICS.md "Source
// terms"; Ly & Norrison (2007) eq 14 is its line part), index units, into d_xi, d_eta.
struct LineSource {
    int direction;  // 0: a xi = const line (acts on P), 1: an eta = const line (acts on Q)
    double line, amplitude, decay;
};
struct PointSource {
    double xi, eta, amplitude, decay;
};
class AttractionControl final : public Control {
public:
    std::unique_ptr<Control> clone() const override { return std::make_unique<AttractionControl>(*this); }
    ControlKind kind() const override { return ControlKind::Sources; }
    void add_to(const Grid &grid, ControlFields &fields) const override;
    std::vector<LineSource> lines;
    std::vector<PointSource> points;
};

// arrays.cpp: the user's P, Q per node (the p1/p2 of Petrilli 1989) into d_xi, d_eta.
// An empty vector is zero.
std::unique_ptr<Control> make_source_arrays(std::vector<double> p, std::vector<double> q);

// middlecoff_thomas.cpp: Petrilli (1989) section 4 (eqs 4.7, 4.8) into a_xi, c_eta.
std::unique_ptr<Control> make_middlecoff_thomas();

// wall.cpp: orthogonality at chosen sides with a first-cell height.
// height[side] < 0: not a wall; 0: orthogonal only; > 0: first-cell height.
// On an O- or C-grid whose only wall is JMIN with a height, the control
// marches a wall layer before the solve and holds it (shape_start), and
// fixes the rows above with add_wall_layer_fields: a static control.
std::unique_ptr<Control> make_wall_control(const std::array<double, 4> &height);
bool is_wall_control(const Control *c);

// wall_layer_fields.cpp: Psi and Phi of the rows above a held wall layer
// (a no-op without held rows).
void add_wall_layer_fields(const Grid &g, double growth, ControlFields &fields);

// parameter_grid.cpp: Khattri (2006) eqs 3-7 from a grid (s, t) on the unit square.
std::unique_ptr<Control> make_parameter_grid(std::vector<double> s, std::vector<double> t);
// The first unknown node where the parameter grid's Jacobian s_xi t_eta -
// s_eta t_xi is zero or of the other sign than the first one (i = -1: none).
struct ParameterFold { int i = -1, j = -1; };
ParameterFold parameter_grid_fold(const Connectivity &conn, const double *s, const double *t);

// weight.cpp: equidistribution of a weight per node into a_xi, c_eta.
std::unique_ptr<Control> make_weight_control(std::vector<double> w);

// clustering.cpp: Khattri's (2006) one-dimensional clustering maps of [0, 1].
enum class Clustering { Line = 0, TwoLines = 1, Boundaries = 2 };
double clustering_map(Clustering kind, double a, double b, double strength, double u);

}  // namespace eg2d
