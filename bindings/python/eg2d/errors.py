"""Exceptions: every failed call raises eg2d.Error (or its subclass for the
status) carrying the status code and the library's message."""
from . import constants as C


class Error(Exception):
    """A failed eg2d call: .status (EG2D_ERR_*) and .message (eg2d_last_error)."""

    def __init__(self, status, message):
        super().__init__(message)
        self.status = status
        self.message = message


class ArgumentError(Error, ValueError):
    pass


class OutOfMemoryError(Error):
    pass


class BoundaryError(Error):
    pass


class StateError(Error):
    pass


class NotConvergedError(Error):
    pass


class DivergedError(Error):
    pass


class FoldedError(Error):
    pass


class FileError(Error):
    pass


class UnsupportedError(Error):
    pass


class StoppedByMonitor(Error):
    pass


class InternalError(Error):
    """A defect inside eg2d, not bad input: please report it with the message."""


_BY_STATUS = {
    C.ERR_ARGUMENT: ArgumentError,
    C.ERR_MEMORY: OutOfMemoryError,
    C.ERR_BOUNDARY: BoundaryError,
    C.ERR_STATE: StateError,
    C.ERR_NOT_CONVERGED: NotConvergedError,
    C.ERR_DIVERGED: DivergedError,
    C.ERR_FOLDED: FoldedError,
    C.ERR_IO: FileError,
    C.ERR_UNSUPPORTED: UnsupportedError,
    C.ERR_INTERRUPTED: StoppedByMonitor,
    C.ERR_INTERNAL: InternalError,
}


def error_for(status, message):
    """The exception for a status (Error for a code this package does not know)."""
    return _BY_STATUS.get(status, Error)(status, message)
