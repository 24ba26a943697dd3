"""Attacks by code that already got past every Python layer: real builtins, real os and ctypes.

Each entry is (name, code). The code is a template with ``{secret}`` (a file planted outside the
sandbox's bound paths), ``{secret_text}`` (its content) and ``{victim}`` / ``{marker}`` (a file that
must survive and one that must not appear). Each attack sets ``modified_trajectory`` only when the
attack worked, so a sandbox that lets it through reports success. The system-call numbers are
x86-64's.
"""

from __future__ import annotations

WORKED = "\nmodified_trajectory = get_trajectory()\n"
CTYPES = "import ctypes\nlibc = ctypes.CDLL(None, use_errno=True)\n"


def _syscall(name: str, call: str) -> tuple[str, str]:
    """An attack that makes one raw system call through ctypes; it worked if the call returned >= 0."""
    code = (
        CTYPES
        + f"r = libc.syscall({call})\nif r < 0:\n    raise OSError(ctypes.get_errno(), 'refused')"
        + WORKED
    )
    return (name, code)


OS_ATTACKS: list[tuple[str, str]] = [
    # read a secret file outside the bound paths
    ("read-open", "print(open({secret!r}).read())" + WORKED),
    ("read-os-open", "import os\nfd = os.open({secret!r}, os.O_RDONLY)\nprint(os.read(fd, 100))" + WORKED),
    ("read-fileio", "import io\nprint(io.FileIO({secret!r}).read())" + WORKED),
    ("read-numpy-fromfile", "print(np.fromfile({secret!r}, dtype=np.uint8))" + WORKED),
    ("read-numpy-loadtxt", "print(np.loadtxt({secret!r}, dtype=str))" + WORKED),
    (
        "read-ctypes-open-mmap",
        CTYPES
        + "fd = libc.open({secret!r}.encode(), 0)\nif fd < 0:\n    raise OSError(ctypes.get_errno(), 'open')\n"
        "libc.mmap.restype = ctypes.c_void_p\np = libc.mmap(None, 4096, 1, 2, fd, 0)\n"
        "print(ctypes.string_at(p, 30))" + WORKED,
    ),
    _syscall("read-syscall-open", "2, {secret!r}.encode(), 0"),
    _syscall("read-syscall-openat", "257, -100, {secret!r}.encode(), 0"),
    _syscall("read-syscall-openat2", "437, -100, {secret!r}.encode(), None, 0"),
    _syscall("read-syscall-open-by-handle", "304, -100, None, 0"),
    _syscall("io-uring-setup", "425, 8, ctypes.create_string_buffer(120)"),
    _syscall("io-uring-enter", "426, 0, 1, 1, 0, None, 0"),
    _syscall("io-uring-register", "427, 0, 0, None, 0"),
    ("read-proc-environ", "print(open('/proc/self/environ').read())" + WORKED),
    ("read-parent-memory", "import os\nprint(open(f'/proc/{{os.getppid()}}/mem', 'rb').read(10))" + WORKED),
    _syscall("process-vm-readv", "310, 1, None, 0, None, 0, 0"),
    # learn about the file system
    ("list-root", "import os\nprint(os.listdir('/'))" + WORKED),
    ("scandir-root", "import os\nprint([e.name for e in os.scandir('/')])" + WORKED),
    ("stat-secret", "import os\nprint(os.stat({secret!r}))" + WORKED),
    (
        "exists-secret",
        "import os\nif os.path.exists({secret!r}):\n    print('seen')" + WORKED.replace("\n", "\n    ", 1),
    ),
    ("getcwd", "import os\nprint(os.getcwd())" + WORKED),
    ("readlink-proc", "import os\nprint(os.readlink('/proc/self/exe'))" + WORKED),
    # write, remove or change files
    ("write-open", "open({marker!r}, 'w').write('x')" + WORKED),
    ("write-os-open", "import os\nos.open({marker!r}, os.O_CREAT | os.O_WRONLY)" + WORKED),
    _syscall("write-syscall-creat", "85, {marker!r}.encode(), 0o644"),
    ("write-numpy-save", "np.save({marker!r}, np.zeros(3))" + WORKED),
    ("mkdir", "import os\nos.mkdir({marker!r})" + WORKED),
    ("unlink-victim", "import os\nos.unlink({victim!r})" + WORKED),
    ("rename-victim", "import os\nos.rename({victim!r}, {marker!r})" + WORKED),
    ("chmod-victim", "import os\nos.chmod({victim!r}, 0o777)" + WORKED),
    ("truncate-victim", "import os\nos.truncate({victim!r}, 0)" + WORKED),
    ("symlink", "import os\nos.symlink({victim!r}, {marker!r})" + WORKED),
    ("hardlink", "import os\nos.link({victim!r}, {marker!r})" + WORKED),
    _syscall("memfd-create", "319, b'x', 0"),
    _syscall("dup-result-pipe", "33, 3, 9"),
    # network
    _syscall("socket-inet", "41, 2, 1, 0"),
    _syscall("socket-unix", "41, 1, 1, 0"),
    _syscall("socket-netlink", "41, 16, 3, 0"),
    _syscall("socketpair", "53, 1, 1, 0, ctypes.create_string_buffer(8)"),
    ("socket-module", "import socket\nsocket.create_connection(('127.0.0.1', 22), timeout=1)" + WORKED),
    # new processes and programs
    ("fork", "import os\nif os.fork() == 0:\n    os._exit(0)" + WORKED),
    _syscall("clone", "56, 17, 0, 0, 0, 0"),
    _syscall("clone3", "435, None, 0"),
    _syscall("vfork", "58"),
    ("exec", "import os\nos.execv('/bin/sh', ['sh', '-c', 'touch {marker}'])" + WORKED),
    _syscall("execveat", "322, -100, b'/bin/sh', None, None, 0"),
    ("system", "import os\nassert os.system('touch {marker}') == 0" + WORKED),
    ("posix-spawn", "import os\nos.posix_spawn('/bin/true', ['true'], {{}})" + WORKED),
    # the worker, other processes, privileges
    ("kill-parent", "import os\nos.kill(os.getppid(), 9)" + WORKED),
    ("kill-all", "import os\nos.kill(-1, 9)" + WORKED),
    ("kill-own-group", "import os\nos.killpg(0, 9)" + WORKED),
    _syscall("tgkill-parent", "234, __import__('os').getppid(), __import__('os').getppid(), 9"),
    _syscall("pidfd-open-parent", "434, __import__('os').getppid(), 0"),
    _syscall("ptrace-attach-parent", "101, 16, __import__('os').getppid(), 0, 0"),
    _syscall("setuid-root", "105, 0"),
    _syscall("setgid-root", "106, 0"),
    _syscall("unshare-user", "272, 0x10000000"),
    _syscall("mount", "165, b'none', b'/', b'tmpfs', 0, None"),
    _syscall("chroot", "161, b'/'"),
    _syscall("prctl", "157, 38, 0, 0, 0, 0"),
    _syscall("ioctl-tiocsti", "16, 0, 0x5412, ctypes.create_string_buffer(b'x')"),
    _syscall("raise-limits", "302, 0, 7, None, None"),
    _syscall("bpf", "321, 0, None, 0"),
    _syscall("perf-event-open", "298, None, 0, -1, -1, 0"),
    _syscall("userfaultfd", "323, 0"),
    _syscall("keyctl", "250, 0, 0, 0, 0"),
    _syscall("personality", "135, 0xffffffff"),
    _syscall("x32-abi-open", "0x40000002, {secret!r}.encode(), 0"),
    # forged answers to the worker
    ("forged-malformed", 'import os\nos.write(3, b\'{{"ok": false, "error": "forged"}}\')\nos._exit(0)'),
    ("forged-not-json", "import os\nos.write(3, b'\\xff\\xfe not json')\nos._exit(0)"),
    (
        "forged-huge",
        "import os\nchunk = b' ' * (1 << 20)\nfor i in range(20):\n    os.write(3, chunk)\nos._exit(0)",
    ),
    (
        "forged-layers",
        'import os\nos.write(3, b\'{{"ok": true, "trajectory": [[0,0,0,1],[1,1,1,1]], "stdout": "", '
        '"error": null, "notes": [], "layers": ["everything"]}}\')\nos._exit(0)',
    ),
    (
        "forged-deep",
        "import os\nos.write(3, b'[' * 100000)\nos._exit(0)",
    ),
    # resources
    ("sleep-forever", "import time\ntime.sleep(1000)" + WORKED),
    ("busy-loop", "while True:\n    pass" + WORKED),
    ("memory-bomb", "x = bytearray(10 ** 10)" + WORKED),
]
