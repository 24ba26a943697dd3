"""The skill library: named, tested trajectory adaptations that generated code calls.

The prompt's function list is rendered from ``SKILLS`` itself (name, signature, first docstring
sentence), so the prompt and the library never drift apart. In the sandbox the functions are bound
to the axis convention the prompt states and to what the user means by near (``speed.NEAR_RULES``).
"""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable
from typing import Any

from trajadapt.model.geometry import PAPER_AXES, Axes
from trajadapt.skills import events, objects, shape, speed

SKILLS: tuple[Callable[..., Any], ...] = (
    shape.shift,
    shape.shift_goal,
    shape.shift_start,
    shape.shift_part,
    shape.lift_middle,
    objects.move_closer,
    objects.move_away,
    objects.avoid,
    objects.pass_through,
    objects.pass_over,
    objects.reach,
    objects.midpoint,
    objects.closest_waypoint,
    speed.scale_speed,
    speed.set_speed,
    speed.speed_profile,
    events.stop_at,
    events.wait,
    events.extend,
    events.append_segment,
    events.spiral,
    events.circle_around,
    shape.set_height,
    shape.stay_above,
    shape.stay_below,
    shape.keep_side,
    shape.rotate,
    shape.scale_about,
    shape.exaggerate_curve,
    shape.zigzag,
    shape.smooth,
    shape.resample,
    shape.add_noise,
    shape.path_size,
)

SKILL_NAMES = tuple(function.__name__ for function in SKILLS)
PROMPT_HIDDEN = frozenset({"axes", "iterations", "count", "seed", "width", "reference"})  # rarely needed


def bind_skills(axes: Axes = PAPER_AXES, near_rule: str = "zone") -> dict[str, Callable[..., Any]]:
    """The skills by name, with the user's conventions bound where a function takes them.

    ``axes`` is the axis convention, ``near_rule`` what "near an object" means to a speed change
    (``speed.NEAR_RULES``).

    Raises:
        ValueError: a near_rule not in ``speed.NEAR_RULES``.
    """
    conventions: dict[str, Any] = {"axes": axes, "near_rule": speed.checked_near_rule(near_rule)}
    bound: dict[str, Callable[..., Any]] = {}
    for function in SKILLS:
        taken = {k: v for k, v in conventions.items() if k in inspect.signature(function).parameters}
        if taken:
            bound[function.__name__] = functools.wraps(function)(functools.partial(function, **taken))
        else:
            bound[function.__name__] = function
    return bound


def signature_line(function: Callable[..., Any]) -> str:
    """``name(args)``: what the prompt shows, without ``axes`` (bound by the sandbox) and optional knobs.

    A required parameter is always shown, whatever its name; an optional keyword-only one never is:
    those are set by the pipeline (the sandbox's ``reference``, a reader's ``part`` of an object move).
    """
    parameters = [
        p
        for p in inspect.signature(function).parameters.values()
        if p.default is inspect.Parameter.empty
        or (p.name not in PROMPT_HIDDEN and p.kind is not inspect.Parameter.KEYWORD_ONLY)
    ]
    rendered = []
    for parameter in parameters:
        if parameter.default is inspect.Parameter.empty:
            rendered.append(parameter.name)
        else:
            rendered.append(f"{parameter.name}={parameter.default!r}")
    return f"{function.__name__}({', '.join(rendered)})"


def summary(function: Callable[..., Any]) -> str:
    """The first paragraph of the docstring, on one line."""
    doc = inspect.getdoc(function) or ""
    return " ".join(doc.split("\n\n")[0].split())


def describe_skills() -> str:
    """The prompt's list of skills: one line each."""
    return "\n".join(f"- {signature_line(f)}: {summary(f)}" for f in SKILLS)


__all__ = ["SKILLS", "SKILL_NAMES", "Axes", "PAPER_AXES", "bind_skills", "describe_skills"]
