#include "grid/initializers.hpp"

#include "eg2d.h"

namespace eg2d {

namespace {
const InitMethod kMethods[] = {
    {EG2D_INIT_TFI, "tfi", tfi_linear},
    {EG2D_INIT_HERMITE, "hermite", tfi_hermite},
    {EG2D_INIT_HYPERBOLIC, "hyperbolic", hyperbolic_march, true},
};
}

const InitMethod *find_init_method(int id) {
    for (const InitMethod &m : kMethods)
        if (m.id == id) return &m;
    return nullptr;
}

}  // namespace eg2d
