"""The lifetime shared by Grid and Curve: an opaque C handle freed by close(),
by the end of a `with` block, or when the object is collected."""
from ctypes import c_void_p

from . import constants as C
from .errors import error_for


class Handle:
    _kind = "handle"  # "grid", "curve": for the message after close()

    def __init__(self):
        self._h = c_void_p()

    def _destroy(self, h):  # the C destructor of the subclass
        raise NotImplementedError

    def close(self):
        """Frees the handle; later calls raise eg2d.StateError. Idempotent."""
        if self._h:
            self._destroy(self._h)
            self._h = c_void_p()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __del__(self):
        try:
            if getattr(self, "_h", None):
                self.close()
        except Exception:  # interpreter shutdown: the library may be gone
            pass

    @property
    def closed(self):
        return not self._h

    def _handle(self):
        if not self._h:
            raise error_for(C.ERR_STATE, f"the {self._kind} is closed")
        return self._h
