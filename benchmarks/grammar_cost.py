"""What constrained decoding costs per answer with the embedded model, decoder by decoder.

For each case (its first request as a session sends it: prompt, examples, grammar), the answer is
written in five ways by one loaded model: free (no grammar), llama.cpp's grammar sampler, and
llguidance masking every token / checking the first choice / checking it and feeding forced text
in batches (the default). The prompt is read once per case (the same tokens for every way), so the
table compares writing only: median seconds, tokens written, model evaluations, milliseconds per
written token, and how many answers are token for token the llama.cpp sampler's. Run it alone: the
numbers are wall-clock.

Run: .venv/bin/python benchmarks/grammar_cost.py CASE_OR_FOLDER... [--limit 12]
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path
from typing import Any

from trajadapt.backends.base import ChatRequest, Completion, Usage
from trajadapt.backends.guided_decoding import Sampling, decode_request
from trajadapt.backends.local import LocalBackend, LocalOptions
from trajadapt.model.case import Case, load_case
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import AdaptationSession, SessionSettings

WAYS = (
    ("free, no grammar", None),
    ("llama.cpp grammar sampler", None),
    ("llguidance, mask every token", Sampling(check_first=False, fast_forward=False)),
    ("llguidance, check the first choice", Sampling(fast_forward=False)),
    ("llguidance, check first + forced text batched", Sampling()),
)


def cases_under(paths: list[Path], limit: int) -> list[Case]:
    """Up to ``limit`` cases from files or folders, spread over the folders in sorted order."""
    files = sorted(
        f for p in paths for f in ([p] if p.is_file() else p.rglob("*.json")) if "expect" not in f.name
    )
    return [load_case(f) for f in files[:: max(1, len(files) // limit)][:limit]]


class _FirstRequest(LocalBackend):
    """Keeps the session's first request instead of answering it."""

    request: ChatRequest | None = None

    def complete(self, request: ChatRequest) -> Completion:
        self.request = self.request or request
        answer = (
            '{"high_level_plan": "1) Keep.", "python_code": "t = get_trajectory()\\nmodified_trajectory = t"}'
        )
        return Completion(text=answer, model="none", usage=Usage())


def first_request(case: Case) -> ChatRequest:
    """The request a session sends for the case's first answer (no memory, defaults)."""
    capture = _FirstRequest(LocalOptions())
    with Sandbox() as sandbox:
        AdaptationSession(case, capture, sandbox, SessionSettings(repair_attempts=0)).draft()
    assert capture.request is not None
    return capture.request


LLAMA_CPP = {
    "free, no grammar": LocalOptions(grammar=False, prompt_cache=False),
    "llama.cpp grammar sampler": LocalOptions(decoder="llama.cpp", prompt_cache=False),
}


def write(backend: LocalBackend, request: ChatRequest, way: str, sampling: Sampling | None) -> dict[str, Any]:
    """One answer written one way; the prompt is already in the context (the loaded model is shared)."""
    llama = backend._load(backend.model_path())
    if sampling is None:
        started = time.perf_counter()
        completion = LocalBackend(LLAMA_CPP[way]).complete(request)
        seconds = time.perf_counter() - started
        tokens = completion.usage.completion_tokens or 0
        return {"text": completion.text, "write_s": seconds, "tokens": tokens, "decodes": tokens}
    decoded = decode_request(llama, request, sampling)
    seconds = decoded.read_s + decoded.write_s
    return {
        "text": decoded.text,
        "write_s": seconds,
        "tokens": decoded.written_tokens,
        "decodes": decoded.decodes,
    }


def main() -> None:
    """Write every case's answer every way and print one table row per way."""
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("paths", nargs="+", type=Path)
    parser.add_argument("--limit", type=int, default=12)
    args = parser.parse_args()
    backend = LocalBackend(LocalOptions())
    backend.prepare()
    requests = [first_request(case) for case in cases_under(args.paths, args.limit)]
    runs: dict[str, list[dict[str, Any]]] = {way: [] for way, _ in WAYS}
    for request in requests:
        backend.complete(request)  # reads this prompt; every way below then reads one token of it
        for way, sampling in WAYS:
            runs[way].append(write(backend, request, way, sampling))
    print(f"{len(requests)} case(s), {backend.describe()}; medians per answer, writing only")
    print("| way | write s | tokens | evaluations | ms per token | same as llama.cpp |")
    print("|---|---|---|---|---|---|")
    reference = [run["text"] for run in runs["llama.cpp grammar sampler"]]
    for way, _ in WAYS:
        rows = runs[way]
        seconds = statistics.median(r["write_s"] for r in rows)
        tokens = statistics.median(r["tokens"] for r in rows)
        evaluations = statistics.median(r["decodes"] for r in rows)
        per_token = statistics.median(1000 * r["write_s"] / max(r["tokens"], 1) for r in rows)
        same = sum(r["text"] == text for r, text in zip(rows, reference, strict=True))
        print(
            f"| {way} | {seconds:.2f} | {tokens:.0f} | {evaluations:.0f} | {per_token:.0f} | {same}/{len(rows)} |"
        )


if __name__ == "__main__":
    main()
