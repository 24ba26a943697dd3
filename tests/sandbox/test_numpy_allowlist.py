"""numpy is reached through an allow-list: array maths runs, raw memory and random state never do.

The reported escapes turned bytes into references and back (an object array's ``tobytes`` and
``np.ndarray(..., buffer=...)``), freed memory (``resize(refcheck=False)``) or read the heap through a
random generator's state setter. Each class, and its near relatives, is refused by the static check
before anything runs; the module proxies refuse the same names at run time.
"""

from __future__ import annotations

import math
from types import ModuleType

import numpy as np
import pytest

from tests.conftest import line_trajectory
from trajadapt.model.scene import Scene, SceneObject
from trajadapt.sandbox.allowed_names import ALLOWED_ATTRIBUTES, MODULE_MEMBERS
from trajadapt.sandbox.guard import ALLOWED_MODULES, check_code
from trajadapt.sandbox.restricted import preload_modules
from trajadapt.sandbox.runner import Sandbox

SUCCESS = "\nmodified_trajectory = get_trajectory()\n"

# Names that read or write raw memory, uninitialised memory or a generator's state.
UNSAFE = frozenset(
    {
        "tobytes", "tostring", "view", "frombuffer", "fromstring", "ndarray", "resize", "data",
        "ctypes", "lib", "stride_tricks", "as_strided", "bit_generator", "state", "set_state",
        "get_state", "MT19937", "Philox", "PCG64", "PCG64DXSM", "SFC64", "BitGenerator",
        "RandomState", "Generator", "SeedSequence", "empty", "empty_like", "base", "setflags",
        "flags", "strides", "from_dlpack", "dtype", "frompyfunc", "memmap", "load", "save",
        "tofile", "fromfile", "random_raw", "advance", "jumped", "itemset", "getfield", "setfield",
        "byteswap", "dumps", "dump", "mtrand", "core", "ma", "char", "rec", "typing", "testing",
    }
)  # fmt: skip

MEMORY_ESCAPES: list[tuple[str, str]] = [
    ("object-tobytes", "a = np.array([print], dtype='O')\nb = a.tobytes()"),
    ("ndarray-buffer", "b = bytes(8)\nc = np.ndarray((1,), dtype='O', buffer=b)"),
    ("ndarray-class-resize", "a = np.zeros(4)\nnp.ndarray.resize(a, 10 ** 6, refcheck=False)"),
    ("resize-refcheck", "a = np.zeros(4)\na.resize(10 ** 6, refcheck=False)"),
    ("mt19937-pos", "g = np.random.MT19937()\ns = g.state\ns['state']['pos'] = -1000\ng.state = s"),
    ("philox-buffer-pos", "p = np.random.Philox()\ns = p.state\ns['buffer_pos'] = -10 ** 6\np.state = s"),
    ("randomstate-set-state", "r = np.random.RandomState(0)\nr.set_state(('MT19937', [0] * 624, 10 ** 9))"),
    ("legacy-set-state", "np.random.set_state(('MT19937', [0] * 624, 10 ** 9))"),
    ("legacy-get-state", "print(np.random.get_state())"),
    ("rng-bit-generator", "g = np.random.default_rng(0)\nprint(g.bit_generator.state)"),
    ("rng-advance", "g = np.random.default_rng(0)\ng.bit_generator.advance(-1)"),
    ("generator-class", "g = np.random.Generator(np.random.PCG64())"),
    ("view-object", "a = np.array([print], dtype='O')\nprint(a.view(np.int64))"),
    ("frombuffer-object", "print(np.frombuffer(bytes(8), dtype='O'))"),
    ("fromstring", "print(np.fromstring(bytes(8), dtype=np.int64))"),
    ("stride-tricks", "a = np.zeros(4)\nprint(np.lib.stride_tricks.as_strided(a, shape=(10 ** 6,)))"),
    ("array-data", "a = np.zeros(4)\nprint(a.data)"),
    ("array-base", "a = np.zeros(4)[1:]\nprint(a.base)"),
    ("setflags", "a = np.zeros(4)\na.setflags(write=True)"),
    ("empty-heap", "print(np.empty(10 ** 5).sum())"),
    ("empty-like-heap", "print(np.empty_like(np.zeros(10 ** 5)).sum())"),
    ("from-dlpack", "print(np.from_dlpack(np.zeros(2)))"),
    ("dtype-type", "a = np.zeros(2)\nprint(a.dtype.type)"),
    ("from-numpy-import-frombuffer", "from numpy import frombuffer\nprint(frombuffer(bytes(8)))"),
    ("from-random-import-mt19937", "from numpy.random import MT19937\nprint(MT19937())"),
    ("match-class-tobytes", "match np.zeros(2):\n    case np.ndarray(tobytes=f):\n        print(f())"),
    ("frompyfunc", "f = np.frompyfunc(print, 1, 1)"),
    ("random-raw", "g = np.random.default_rng(0)\nprint(g.bit_generator.random_raw())"),
    ("getfield", "a = np.zeros(2)\nprint(a.getfield(np.int64))"),
]

ORDINARY_PROGRAMS: list[tuple[str, str]] = [
    (
        "blend-left",
        "import numpy as np\nt = get_trajectory()\nw = np.linspace(0, 1, len(t))\n"
        "t[:, 0] += 0.2 * w\nmodified_trajectory = t",
    ),
    (
        "away-from-object",
        "t = get_trajectory()\np = np.array(detect_objects('box'))\nd = t[:, :3] - p\n"
        "n = np.linalg.norm(d, axis=1, keepdims=True)\nt[:, :3] += 0.1 * d / np.maximum(n, 1e-9)\n"
        "modified_trajectory = t",
    ),
    (
        "slow-near",
        "t = get_trajectory()\np = np.asarray(detect_objects('box'))\n"
        "near = np.linalg.norm(t[:, :3] - p, axis=1) < 0.5\nt[near, 3] *= 0.5\n"
        "modified_trajectory = np.clip(t, -10, 10)",
    ),
    (
        "resample",
        "t = get_trajectory()\ns = np.linspace(0, len(t) - 1, 2 * len(t))\n"
        "cols = [np.interp(s, np.arange(len(t)), t[:, k]) for k in range(4)]\n"
        "modified_trajectory = np.stack(cols, axis=1)",
    ),
    (
        "seeded-noise",
        "rng = np.random.default_rng(3)\nt = get_trajectory()\n"
        "t[1:-1, 2] += rng.normal(0, 0.01, len(t) - 2)\nmodified_trajectory = t",
    ),
    (
        "math-and-lists",
        "import math\nt = get_trajectory().tolist()\nrows = []\nfor x, y, z, v in t:\n"
        "    rows.append([x, y, z + 0.1 * math.sin(math.pi * x), max(v, 0.0)])\n"
        "modified_trajectory = np.array(rows)",
    ),
    (
        "polynomial-fit",
        "t = get_trajectory()\ni = np.arange(len(t))\np = np.polynomial.Polynomial.fit(i, t[:, 1], 2)\n"
        "t[:, 1] = p(i)\nmodified_trajectory = t",
    ),
]


@pytest.mark.parametrize(("name", "code"), MEMORY_ESCAPES, ids=[n for n, _ in MEMORY_ESCAPES])
def test_memory_escape_is_refused_before_it_runs(sandbox: Sandbox, name: str, code: str) -> None:
    result = sandbox.run(code + SUCCESS, line_trajectory(), Scene())
    assert not result.ok, f"{name} ran to a result"
    assert result.error is not None and result.error.type == "Rejected", (name, result.error)


@pytest.mark.parametrize(("name", "code"), ORDINARY_PROGRAMS, ids=[n for n, _ in ORDINARY_PROGRAMS])
def test_ordinary_numpy_programs_run(sandbox: Sandbox, name: str, code: str) -> None:
    scene = Scene((SceneObject("box", 0.5, 0.2, 0.0),))
    result = sandbox.run(code, line_trajectory(), scene)
    assert result.ok, (name, result.error)


def test_no_unsafe_name_is_allowed() -> None:
    assert not UNSAFE & ALLOWED_ATTRIBUTES


def test_every_allowed_member_exists_and_is_no_foreign_module() -> None:
    for module_name, members in MODULE_MEMBERS.items():
        module: ModuleType = math if module_name == "math" else np
        for part in module_name.split(".")[1:]:
            module = getattr(module, part)
        for member in members:
            value = getattr(module, member)
            if isinstance(value, ModuleType):
                assert f"{module_name}.{member}" in ALLOWED_MODULES, (module_name, member)


def test_every_attribute_of_numpy_values_is_allowed_only_when_listed() -> None:
    """Walk every public name numpy's modules, arrays and generators have; only the listed pass."""
    names: set[str] = set()
    for value in (np, np.linalg, np.random, np.zeros(2), np.random.default_rng(0), np.random.MT19937()):
        names |= {name for name in dir(value) if not name.startswith("_")}
    for name in sorted(names):
        refused = check_code(f"x = np.zeros(2)\ny = x.{name}") is not None
        assert refused == (name not in ALLOWED_ATTRIBUTES), name


def test_module_proxies_serve_only_their_members() -> None:
    modules = preload_modules()
    assert modules["numpy"].linspace is np.linspace
    for module_name, attribute in [
        ("numpy", "frombuffer"),
        ("numpy", "ndarray"),
        ("numpy", "empty"),
        ("numpy.random", "MT19937"),
        ("numpy.random", "set_state"),
        ("numpy", "lib"),
        ("numpy.linalg", "linalg"),
    ]:
        with pytest.raises(AttributeError):
            getattr(modules[module_name], attribute)
    assert "frombuffer" not in dir(modules["numpy"])
