#include "demos.hpp"

namespace eg2dtool {

// the elliptic-grid course notes' swan: the README's first command shows it.
const char *default_demo() { return "swan"; }

}  // namespace eg2dtool
