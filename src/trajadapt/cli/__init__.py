"""The ``trajadapt`` command line: one module per command group, thin over the session API.

``main`` (the group and error handling), ``adapt``, ``bench``, ``backends``, ``logs``, ``serve``
(the review page), ``robots`` (``simulate``, ``plan``), ``ros`` (``export``); ``common`` holds the
options several commands share and ``console`` what they print.
"""

from trajadapt.cli.main import cli

__all__ = ["cli"]
