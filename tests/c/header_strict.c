/* The public header compiles as strict C89 with every warning an error
 * (this file is built with -std=c89 -pedantic -Werror); see CMakeLists. */
#include "eg2d.h"

int main(void) {
    int major;
    eg2d_version(&major, 0, 0);
    return major == EG2D_VERSION_MAJOR ? 0 : 1;
}
