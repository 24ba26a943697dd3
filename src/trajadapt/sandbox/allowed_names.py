"""What generated code may name: an allow-list of module members and value attributes.

Wherever numpy may be written (free decoding, paper mode, a backend that does not follow the
grammar), the code reaches numpy through these lists and nothing else. They hold array maths:
creating, reshaping, combining and reducing arrays, elementwise functions, linear algebra and
seeded random numbers. They hold nothing that reads or writes an array's raw memory or a random
generator's state, and no uninitialised memory (``empty``, ``tobytes``, ``view``, ``frombuffer``,
``ndarray``, ``resize``, ``data``, ``ctypes``, ``lib.stride_tricks``, ``bit_generator``,
``set_state``, ``MT19937``): those turn bytes into references and back, or read the heap. Without
them an object array is only a list of Python objects.

The static check (``guard``) refuses any attribute outside ``ALLOWED_ATTRIBUTES``; the module proxies
(``restricted``) serve only ``MODULE_MEMBERS`` of their module, so a name the check missed is still
not there when the code runs.
"""

from __future__ import annotations

import math

NUMPY_MEMBERS = frozenset(
    {
        # submodules (served as proxies, each with its own list below)
        "linalg", "random", "fft", "polynomial",
        # constants and element types
        "pi", "e", "inf", "nan", "newaxis", "float64", "float32", "int64", "int32", "bool_",
        # creating arrays
        "array", "asarray", "zeros", "ones", "full", "zeros_like", "ones_like", "full_like",
        "linspace", "arange", "geomspace", "logspace", "eye",
        "identity", "meshgrid", "copy", "diag",
        # shape and order
        "reshape", "concatenate", "stack", "vstack", "hstack", "column_stack", "append",
        "insert", "delete", "repeat", "tile", "flip", "flipud", "fliplr", "roll", "squeeze",
        "expand_dims", "transpose", "atleast_1d", "atleast_2d", "ravel", "sort", "argsort",
        "unique", "where", "nonzero", "argwhere", "searchsorted", "take", "split",
        "array_split", "c_", "r_",
        # reductions and statistics
        "sum", "prod", "mean", "median", "average", "std", "var", "min", "max", "amin",
        "amax", "argmin", "argmax", "cumsum", "cumprod", "diff", "gradient", "ptp",
        "percentile", "quantile", "count_nonzero", "any", "all", "trapezoid", "histogram",
        # elementwise
        "abs", "absolute", "sign", "sqrt", "cbrt", "square", "power", "exp", "exp2", "expm1",
        "log", "log10", "log2", "log1p", "sin", "cos", "tan", "arcsin", "arccos", "arctan",
        "arctan2", "sinh", "cosh", "tanh", "hypot", "deg2rad", "rad2deg", "radians",
        "degrees", "floor", "ceil", "round", "around", "rint", "trunc", "clip", "minimum",
        "maximum", "fmin", "fmax", "mod", "fmod", "remainder", "add", "subtract", "multiply",
        "divide", "true_divide", "floor_divide", "negative", "reciprocal", "isnan", "isinf",
        "isfinite", "nan_to_num", "isclose", "allclose", "array_equal", "logical_and",
        "logical_or", "logical_not", "logical_xor", "greater", "less", "equal", "not_equal",
        "greater_equal", "less_equal", "interp", "convolve", "unwrap",
        # products
        "dot", "vdot", "cross", "outer", "inner", "matmul", "einsum", "tensordot", "kron",
        # polynomials the plain way
        "polyfit", "polyval", "poly1d",
    }
)  # fmt: skip

LINALG_MEMBERS = frozenset(
    {"norm", "inv", "pinv", "det", "solve", "lstsq", "svd", "eig", "eigh", "qr", "matrix_rank", "cross"}
)

# The seeded functions; neither the generator classes nor any state getter or setter (their
# setters take positions that read the heap).
RANDOM_MEMBERS = frozenset(
    {
        "default_rng", "seed", "rand", "randn", "random", "uniform", "normal", "randint",
        "choice", "shuffle", "permutation", "standard_normal",
    }
)  # fmt: skip

GENERATOR_METHODS = frozenset(
    {"random", "uniform", "normal", "integers", "choice", "shuffle", "permutation", "standard_normal"}
)

FFT_MEMBERS = frozenset({"fft", "ifft", "rfft", "irfft", "fftfreq", "rfftfreq", "fftshift", "ifftshift"})

POLYNOMIAL_MEMBERS = frozenset({"Polynomial", "Chebyshev"})

MATH_MEMBERS = frozenset(name for name in dir(math) if not name.startswith("_"))

MODULE_MEMBERS: dict[str, frozenset[str]] = {
    "numpy": NUMPY_MEMBERS,
    "numpy.linalg": LINALG_MEMBERS,
    "numpy.random": RANDOM_MEMBERS,
    "numpy.fft": FFT_MEMBERS,
    "numpy.polynomial": POLYNOMIAL_MEMBERS,
    "math": MATH_MEMBERS,
}

ARRAY_ATTRIBUTES = frozenset(
    {
        "shape", "ndim", "size", "T", "copy", "tolist", "reshape", "flatten", "ravel", "mean",
        "sum", "prod", "min", "max", "argmin", "argmax", "std", "var", "cumsum", "cumprod",
        "clip", "astype", "round", "dot", "transpose", "swapaxes", "any", "all", "sort",
        "argsort", "item", "squeeze", "nonzero", "repeat", "take", "diagonal", "trace",
        "conj", "real", "imag", "fill", "searchsorted",
        # a fitted numpy.polynomial series
        "fit", "deriv", "integ", "roots", "coef",
    }
)  # fmt: skip

PYTHON_ATTRIBUTES = frozenset(
    {
        # list
        "append", "extend", "insert", "pop", "index", "count", "reverse", "remove", "clear",
        # dict
        "get", "items", "keys", "values", "update", "setdefault",
        # str
        "lower", "upper", "strip", "lstrip", "rstrip", "split", "join", "startswith",
        "endswith", "replace", "title", "capitalize", "format", "is_integer",
    }
)  # fmt: skip

ALLOWED_ATTRIBUTES = frozenset().union(
    *MODULE_MEMBERS.values(), ARRAY_ATTRIBUTES, GENERATOR_METHODS, PYTHON_ATTRIBUTES
)
