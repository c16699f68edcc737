// SPDX-License-Identifier: GPL-3.0-or-later
/* Loads fracterra.dll as CPython's ctypes.CDLL does on Windows (3.8+: a full
 * path, LoadLibraryExW with LOAD_LIBRARY_SEARCH_DEFAULT_DIRS |
 * LOAD_LIBRARY_SEARCH_DLL_LOAD_DIR, so only the DLL's own folder and the
 * system's are searched), resolves every symbol named on standard input (one
 * a line: the add-on binding's table) and calls ft_abi_version and
 * ft_version_string. Stands in for a Windows Python, which this machine cannot
 * fetch (check_wheel_dll.py).
 * Usage: dll_probe.exe PATH\fracterra.dll < symbols.txt
 * Prints "abi MAJOR.MINOR", "version X", then "missing NAME" per missing
 * symbol; exit 0 when all resolve, 1 otherwise, 2 when the DLL does not load. */
#include <stdio.h>
#include <string.h>
#include <windows.h>

int main(void) {
  int argc = 0;
  wchar_t** argv = CommandLineToArgvW(GetCommandLineW(), &argc);
  if (argc != 2) {
    fprintf(stderr, "usage: dll_probe.exe PATH\\fracterra.dll < symbols.txt\n");
    return 2;
  }
  HMODULE dll = LoadLibraryExW(argv[1], NULL, LOAD_LIBRARY_SEARCH_DEFAULT_DIRS | LOAD_LIBRARY_SEARCH_DLL_LOAD_DIR);
  if (dll == NULL) {
    printf("load failed: error %lu\n", (unsigned long)GetLastError());
    return 2;
  }
  typedef unsigned (*abi_fn)(void);
  typedef const char* (*version_fn)(void);
  abi_fn abi = (abi_fn)(void*)GetProcAddress(dll, "ft_abi_version");
  version_fn version = (version_fn)(void*)GetProcAddress(dll, "ft_version_string");
  if (abi != NULL) printf("abi %u.%u\n", abi() >> 16, abi() & 0xFFFFu);
  if (version != NULL) printf("version %s\n", version());
  char name[256];
  int missing = 0, found = 0;
  while (fgets(name, sizeof name, stdin) != NULL) {
    name[strcspn(name, "\r\n")] = 0;
    if (name[0] == 0) continue;
    if (GetProcAddress(dll, name) == NULL) {
      printf("missing %s\n", name);
      ++missing;
    } else {
      ++found;
    }
  }
  printf("resolved %d, missing %d\n", found, missing);
  return missing == 0 && abi != NULL && version != NULL ? 0 : 1;
}
