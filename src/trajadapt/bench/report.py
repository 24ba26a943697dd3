"""Benchmark summary and markdown report: pass rates, failure reasons, shape metrics, latency, figures."""

from __future__ import annotations

import logging
import re
import statistics
from collections import Counter
from pathlib import Path
from typing import Any

import numpy as np

from trajadapt.files.atomic_files import write_bytes_atomic, write_json_atomic
from trajadapt.files.plot import plot_comparison
from trajadapt.model.geometry import AXIS_CONVENTIONS
from trajadapt.model.scene import Scene, parse_objects
from trajadapt.model.trajectory import Trajectory

logger = logging.getLogger(__name__)


def _subset(record: dict[str, Any]) -> str:
    task = str(record["evaluation"]["task_id"])
    parts = task.split("/")
    return parts[1] if len(parts) > 2 else parts[0]


def _rate(records: list[dict[str, Any]]) -> dict[str, Any]:
    judged = [r for r in records if r["evaluation"]["judged"]]
    passed = sum(1 for r in judged if r["evaluation"]["passed"])
    executed = sum(1 for r in records if r["status"] == "ok")
    return {
        "cases": len(records),
        "judged": len(judged),
        "passed": passed,
        "pass_rate": passed / len(judged) if judged else None,
        "executable_rate": executed / len(records) if records else None,
    }


def _kind_of_older_result(record: dict[str, Any]) -> str:
    """Result files written before ``error_kind`` existed: the error line's first word."""
    match = re.match(r"(\w+)", str(record.get("error") or ""))
    return match.group(1) if match else "unknown"


def failure_kind(record: dict[str, Any]) -> str:
    """A short label for why a judged case failed: the error type, or the first failing check kind."""
    if record["status"] != "ok":
        kind = record.get("error_kind") or _kind_of_older_result(record)
        return "error: " + kind
    failed = [c["kind"] for c in record["evaluation"]["checks"] if not c["passed"]]
    return "check: " + (failed[0] if failed else "none")


def summarize(records: list[dict[str, Any]]) -> dict[str, Any]:
    """Overall and per-subset pass rates, failure kinds, repairs, shape metrics, latency and tokens."""
    latencies = [r["timings_s"]["total"] for r in records if r["timings_s"].get("total") is not None]
    subsets = sorted({_subset(r) for r in records})
    failed = [r for r in records if r["evaluation"]["judged"] and not r["evaluation"]["passed"]]
    return {
        "overall": _rate(records),
        "subsets": {name: _rate([r for r in records if _subset(r) == name]) for name in subsets},
        "failure_kinds": Counter(failure_kind(r) for r in failed).most_common(),
        "repair_rounds": Counter(int(r.get("repair_rounds", 0)) for r in records).most_common(),
        "latency_s": {
            "median": statistics.median(latencies) if latencies else None,
            "p90": float(np.percentile(latencies, 90)) if latencies else None,
        },
        "tokens": {
            "prompt_mean": _mean([r.get("tokens", {}).get("prompt") for r in records]),
            "completion_mean": _mean([r.get("tokens", {}).get("completion") for r in records]),
        },
        "shape": {
            "frechet_median": _median([r["metrics"]["frechet"] for r in records]),
            "dtw_median": _median([r["metrics"]["dtw"] for r in records]),
            "roughness_ratio_median": _median(
                [
                    r["metrics"]["roughness"] / r["metrics"]["roughness_original"]
                    for r in records
                    if r["metrics"]["roughness"] is not None and r["metrics"]["roughness_original"]
                ]
            ),
        },  # fmt: skip
        "targets": target_summary(records),
        "backend": records[0]["backend"] if records else None,
        "model": records[0]["model"] if records else None,
        "mode": records[0].get("mode") if records else None,
    }


LATTE_METRICS = ("mse", "mae", "dtw", "dfd")


def target_summary(records: list[dict[str, Any]]) -> dict[str, Any] | None:
    """Mean LaTTe metrics of the tool and of copying the input, per subset and overall (None: no targets)."""
    scored = [r for r in records if r.get("target_scores")]
    if not scored:
        return None
    groups = {
        name: [r for r in scored if _subset(r) == name] for name in sorted({_subset(r) for r in scored})
    }
    return {name: _target_means(group) for name, group in {**groups, "overall": scored}.items()}


def _target_means(records: list[dict[str, Any]]) -> dict[str, Any]:
    means = {
        who: {
            metric: float(np.mean([r["target_scores"][who][metric] for r in records]))
            for metric in LATTE_METRICS
        }
        for who in ("tool", "copy")
    }
    return {"cases": len(records), **means}


def _target_table(targets: dict[str, Any]) -> list[str]:
    lines = [
        "",
        "LaTTe's metrics against the reference targets (mean; lower is better; tool vs copying the input):",
        "",
        "| subset | cases | MSE tool | MSE copy | MAE tool | MAE copy | DTW tool | DTW copy | DFD tool "
        "| DFD copy |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for name, group in targets.items():
        cells = [f"{_number(group[who][m], 4)}" for m in LATTE_METRICS for who in ("tool", "copy")]
        lines.append(f"| {name} | {group['cases']} | " + " | ".join(cells) + " |")
    return lines


def _mean(values: list[Any]) -> float | None:
    numbers = [float(v) for v in values if v]
    return sum(numbers) / len(numbers) if numbers else None


def _median(values: list[Any]) -> float | None:
    numbers = [float(v) for v in values if v is not None]
    return statistics.median(numbers) if numbers else None


def _percent(value: float | None) -> str:
    return "-" if value is None else f"{100 * value:.1f}%"


def _number(value: float | None, digits: int = 3) -> str:
    return "-" if value is None else f"{value:.{digits}g}"


def render_markdown(summary: dict[str, Any], records: list[dict[str, Any]]) -> str:
    """The report: headline, per-subset table, failure kinds, metrics, then one row per case."""
    lines = [f"# Benchmark: {summary['backend']} ({summary['model']}), prompt mode {summary['mode']}", ""]
    lines += [_headline(summary["overall"]), ""]
    lines += ["| subset | cases | judged | passed | pass rate | executable |", "|---|---|---|---|---|---|"]
    for name, rate in summary["subsets"].items():
        cells = [name, rate["cases"], rate["judged"], rate["passed"], _percent(rate["pass_rate"])]
        lines.append("| " + " | ".join(str(c) for c in cells) + f" | {_percent(rate['executable_rate'])} |")
    latency, tokens, shape = summary["latency_s"], summary["tokens"], summary["shape"]
    rounds = ", ".join(f"{n} round(s): {count} case(s)" for n, count in sorted(summary["repair_rounds"]))
    lines += [
        "",
        f"Latency per case: median {_number(latency['median'])} s, "
        f"90th percentile {_number(latency['p90'])} s.",
        f"Tokens per case (mean): prompt {_number(tokens['prompt_mean'], 4)}, "
        f"completion {_number(tokens['completion_mean'], 4)}.",
        f"Shape: median discrete Fréchet {_number(shape['frechet_median'])}, median DTW "
        f"{_number(shape['dtw_median'])}, median roughness ratio {_number(shape['roughness_ratio_median'])}.",
        *(_target_table(summary["targets"]) if summary.get("targets") else []),
        "",
        "Repair rounds used: " + rounds,
        "",
        "## Most common failure kinds",
        "",
        *[f"- {kind}: {count}" for kind, count in summary["failure_kinds"]],
        "",
        "## Cases",
        "",
        "| case | instruction | result | reason |",
        "|---|---|---|---|",
    ]
    lines += [_case_row(record) for record in records]
    return "\n".join(lines) + "\n"


def _headline(overall: dict[str, Any]) -> str:
    return (
        f"Passed **{overall['passed']} of {overall['judged']}** judged cases "
        f"({_percent(overall['pass_rate'])}); {overall['cases'] - overall['judged']} not judged; the code "
        f"ran to a valid trajectory in {_percent(overall['executable_rate'])} of {overall['cases']} cases."
    )


def _case_row(record: dict[str, Any]) -> str:
    evaluation = record["evaluation"]
    failed = evaluation["judged"] and not evaluation["passed"]
    verdict = "not judged" if not evaluation["judged"] else ("**fail**" if failed else "pass")
    figure = f" ([figure](figures/{_figure_name(record)}))" if failed else ""
    reason = str(evaluation.get("reason") or "").replace("|", "/")[:160]
    instruction = record["instruction"][:70].replace("|", "/")
    return f"| {evaluation['task_id']} | {instruction} | {verdict}{figure} | {reason} |"


def _figure_name(record: dict[str, Any]) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", str(record["evaluation"]["task_id"])) + ".png"


def write_report(out_dir: Path, records: list[dict[str, Any]]) -> dict[str, Any]:
    """Write summary.json, report.md and a figure per failed case into ``out_dir``; return the summary."""
    summary = summarize(records)
    write_json_atomic(out_dir / "summary.json", summary)
    write_bytes_atomic(out_dir / "report.md", render_markdown(summary, records).encode("utf-8"))
    for record in records:
        if record["evaluation"]["judged"] and not record["evaluation"]["passed"]:
            try:
                _figure(out_dir / "figures" / _figure_name(record), record)
            except Exception as exc:  # noqa: BLE001 - one figure that cannot be drawn must not lose the report
                logger.warning(
                    "no figure for %s: %s: %s", record["evaluation"]["task_id"], type(exc).__name__, exc
                )
    return summary


def _figure(path: Path, record: dict[str, Any]) -> None:
    adapted = record.get("modified_trajectory")
    scene = Scene(parse_objects(record.get("objects"), "result objects"))
    plot_comparison(
        Trajectory(np.asarray(record["original_trajectory"])),
        Trajectory(np.asarray(adapted)) if adapted else None,
        scene,
        path,
        AXIS_CONVENTIONS[record.get("axes", "paper")],
        title=f"{record['instruction']} [FAIL: {failure_kind(record)}]",
    )
