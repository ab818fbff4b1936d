#!/usr/bin/env python3
"""Checks that each module's include edges are its link edges.

A module is a folder under src/ built as the library epviz_<folder> by
CMakeLists.txt's epviz_module(<folder> DEPS ...). For every module, the set of
other modules whose headers it includes must equal the set of epviz_<module>
libraries it lists in DEPS, so that the build graph says what the code does.
The command line (src/app) is checked against EPVIZ_APP_DEPS and the optional
libraries it adds with target_link_libraries(epviz ...).
The module table of docs/architecture.md ("may include") is checked against
the same include edges, so that the documented dependencies are the code's.
Exit 0 when they match, 1 with one line per mismatch otherwise.
"""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
cmake = (root / "CMakeLists.txt").read_text()
modules = sorted(p.name for p in (root / "src").iterdir() if p.is_dir())

# set(VAR ...) and list(APPEND VAR ...) values, so that DEPS ${VAR} can be expanded.
variables = {}
for name, body in re.findall(r"\bset\((\w+)([^)]*)\)", cmake):
    variables.setdefault(name, []).append(body)
for name, body in re.findall(r"\blist\(APPEND\s+(\w+)([^)]*)\)", cmake):
    variables.setdefault(name, []).append(body)


def libraries(text):
    """The epviz_<module> names in `text`, with ${VAR} expanded."""
    found = set(re.findall(r"\bepviz_(\w+)", re.sub(r"\$\{\w+\}", "", text)))
    for var in re.findall(r"\$\{(\w+)\}", text):
        for body in variables.get(var, []):
            found |= libraries(body)
    return found


declared = {}
for name, deps in re.findall(r"epviz_module\((\w+)(?:\s+DEPS([^)]*))?\)", cmake):
    declared.setdefault(name, set()).update(libraries(deps or ""))
app = libraries("${EPVIZ_APP_DEPS}")
for body in re.findall(r"target_link_libraries\(epviz\s+PRIVATE([^)]*)\)", cmake):
    app |= libraries(body)
declared["app"] = app - {"app"}

include = re.compile(r'^\s*#\s*include\s+"(\w+)/', re.M)
problems = []
for m in modules:
    used = set()
    for f in (root / "src" / m).rglob("*"):
        if f.suffix in (".cpp", ".hpp"):
            used |= {u for u in include.findall(f.read_text()) if u in modules and u != m}
    if m not in declared:
        problems.append(f"src/{m}: not declared with epviz_module() in CMakeLists.txt")
        continue
    deps = declared[m] & set(modules)
    for u in sorted(used - deps):
        problems.append(f"src/{m} includes {u}/ headers but does not link epviz_{u}")
    for d in sorted(deps - used):
        problems.append(f"src/{m} links epviz_{d} but includes none of its headers")

# The table of docs/architecture.md, "may include": the modules named in
# backticks in its last column (before any ';', after which come third-party
# libraries) must be the modules the folder's code includes; "everything"
# (the command line) is not checked.
doc = (root / "docs" / "architecture.md").read_text()
documented = {}
for folder, allowed in re.findall(r"^\| `(\w+)` \|.*\| ([^|]*) \|$", doc, re.M):
    if folder in modules:
        ours = allowed.split(";")[0]
        documented[folder] = None if ours.strip() == "everything" else {
            n for n in re.findall(r"`(\w+)`", ours) if n in modules}
for m in modules:
    if m not in documented:
        problems.append(f"src/{m}: no row in docs/architecture.md's module table")
        continue
    if documented[m] is None:
        continue
    used = set()
    for f in (root / "src" / m).rglob("*"):
        if f.suffix in (".cpp", ".hpp"):
            used |= {u for u in include.findall(f.read_text()) if u in modules and u != m}
    for u in sorted(used - documented[m]):
        problems.append(f"src/{m} includes {u}/ headers but docs/architecture.md does not list {u}")
    for d in sorted(documented[m] - used):
        problems.append(f"docs/architecture.md lists {d} for src/{m}, which includes none of its headers")

for p in problems:
    print(p)
if problems:
    sys.exit(1)
print(f"module edges: {len(modules)} modules, include edges match link edges and the docs")
