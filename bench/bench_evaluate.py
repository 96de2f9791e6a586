#!/usr/bin/env python3
"""sdfwb.evaluate against the same analytic SDFs in PyTorch and NumPy, measured in the same run (#18 point 4).

    env -u DISPLAY PYTHONPATH=build/python /usr/bin/python3 bench/bench_evaluate.py [--points 10000000] [--repeats 3]
        [--markdown FILE]

Three classes: a sphere (one length), a CSG shape (box intersected with a sphere, minus three cylinders: the
classic CSG tree) and a fractal (Mandelbulb, power 8, 8 iterations, bailout 2). Each is written with the same
formulas in GLSL for sdfwb.evaluate (distance only, gradient=False), in PyTorch (CPU, float32) and in NumPy
(float32). Every implementation gets the same float32 points, uniform in [-1.2, 1.2]^3.

Fairness: the references are given their best, and the table says what that was.
- PyTorch is timed at every thread count from 1 to os.cpu_count() (torch.set_num_threads(k), inter-op threads 1)
  and in several forms a competent user would write: "eager" (the formulas shared with NumPy, escaped fractal
  points masked with where), "compacted" (the fractal iterates only the points that have not escaped, which is
  what GLSL's break does), "in-place" (the same formulas with in-place ops) and "jit.script" (the eager formulas
  and the compacted fractal compiled by TorchScript). All under torch.inference_mode(), on contiguous float32
  columns. The table reports the fastest (form, thread count); a second table lists every one.
- NumPy is single-threaded (element-wise ufuncs do not use threads); it is timed in the "eager" and
  "compacted" forms and reported at its best.
- sdfwb runs on the GL renderer the configuration line names (Mesa llvmpipe on this machine, which uses every
  core unless LP_NUM_THREADS says otherwise).
Every time is the median of --repeats runs after one warm-up run of the same size. The accuracy columns are the
largest difference from a float64 NumPy evaluation of the first 100,000 points (finite values only), next to
every time. The goal (#18: at least 5x PyTorch on the CSG and fractal classes) is checked against PyTorch at its
best, and its accuracy is compared too.
"""
import datetime
import os
import platform
import shlex
import socket
import statistics
import sys
import tempfile
import time

import numpy as np
import torch

import sdfwb

from machine import cpu_model  # bench/machine.py

args = sys.argv[1:]
N = int(args[args.index("--points") + 1]) if "--points" in args else 10_000_000
REPEATS = int(args[args.index("--repeats") + 1]) if "--repeats" in args else 3
MARKDOWN = args[args.index("--markdown") + 1] if "--markdown" in args else None
CPUS = os.cpu_count()
THREADS = list(range(1, CPUS + 1))
GOAL = 5.0            # #18: sdfwb at least 5x faster than PyTorch on these classes
GOAL_CLASSES = ("csg", "fractal")
try:
    torch.set_num_interop_threads(1)  # only allowed before any inter-op work; the benchmark uses none anyway
except RuntimeError:
    pass
TORCH_DEFAULT_THREADS = torch.get_num_threads()

GLSL = {
    "sphere": "float sdf(vec3 p) { return length(p) - 0.8; }",
    "csg": """
float sdBox(vec3 p, vec3 b) { vec3 q = abs(p) - b; return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); }
float sdf(vec3 p) {
    float solid = max(sdBox(p, vec3(0.6)), length(p) - 0.8);
    float holes = min(min(length(p.yz), length(p.xz)), length(p.xy)) - 0.3;
    return max(solid, -holes);
}""",
    "fractal": """
float sdf(vec3 p) {
    vec3 z = p; float dr = 1.0; float r = length(z);
    for (int i = 0; i < 8; ++i) {
        r = length(z);
        if (r > 2.0) break;
        float theta = acos(clamp(z.z / r, -1.0, 1.0)) * 8.0;
        float phi = atan(z.y, z.x) * 8.0;
        dr = pow(r, 7.0) * 8.0 * dr + 1.0;
        z = pow(r, 8.0) * vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta)) + p;
    }
    return 0.5 * log(r) * r / dr;
}""",
}


def make(xp):
    """The SDFs over an array library with NumPy's names (numpy, or torch through a thin table)."""
    T = xp

    def length(x, y, z):
        return T.sqrt(x * x + y * y + z * z)

    def sphere(x, y, z):
        return length(x, y, z) - 0.8

    def box(x, y, z, b):
        qx, qy, qz = T.abs(x) - b, T.abs(y) - b, T.abs(z) - b
        zero = T.zeros_like(qx)
        outside = length(T.maximum(qx, zero), T.maximum(qy, zero), T.maximum(qz, zero))
        return outside + T.minimum(T.maximum(qx, T.maximum(qy, qz)), zero)

    def csg(x, y, z):
        solid = T.maximum(box(x, y, z, 0.6), length(x, y, z) - 0.8)
        holes = T.minimum(T.minimum(T.sqrt(y * y + z * z), T.sqrt(x * x + z * z)), T.sqrt(x * x + y * y)) - 0.3
        return T.maximum(solid, -holes)

    def fractal(x, y, z):
        """Every point through all 8 iterations; escaped points keep their values through where."""
        zx, zy, zz = x, y, z
        dr = T.ones_like(x)
        r = length(zx, zy, zz)
        active = T.ones_like(x) > 0
        for _ in range(8):
            r_new = length(zx, zy, zz)
            r = T.where(active, r_new, r)
            active = active & (r <= 2.0)
            theta = T.arccos(T.clip(zz / r, -1.0, 1.0)) * 8.0
            phi = T.arctan2(zy, zx) * 8.0
            r7 = r ** 7
            dr = T.where(active, r7 * 8.0 * dr + 1.0, dr)
            r8 = r7 * r
            st = T.sin(theta)
            zx = T.where(active, r8 * st * T.cos(phi) + x, zx)
            zy = T.where(active, r8 * st * T.sin(phi) + y, zy)
            zz = T.where(active, r8 * T.cos(theta) + z, zz)
        return 0.5 * T.log(r) * r / dr

    def fractal_compacted(x, y, z):
        """The same formulas on the points that have not escaped yet only (GLSL's break)."""
        r = length(x, y, z)
        dr = T.ones_like(x)
        index = T.arange(x.shape[0])
        px, py, pz, zx, zy, zz, d = x, y, z, x, y, z, dr
        for _ in range(8):
            rr = length(zx, zy, zz)
            r[index] = rr
            keep = rr <= 2.0
            index, rr, d = index[keep], rr[keep], d[keep]
            px, py, pz, zx, zy, zz = px[keep], py[keep], pz[keep], zx[keep], zy[keep], zz[keep]
            theta = T.arccos(T.clip(zz / rr, -1.0, 1.0)) * 8.0
            phi = T.arctan2(zy, zx) * 8.0
            r7 = rr ** 7
            d = r7 * 8.0 * d + 1.0
            dr[index] = d
            r8 = r7 * rr
            st = T.sin(theta)
            zx, zy, zz = r8 * st * T.cos(phi) + px, r8 * st * T.sin(phi) + py, r8 * T.cos(theta) + pz
        return 0.5 * T.log(r) * r / dr

    return {"sphere": {"eager": sphere}, "csg": {"eager": csg},
            "fractal": {"eager": fractal, "compacted": fractal_compacted}}


class TorchNames:
    """NumPy's function names over torch (the formulas above are written once)."""
    sqrt, abs, maximum, minimum, where = torch.sqrt, torch.abs, torch.maximum, torch.minimum, torch.where
    zeros_like, ones_like, sin, cos, log = torch.zeros_like, torch.ones_like, torch.sin, torch.cos, torch.log
    arccos, arctan2, arange = torch.acos, torch.atan2, torch.arange

    @staticmethod
    def clip(v, lo, hi):
        return torch.clamp(v, lo, hi)


# ---- PyTorch written directly: in-place ops, and the forms TorchScript compiles (same formulas). TorchScript
# compiles only code typed as torch.Tensor, not the library-generic versions in make() above, so these
# restate those formulas with torch names (a repeat on purpose: keep the two in step) ----

def _length(x: torch.Tensor, y: torch.Tensor, z: torch.Tensor) -> torch.Tensor:
    return torch.sqrt(x * x + y * y + z * z)


def t_sphere(x: torch.Tensor, y: torch.Tensor, z: torch.Tensor) -> torch.Tensor:
    return _length(x, y, z) - 0.8


def t_csg(x: torch.Tensor, y: torch.Tensor, z: torch.Tensor) -> torch.Tensor:
    qx, qy, qz = torch.abs(x) - 0.6, torch.abs(y) - 0.6, torch.abs(z) - 0.6
    outside = _length(torch.clamp(qx, min=0.0), torch.clamp(qy, min=0.0), torch.clamp(qz, min=0.0))
    box = outside + torch.clamp(torch.maximum(qx, torch.maximum(qy, qz)), max=0.0)
    solid = torch.maximum(box, _length(x, y, z) - 0.8)
    holes = torch.minimum(torch.minimum(torch.sqrt(y * y + z * z), torch.sqrt(x * x + z * z)), torch.sqrt(x * x + y * y)) - 0.3
    return torch.maximum(solid, -holes)


def t_fractal(x: torch.Tensor, y: torch.Tensor, z: torch.Tensor) -> torch.Tensor:
    zx, zy, zz = x, y, z
    dr = torch.ones_like(x)
    r = _length(zx, zy, zz)
    active = torch.ones_like(x) > 0
    for _ in range(8):
        r = torch.where(active, _length(zx, zy, zz), r)
        active = active & (r <= 2.0)
        theta = torch.acos(torch.clamp(zz / r, -1.0, 1.0)) * 8.0
        phi = torch.atan2(zy, zx) * 8.0
        r7 = r ** 7
        dr = torch.where(active, r7 * 8.0 * dr + 1.0, dr)
        r8 = r7 * r
        st = torch.sin(theta)
        zx = torch.where(active, r8 * st * torch.cos(phi) + x, zx)
        zy = torch.where(active, r8 * st * torch.sin(phi) + y, zy)
        zz = torch.where(active, r8 * torch.cos(theta) + z, zz)
    return 0.5 * torch.log(r) * r / dr


def t_fractal_compacted(x: torch.Tensor, y: torch.Tensor, z: torch.Tensor) -> torch.Tensor:
    r = _length(x, y, z)
    dr = torch.ones_like(x)
    index = torch.arange(x.shape[0])
    px, py, pz, zx, zy, zz, d = x, y, z, x, y, z, dr
    for _ in range(8):
        rr = _length(zx, zy, zz)
        r[index] = rr
        keep = rr <= 2.0
        index, rr, d = index[keep], rr[keep], d[keep]
        px, py, pz, zx, zy, zz = px[keep], py[keep], pz[keep], zx[keep], zy[keep], zz[keep]
        theta = torch.acos(torch.clamp(zz / rr, -1.0, 1.0)) * 8.0
        phi = torch.atan2(zy, zx) * 8.0
        r7 = rr ** 7
        d = r7 * 8.0 * d + 1.0
        dr[index] = d
        r8 = r7 * rr
        st = torch.sin(theta)
        zx, zy, zz = r8 * st * torch.cos(phi) + px, r8 * st * torch.sin(phi) + py, r8 * torch.cos(theta) + pz
    return 0.5 * torch.log(r) * r / dr


def _length_(x, y, z):
    """|(x, y, z)| into a new tensor, with in-place ops after the first product."""
    return (x * x).addcmul_(y, y).addcmul_(z, z).sqrt_()


def i_sphere(x, y, z):
    return _length_(x, y, z).sub_(0.8)


def i_csg(x, y, z):
    qx, qy, qz = x.abs().sub_(0.6), y.abs().sub_(0.6), z.abs().sub_(0.6)
    inside = torch.maximum(qx, torch.maximum(qy, qz)).clamp_(max=0.0)
    box = _length_(qx.clamp_(min=0.0), qy.clamp_(min=0.0), qz.clamp_(min=0.0)).add_(inside)
    solid = torch.maximum(box, _length_(x, y, z).sub_(0.8), out=box)
    xx, yy, zz = x * x, y * y, z * z
    holes = torch.minimum(torch.minimum((yy + zz).sqrt_(), (xx + zz).sqrt_()), (xx + yy).sqrt_()).sub_(0.3)
    return torch.maximum(solid, holes.neg_(), out=solid)


def i_fractal_compacted(x, y, z):
    r = _length_(x, y, z)
    dr = torch.ones_like(x)
    index = torch.arange(x.shape[0])
    px, py, pz, zx, zy, zz, d = x, y, z, x, y, z, dr
    for _ in range(8):
        rr = _length_(zx, zy, zz)
        r[index] = rr
        keep = rr <= 2.0
        index, rr, d = index[keep], rr[keep], d[keep]
        px, py, pz, zx, zy, zz = px[keep], py[keep], pz[keep], zx[keep], zy[keep], zz[keep]
        theta = zz.div_(rr).clamp_(-1.0, 1.0).acos_().mul_(8.0)
        phi = torch.atan2(zy, zx).mul_(8.0)
        r7 = rr.pow(7)
        d = (r7 * 8.0).mul_(d).add_(1.0)
        dr[index] = d
        r8 = r7.mul_(rr)
        st = theta.sin().mul_(r8)
        zx = phi.cos().mul_(st).add_(px)
        zy = phi.sin_().mul_(st).add_(py)
        zz = theta.cos_().mul_(r8).add_(pz)
    return r.log().mul_(r).div_(dr).mul_(0.5)


NUMPY, TORCH = make(np), make(TorchNames)
TORCH["sphere"].update({"in-place": i_sphere, "jit.script": torch.jit.script(t_sphere)})
TORCH["csg"].update({"in-place": i_csg, "jit.script": torch.jit.script(t_csg)})
TORCH["fractal"].update({"in-place": i_fractal_compacted, "jit.script": torch.jit.script(t_fractal),
                         "jit.script compacted": torch.jit.script(t_fractal_compacted)})


def timed(work):
    """The median of REPEATS runs after one warm-up run, and the last result."""
    result = work()
    times = []
    for _ in range(REPEATS):
        start = time.perf_counter()
        result = work()
        times.append(time.perf_counter() - start)
    return statistics.median(times), result


def error(values, truth):
    values = np.asarray(values[: len(truth)], np.float64)
    finite = np.isfinite(values) & np.isfinite(truth)
    return float(np.max(np.abs(values[finite] - truth[finite])))




def gl_renderer():
    """The GL renderer sdfwb's headless context runs on, from a tiny sample run's report."""
    with tempfile.TemporaryDirectory() as folder:
        report = sdfwb.run({"kind": "sample", "source": GLSL["sphere"], "pattern": "rand", "n": 256,
                            "output": os.path.join(folder, "renderer.bin")})
    return report.get("gl_renderer") or "unknown"


def cpu_busy():
    """(busy seconds of the whole machine, CPU seconds of this process and its threads) so far."""
    with open("/proc/stat") as stat:
        fields = [int(v) for v in stat.readline().split()[1:]]
    idle = fields[3] + fields[4]  # idle + iowait
    own = os.times()
    return (sum(fields[:8]) - idle) / os.sysconf("SC_CLK_TCK"), own.user + own.system


def seconds(t):
    return f"{t:.4f}"


points = (np.random.default_rng(7).random((N, 3), dtype=np.float32) * 2.4 - 1.2).astype(np.float32)
columns = [np.ascontiguousarray(points[:, k]) for k in range(3)]
tensors = [torch.from_numpy(c) for c in columns]
check = points[:100_000].astype(np.float64)
renderer = gl_renderer()
llvmpipe = "llvmpipe" in renderer
lp_threads = os.environ.get("LP_NUM_THREADS")
started = datetime.datetime.now(datetime.timezone.utc)
command = " ".join(filter(None, [
    "env -u DISPLAY" if "DISPLAY" not in os.environ else "",
    f"PYTHONPATH={shlex.quote(os.environ['PYTHONPATH'])}" if os.environ.get("PYTHONPATH") else "",
    f"LP_NUM_THREADS={lp_threads}" if lp_threads else "",
    sys.executable, shlex.join(sys.argv)]))
config = [
    f"Machine: {socket.gethostname()}, {CPUS} logical CPUs ({cpu_model()}), {platform.system()} {platform.release()}; "
    f"started {started.strftime('%Y-%m-%d %H:%M')} UTC.",
    f"sdfwb {sdfwb.__version__}: GL renderer `{renderer}`"
    + (f": Mesa's CPU rasteriser, no GPU; it uses {lp_threads if lp_threads else f'all {CPUS}'} "
       f"cores{' (LP_NUM_THREADS)' if lp_threads else ''}" if llvmpipe else "") + ".",
    f"PyTorch {torch.__version__} (CPU, float32, inference_mode): intra-op threads tried "
    f"{', '.join(map(str, THREADS))} (its default here: {TORCH_DEFAULT_THREADS}), inter-op threads "
    f"{torch.get_num_interop_threads()}; forms tried: eager, compacted (fractal), in-place, jit.script.",
    f"NumPy {np.__version__}: single-threaded (element-wise ufuncs use one core); forms tried: eager, "
    "compacted (fractal).",
    f"Python {platform.python_version()}; {N:,} float32 points uniform in [-1.2, 1.2]^3; every time is the median "
    f"of {REPEATS} runs after one warm-up run of the same size, all in this one run.",
]
print("\n".join(config), flush=True)

rows, details = [], []
busy_start, own_start, wall_start = *cpu_busy(), time.perf_counter()
with np.errstate(all="ignore"), torch.inference_mode():
    for name, source in GLSL.items():
        truth = NUMPY[name]["eager"](check[:, 0], check[:, 1], check[:, 2])
        sdfwb.evaluate(source, points[:1000], gradient=False)  # compile once outside the timing (a cached program)
        t_ours, ours = timed(lambda: sdfwb.evaluate(source, points, gradient=False)["distance"])
        e_ours = error(ours, truth)
        details.append((name, "sdfwb", "evaluate", "all (llvmpipe)" if llvmpipe else "-", t_ours, e_ours))
        print(f"{name:8s} sdfwb   {'evaluate':20s} {'all':9s} {seconds(t_ours)} s, max |error| {e_ours:.2g}", flush=True)
        torch_runs = []
        for form, function in TORCH[name].items():
            for k in THREADS:
                torch.set_num_threads(k)
                t, result = timed(lambda: function(*tensors))
                e = error(result.numpy(), truth)
                torch_runs.append((t, form, k, e))
                details.append((name, "PyTorch", form, str(k), t, e))
                print(f"{name:8s} PyTorch {form:20s} {k} thread{'s' if k > 1 else ' '} {seconds(t)} s, "
                      f"max |error| {e:.2g}", flush=True)
        torch.set_num_threads(TORCH_DEFAULT_THREADS)
        numpy_runs = []
        for form, function in NUMPY[name].items():
            t, result = timed(lambda: function(*columns))
            e = error(result, truth)
            numpy_runs.append((t, form, 1, e))
            details.append((name, "NumPy", form, "1", t, e))
            print(f"{name:8s} NumPy   {form:20s} 1 thread  {seconds(t)} s, max |error| {e:.2g}", flush=True)
        rows.append((name, t_ours, e_ours, min(torch_runs), min(numpy_runs)))
busy_end, own_end, wall = *cpu_busy(), time.perf_counter() - wall_start
others = max(0.0, (busy_end - busy_start) - (own_end - own_start))
config.append(f"Quiet machine check: during the {wall:.0f} s of measurements other processes used {others:.1f} CPU-seconds "
              f"({100 * others / (wall * CPUS):.1f}% of the {CPUS} CPUs); load average at the end "
              f"{os.getloadavg()[0]:.2f}.")
print(config[-1])


def ratio_words(ratio, other):
    return f"{ratio:.2f}x {other}" + (": slower" if ratio < 1 else "")


def accuracy_words(name, e_ours, e_ref, other):
    if e_ours > 2 * e_ref and e_ours > 1e-6:
        return f"sdfwb's {name} error {e_ours:.2g} is {e_ours / e_ref:.0f}x {other}'s ({e_ref:.2g}): less accurate"
    return f"sdfwb's {name} error {e_ours:.2g} is comparable to {other}'s ({e_ref:.2g})"


verdicts = []
for name, t_ours, e_ours, (t_torch, form, k, e_torch), (t_numpy, nform, _, e_numpy) in rows:
    line = (f"{name}: sdfwb is {ratio_words(t_torch / t_ours, 'PyTorch')} (PyTorch at its best: {form}, {k} "
            f"thread{'s' if k > 1 else ''}) and {ratio_words(t_numpy / t_ours, 'NumPy')}; "
            f"{accuracy_words(name, e_ours, e_torch, 'PyTorch')}.")
    verdicts.append(line)
goal_lines = []
for name, t_ours, e_ours, (t_torch, form, k, e_torch), _ in rows:
    if name not in GOAL_CLASSES:
        continue
    ratio = t_torch / t_ours
    text = f"{name}: {ratio:.2f}x PyTorch at its best, goal >= {GOAL:g}x {'met' if ratio >= GOAL else 'not met'}"
    if ratio < 1:
        text += " (sdfwb is slower)"
    if e_ours > 2 * e_torch and e_ours > 1e-6:
        text += (f"; {'but' if ratio >= GOAL else 'and'} sdfwb's error {e_ours:.2g} is {e_ours / e_torch:.0f}x "
                 f"PyTorch's ({e_torch:.2g}): less accurate")
    goal_lines.append(text + ".")
all_met = all(t_torch / t_ours >= GOAL for name, t_ours, _, (t_torch, *_), _ in rows if name in GOAL_CLASSES)
goal_summary = (f"Goal (#18: at least {GOAL:g}x PyTorch on the CSG and fractal classes), against PyTorch at its best "
                f"form and thread count: {'met' if all_met else 'not met'} in this run.")
print("\n".join(verdicts + [goal_summary] + goal_lines))

if MARKDOWN:
    with open(MARKDOWN, "w") as out:
        out.write("# Evaluating SDFs at given points: sdfwb.evaluate against PyTorch and NumPy\n\n")
        out.write(f"Generated by `{command}` (bench/bench_evaluate.py; nothing below is typed by hand).\n\n")
        out.write("".join(f"- {line}\n" for line in config) + "\n")
        out.write("sdfwb: `sdfwb.evaluate(glsl, points, gradient=False)` on the (N, 3) array (the program compiled once "
                  "before timing, as a training loop would). PyTorch and NumPy: the same formulas on contiguous float32 "
                  "columns. Forms: *eager* is the formulas as written (the fractal's escaped points masked with `where`, "
                  "every point through all 8 iterations); *compacted* iterates only the points that have not escaped "
                  "(what GLSL's `break` does); *in-place* is eager with in-place ops (for the fractal: compacted with "
                  "in-place ops); *jit.script* is the eager form (and *jit.script compacted* the compacted one) compiled "
                  "by TorchScript. Error: the largest difference from a float64 NumPy evaluation on the first 100,000 "
                  "points. Ratios are reference time / sdfwb time (above 1: sdfwb is faster).\n\n")
        out.write("| SDF | sdfwb s | sdfwb max error | PyTorch best s | PyTorch form, threads | PyTorch max error | "
                  "NumPy best s (1 thread) | NumPy form | NumPy max error | sdfwb vs PyTorch | sdfwb vs NumPy |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|\n")
        for name, t_ours, e_ours, (t_torch, form, k, e_torch), (t_numpy, nform, _, e_numpy) in rows:
            out.write(f"| {name} | {seconds(t_ours)} | {e_ours:.2g} | {seconds(t_torch)} | {form}, {k} "
                      f"thread{'s' if k > 1 else ''} | {e_torch:.2g} | {seconds(t_numpy)} | {nform} | {e_numpy:.2g} | "
                      f"{t_torch / t_ours:.2f}x | {t_numpy / t_ours:.2f}x |\n")
        out.write("\n" + "".join(f"- {line}\n" for line in verdicts))
        out.write(f"\n**{goal_summary}**\n\n" + "".join(f"- {line}\n" for line in goal_lines))
        out.write("\n## Every implementation, form and thread count\n\n"
                  "| SDF | implementation | form | threads | median s | max error |\n|---|---|---|---|---|---|\n")
        for name, who, form, threads, t, e in details:
            out.write(f"| {name} | {who} | {form} | {threads} | {seconds(t)} | {e:.2g} |\n")
    print(f"wrote {MARKDOWN}")
