"""LLM backends behind one small interface, registered by name (built-ins and plugins alike).

``Backend`` is the interface, ``get_backend(name, options)`` builds one from the registry
(``trajadapt.backends`` entry points), and ``backends.conformance`` checks a new one.
"""

from trajadapt.backends.base import Backend, ChatMessage, ChatRequest, Completion, Usage
from trajadapt.backends.registry import backend_class, get_backend, registered_backends

__all__ = [
    "Backend",
    "ChatMessage",
    "ChatRequest",
    "Completion",
    "Usage",
    "backend_class",
    "get_backend",
    "registered_backends",
]
