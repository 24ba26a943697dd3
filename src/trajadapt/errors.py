"""The error tree of trajadapt: one class per kind of failure, each message naming the next step.

::

    TrajadaptError
    ├── InputError                  a case, trajectory or scene file is missing or malformed
    │   ├── LogUnusable             the log database cannot be opened, read or written
    │   └── MemoryUnusable          the bank of remembered examples (or a file to import) is unusable
    ├── BackendError                the LLM could not be asked or did not answer usefully
    │   ├── BackendUnavailable      refused connection, DNS failure, HTTP 5xx, model not loaded
    │   ├── BackendTimeout          no answer in time
    │   ├── BackendRejected         HTTP 4xx: bad key, unknown model, request too long
    │   └── EmptyCompletion         the server answered with no text
    ├── UnknownBackend              no backend registered under that name
    ├── BackendOptionError          an option the backend does not take, or a bad value
    ├── AnswerParseError            the answer holds no plan and code we can read
    ├── SandboxError                generated code could not be run to a result
    │   ├── CodeRejected            the static check refused the code before it ran
    │   └── InvalidTrajectory       the code ran but its result is not a valid trajectory
    ├── ModelFileError              the embedded model is missing, incomplete or not the pinned one
    ├── SessionStateError           a session method was called out of order
    └── DependencyNotInstalled      an optional extra is needed
"""

from __future__ import annotations


class TrajadaptError(Exception):
    """Base class of every error trajadapt raises on purpose."""


class InputError(TrajadaptError):
    """A case, trajectory or scene file is missing or malformed."""


class LogUnusable(InputError):
    """The log file (logs.db) cannot be opened, read or written: the message names it and what to do."""


class MemoryUnusable(InputError):
    """The bank of remembered examples cannot be read or written, or a file to import is not one."""


class InvalidWaypoints(TrajadaptError, ValueError):
    """An array is not a trajectory: N x 4 (2 <= N <= 100,000), finite, within ±1e9, v >= 0.

    Raised by ``Trajectory`` itself, the one place the rule is enforced; the edges map it to
    ``InputError`` (a file) or ``InvalidTrajectory`` (generated code), naming the source.
    """


class BackendError(TrajadaptError):
    """The LLM backend could not be asked or did not answer usefully."""


class BackendUnavailable(BackendError):
    """The backend could not be reached (refused connection, server error)."""


class BackendTimeout(BackendError):
    """The backend did not answer within the time limit."""


class BackendRejected(BackendError):
    """The backend refused the request (HTTP 4xx)."""


class EmptyCompletion(BackendError):
    """The backend answered with no text."""


class UnknownBackend(TrajadaptError):
    """No backend is registered under the requested name."""


class BackendOptionError(TrajadaptError):
    """A backend was given an option it does not take, or a bad value."""


class AnswerParseError(TrajadaptError):
    """The LLM answer holds no high-level plan and code that can be read."""


class SandboxError(TrajadaptError):
    """Generated code could not be run to a valid trajectory."""


class CodeRejected(SandboxError):
    """The static check refused the code before it ran."""


class InvalidTrajectory(SandboxError):
    """The code ran but did not produce a valid trajectory."""


class ModelFileError(TrajadaptError):
    """The embedded model file is missing, incomplete or not the pinned one."""


class SessionStateError(TrajadaptError):
    """A session method was called when the session was not ready for it."""


class DependencyNotInstalled(TrajadaptError):
    """An optional dependency is needed; the message names the extra to install."""


class SimulationError(TrajadaptError):
    """A trajectory could not be run on a simulated robot (unknown robot, no timing, too long)."""


class PlanningError(TrajadaptError):
    """No initial trajectory could be planned between the given start and goal."""
