"""On-disk cache of llama.cpp's state after the prompt's fixed prefix, so a new process starts warm.

Within one process llama.cpp already reuses the cached prefix. A new ``trajadapt adapt`` process
would read the whole ~2,000-token fixed prompt again (about 35 s on 2 cores); restoring the saved
state instead takes well under a second. The state is saved with llama.cpp's own
``llama_state_save_file`` (KV cache and tokens only), not ``Llama.save_state``, which copies the whole
score matrix and costs about 1 GB of memory. This module touches llama-cpp-python internals
(``_ctx``, ``input_ids``, ``n_tokens``) and is tied to the pinned version 0.3.36.
"""

from __future__ import annotations

import ctypes
import hashlib
import logging
import os
from pathlib import Path
from typing import Any

logger = logging.getLogger(__name__)


class PromptStateCache:
    """Saves and restores the llama.cpp state for a given fixed prompt prefix, keyed by its text."""

    def __init__(self, folder: Path, model_key: str) -> None:
        self.folder = folder
        self.model_key = model_key

    def path_for(self, prefix: str) -> Path:
        """The state file for ``prefix`` with this model and settings."""
        digest = hashlib.sha256(f"{self.model_key}\n{prefix}".encode()).hexdigest()[:24]
        return self.folder / f"{digest}.llama-state"

    def restore(self, llama: Any, prefix: str) -> int:
        """Load the saved state for ``prefix`` into a fresh context; returns the tokens restored (0: none)."""
        path = self.path_for(prefix)
        if not path.is_file() or int(llama.n_tokens) != 0:
            return 0
        import llama_cpp

        capacity = int(llama.n_ctx())
        tokens = (llama_cpp.llama_token * capacity)()
        count = ctypes.c_size_t(0)
        if not llama_cpp.llama_state_load_file(
            llama._ctx.ctx, str(path).encode(), tokens, capacity, ctypes.byref(count)
        ):
            logger.warning("could not load prompt state %s; removing it", path)
            path.unlink(missing_ok=True)
            llama.reset()
            return 0
        restored = int(count.value)
        llama.input_ids[:restored] = tokens[:restored]
        llama.n_tokens = restored
        llama._requires_eval = True  # logits come from a restored state: evaluate at least one token
        return restored

    def save(self, llama: Any, prefix: str) -> None:
        """Write the current state (prompt and answer tokens) for ``prefix``, atomically."""
        import llama_cpp

        count = int(llama.n_tokens)
        if count == 0:
            return
        self.folder.mkdir(parents=True, exist_ok=True)
        path = self.path_for(prefix)
        temporary = path.with_name(path.name + f".{os.getpid()}.partial")
        tokens = (llama_cpp.llama_token * count)(*[int(t) for t in llama.input_ids[:count]])
        if llama_cpp.llama_state_save_file(llama._ctx.ctx, str(temporary).encode(), tokens, count):
            os.replace(temporary, path)
        else:
            temporary.unlink(missing_ok=True)
            logger.warning("could not save prompt state to %s", path)
