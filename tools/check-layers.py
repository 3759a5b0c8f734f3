#!/usr/bin/env python3
"""The layer check (CTest layers.check): every library follows the DAG of spec/layers.tsv.

    tools/check-layers.py [ROOT]      ROOT: the source tree (default: this script's repository)

Checked, for every library folder ROOT/<lib>/ (one with a CMakeLists.txt calling fapcast_library):
  1. spec/layers.tsv names each library once, uses only libraries listed above it (a DAG), and
     lists exactly the library folders there are;
  2. each fapcast::<other> in the library's fapcast_library(... PUBLIC ... PRIVATE ...) call is an
     arrow of the table;
  3. each #include "fapcast/<other>/..." under <lib>/include and <lib>/src is an arrow of the table,
     names a public header that exists, and is linked: PUBLIC when a public header includes it,
     PUBLIC or PRIVATE when only sources do; a PUBLIC library no public header includes should
     be PRIVATE, and a linked library nothing includes should not be linked;
  4. a quoted include without "fapcast/" names a private header of the same library's src/, and
     no public header includes one;
  5. the layout tables of README.md and spec/architecture.md (where they exist) show the same
     arrows as the table.
Each violation is printed as "FILE:LINE: RULE: DETAIL"; the last line is "layers: ok (...)" or
"layers: FAILED (N violations)", and the exit code is 0 or 1.
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
LIBRARY_CALL = re.compile(r'fapcast_library\s*\(([^)]*)\)', re.S)


def main(argv):
    root = pathlib.Path(argv[1] if len(argv) > 1 else pathlib.Path(__file__).parent.parent).resolve()
    problems = []

    def report(path, line, rule, detail):
        problems.append(f"{path.relative_to(root)}:{line}: {rule}: {detail}")

    table = root / "spec" / "layers.tsv"
    uses, order = {}, []
    for number, text in enumerate(table.read_text().splitlines(), 1):
        if not text.strip() or text.startswith("#") or text.startswith("library\t"):
            continue
        fields = text.split("\t")
        if len(fields) < 2:
            report(table, number, "layers-row", "expected library<TAB>uses<TAB>what it knows")
            continue
        name, used = fields[0], [] if fields[1].strip() == "-" else fields[1].split()
        if name in uses:
            report(table, number, "layers-duplicate", f"{name} is listed twice")
        for u in used:
            if u not in uses:
                report(table, number, "layers-order",
                       f"{name} uses {u}, which is not listed above it (the arrows must form a DAG)")
        uses[name] = set(used)
        order.append(name)

    libraries = {}
    for cmake in sorted(root.glob("*/CMakeLists.txt")):
        call = LIBRARY_CALL.search(cmake.read_text())
        if call:
            libraries[cmake.parent.name] = (cmake, call)
    for name in order:
        if name not in libraries:
            report(table, 1, "layers-folder", f"{name} is in the table but {name}/CMakeLists.txt defines no fapcast_library")
    for name, (cmake, _) in libraries.items():
        if name not in uses:
            report(cmake, 1, "layers-unlisted", f"library {name} is not in spec/layers.tsv")
            uses[name] = set()

    for name, (cmake, call) in sorted(libraries.items()):
        text = cmake.read_text()
        call_line = text[:call.start()].count("\n") + 1
        if call.group(1).split()[0] != name:
            report(cmake, call_line, "layers-name", f"fapcast_library({call.group(1).split()[0]} ...) in folder {name}/")
        linked, section = {}, None
        for word in call.group(1).split()[1:]:
            if word in ("PUBLIC", "PRIVATE"):
                section = word
            elif word.startswith("fapcast::"):
                other = word[len("fapcast::"):]
                linked[other] = section
                if other not in uses.get(name, set()):
                    report(cmake, call_line, "layers-link",
                           f"{name} links fapcast::{other}, which spec/layers.tsv does not let it use")
        included = {}  # other library -> whether a public header includes it
        folder = root / name
        for path in sorted(p for p in folder.rglob("*") if p.suffix in (".hpp", ".cpp", ".h")):
            public = (folder / "include") in path.parents
            for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                target = m.group(1)
                if not target.startswith("fapcast/"):
                    if public:
                        report(path, number, "layers-private-in-public",
                               f'public header includes "{target}", which is not a public header')
                    elif not (folder / "src" / target).is_file():
                        report(path, number, "layers-private",
                               f'"{target}" is not a private header of {name} ({name}/src/{target})')
                    continue
                parts = target.split("/")
                other = parts[1] if len(parts) > 2 else ""
                if not (root / other / "include" / target).is_file():
                    report(path, number, "layers-missing", f'"{target}" is no public header of any library')
                    continue
                if other == name:
                    continue
                if other not in uses.get(name, set()):
                    report(path, number, "layers-include",
                           f'includes {target}: {name} may not use {other} (spec/layers.tsv: {name} uses '
                           f'{" ".join(sorted(uses.get(name, set()))) or "nothing"})')
                    continue
                included[other] = included.get(other, False) or public
                if other not in linked:
                    report(path, number, "layers-unlinked",
                           f"includes {target} but {name}/CMakeLists.txt does not link fapcast::{other}")
                elif public and linked[other] != "PUBLIC":
                    report(path, number, "layers-public",
                           f"a public header includes {target}: {name} must link fapcast::{other} PUBLIC")
        for other, section in sorted(linked.items()):
            if other not in uses.get(name, set()):
                continue
            if other not in included:
                report(cmake, call_line, "layers-unused", f"{name} links fapcast::{other} but includes nothing of it")
            elif section == "PUBLIC" and not included[other]:
                report(cmake, call_line, "layers-public-unneeded",
                       f"{name} links fapcast::{other} PUBLIC but only its sources include it: PRIVATE")

    for readme in (root / "README.md", root / "spec" / "architecture.md"):
        if not readme.is_file():
            continue
        row = re.compile(r"^\| `(\w+)/` \| `fapcast::(\w+)` \| ([^|]*) \|")
        shown = {}
        for number, text in enumerate(readme.read_text().splitlines(), 1):
            m = row.match(text)
            if not m:
                continue
            cell = m.group(3).strip()
            shown[m.group(1)] = (number, set() if cell in ("—", "-") else {u.strip() for u in cell.split(",")})
        for name in order:
            if name not in shown:
                report(readme, 1, "layers-readme", f"the layout table has no row for {name}/")
            elif shown[name][1] != uses[name]:
                report(readme, shown[name][0], "layers-readme",
                       f"{name}/ uses {', '.join(sorted(shown[name][1])) or 'nothing'} here but "
                       f"{' '.join(sorted(uses[name])) or 'nothing'} in spec/layers.tsv")

    for p in problems:
        print(p)
    if problems:
        print(f"layers: FAILED ({len(problems)} violations)")
        return 1
    print(f"layers: ok ({len(libraries)} libraries, spec/layers.tsv)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
