"""Generated code that must never run to a result in the sandbox, with what each one tries.

Each entry: (name, code). Snippets that try to write set ``modified_trajectory`` at the end so
that a sandbox letting the attack through would report success.
"""

from __future__ import annotations

MARKER = "/tmp/trajadapt-sandbox-escape-marker"
SUCCESS = "\nmodified_trajectory = get_trajectory()\n"

HOSTILE_SNIPPETS: list[tuple[str, str]] = [
    ("import-os", "import os\nos.system('touch " + MARKER + "')" + SUCCESS),
    ("import-subprocess", "import subprocess\nsubprocess.run(['touch', '" + MARKER + "'])" + SUCCESS),
    ("import-socket", "import socket\nsocket.create_connection(('127.0.0.1', 80))" + SUCCESS),
    ("from-os-import", "from os import system\nsystem('true')" + SUCCESS),
    ("import-sys", "import sys\nsys.modules['os'].system('true')" + SUCCESS),
    ("open-write", "f = open('" + MARKER + "', 'w')\nf.write('x')" + SUCCESS),
    ("open-read", "print(open('/etc/passwd').read())" + SUCCESS),
    ("dunder-import", "__import__('os').system('true')" + SUCCESS),
    ("builtins-dict", "__builtins__['__import__']('os')" + SUCCESS),
    ("class-walk", "().__class__.__bases__[0].__subclasses__()" + SUCCESS),
    ("mro-walk", "t = type(()).mro()[-1]" + SUCCESS),
    ("getattr-built-string", "getattr((), '__cl' + 'ass__')" + SUCCESS),
    ("eval", "eval('1+1')" + SUCCESS),
    ("exec", "exec('import os')" + SUCCESS),
    ("compile", "compile('1', 'x', 'eval')" + SUCCESS),
    ("globals", "globals()['__builtins__']" + SUCCESS),
    ("format-dunder", "'{0.__class__.__mro__}'.format(())" + SUCCESS),
    ("format-passed-around", "f = '{0.__class__}'.format\nprint(f(()))" + SUCCESS),
    ("format-map-dynamic", "t = '{x.' + '__class__}'\nprint(t.format_map({'x': 1}))" + SUCCESS),
    ("generator-frame", "g = (i for i in [1])\nprint(g.gi_frame.f_globals)" + SUCCESS),
    ("function-globals", "def f():\n    pass\nprint(f.__globals__)" + SUCCESS),
    ("numpy-save", "import numpy as np\nnp.save('" + MARKER + "', np.zeros(3))" + SUCCESS),
    ("numpy-loadtxt", "import numpy as np\nnp.loadtxt('/etc/hostname')" + SUCCESS),
    ("numpy-tofile", "import numpy as np\nnp.zeros(3).tofile('" + MARKER + "')" + SUCCESS),
    ("numpy-memmap", "import numpy as np\nnp.memmap('" + MARKER + "', mode='w+', shape=(3,))" + SUCCESS),
    ("numpy-mtrand-walk", "import numpy as np\nnp.random.mtrand.warnings.sys.modules['os']" + SUCCESS),
    ("numpy-lib-walk", "import numpy as np\nnp.lib.npyio.os.system('true')" + SUCCESS),
    ("numpy-ctypes", "import numpy as np\na = np.zeros(3)\nprint(a.ctypes.data)" + SUCCESS),
    ("numpy-submodule-import", "import numpy.testing" + SUCCESS),
    ("numpy-core-attr", "import numpy as np\nprint(np.core)" + SUCCESS),
    ("relative-import", "from . import child" + SUCCESS),
    ("star-import", "from numpy import *" + SUCCESS),
    ("infinite-loop-python", "while True:\n    pass" + SUCCESS),
    (
        "infinite-loop-c",
        "import numpy as np\nx = np.ones((3000, 3000))\nwhile True:\n    x = x @ x" + SUCCESS,
    ),
    ("memory-bomb-list", "x = [0] * (10 ** 10)" + SUCCESS),
    ("memory-bomb-numpy", "import numpy as np\nx = np.ones(10 ** 10)" + SUCCESS),
    ("memory-bomb-growth", "x = ['a' * 10 ** 6]\nwhile True:\n    x.append(x[-1] + 'a')" + SUCCESS),
    ("fork-bomb-os", "import os\nwhile True:\n    os.fork()" + SUCCESS),
    (
        "fork-bomb-multiprocessing",
        "import multiprocessing\nmultiprocessing.Process(target=print).start()" + SUCCESS,
    ),
    ("ctypes-import", "import ctypes\nctypes.CDLL(None).system(b'true')" + SUCCESS),
    ("class-definition", "class A:\n    pass" + SUCCESS),
    ("private-name", "_secret = 1\nprint(_secret)" + SUCCESS),
    ("breakpoint", "breakpoint()" + SUCCESS),
    ("huge-result", "import numpy as np\nmodified_trajectory = np.zeros((10 ** 6, 4))"),
    # reported escapes: attribute names in match class patterns and fields nested in format specs
    (
        "match-class-reduce-escape",
        "p = np.polynomial.Polynomial([1.0, 2.0])\nmatch p:\n    case np.polynomial.Polynomial(__reduce_ex__=r):\n"
        "        red = r(1)\nobj = red[1][1]\nmatch red[0]:\n    case obj(__globals__=g):\n        pass\n"
        "osm = g['__builtins__']['__import__']('os')" + SUCCESS,
    ),
    (
        "match-class-globals",
        "match detect_objects:\n    case np.ndarray(__globals__=g):\n        print(g)" + SUCCESS,
    ),
    ("match-class-class", "match 1:\n    case int(__class__=c):\n        print(c)" + SUCCESS),
    ("match-capture-underscore", "match 1:\n    case _x:\n        print(_x)" + SUCCESS),
    ("match-star-underscore", "match [1, 2]:\n    case [*_rest]:\n        print(_rest)" + SUCCESS),
    (
        "match-mapping-rest",
        "match {{}}:\n    case {{**_rest}}:\n        print(_rest)".replace("{{", "{").replace("}}", "}")
        + SUCCESS,
    ),
    (
        "format-nested-spec",
        "print('{0:{1.__globals__[__builtins__]}}'.format('x', detect_objects))" + SUCCESS,
    ),
    ("format-nested-spec-item", "print('{0:{1[0]}}'.format('x', ['>5']))" + SUCCESS),
    ("format-nested-twice", "print('{0:{1:{2.__class__}}}'.format(1, 2, 3))" + SUCCESS),
    ("format-map-nested", "print('{a:{b.__class__}}'.format_map({'a': 1, 'b': 2}))" + SUCCESS),
    ("format-attribute-plain", "print('{0.real}'.format(1))" + SUCCESS),
    ("format-method-stored", "f = str.format\nprint(f('{0.__class__}', 1))" + SUCCESS),
    ("format-on-variable", "t = '{0.__class__}'\nprint(t.format(1))" + SUCCESS),
    ("fstring-dunder", "print(f'{detect_objects.__globals__}')" + SUCCESS),
    ("fstring-spec-dunder", "print(f'{1:{detect_objects.__globals__}}')" + SUCCESS),
    # dunder and private attributes in every position
    ("function-closure", "print(get_trajectory.__closure__)" + SUCCESS),
    ("lambda-code", "print((lambda: 0).__code__)" + SUCCESS),
    ("numpy-dict", "print(np.__dict__)" + SUCCESS),
    ("math-loader", "print(math.__loader__)" + SUCCESS),
    ("str-mro", "print(str.__mro__)" + SUCCESS),
    ("print-self", "print(print.__self__)" + SUCCESS),
    (
        "exception-traceback",
        "try:\n    1 / 0\nexcept ZeroDivisionError as e:\n    print(e.__traceback__)" + SUCCESS,
    ),
    (
        "traceback-frame",
        "try:\n    1 / 0\nexcept ZeroDivisionError as e:\n    tb = e.with_traceback(None)\n    print(tb.tb_frame)"
        + SUCCESS,
    ),
    ("coroutine-frame", "async def f():\n    pass\nprint(f().cr_frame)" + SUCCESS),
    ("numpy-version-private", "print(np.__version__)" + SUCCESS),
    ("keyword-dunder", "print(dict(__class__=1))" + SUCCESS),
    ("lambda-arg-underscore", "f = lambda _x: _x\nprint(f(1))" + SUCCESS),
    ("global-underscore", "def f():\n    global _g\n    _g = 1\nf()" + SUCCESS),
    ("walrus-underscore", "print((_x := 1))" + SUCCESS),
    ("import-alias-underscore", "import numpy as _np" + SUCCESS),
    # modules and helpers that lead to files, memory or other modules
    ("from-numpy-import-save", "from numpy import save\nsave('/tmp/x', np.zeros(3))" + SUCCESS),
    ("from-numpy-import-lib", "from numpy import lib\nprint(lib)" + SUCCESS),
    ("from-random-import-mtrand", "from numpy.random import mtrand\nprint(mtrand)" + SUCCESS),
    ("numpy-char-module", "print(np.char)" + SUCCESS),
    ("numpy-ma-module", "print(np.ma)" + SUCCESS),
    ("numpy-rec-module", "print(np.rec)" + SUCCESS),
    ("numpy-emath-module", "print(np.emath)" + SUCCESS),
    ("numpy-typing-module", "print(np.typing)" + SUCCESS),
    ("numpy-polyutils-module", "print(np.polynomial.polyutils)" + SUCCESS),
    ("numpy-bit-generator-module", "print(np.random.bit_generator)" + SUCCESS),
    ("numpy-linalg-shim", "print(np.linalg.linalg)" + SUCCESS),
    ("numpy-fromregex", "print(np.fromregex('/etc/passwd', 'x', []))" + SUCCESS),
    ("numpy-genfromtxt", "print(np.genfromtxt('/etc/passwd'))" + SUCCESS),
    ("numpy-datasource", "print(np.DataSource())" + SUCCESS),
    ("numpy-show-config", "np.show_config()" + SUCCESS),
    ("numpy-get-include", "print(np.get_include())" + SUCCESS),
    ("numpy-f2py", "print(np.f2py)" + SUCCESS),
    ("numpy-ctypeslib", "print(np.ctypeslib)" + SUCCESS),
    ("numpy-vectorize-save", "f = np.vectorize(np.save)" + SUCCESS),
    ("numpy-ndarray-tofile", "np.ndarray.tofile(np.zeros(2), '/tmp/x')" + SUCCESS),
    # builtins that are not there
    ("vars", "print(vars())" + SUCCESS),
    ("dir", "print(dir())" + SUCCESS),
    ("type-call", "print(type(1))" + SUCCESS),
    ("memoryview", "print(memoryview(b'x'))" + SUCCESS),
    ("super", "print(super())" + SUCCESS),
    ("input", "input()" + SUCCESS),
    ("help", "help()" + SUCCESS),
    ("exit", "exit()" + SUCCESS),
    ("builtins-name", "print(__builtins__)" + SUCCESS),
    ("locals", "print(locals())" + SUCCESS),
]
