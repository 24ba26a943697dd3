"""The limits a program sets at its close, kept together.

A program that ends with several limit steps asks all of them of its result: "don't get within 0.6 m
of the person, and don't dip below 0.2 m" came back as ``avoid(t, detect_objects('Person'), 0.6)``
then ``stay_above(t, 0.2)``, and lifting the path above 0.2 brought it back to 0.247 from the person.
Each step keeps its own limit only when it runs. The closing run of limit steps (``avoid`` of scene
objects with a stated clearance, ``stay_above``, ``stay_below``: every step after the program's last
other step; a speed step between them moves no waypoint and does not end the run) is applied again
in turn, at most ``ROUNDS`` times, until every limit holds; the result is kept only if they all hold
then, with a note that says which limit a later step had broken and how far the waypoints moved.
A clearance written before another kind of step is held with them when no later step names its
object and the start and goal stay where the program put them (``earlier_clearances``); a later
step on the same object is that program's own business (``avoid`` of a box, then ``reach`` of the
box, asks the path to end at the box). A projection onto the robot's limits keeps both kinds
(``kept_clearances``).

Only literal numbers and ``detect_objects`` of scene objects are read from the code: nothing of it
runs here, and the skills applied are the product's own.
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from trajadapt.code_parse import SPEED_STEPS, detected_name, detected_names, objects_of, parse_code
from trajadapt.model.geometry import Array, progress
from trajadapt.model.scene import Scene
from trajadapt.skills import bind_skills
from trajadapt.skills.objects import clearance_push
from trajadapt.skills.shape import LIMIT_FADE

ROUNDS = 10
"""How often the closing limits are applied in turn at most (two rounds sufficed where measured)."""
SLACK = 1e-6
NUDGE_MARGIN = 1.02
"""A nudged waypoint goes this much beyond its clearance (as ``avoid``'s own passes do): pushes out of
two overlapping clearances in turn otherwise close in on their meeting point ever more slowly."""
LIMIT_STEPS = ("avoid", "stay_above", "stay_below")


@dataclass(frozen=True)
class Limit:
    """One limit a closing step sets: a clearance from points, or a height bound."""

    skill: str
    value: float
    points: tuple[tuple[float, float, float], ...] = ()
    names: tuple[str, ...] = ()
    keep_ends: bool = False  # a height limit that holds away from the start and the goal

    def holds(self, trajectory: Array) -> bool:
        """Whether every waypoint keeps this limit."""
        return self.worst(trajectory) >= -SLACK

    def worst(self, trajectory: Array) -> float:
        """By how much the worst waypoint keeps the limit (negative: broken by that much)."""
        z = trajectory[:, 2]
        if self.keep_ends:
            s = progress(trajectory)
            z = z[(s >= LIMIT_FADE) & (s <= 1.0 - LIMIT_FADE)]
        if self.skill == "stay_above":
            return float(z.min() - self.value)
        if self.skill == "stay_below":
            return float(self.value - z.max())
        nearest = min(float(np.linalg.norm(trajectory[:, :3] - p, axis=1).min()) for p in self.points)
        return nearest - self.value

    def describe(self) -> str:
        """The limit in words."""
        if self.skill == "avoid":
            return f"the clearance {self.value:g} from {' and '.join(self.names)}"
        return f"a height {'above' if self.skill == 'stay_above' else 'below'} {self.value:g}"

    def apply(self, trajectory: Array, skills: dict[str, Callable[..., Array]]) -> Array:
        """The trajectory after this limit's skill."""
        if self.skill == "avoid":
            return skills["avoid"](trajectory, [list(p) for p in self.points], self.value)
        return skills[self.skill](trajectory, self.value, keep_ends=self.keep_ends)

    def nudge(self, trajectory: Array, skills: dict[str, Callable[..., Array]]) -> Array:
        """The trajectory with only the waypoints that break this limit moved.

        Out of a clearance straight away from its point (no smooth detour, which pushes into a
        neighbouring clearance), or by this limit's height skill.
        """
        if self.skill != "avoid":
            return self.apply(trajectory, skills)
        held = trajectory.copy()
        for point in self.points:
            held[:, :3] += clearance_push(held, np.asarray(point), self.value * NUDGE_MARGIN, sideways=False)
        return held


def closing_limits(code: str, scene: Scene) -> list[Limit]:
    """The limits of the program's closing run of limit steps, in order ([] when one cannot be read)."""
    steps = _steps(code)
    limits: list[Limit] = []
    for statement in reversed(steps):
        call, name = _call(statement), _step_name(statement)
        if name in SPEED_STEPS:
            continue  # a pace moves no waypoint: "keep 1 m from the fan, and slow down near the bottle"
        if name not in LIMIT_STEPS:
            break
        limit = _limit(name, call, scene)  # type: ignore[arg-type]
        if limit is None:
            return []
        limits.insert(0, limit)
    return limits


def hold_closing_limits(
    code: str, trajectory: Array, scene: Scene, skills: dict[str, Callable[..., Array]] | None = None
) -> tuple[Array, str | None]:
    """``trajectory`` with the program's closing limits held together, and a note saying so.

    Unchanged, with None, when they hold already, when there is one closing limit and no earlier
    clearance broken, or when they cannot all be held.
    """
    limits, earlier = closing_limits(code, scene), earlier_clearances(code, scene)
    broken = [limit for limit in (*earlier, *limits) if not limit.holds(trajectory)]
    if not broken or (len(limits) < 2 and not any(limit in earlier for limit in broken)):
        return trajectory, None
    skills = skills or bind_skills()
    held = _held(trajectory, [*earlier, *limits], skills, keep_ends=bool(earlier))
    if held is not None:
        moved = float(np.linalg.norm(held[:, :3] - trajectory[:, :3], axis=1).max())
        what = "; ".join(f"{x.describe()} (short by {-x.worst(trajectory):.3g})" for x in broken)
        return held, (
            f"the closing limits held together: a later limit step had broken {what}; "
            f"waypoints moved by at most {moved:.4g}"
        )
    return trajectory, None


def _held(
    trajectory: Array, limits: list[Limit], skills: dict[str, Callable[..., Array]], keep_ends: bool = False
) -> Array | None:
    """The trajectory with every limit holding (and, if ``keep_ends``, its ends where they are), or None.

    Each limit's skill in turn, then (where clearances overlap and the detours push into each other)
    only the breaking waypoints nudged.
    """
    ends = trajectory[[0, -1], :3]
    for step in (Limit.apply, Limit.nudge):
        held = trajectory.copy()
        for _ in range(ROUNDS):
            for limit in limits:
                held = step(limit, held, skills)
            if all(limit.holds(held) for limit in limits):
                break
        kept = not keep_ends or np.allclose(held[[0, -1], :3], ends, rtol=0.0, atol=1e-9)
        if kept and all(limit.holds(held) for limit in limits):
            return held
    return None


def earlier_clearances(code: str, scene: Scene) -> list[Limit]:
    """The clearances of ``avoid`` steps before the closing run that no later step names the objects of.

    "Stay at least 0.3 from the Dustbin, and keep the landing spot where it is" came back as
    ``avoid(t, detect_objects('Dustbin'), 0.3)`` then ``reach(t, detect_objects('goal'))``, and the
    pull back to the goal brought the path 0.282 from the Dustbin. A later step on the same object
    (``reach`` of it, ``pass_through`` it) asks something of it that the program means instead, so
    that clearance is not kept; nor is any where a later step goes by a point given as coordinates
    or a variable (it may be that object).
    """
    steps = _steps(code)
    found: list[Limit] = []
    for index, statement in enumerate(steps):
        call, later = _call(statement), steps[index + 1 :]
        if any(_unnamed_point(s) for s in later):
            break  # a later step goes by a point the code gives otherwise: which object it is, is unknown
        if call is None or _step_name(statement) != "avoid":
            continue
        if all(_step_name(s) in (*SPEED_STEPS, *LIMIT_STEPS) for s in later):
            break  # the closing run: held as such
        limit = _limit("avoid", call, scene)
        named = {n.casefold() for s in later for n in detected_names(s)}
        if limit is not None and not named & {n.casefold() for n in limit.names}:
            found.append(limit)
    return found


POINT_STEPS = (
    "avoid", "move_away", "move_closer", "pass_through", "pass_over", "reach", "stop_at", "circle_around",
    "append_segment", "scale_about",
)  # fmt: skip
"""Steps whose second argument is a point (or a list of points)."""


def _unnamed_point(statement: ast.stmt) -> bool:
    """Whether a step's point is given otherwise than by ``detect_objects`` (coordinates, a variable)."""
    call = _call(statement)
    return _step_name(statement) in POINT_STEPS and "" in objects_of(call)


def _steps(code: str) -> list[ast.stmt]:
    """The statements that do something (not ``modified_trajectory = t``); [] if the code does not parse."""
    try:
        body = parse_code(code).body
    except SyntaxError:
        return []
    return [s for s in body if not _passes_on(s)]


def _step_name(statement: ast.stmt) -> str:
    """The skill a step ``t = skill(...)`` calls, or ''."""
    call = _call(statement)
    return call.func.id if call is not None and isinstance(call.func, ast.Name) else ""


def _call(statement: ast.stmt) -> ast.Call | None:
    """The call of a step ``t = skill(...)``, or None."""
    call = statement.value if isinstance(statement, ast.Assign) else None
    return call if isinstance(call, ast.Call) and isinstance(call.func, ast.Name) else None


def kept_clearances(code: str, scene: Scene) -> tuple[tuple[tuple[float, float, float], float], ...]:
    """(point, least distance) for each clearance the program keeps: its closing and earlier ``avoid``s."""
    limits = [*earlier_clearances(code, scene), *closing_limits(code, scene)]
    return tuple((point, limit.value) for limit in limits if limit.skill == "avoid" for point in limit.points)


def _passes_on(statement: ast.stmt) -> bool:
    """Whether a statement only hands the result on (``modified_trajectory = t``) or is a blank expression."""
    if isinstance(statement, ast.Assign):
        return isinstance(statement.value, ast.Name)
    return isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Constant)


def _limit(name: str, call: ast.Call, scene: Scene) -> Limit | None:
    """The limit a step sets, when its numbers are literal and its points scene objects."""
    if name != "avoid":
        return _height_limit(name, call)
    arguments = list(call.args[1:]) + [k.value for k in call.keywords]
    if len(arguments) != 2:
        return None
    names = _object_names(arguments[0])
    value = _number(arguments[1])
    found = [scene.find(n) for n in names]
    if value is None or not names or any(obj is None for obj in found):
        return None
    points = tuple(obj.position for obj in found if obj is not None)
    return Limit(name, value, points, tuple(names))


def _height_limit(name: str, call: ast.Call) -> Limit | None:
    """The height limit of ``stay_above(t, 0.3)`` or ``stay_below(t, 0.3, keep_ends=True)``, if literal."""
    options = {k.arg: k.value for k in call.keywords}
    keep = options.pop("keep_ends", ast.Constant(False))
    value = _number(call.args[1]) if len(call.args) == 2 and not options else None
    if value is None or not isinstance(keep, ast.Constant) or not isinstance(keep.value, bool):
        return None
    return Limit(name, value, keep_ends=keep.value)


def _number(node: ast.expr) -> float | None:
    value = node.value if isinstance(node, ast.Constant) else None
    return float(value) if isinstance(value, int | float) and not isinstance(value, bool) else None


def _object_names(node: ast.expr) -> list[str]:
    """The names of ``detect_objects('X')`` or a list of such calls; [] for anything else."""
    items = node.elts if isinstance(node, ast.List | ast.Tuple) else [node]
    names = [detected_name(item) for item in items]
    return [name for name in names if name] if all(names) else []
