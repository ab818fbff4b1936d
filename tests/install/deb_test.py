#!/usr/bin/env python3
"""The .deb is honest: what it declares is what the binary needs.

    deb_test.py BUILD_DIR SOURCE_DIR

Builds the package with cpack into a scratch directory, extracts it with
dpkg-deb -x into a scratch root and checks, with the source tree hidden
(EPVIZ_IGNORE_SOURCE_TREE):
  - every library the binary links (its NEEDED entries) comes from a package
    that Depends names without an alternative;
  - a render through each way Depends allows (the EGL stack, or OSMesa alone)
    loads only libraries, and reads only the font, of packages in the
    dependency closure of that choice (apt-cache depends --recurse): the
    package renders with what it declares and nothing else;
  - the programs it runs (ffmpeg) are in Depends or Recommends;
  - the copyright file and LICENSE state one licence;
  - the shipped jobs are installed, `render --list-jobs` lists them from the
    installed share/epviz (and, from a build tree, from the sources), and a
    name from that list renders;
  - the Python module, where it was built, is installed, imports, simulates
    and draws from the package alone, and what its extension links is in Depends.
Exit 0 when all hold, 1 with one line per problem otherwise.
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

build, source = (os.path.abspath(p) for p in sys.argv[1:3])
work = tempfile.mkdtemp(prefix="epviz-deb-")
problems = []


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


def must(cmd, **kw):
    r = run(cmd, **kw)
    if r.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)} exited {r.returncode}: {r.stderr.strip()[-2000:]}")
    return r.stdout


def groups(field):
    """A Depends-style field as a list of alternative groups of package names."""
    out = []
    for group in filter(None, (g.strip() for g in field.split(","))):
        out.append([re.sub(r"\s*\(.*\)", "", a).strip() for a in group.split("|")])
    return out


def owners(paths):
    """{path: package} for the paths dpkg knows (usrmerge: /lib is /usr/lib)."""
    candidates = {}
    for p in paths:
        forms = {p, os.path.realpath(p)}
        for f in list(forms):
            forms.add(f[len("/usr"):] if f.startswith("/usr/lib/") else "/usr" + f)
        candidates[p] = forms
    known = {}
    every = sorted(set().union(*candidates.values())) if candidates else []
    for line in run(["dpkg", "-S", *every]).stdout.splitlines():
        packages, _, path = line.partition(": ")
        if path and not line.startswith("diversion"):
            known[path] = packages.split(",")[0].split(":")[0].strip()
    found = {}
    for p, forms in candidates.items():
        for f in sorted(forms):
            if f in known:
                found[p] = known[f]
                break
    return found


def closure(packages):
    out = run(["apt-cache", "depends", "--recurse", "--installed", "--no-recommends",
               "--no-suggests", "--no-conflicts", "--no-breaks", "--no-replaces",
               "--no-enhances", *packages]).stdout
    return {line.strip("<>").split(":")[0] for line in out.splitlines()
            if line and not line[0].isspace()}


try:
    must(["cpack", "--config", os.path.join(build, "CPackConfig.cmake"), "-G", "DEB",
          "-B", os.path.join(work, "pkg")])
    debs = glob.glob(os.path.join(work, "pkg", "*.deb"))
    if len(debs) != 1:
        sys.exit(f"FAIL: cpack made {len(debs)} .deb files")
    deb = debs[0]
    depends = groups(must(["dpkg-deb", "-f", deb, "Depends"]))
    recommends = groups(must(["dpkg-deb", "-f", deb, "Recommends"]))
    root = os.path.join(work, "root")
    must(["dpkg-deb", "-x", deb, root])
    epviz = os.path.join(root, "usr", "bin", "epviz")
    data = os.path.join(root, "usr", "share", "epviz")
    doc = os.path.join(root, "usr", "share", "doc", "epviz")

    # One licence, stated alike in the repository and the package.
    copyright_text = open(os.path.join(doc, "copyright")).read()
    license_text = open(os.path.join(source, "LICENSE")).read()
    if "License: GPL-3+" not in copyright_text or "GPL-3.0-or-later" not in license_text:
        problems.append("copyright (License: GPL-3+) and LICENSE (GPL-3.0-or-later) disagree")
    for f in ("LICENSE", "licenses.md"):
        if not os.path.exists(os.path.join(doc, f)):
            problems.append(f"not in the package: share/doc/epviz/{f}")

    # Linked libraries: each from a package Depends names on its own.
    needed = re.findall(r"NEEDED\s+(\S+)", must(["objdump", "-p", epviz]))
    ldd = dict(re.findall(r"^\s*(\S+) => (\S+)", must(["ldd", epviz]), re.M))
    required = {g[0] for g in depends if len(g) == 1}
    licenses = open(os.path.join(doc, "licenses.md")).read()
    for soname, package in owners([ldd.get(n, n) for n in needed]).items():
        if package not in required:
            problems.append(f"links {soname} of {package}, which Depends does not name alone")
        if not re.search(rf"\b{re.escape(package)}\b", licenses):
            problems.append(f"links {soname} of {package}, whose licence docs/licenses.md omits")

    # Programs it runs.
    declared = {a for g in depends + recommends for a in g}
    ffmpeg = shutil.which("ffmpeg")
    if ffmpeg is None:
        sys.exit("FAIL: ffmpeg not installed here (scripts/setup.sh --runtime installs it)")
    for path, package in owners([ffmpeg]).items():
        if package not in declared:
            problems.append(f"runs {path} of {package}, in neither Depends nor Recommends")

    env = {k: v for k, v in os.environ.items() if not k.startswith("EPVIZ_")}
    env["EPVIZ_IGNORE_SOURCE_TREE"] = "1"

    # The shipped jobs, installed and listed, and the sections and sweeps
    # listed under their own commands.
    shipped = sorted(os.path.basename(p)[:-5] for p in glob.glob(os.path.join(source, "render_jobs", "*.json"))
                     if not p.endswith((".sweep.json", ".section.json")))
    listed_text = must([epviz, "render", "--list-jobs"], env=env, cwd=work)
    if os.path.join(data, "render_jobs") not in listed_text:
        problems.append("--list-jobs does not name the installed share/epviz/render_jobs")
    # Each command's files under its heading ("epviz render NAME:", then
    # "epviz section NAME:" and "epviz sweep NAME:").
    groups = {}
    for heading, body in re.findall(r"^epviz (\w+) NAME:\n((?:  .*\n)*)", listed_text, re.M):
        groups[heading] = sorted(re.findall(r"^  (\S+)  ", body, re.M))
    listed = groups.get("render", [])
    if listed != shipped:
        problems.append(f"--list-jobs lists {listed}, the sources ship {shipped}")
    for command, suffix in (("section", ".section.json"), ("sweep", ".sweep.json")):
        files = sorted(os.path.basename(p)[:-len(suffix)]
                       for p in glob.glob(os.path.join(source, "render_jobs", "*" + suffix)))
        if groups.get(command, []) != files:
            problems.append(f"--list-jobs lists {groups.get(command)} for epviz {command}, "
                            f"the sources ship {files}")
    build_env = {k: v for k, v in os.environ.items() if not k.startswith("EPVIZ_")}
    from_build = must([os.path.join(build, "epviz"), "render", "--list-jobs"], env=build_env, cwd=work)
    if os.path.join(source, "render_jobs") not in from_build:
        problems.append("a build tree's --list-jobs does not name the source tree's render_jobs")

    # A render by each way Depends allows, by a listed name, opens only files
    # of what the declared packages bring (strace: every library, driver and
    # font it opened); the font, without which it refuses to draw, is named
    # by Depends itself.
    if shutil.which("strace") is None:
        sys.exit("FAIL: strace not installed here (scripts/setup.sh --test installs it)")
    choices = {"egl": [g[0] for g in depends],
               "osmesa": ["libosmesa6" if "libosmesa6" in g else g[0] for g in depends]}
    for gl, packages in choices.items():
        allowed = closure(packages)
        out = os.path.join(work, "out-" + gl)
        report = os.path.join(work, gl + ".json")
        trace = os.path.join(work, gl + ".strace")
        r = run(["strace", "-f", "-qq", "-e", "trace=open,openat", "-e", "status=successful",
                 "-o", trace, epviz, "render", "kovalevskaya", "--frames", "0", "--width", "160", "--height",
                 "120", "--format", "png", "--out", out, "--quiet", "--report-json", report],
                env={**env, "EPVIZ_GL": gl}, cwd=work)
        if r.returncode != 0 or not os.path.exists(os.path.join(out, "kovalevskaya_0000.png")):
            problems.append(f"{gl}: the listed job kovalevskaya did not render: {r.stderr[-500:]}")
            continue
        if f'"gl_backend": "{gl}"' not in open(report).read():
            problems.append(f"{gl}: the report names another GL backend")
        opened = set(re.findall(r'open(?:at)?\((?:AT_FDCWD, )?"([^"]+)"', open(trace).read()))
        used = [p for p in opened
                if p.startswith("/") and not p.startswith((root, work)) and not os.path.isdir(p)]
        fonts = 0
        for path, package in sorted(owners(used).items()):
            if package not in allowed:
                problems.append(f"{gl}: opens {path} of {package}, which the Depends chosen "
                                f"({', '.join(packages)}) do not bring")
            if path.startswith("/usr/share/fonts/"):
                fonts += 1
                if package not in required:
                    problems.append(f"{gl}: draws with {path} of {package}, which Depends "
                                    "does not name alone")
        if fonts == 0:
            problems.append(f"{gl}: no font opened: is the test looking at the render?")

    # The Python module, where it was built: `import epviz` works from the
    # package alone (the sources hidden), and what its extension links is
    # named by Depends, as for the binary.
    module = os.path.join(root, "usr", "lib", "python3", "dist-packages", "epviz")
    if os.path.isdir(os.path.join(build, "python", "epviz")) and not os.path.isdir(module):
        problems.append("the Python module was built but the package does not install it")
    if os.path.isdir(module):
        names = {a for g in depends for a in g}
        for package in ("python3", "python3-numpy"):
            if package not in names:
                problems.append(f"installs the Python module without {package} in Depends")
        for extension in glob.glob(os.path.join(module, "_epviz*.so")):
            linked = re.findall(r"NEEDED\s+(\S+)", must(["objdump", "-p", extension]))
            resolved = dict(re.findall(r"^\s*(\S+) => (\S+)", must(["ldd", extension]), re.M))
            for soname, package in owners([resolved.get(n, n) for n in linked]).items():
                if package not in required:
                    problems.append(f"the Python module links {soname} of {package}, which "
                                    "Depends does not name alone")
        py_env = {**env, "PYTHONPATH": os.path.dirname(module), "PYTHONDONTWRITEBYTECODE": "1",
                  "EPVIZ_DATA_DIR": data}
        script = ("import epviz\n"
                  "assert epviz.__file__.startswith(%r), epviz.__file__\n"
                  "r = epviz.simulate(case='euler', t_end=1, samples=4)\n"
                  "assert r['t'].shape == (5,) and r.report['steps'] > 0\n"
                  "image = epviz.render_frame('kovalevskaya', width=64, height=48, gl='osmesa')\n"
                  "assert image.shape == (48, 64, 4) and image.std() > 0\n"
                  "print('ok')\n") % module
        r = run(["/usr/bin/python3", "-c", script], env=py_env, cwd=work)
        if r.returncode != 0 or r.stdout.strip() != "ok":
            problems.append(f"the installed Python module does not work: {r.stderr.strip()[-500:]}")
finally:
    shutil.rmtree(work, ignore_errors=True)

for p in problems:
    print("FAIL:", p)
if problems:
    sys.exit(1)
print("the .deb declares what it needs")
