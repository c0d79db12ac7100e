#!/usr/bin/env python3
"""Every usage example in a public header is code that is built.

    python3 scripts/header-examples.py             check: every \\code block of the headers of a module
                                                   that has its file examples/headers/<module>.cpp is a
                                                   verbatim part (line by line, indentation aside) of a
                                                   file there, which the build compiles
    python3 scripts/header-examples.py --missing M   print a function for each block of module M not found yet
    python3 scripts/header-examples.py --skeleton M  print a file for module M with each of its blocks
                                                   in a function of its own (a start for examples/headers/M.cpp)
Exit status 1 naming each block not found (header and line), 2 for a usage error.
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def blocks(header):
    """(line number, [lines]) of each \\code ... \\endcode block of header."""
    out, cur, start = [], None, 0
    for n, line in enumerate(header.read_text().splitlines(), 1):
        if cur is None and re.search(r"\\code\b", line):
            cur, start = [], n
        elif cur is not None and "\\endcode" in line:
            out.append((start, cur))
            cur = None
        elif cur is not None:
            cur.append(line)
    return out


def normal(lines):
    return [l.strip() for l in lines if l.strip()]


def headers(module=None):
    pattern = f"modules/{module or '*'}/include/**/*.h"
    return sorted(ROOT.glob(pattern))


def check():
    """Every block of a module that has its file examples/headers/<module>.cpp found in one of the files."""
    folder = ROOT / "examples" / "headers"
    sources = {p: normal(p.read_text().splitlines()) for p in sorted(folder.glob("*.cpp"))}
    missing, built, pending = [], 0, {}
    for h in headers():
        module = h.relative_to(ROOT / "modules").parts[0]
        for start, lines in blocks(h):
            if not (folder / f"{module}.cpp").exists():
                pending[module] = pending.get(module, 0) + 1
                continue
            want = normal(lines)
            if want and not any(contains(src, want) for src in sources.values()):
                missing.append(f"{h.relative_to(ROOT)}:{start}")
            else:
                built += 1
    for m in missing:
        print(f"error: {m}: a usage example not in any file of examples/headers/ (not built: it may not compile)")
    print(f"header examples: {built} built, {len(missing)} not found" +
          ("; modules without their examples file yet: " + ", ".join(f"{m} ({n})" for m, n in sorted(pending.items())) if pending else ""))
    return 1 if missing else 0


def contains(src, want):
    n = len(want)
    for i in range(len(src) - n + 1):
        if src[i:i + n] == want:
            return True
    return False


def dedented(lines):
    ind = min((len(l) - len(l.lstrip()) for l in lines if l.strip()), default=0)
    return [l[ind:].rstrip() for l in lines]


def missing(module):
    """The functions (as skeleton() writes them) of module's blocks not yet in examples/headers/."""
    folder = ROOT / "examples" / "headers"
    sources = [normal(p.read_text().splitlines()) for p in sorted(folder.glob("*.cpp"))]
    for h in headers(module):
        for k, (start, lines) in enumerate(blocks(h)):
            if any(contains(src, normal(lines)) for src in sources):
                continue
            print(f"\n// {h.stem}.h\nvoid example{h.stem}{k + 1 if k else ''}()\n{{")
            for l in dedented(lines):
                print(("  " + l).rstrip())
            print("}")


def skeleton(module):
    """A start for examples/headers/<module>.cpp on stdout; a whole program (one with main()) is written
    to examples/headers/<module>_<Header>.cpp as it is (the library compiles it as it is, never links it)."""
    print(f"""// The usage examples of pm::{module}'s headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.""")
    includes = sorted({h.relative_to(ROOT / "modules" / module / "include") for h in headers(module) if blocks(h)})
    for rel in includes:
        print(f'#include "{rel}"')
    print("\nnamespace pm_examples {")
    for h in headers(module):
        for k, (start, lines) in enumerate(blocks(h)):
            name = h.stem + (f"{k + 1}" if k else "")
            code = dedented(lines)
            if any("int main(" in l for l in code):
                program = ROOT / "examples" / "headers" / f"{module}_{name}.cpp"
                if not program.exists():
                    program.write_text(f"// The usage example of {h.relative_to(ROOT)}, a whole program (compiled, never linked).\n" +
                                       "\n".join(code) + "\n")
                continue
            print(f"\n// {h.stem}.h\nvoid example{name}()\n{{")
            for l in code:
                print(("  " + l).rstrip())
            print("}")
    print("\n} // namespace pm_examples")


if __name__ == "__main__":
    if len(sys.argv) == 1:
        sys.exit(check())
    if len(sys.argv) == 3 and sys.argv[1] == "--missing":
        missing(sys.argv[2])
        sys.exit(0)
    if len(sys.argv) == 3 and sys.argv[1] == "--skeleton":
        skeleton(sys.argv[2])
        sys.exit(0)
    print(__doc__, file=sys.stderr)
    sys.exit(2)
