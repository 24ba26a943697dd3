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
]
