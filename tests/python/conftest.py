"""The package's tests run with the floating-point traps a host solver built
with -ffpe-trap sets (invalid, divide-by-zero, overflow), so that no call into
libeg2d raises one on valid input. numpy is loaded first: it raises flags
while it loads (numpy.core.getlimits)."""
import ctypes
import platform

import numpy  # noqa: F401

# fenv.h's FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW on x86-64 (glibc)
if platform.system() == "Linux" and platform.machine() == "x86_64":
    ctypes.CDLL("libm.so.6").feenableexcept(0x01 | 0x04 | 0x08)
