#!/usr/bin/env bash
# The Debian package: `cpack -G DEB` in the build folder makes a .deb holding the binary, the
# dataset, the GLSL library, the matcaps, the Python package, the desktop entry, icons, MIME type,
# bash completion and man page; installed with apt-get, `sdfwb --batch render` and `import sdfwb`
# work from a folder outside the tree with nothing pointing at it, the dataset they use is the
# installed one, and purging the package leaves none of it behind.
#
#   tests/package/check_deb.sh CPACK BUILD_DIR SOURCE_DIR SCRATCH_DIR WITH_GUI WITH_PYTHON
#
# WITH_GUI, WITH_PYTHON (1 or 0): whether the build has the workbench (then the package has the
# desktop entry, icons and MIME type) and the Python module; what a build lacks is not expected.
# It installs into /usr, so it runs as root (or through `sudo -n`) and refuses to start when an
# sdfwb package or an unpackaged /usr/bin/sdfwb is already there: it never removes a user's own.
set -uo pipefail
cpack="$1"
build_dir="$(cd "$2" && pwd)"
source_dir="$(cd "$3" && pwd)"
scratch="$4"
with_gui="${5:-1}"
with_python="${6:-1}"

failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}
ok() { echo "ok: $*"; }
die() {
  echo "FAIL: $*"
  exit 1
}

# One package test at a time on this machine (two would install and purge under each other).
exec 9> /tmp/sdfwb-package-test.lock
flock -w 900 9 || die "another package test holds /tmp/sdfwb-package-test.lock"

sudo=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo > /dev/null 2>&1 && sudo -n true 2> /dev/null; then
    sudo=(sudo -n)
  else
    die "installing the .deb needs root: run as root or with password-less sudo (nothing was checked)"
  fi
fi
for tool in dpkg-deb dpkg-shlibdeps apt-get desktop-file-validate man; do
  command -v "$tool" > /dev/null 2>&1 || die "$tool is missing (scripts/bootstrap installs it)"
done
state="$(dpkg-query -W -f='${db:Status-Status}' sdfwb 2> /dev/null)"
if [ -n "$state" ] && [ "$state" != not-installed ]; then
  die "an sdfwb package is already on this machine ($(dpkg-query -W -f='${Version} ${Status}' sdfwb)): this test installs and purges sdfwb, so it will not run over it; remove it first (apt-get purge sdfwb)"
fi
for path in /usr/bin/sdfwb /usr/share/sdfwb /usr/lib/python3/dist-packages/sdfwb; do
  [ -e "$path" ] && die "$path exists but belongs to no package: this test would overwrite and then delete it"
done
glsl_types_before=$(grep -c 'text/x-glsl' /usr/share/mime/globs2 2> /dev/null)

rm -rf "$scratch"
mkdir -p "$scratch/deb"
# The installed programs run in a folder outside the source and build trees.
work="$(mktemp -d "${TMPDIR:-/tmp}/sdfwb-package-XXXXXX")"
case "$work/" in
  "$source_dir"/* | "$build_dir"/*) die "the scratch folder $work is inside the tree" ;;
esac
trap 'rm -rf "$work"' EXIT

# --- build the package ---------------------------------------------------------------------------
# cpack copies what the build made and builds nothing (Ninja has no preinstall step). Where builds
# serialise through /tmp/sdfwb-build.lock (the sdfwb-build wrapper), it waits for a running one,
# so that it never copies a binary half linked.
lock=()
[ -e /tmp/sdfwb-build.lock ] && lock=(flock -s -w 1800 /tmp/sdfwb-build.lock)
start=$SECONDS
if ! (cd "$build_dir" && "${lock[@]}" "$cpack" -G DEB -B "$scratch/deb") > "$scratch/cpack.log" 2>&1; then
  tail -20 "$scratch/cpack.log"
  die "cpack -G DEB failed (log: $scratch/cpack.log)"
fi
debs=("$scratch"/deb/sdfwb_*.deb)
if [ ${#debs[@]} -ne 1 ] || [ ! -f "${debs[0]}" ]; then
  die "cpack made no single sdfwb_*.deb: ${debs[*]}"
fi
deb="${debs[0]}"
ok "cpack -G DEB: $(basename "$deb"), $(du -k "$deb" | cut -f1) KiB, in $((SECONDS - start)) s"

# --- what it holds -------------------------------------------------------------------------------
dpkg-deb -c "$deb" | awk '{print $NF}' | sed 's|^\./|/|' > "$scratch/contents.txt"
has() { grep -qx -- "$1" "$scratch/contents.txt"; }
has_match() { grep -qE -- "$1" "$scratch/contents.txt"; }
required=(/usr/bin/sdfwb /usr/share/bash-completion/completions/sdfwb /usr/share/man/man1/sdfwb.1.gz
  /usr/share/sdfwb/dataset/report.json /usr/share/sdfwb/bench/plot_benchmarks.py)
if [ "$with_gui" = 1 ]; then
  required+=(/usr/share/applications/sdfwb.desktop /usr/share/mime/packages/sdfwb.xml
    /usr/share/icons/hicolor/scalable/apps/sdfwb.svg /usr/share/icons/hicolor/256x256/apps/sdfwb.png)
fi
[ "$with_python" = 1 ] && required+=(/usr/lib/python3/dist-packages/sdfwb/__init__.py /usr/lib/python3/dist-packages/sdfwb/_native.pyi
  /usr/lib/python3/dist-packages/sdfwb/py.typed)
for path in "${required[@]}"; do
  has "$path" || fail "the .deb lacks $path"
done
if [ "$with_python" = 1 ]; then
  has_match '^/usr/lib/python3/dist-packages/sdfwb/_native\.cpython-[0-9]+-[^/]*\.so$' ||
    fail "the .deb lacks /usr/lib/python3/dist-packages/sdfwb/_native*.so"
fi
# Every data file of the source tree the binary reads, under /usr/share/sdfwb.
missing=0
while IFS= read -r file; do
  has "/usr/share/sdfwb/${file#./}" || { missing=$((missing + 1)); [ $missing -le 5 ] && fail "the .deb lacks /usr/share/sdfwb/${file#./}"; }
done < <(cd "$source_dir" && find dataset -name '*.glsl' && find shaders/lib -type f && find resources/matcaps -name '*.png')
shapes_in_tree=$(cd "$source_dir" && find dataset -mindepth 2 -maxdepth 2 -name '*.glsl' -not -path 'dataset/lib/*' | wc -l)
[ "$missing" -eq 0 ] && ok "the .deb holds the $shapes_in_tree dataset shapes, dataset/lib, shaders/lib and the matcaps"
outside="$(grep -vE '^/(usr/.*)?$' "$scratch/contents.txt")"
[ -z "$outside" ] || fail "the .deb holds paths outside /usr: $(head -3 <<< "$outside")"
control="$(dpkg-deb -f "$deb" Depends)"
dependencies=(libegl1 libgl1-mesa-dri 'libc6 (>= ' libepoxy0)
[ "$with_gui" = 1 ] && dependencies+=(libqt6widgets6 qt6-qpa-plugins)
[ "$with_python" = 1 ] && dependencies+=('python3 (>= ' python3-numpy)
before=$failures
for dependency in "${dependencies[@]}"; do
  [[ "$control" == *"$dependency"* ]] || fail "Depends lacks $dependency: $control"
done
[ "$failures" -eq "$before" ] && ok "Depends: $control"

# --- install it ----------------------------------------------------------------------------------
installed=0
cleanup() {
  local state
  state="$(dpkg-query -W -f='${db:Status-Status}' sdfwb 2> /dev/null)"
  if [ "$installed" -eq 1 ] && [ -n "$state" ] && [ "$state" != not-installed ]; then
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get purge -y -q -o DPkg::Lock::Timeout=300 sdfwb > "$scratch/purge.log" 2>&1 ||
      echo "FAIL: apt-get purge sdfwb failed (log: $scratch/purge.log): remove it by hand"
    installed=0
  fi
}
trap 'cleanup; rm -rf "$work"' EXIT
trap 'exit 130' INT TERM
installed=1
if ! DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends \
  -o DPkg::Lock::Timeout=300 "$deb" > "$scratch/install.log" 2>&1; then
  tail -20 "$scratch/install.log"
  die "apt-get install ${deb} failed (log: $scratch/install.log)"
fi
dpkg-query -W -f='${Status}' sdfwb | grep -q "install ok installed" || die "dpkg does not list sdfwb as installed after apt-get install"
ok "apt-get install ./$(basename "$deb")"

# Nothing that could lead to the source tree: no SDFWB_DATA_DIR, PYTHONPATH, DISPLAY, pyenv; the
# working folder is a scratch folder.
run() {
  (cd "$work" && env -i HOME="$work" PATH=/usr/bin:/bin LANG=C.UTF-8 \
    ${SDFWB_EGL_PLATFORM:+SDFWB_EGL_PLATFORM="$SDFWB_EGL_PLATFORM"} "$@")
}

version="$(run /usr/bin/sdfwb --version 2>&1)"
if [[ "$version" == "sdfwb "* ]]; then
  ok "sdfwb --version: $version"
else
  fail "sdfwb --version printed '$version'"
fi

# The dataset the installed binary uses is the installed one: every path `--batch list --json`
# prints is under /usr/share/sdfwb/dataset, and there are as many as in the tree.
run /usr/bin/sdfwb --batch list --json > "$scratch/list.json" 2> "$scratch/list.err" || fail "sdfwb --batch list --json failed: $(cat "$scratch/list.err")"
paths=$(grep -c '"path"' "$scratch/list.json")
outside=$(grep '"path"' "$scratch/list.json" | grep -vc '"/usr/share/sdfwb/dataset/')
if [ "$paths" -eq "$shapes_in_tree" ] && [ "$outside" -eq 0 ]; then
  ok "sdfwb --batch list: $paths shapes, every one under /usr/share/sdfwb/dataset"
else
  fail "sdfwb --batch list: $paths shapes (the tree has $shapes_in_tree), $outside outside /usr/share/sdfwb/dataset: $(grep -m3 '"path"' "$scratch/list.json")"
fi

# A PNG with a shape in it: between 1/50 and 1/2 of the pixels differ from the corner's.
check_png() { # FILE WHAT
  /usr/bin/python3 - "$1" << 'EOF' || fail "$2: the PNG is not a 64x48 picture of a shape"
import sys
import matplotlib.image as image
import numpy as np
pixels = image.imread(sys.argv[1])
assert pixels.shape[:2] == (48, 64), pixels.shape
rgb = pixels[..., :3]
covered = np.any(np.abs(rgb - rgb[0, 0]) > 0.02, axis=-1).mean()
assert 0.02 < covered < 0.5, covered
print(f"  {sys.argv[1]}: {covered:.0%} of the frame is shape")
EOF
}
if run /usr/bin/sdfwb --batch render --sdf torus --output x.png --size 64x48 > "$scratch/render.log" 2>&1 && [ -s "$work/x.png" ]; then
  ok "sdfwb --batch render --sdf torus --output x.png --size 64x48 (from $work)"
  check_png "$work/x.png" "render torus"
else
  fail "sdfwb --batch render --sdf torus failed: $(tail -5 "$scratch/render.log")"
fi
# A shape that includes dataset/lib/modelling.glsl, which includes shaders/lib/primitives.glsl,
# shaded with a matcap named, not given as a file: all three come from /usr/share/sdfwb.
if run /usr/bin/sdfwb --batch render --sdf snowman --shading matcap --matcap jade --output snowman.png --size 64x48 \
  > "$scratch/render2.log" 2>&1 && [ -s "$work/snowman.png" ]; then
  ok "sdfwb --batch render --sdf snowman --shading matcap --matcap jade (includes and matcap from the prefix)"
  check_png "$work/snowman.png" "render snowman"
else
  fail "sdfwb --batch render --sdf snowman --shading matcap --matcap jade failed: $(tail -5 "$scratch/render2.log")"
fi

# Debian's python3 imports the installed package and samples the torus.
if [ "$with_python" != 1 ]; then
  echo "not checked: import sdfwb (this build has no Python module, SDFWB_BUILD_PYTHON=OFF)"
elif run /usr/bin/python3 - > "$scratch/python.log" 2>&1 << 'EOF'; then
import numpy as np
import sdfwb
assert sdfwb.__file__ == "/usr/lib/python3/dist-packages/sdfwb/__init__.py", sdfwb.__file__
paths = [entry["path"] for entry in sdfwb.list_sdfs()]
assert paths and all(p.startswith("/usr/share/sdfwb/dataset/") for p in paths), paths[:3]
result = sdfwb.sample("torus", "rand", 256, seed=7)
p, d, g = result["position"], result["distance"], result["gradient"]
assert p.shape == (256, 3) and d.shape == (256,) and g.shape == (256, 3), (p.shape, d.shape, g.shape)
assert p.dtype == d.dtype == g.dtype == np.float32
# The torus of dataset/Geometry/Torus.glsl: tilted 30 degrees about X, radii 0.65 and 0.25.
c, s = np.cos(np.pi / 6), np.sin(np.pi / 6)
q = np.stack([p[:, 0], c * p[:, 1] + s * p[:, 2], -s * p[:, 1] + c * p[:, 2]], axis=1).astype(np.float64)
exact = np.hypot(np.hypot(q[:, 0], q[:, 2]) - 0.65, q[:, 1]) - 0.25
assert np.max(np.abs(d - exact)) < 1e-4, np.max(np.abs(d - exact))
assert np.allclose(np.linalg.norm(g, axis=1), 1, atol=1e-2)
print(f"  sdfwb.sample('torus', 'rand', 256): {len(paths)} shapes listed, distances within "
      f"{np.max(np.abs(d - exact)):.1e} of the exact torus")
EOF
  ok "/usr/bin/python3 -c 'import sdfwb; sdfwb.sample(...)' (from $work)"
  cat "$scratch/python.log"
else
  fail "import sdfwb / sdfwb.sample in /usr/bin/python3: $(tail -8 "$scratch/python.log")"
fi

# While the package is installed, the build tree's module still reads the source tree: it finds
# its data from the file that holds its code, not from the interpreter (/usr/bin/python3).
if [ "$with_python" = 1 ]; then
  build_list="$(cd "$work" && env -i PATH=/usr/bin:/bin PYTHONPATH="$build_dir/python" /usr/bin/python3 -c \
    'import sdfwb; print(sdfwb.__file__); print(sdfwb.list_sdfs()[0]["path"])' 2>&1)"
  if [[ "$build_list" == "$build_dir/python/sdfwb/__init__.py"*"$source_dir/dataset/"* ]]; then
    ok "the build tree's module, with the package installed, lists the source tree's dataset"
  else
    fail "the build tree's module should list $source_dir/dataset: $build_list"
  fi
fi

# The man page renders and has the per-command options.
man_text="$(MANWIDTH=100 man -l /usr/share/man/man1/sdfwb.1.gz 2> /dev/null)"
if [[ "$man_text" == *"sdfwb - the SDF Workbench"* && "$man_text" == *"sdfwb --batch render"* && "$man_text" == *"--output"* ]]; then
  ok "man -l /usr/share/man/man1/sdfwb.1.gz ($(wc -l <<< "$man_text") lines)"
else
  fail "the man page does not render as expected: $(head -5 <<< "$man_text")"
fi
run man -w sdfwb > /dev/null 2>&1 || fail "man -w sdfwb does not find the page"

# The modules the binary loads on first use (core/Plugins.h) are in the package and load with the
# libraries it depends on; the workbench's only when the build has one.
modules=(/usr/lib/sdfwb/libsdfwb_media.so:sdfwb_media_api)
[ "$with_gui" = 1 ] && modules+=(/usr/lib/sdfwb/libsdfwb_workbench.so:sdfwb_workbench_main)
for module in "${modules[@]}"; do
  if run /usr/bin/python3 -c 'import ctypes, sys; path, name = sys.argv[1].split(":"); getattr(ctypes.CDLL(path), name)' \
    "$module" > "$scratch/module.log" 2>&1; then
    ok "${module%%:*} loads and exports ${module##*:}"
  else
    fail "${module%%:*} does not load: $(tail -3 "$scratch/module.log")"
  fi
done

# The desktop entry: valid, opens .glsl files (text/x-glsl, declared by the package's MIME XML).
if [ "$with_gui" != 1 ]; then
  echo "not checked: the desktop entry (this build has no workbench, SDFWB_BUILD_GUI=OFF)"
elif ! desktop-file-validate /usr/share/applications/sdfwb.desktop > "$scratch/desktop.log" 2>&1; then
  fail "desktop-file-validate: $(cat "$scratch/desktop.log")"
else
  ok "desktop-file-validate /usr/share/applications/sdfwb.desktop"
  before=$failures
  grep -q '^Exec=sdfwb %[fF]$' /usr/share/applications/sdfwb.desktop || fail "the desktop entry's Exec does not pass files"
  grep -q '^MimeType=.*text/x-glsl;' /usr/share/applications/sdfwb.desktop || fail "the desktop entry lacks MimeType text/x-glsl"
  grep -q '^text/x-glsl=.*sdfwb.desktop' /usr/share/applications/mimeinfo.cache 2> /dev/null ||
    fail "update-desktop-database did not register sdfwb.desktop for text/x-glsl"
  grep -q 'text/x-glsl:\*\.glsl' /usr/share/mime/globs2 2> /dev/null || fail "update-mime-database did not map *.glsl to text/x-glsl"
  [ -s /usr/share/icons/hicolor/scalable/apps/sdfwb.svg ] || fail "the icon is missing"
  [ "$failures" -eq "$before" ] && ok "the desktop entry is registered for text/x-glsl and *.glsl is text/x-glsl"
fi

# Bash completion: commands, options of a command, dataset shapes (through the installed binary).
completion="$(run bash -c '
  source /usr/share/bash-completion/completions/sdfwb
  t() { COMP_WORDS=("$@"); COMP_CWORD=$(( ${#COMP_WORDS[@]} - 1 )); COMPREPLY=(); _sdfwb; echo "${COMPREPLY[*]}"; }
  t sdfwb --batch ren; t sdfwb --batch render --out; t sdfwb --batch sample --sdf toru; t sdfwb --batch sample --pat' 2>&1)"
if [ "$completion" == $'render\n--output\ntorus\n--pattern' ]; then
  ok "bash completion: --batch ren -> render, render --out -> --output, --sdf toru -> torus, sample --pat -> --pattern"
else
  fail "bash completion gave: $(tr '\n' '|' <<< "$completion")"
fi

# --- remove it -----------------------------------------------------------------------------------
cleanup
before=$failures
for path in /usr/bin/sdfwb /usr/share/sdfwb /usr/lib/python3/dist-packages/sdfwb /usr/share/applications/sdfwb.desktop \
  /usr/share/man/man1/sdfwb.1.gz /usr/share/bash-completion/completions/sdfwb; do
  [ -e "$path" ] && fail "$path is still there after apt-get purge sdfwb"
done
dpkg-query -W -f='${Status}' sdfwb 2> /dev/null | grep -q "install ok installed" && fail "sdfwb is still installed after apt-get purge"
[ "$(grep -c 'text/x-glsl' /usr/share/mime/globs2 2> /dev/null)" = "$glsl_types_before" ] ||
  fail "the MIME database's text/x-glsl entries differ from before the install"
[ "$failures" -eq "$before" ] && ok "apt-get purge sdfwb: nothing left behind"
echo "package test: $((SECONDS)) s, $failures failure(s)"
[ "$failures" -eq 0 ]
