"""A kernel-level system-call filter for the sandbox child (Linux seccomp, x86-64 and arm64).

Third layer of the sandbox: even if generated code found a way past the static check and the
restricted namespace, the kernel refuses new processes, program execution, sockets, and opening,
creating or removing files. The filter is a short classic-BPF deny list, installed with prctl.
"""

from __future__ import annotations

import ctypes
import errno
import platform
import struct

PR_SET_NO_NEW_PRIVS = 38
PR_SET_SECCOMP = 22
SECCOMP_MODE_FILTER = 2
SECCOMP_RET_ALLOW = 0x7FFF0000
SECCOMP_RET_KILL_PROCESS = 0x80000000
SECCOMP_RET_ERRNO = 0x00050000
X32_SYSCALL_BIT = 0x40000000

BPF_LD_W_ABS = 0x20
BPF_JEQ_K = 0x15
BPF_JGE_K = 0x35
BPF_RET_K = 0x06
OFFSET_NR = 0
OFFSET_ARCH = 4

# name -> number, per architecture (from the kernel's syscall tables)
DENIED_SYSCALLS: dict[str, tuple[int, dict[str, int]]] = {
    "x86_64": (
        0xC000003E,
        {
            "open": 2, "openat": 257, "openat2": 437, "creat": 85, "socket": 41,
            "socketpair": 53, "connect": 42, "accept": 43, "accept4": 288, "bind": 49,
            "listen": 50, "clone": 56, "clone3": 435, "fork": 57, "vfork": 58, "execve": 59,
            "execveat": 322, "ptrace": 101, "unlink": 87, "unlinkat": 263, "rename": 82,
            "renameat": 264, "renameat2": 316, "mkdir": 83, "mkdirat": 258, "rmdir": 84,
            "truncate": 76, "link": 86, "linkat": 265, "symlink": 88, "symlinkat": 266,
            "chmod": 90, "fchmodat": 268, "mknod": 133, "mknodat": 259, "mount": 165,
            "process_vm_writev": 311,
        },
    ),
    "aarch64": (
        0xC00000B7,
        {
            "openat": 56, "openat2": 437, "socket": 198, "socketpair": 199, "bind": 200,
            "listen": 201, "accept": 202, "connect": 203, "accept4": 242, "clone": 220,
            "clone3": 435, "execve": 221, "execveat": 281, "ptrace": 117, "unlinkat": 35,
            "renameat": 38, "renameat2": 276, "mkdirat": 34, "truncate": 45, "linkat": 37,
            "symlinkat": 36, "fchmodat": 53, "mknodat": 33, "mount": 40,
            "process_vm_writev": 271,
        },
    ),
}  # fmt: skip


class _SockFprog(ctypes.Structure):
    _fields_ = [("len", ctypes.c_ushort), ("filter", ctypes.c_void_p)]


def _instruction(code: int, jump_true: int, jump_false: int, k: int) -> bytes:
    return struct.pack("HBBI", code, jump_true, jump_false, k)


def build_filter(machine: str) -> bytes:
    """Return the BPF program for ``machine`` (as ``platform.machine()`` names it).

    Raises:
        KeyError: no syscall table is known for that machine.
    """
    audit_arch, numbers = DENIED_SYSCALLS[machine]
    kill = _instruction(BPF_RET_K, 0, 0, SECCOMP_RET_KILL_PROCESS)
    program = [
        _instruction(BPF_LD_W_ABS, 0, 0, OFFSET_ARCH),
        _instruction(BPF_JEQ_K, 1, 0, audit_arch),
        kill,
        _instruction(BPF_LD_W_ABS, 0, 0, OFFSET_NR),
    ]
    if machine == "x86_64":
        program += [_instruction(BPF_JGE_K, 0, 1, X32_SYSCALL_BIT), kill]
    for number in sorted(set(numbers.values())):
        program.append(_instruction(BPF_JEQ_K, 0, 1, number))
        program.append(_instruction(BPF_RET_K, 0, 0, SECCOMP_RET_ERRNO | errno.EPERM))
    program.append(_instruction(BPF_RET_K, 0, 0, SECCOMP_RET_ALLOW))
    return b"".join(program)


def install_filter() -> bool:
    """Install the deny-list filter on the calling process; False where it is not supported."""
    machine = platform.machine()
    if machine not in DENIED_SYSCALLS or platform.system() != "Linux":
        return False
    program = build_filter(machine)
    buffer = ctypes.create_string_buffer(program, len(program))
    fprog = _SockFprog(len(program) // 8, ctypes.cast(buffer, ctypes.c_void_p))
    libc = ctypes.CDLL(None, use_errno=True)
    if libc.prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
        return False
    return bool(libc.prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, ctypes.byref(fprog), 0, 0) == 0)
