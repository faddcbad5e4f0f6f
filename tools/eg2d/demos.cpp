#include "demos.hpp"

namespace eg2dtool {

// Seed 003's swan: the README's first command shows it.
const char *default_demo() { return "swan"; }

}  // namespace eg2dtool
