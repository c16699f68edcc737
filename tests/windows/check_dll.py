# SPDX-License-Identifier: GPL-3.0-or-later
"""fracterra.dll (and fracterra.exe) need only DLLs that every Windows ships,
and the DLL exports only the C ABI (ft_*), as check_zip.py asks of
libfracterra.so. The C++ runtime, libgomp and winpthreads are linked in: a
libstdc++-6.dll, libgomp-1.dll or libwinpthread-1.dll import would make the
add-on fail to load on an artist's machine with "module not found".

And no code moves a 32- or 64-byte AVX register to or from the stack with an
aligned move (vmovaps/vmovapd/vmovdqa): Windows aligns the stack to 16 bytes
only, so such a spill crashes at random (GCC bug 54412; the build assembles
with -muse-unaligned-vector-move, CMakeLists.txt).

Run as: python3 check_dll.py fracterra.dll [fracterra.exe ...]   (uses binutils-mingw-w64's objdump)
Checked by breaking it: with libgomp.dll.a (FindOpenMP's first choice) the
DLL imported libgomp-1.dll and this failed; `vmovaps %ymm6, 0x20(%rsp)`
assembled without -muse-unaligned-vector-move is found, with it not (GCC 12
realigns the frames of this build's AVX kernels itself: none is found even
without the option, which stays as the guard).
"""

import re
import shutil
import subprocess
import sys
from pathlib import Path

OBJDUMP = "x86_64-w64-mingw32-objdump"
# The system DLLs of Windows 10 and later (msvcrt.dll is the C runtime mingw-w64 links by default,
# api-ms-win-crt-* the Universal CRT's forwarders).
SYSTEM = {"kernel32.dll", "msvcrt.dll", "ucrtbase.dll", "user32.dll", "advapi32.dll", "ws2_32.dll", "shell32.dll",
          "ole32.dll", "bcrypt.dll", "ntdll.dll"}


def pe_tables(path):
    """(imported DLL names, exported symbol names) of a PE file, from objdump -p."""
    out = subprocess.run([OBJDUMP, "-p", str(path)], check=True, capture_output=True, text=True).stdout
    imports = re.findall(r"^\s*DLL Name: (\S+)", out, re.M)
    exports = []
    table = re.search(r"\[Ordinal/Name Pointer\] Table\n(.*?)(?:\n\s*\n|\Z)", out, re.S)
    if table:
        exports = [line.split()[-1] for line in table.group(1).splitlines() if line.strip()]
    return imports, exports


ALIGNED_STACK_MOVE = re.compile(r"\bvmova(?:ps|pd|dqa|dqa32|dqa64)\s+(?:%[yz]mm\d+,\s*\S*\(%r[sb]p\)|\S*\(%r[sb]p\),\s*%[yz]mm\d+)")


def aligned_stack_moves(path):
    """The instructions of `path` that move a ymm register to or from the stack with an aligned move."""
    out = subprocess.run([OBJDUMP, "-d", "--no-show-raw-insn", str(path)], check=True, capture_output=True,
                         text=True).stdout
    return [line.strip() for line in out.splitlines() if ALIGNED_STACK_MOVE.search(line)]


def problems_of(path):
    """Every way `path` breaks the rules, as messages; also prints what it found."""
    problems = []
    imports, exports = pe_tables(path)
    print(f"{Path(path).name}: imports {', '.join(imports)}; exports {len(exports)} symbols")
    # A test program may import the DLL it tests.
    allowed = SYSTEM if path.name.lower() == "fracterra.dll" else SYSTEM | {"fracterra.dll"}
    for name in imports:
        if name.lower() not in allowed and not name.lower().startswith("api-ms-win-"):
            problems.append(f"{Path(path).name} imports {name}, which Windows does not ship")
    moves = aligned_stack_moves(path)
    if moves:
        problems.append(f"{path.name}: {len(moves)} aligned AVX moves to or from the stack, which crash on "
                        f"Windows' 16-byte aligned stack: {moves[:3]}")
    if path.name.lower().endswith(".dll"):
        stray = [s for s in exports if not s.startswith("ft_")]
        if stray:
            problems.append(f"{path.name} exports {len(stray)} symbols outside ft_*: {stray[:10]}")
        for needed in ("ft_abi_version", "ft_terrain_generate", "ft_erode", "ft_build_features"):
            if needed not in exports:
                problems.append(f"{path.name} does not export {needed}")
    return problems


def main(paths):
    if not shutil.which(OBJDUMP):
        print(f"SKIP: {OBJDUMP} is missing (Debian binutils-mingw-w64-x86-64; scripts/install-deps.sh windows)")
        return 77
    missing = [p for p in paths if not Path(p).is_file()]
    if missing:
        print(f"SKIP: no Windows build ({', '.join(missing)} missing): scripts/build-windows.sh makes it")
        return 77
    problems = [p for path in paths for p in problems_of(Path(path))]
    for p in problems:
        print("FAIL:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
