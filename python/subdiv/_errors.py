"""The exceptions subdiv raises, mirroring the library's hierarchy.

Every message is the library's one line: it names the file and line, or
the element (vertex, face, edge), that is wrong.
"""


class Error(Exception):
    """Base of every error subdiv raises on purpose."""


class InvalidInputError(Error, ValueError):
    """Unusable arguments or a malformed mesh (bad shape, index or value)."""


class ParameterError(InvalidInputError):
    """A scheme parameter outside its family's valid range."""


class TopologyError(InvalidInputError):
    """Connectivity the operation cannot take (non-manifold, out-of-range indices)."""


class ValidationError(TopologyError):
    """A mesh that fails validation; ``issues`` lists what validation found."""

    def __init__(self, message, issues=()):
        super().__init__(message)
        self.issues = list(issues)


class IoError(Error, OSError):
    """A file that cannot be opened, read or written."""


class ParseError(IoError):
    """A malformed file: ``path`` names it, ``line`` is 1-based (0: no line)."""

    def __init__(self, message, path="", line=0):
        super().__init__(message)
        self.path = path
        self.line = line

    def __str__(self):
        return self.args[0] if self.args else ""
