#!/usr/bin/env python3
"""Opens, renders and samples every whole Shadertoy shader in a folder the way a new user would:
pasted as is, no --entry. The folder is yours (public shaders are not in this repository); each
file is one single-pass image shader. Prints one line per file and a summary; with --doc FILE also
writes a Markdown table with its date and machine line.

    /usr/bin/python3 scripts/pasted_shaders_report.py FOLDER [--binary build/app/sdfwb] [--doc docs/pasted-shaders.md]
        [--hosts]   (the folder holds whole shaders of other hosts: glslViewer, GLSL Sandbox, Bonzomatic,
                     KodeLife, three.js, WebGL pages, ports, Fragmentarium, ISF, Processing, the VS Code Shader Toy
                     extension, Synesthesia (a NAME.synScene folder), TouchDesigner, p5.js; the doc says so and names the host
                     sdfwb read each file as)

Per file: render (320x180, the default camera), sample (`rand`, 2,000 rows) and how the entry was
chosen (the march, a conventional name or `sdf`), each with the first error line when it failed.
"""
import datetime
import os
import platform
import re
import subprocess
import sys
import tempfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def option(name, default):
    return sys.argv[sys.argv.index(name) + 1] if name in sys.argv else default


args = [a for i, a in enumerate(sys.argv[1:], 1) if not a.startswith("--") and not sys.argv[i - 1].startswith("--")]
if not args:
    sys.exit(__doc__)
FOLDER = args[0]
BINARY = option("--binary", os.path.join(ROOT, "build", "app", "sdfwb"))
DOC = option("--doc", "")
HOSTS = "--hosts" in sys.argv
HOST = re.compile(r"read as (an? [^:]+?)(?: shader)?:")
ENV = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
ENTRY = re.compile(r"entry automatic: (\S+) \(called by the march at line (\d+)\)")
UNION_ENTRY = re.compile(r"entry automatic: the union of (.*?): the primary ray marches each")
UNION_PART = re.compile(r"(\S+) \(called by the march at line (\d+)\)")
INLINE_ENTRY = re.compile(r"entry automatic: (\S+) \(its march at line (\d+) writes the field inline")
LEVEL_ENTRY = re.compile(r"entry automatic: (\S+) \(its march at line (\d+) steps .*? and stops where")


def run(command):
    result = subprocess.run(command, capture_output=True, text=True, env=ENV, timeout=600)
    lines = result.stderr.strip().splitlines()
    errors = [line for line in lines if "error" in line.lower()]
    first = errors[0] if errors else (lines[-1] if lines else "")
    return result.returncode, first.split("error: ", 1)[-1], result.stderr


# A function of a point returning a distance (float, vec2, vec4, or a struct holding one; a vec3
# is a colour, a normal or a hash). A shader without one
# writes its field inline in mainImage's loop (golfed and "volumetric glow" styles): there is no
# function to open, and the report counts it apart.
POINT_FUNCTION = re.compile(r"\b(?:float|vec2|vec4|[A-Z]\w*)\s+\w+\s*\(\s*(?:in\s+|const\s+)*vec3\s+\w+")


def changes_sign(npz):
    import numpy
    with numpy.load(npz) as rows_file:
        distances = rows_file["distance"]
    finite = distances[numpy.isfinite(distances)]
    return bool(finite.size) and bool((finite < 0).any() and (finite > 0).any())


def first_error(text):
    # "no SDF here: define ... metadata line (WHY)": the why, which is each file's own.
    marker = "metadata line ("
    if text.startswith("no SDF here") and marker in text:
        text = "no SDF here: " + text.split(marker, 1)[1].rstrip(")")
    return text.replace("|", "\\|")[:240]


rows = []
renders = samples = both = 0
with tempfile.TemporaryDirectory() as scratch:
    # A Synesthesia scene is a folder (NAME.synScene: main.glsl and the scene.json declaring its controls).
    # A Max/Jitter shader is its .jxs file (XML holding the programs).
    files = sorted(f for f in os.listdir(FOLDER) if f.endswith(".glsl") or f.endswith(".jxs") or
                   (f.endswith(".synScene") and os.path.isfile(os.path.join(FOLDER, f, "main.glsl"))))
    for name in files:
        path = os.path.join(FOLDER, name, "main.glsl") if name.endswith(".synScene") else os.path.join(FOLDER, name)
        code, error, log = run([BINARY, "--batch", "render", "--sdf", path, "--size", "320x180", "--output",
                                os.path.join(scratch, "picture.png")])
        rendered = code == 0
        host_match = HOST.search(log)
        host = host_match.group(1) if host_match else ""
        match = ENTRY.search(log)
        inline_match = INLINE_ENTRY.search(log)
        level_match = LEVEL_ENTRY.search(log)
        union_match = UNION_ENTRY.search(log)
        united = UNION_PART.findall(union_match.group(1)) if union_match else []
        entry = (f"{match.group(1)} (march, line {match.group(2)})" if match else
                 "union of " + " and ".join(f"{name} (march, line {line})" for name, line in united) if united else
                 f"{inline_match.group(1)} (inline march, line {inline_match.group(2)})" if inline_match else
                 f"{level_match.group(1)} (level march, line {level_match.group(2)})" if level_match else "")
        sample_code, sample_error, sample_log = run([BINARY, "--batch", "sample", "--sdf", path, "--pattern", "rand", "-n", "2000",
                                            "--output", os.path.join(scratch, "rows.npz")])
        sampled = sample_code == 0
        # Whether the field changes sign among the 2,000 rows: a surface in the box (a glow's
        # density never does).
        surface = sampled and changes_sign(os.path.join(scratch, "rows.npz"))
        # Without one in [-1, 1]^3: the same run framed by the surface's box (--normalize unit-cube),
        # "yes" when the framed rows change sign, "none" when no surface was found within [-64, 64]^3.
        framed = ""
        floor_only = sampled and surface and "holds only the plane" in sample_log
        if floor_only:  # [-1, 1]^3 holds only its floor: framed, what stands on it ("on floor" when that has a surface)
            framed_code, _, _ = run([BINARY, "--batch", "sample", "--sdf", path, "--normalize", "unit-cube", "--pattern",
                                     "rand", "-n", "2000", "--output", os.path.join(scratch, "framed.npz")])
            framed = "on floor" if framed_code == 0 and changes_sign(os.path.join(scratch, "framed.npz")) else "failed"
        if sampled and not surface:
            framed_code, _, framed_log = run([BINARY, "--batch", "sample", "--sdf", path, "--normalize", "unit-cube",
                                                "--pattern", "rand", "-n", "2000", "--output", os.path.join(scratch, "framed.npz")])
            framed = ("yes" if changes_sign(os.path.join(scratch, "framed.npz")) else "no") if framed_code == 0 else (
                "none" if any(why in framed_log for why in ("no surface within", "never negative", "not finite anywhere",
                                                    "a constant, with no surface"))
                else "failed")
        # An unsigned field (never negative, near 0: the run's warning says so): whether the level set
        # its own march stops at (the threshold the warning names, read from the shader; else a usual
        # one, 0.001) has a surface in the box (framed if needed).
        level = ""
        if sampled and not surface and "never negative" in sample_log:
            level = "no"
            named = re.search(r"--level ([0-9.eE+-]+) takes that level set", sample_log)
            for extra in ([], ["--normalize", "unit-cube"]):
                code, _, _ = run([BINARY, "--batch", "sample", "--sdf", path, "--level", named.group(1) if named else "0.001",
                                  *extra, "--pattern", "rand",
                                  "-n", "2000", "--output", os.path.join(scratch, "level.npz")])
                if code == 0 and changes_sign(os.path.join(scratch, "level.npz")):
                    level = "yes" if not extra else "yes, framed"
                    break
        renders += rendered
        samples += sampled
        both += rendered and sampled
        problem = "" if rendered and sampled else first_error(error if not rendered else sample_error)
        inline = not POINT_FUNCTION.search(open(path, errors="replace").read())
        rows.append((name, entry, rendered, sampled, problem, inline, surface, host, framed, level))
        print(f"{name}: render {'ok' if rendered else 'FAILED'}, sample {'ok' if sampled else 'FAILED'} {entry} {problem}",
              flush=True)

n = max(len(rows), 1)
inlines = [row for row in rows if row[5]]
functions = [row for row in rows if not row[5]]
ok = sum(1 for row in functions if row[2] and row[3])
inline_ok = [row for row in inlines if row[2] and row[3]]
summary = (f"{len(rows)} shaders: {renders} render ({100 * renders / n:.1f} %), {samples} sample "
           f"({100 * samples / n:.1f} %), {both} both ({100 * both / n:.1f} %). Of the {len(functions)} with a function "
           f"of a point, {ok} render and sample ({100 * ok / max(len(functions), 1):.1f} %); of the {len(inlines)} that "
           f"write their field inline in a march loop, {len(inline_ok)} "
           f"({100 * len(inline_ok) / max(len(inlines), 1):.1f} %), and the field of "
           f"{sum(1 for row in inline_ok if row[6])} of those changes sign in the box (a surface; a glow's density "
           f"does not). Surface: the 2,000 sampled values hold both signs. Of the "
           f"{sum(1 for row in rows if row[3] and not row[6])} that sample without a surface in [-1, 1]^3, "
           f"{sum(1 for row in rows if row[8] == 'yes')} have one once framed (`--normalize unit-cube`: the box of "
           f"their surface, found by their values, framed as the unit box); "
           f"{sum(1 for row in rows if row[8] == 'none')} have none within [-64, 64]^3 (glows, fields drawn from "
           f"textures or the pixel, constants). Of those with a surface there, {sum(1 for row in rows if row[8] == 'on floor')} "
           f"hold only their floor (a plane across the box) and what stands on it lies outside: the run names that "
           f"box, and framed by it the rows change sign (column framed: on floor). {sum(1 for row in rows if row[9])} are unsigned (never negative, near 0: the run "
           f"warns and names `--level`); the level set where its own march stops (`--level` at the threshold read "
           f"from the shader, else 0.001) gives "
           f"{sum(1 for row in rows if row[9].startswith('yes'))} of them a surface (column level)")
print(summary)
if DOC:
    renderer = subprocess.run([BINARY, "--batch", "audit", "--sdf", "sphere", "--samples", "64"], capture_output=True, text=True,
                              env=ENV).stderr
    gl = re.search(r"gl: (.*)", renderer)
    with open(DOC, "w") as out:
        out.write("# Pasted shaders from other hosts: open, render, sample\n\n" if HOSTS else
                  "# Pasted Shadertoy shaders: open, render, sample\n\n")
        out.write(f"Generated by `/usr/bin/python3 scripts/pasted_shaders_report.py FOLDER{' --hosts' if HOSTS else ''} --doc ...`; do not edit by hand. "
                  f"{datetime.date.today().isoformat()}, {platform.node() or 'this machine'}: {os.cpu_count()} cores, "
                  f"{gl.group(1).strip() if gl else 'unknown renderer'}.\n\n")
        out.write(("Each file a whole fragment shader written for another host than Shadertoy (glslViewer and The Book of "
                   "Shaders, GLSL Sandbox, Bonzomatic, KodeLife, three.js, a WebGL page, a Shadertoy port, Fragmentarium, ISF, "
                   "Processing and openFrameworks, SHADERed, Synesthesia, TouchDesigner, p5.js, MadMapper, Max/Jitter, sokol-shdc, "
                   "RetroArch, Vulkan GLSL, raylib, bgfx), from "
                   "public repositories, opened as is with no `--entry` (the files are not in this repository); host: what sdfwb "
                   "read it as (docs/foreign-code.md, 'Shaders from other hosts'). " if HOSTS else
                   "Each file a whole single-pass Shadertoy image shader from public repositories, pasted as is and opened with "
                   "no `--entry` (the files are not in this repository). ") + "Render: `sdfwb --batch render --size 320x180`; "
                  "sample: `sdfwb --batch sample --pattern rand -n 2000`. Entry: the function the shader's march steps by "
                  "where that chose it (the union of two a primary ray marches as often), the function whose march loop writes the field inline (inline march), the function whose loop steps a fixed amount and "
                  "stops where a value of its point crosses a level, a height field's `p.y < h` (level march: the field is that "
                  "difference, not a distance), else a conventional name.\n\n")
        sources = os.path.join(FOLDER, "SOURCES.txt")  # local name, repository, path, commit (tab-separated)
        if os.path.exists(sources):
            repos = {}
            for line in open(sources):
                fields = line.rstrip("\n").split("\t")
                if len(fields) >= 2:
                    repos[fields[1]] = repos.get(fields[1], 0) + 1
            out.write("Sources (GitHub repositories, files): " +
                      ", ".join(f"{repo} ({count})" for repo, count in sorted(repos.items(), key=lambda kv: -kv[1])) + ".\n\n")
        out.write(summary + ".\n\n| file | " + ("host | " if HOSTS else "") +
                  "entry | render | sample | surface | framed | level | first error |\n|---|" + ("---|" if HOSTS else "") +
                  "---|---|---|---|---|---|---|\n")
        for name, entry, rendered, sampled, problem, inline_field, surface, host, framed, level in rows:
            out.write(f"| {name} | " + (f"{host or '-'} | " if HOSTS else "") +
                      f"{entry or ('none: inline field' if inline_field else 'by name')} | "
                      f"{'yes' if rendered else 'no'} | {'yes' if sampled else 'no'} | {'yes' if surface else 'no'} | {framed or '-'} | "
                      f"{level or '-'} | {problem or '-'} |\n")
    print(f"wrote {DOC}")
