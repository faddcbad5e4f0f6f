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

Table<InitMethod> init_method_table() { return table_of(kMethods); }

const InitMethod *find_init_method(int id) { return init_method_table().find(id); }

}  // namespace eg2d
