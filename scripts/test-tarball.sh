#!/usr/bin/env bash
# Proves the relocatable tarball (scripts/make-tarball.sh) on this machine: it runs in chroots
# that hold nothing of Debian but glibc and an EGL driver stack, with an empty environment.
#   scripts/test-tarball.sh [TARBALL] [--full]    (as root; default TARBALL: the script's output)
# Two chroots, in a private mount namespace (unshare -m), each with busybox as the shell:
#   bare    glibc + the unpacked tarball: `vtkao --help` runs (on the bundled libstdc++, the
#           chroot has none) and `vtkao gl-info` fails with its one-line message (no EGL).
#   driver  bare + the EGL driver stack a vendor would install, here libglvnd (libEGL,
#           libGLdispatch, libOpenGL, libGL, libGLX), Mesa's libEGL_mesa and swrast_dri (llvmpipe)
#           with their own dependencies, and egl_vendor.d: bin/vtkao-gpu-check (quick bench
#           series unless --full) renders through EGL. Under LD_DEBUG=libs every library any of
#           its processes loads is listed: each must come from the tarball, or be glibc or the
#           driver stack, and no library the tarball bundles may come from anywhere else
#           (libstdc++ and libgcc_s excepted: the host's are preferred when new enough).
# Output: the check's JSON and the loader report in build-95/tarball-test/ (VTKAO_TARBALL_TEST).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
tarball="$here/build-95/vtkao-gpu-linux-x86_64.tar.xz"
quick=--quick
for arg in "$@"; do
  case "$arg" in
    --full) quick= ;;
    -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
    *) tarball="$(realpath "$arg")" ;;
  esac
done
[ -f "$tarball" ] || { echo "test-tarball: no $tarball (scripts/make-tarball.sh makes it)" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || { echo "test-tarball: needs root (chroot, mounts)" >&2; exit 1; }
# shellcheck source=apt-install-missing.sh
. "$here/scripts/apt-install-missing.sh"
apt_install_missing busybox-static libegl1 libegl-mesa0 libgl1-mesa-dri libopengl0 libgl1 xz-utils
out="${VTKAO_TARBALL_TEST:-$here/build-95/tarball-test}"
rm -rf "$out"
mkdir -p "$out"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
multiarch=usr/lib/x86_64-linux-gnu

# Copies files (and the files their ldd closure resolves to) into chroot $1 at their paths
# under /usr (the chroot is merged-/usr: /lib and /lib64 link to usr/).
install_files() {
  local root="$1" f dep
  shift
  for f in "$@"; do
    for dep in "$f" $(ldd "$f" 2>/dev/null | awk '$3 ~ /^\// {print $3} $1 ~ /^\// {print $1}'); do
      dep="$(realpath -s "$dep")"
      local target="$root/usr${dep#/usr}"
      [ -e "$target" ] || { mkdir -p "$(dirname "$target")" && cp -L "$dep" "$target"; }
    done
  done
}

make_root() {
  local root="$1"
  mkdir -p "$root"/{usr/bin,usr/lib64,$multiarch,etc,proc,dev,tmp,opt,out}
  ln -s usr/bin "$root/bin"
  ln -s usr/lib "$root/lib"
  ln -s usr/lib64 "$root/lib64"
  chmod 1777 "$root/tmp"
  cp /bin/busybox "$root/usr/bin/busybox"
  chroot "$root" /bin/busybox --install -s /bin
  install_files "$root" /lib64/ld-linux-x86-64.so.2 /lib/x86_64-linux-gnu/libc.so.6 \
    /lib/x86_64-linux-gnu/libm.so.6 /lib/x86_64-linux-gnu/libdl.so.2 \
    /lib/x86_64-linux-gnu/libpthread.so.0 /lib/x86_64-linux-gnu/librt.so.1
  touch "$root"/dev/{null,zero,urandom}
  tar -C "$root/opt" -xJf "$tarball"
}

# Runs a command in chroot $1 with an empty environment (PATH and HOME only), /proc and three
# device nodes mounted in a private mount namespace that ends with it.
in_root() {
  local root="$1"
  shift
  unshare -m --propagation private sh -c '
    root="$1"; shift
    mount -t proc proc "$root/proc"
    for d in null zero urandom; do mount --bind /dev/$d "$root/dev/$d"; done
    exec chroot "$root" /bin/env -i PATH=/bin HOME=/tmp "$@"' sh "$root" "$@"
}

start=$(date +%s)
echo "== bare chroot: glibc, busybox, the tarball"
bare="$work/bare"
make_root "$bare"
ls "$bare/$multiarch" | sed 's/^/   /'
in_root "$bare" /opt/vtkao-gpu/bin/vtkao --help | head -1
set +e
message="$(in_root "$bare" VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow \
  /opt/vtkao-gpu/bin/vtkao gl-info 2>&1)"
rc=$?
set -e
echo "   vtkao gl-info without a driver: exit $rc: $message"
if [ "$rc" -ne 1 ] || [ "$(printf '%s\n' "$message" | wc -l)" -ne 1 ]; then
  echo "test-tarball: FAILED: expected one line and exit status 1 without a driver" >&2
  exit 1
fi

echo "== driver chroot: bare + libglvnd, Mesa's EGL and swrast (llvmpipe)"
root="$work/driver"
make_root "$root"
before="$(cd "$root" && find . -type f | sort)"
install_files "$root" /$multiarch/libEGL.so.1 /$multiarch/libGLdispatch.so.0 \
  /$multiarch/libOpenGL.so.0 /$multiarch/libGL.so.1 /$multiarch/libGLX.so.0 \
  /$multiarch/libEGL_mesa.so.0 /$multiarch/dri/swrast_dri.so
mkdir -p "$root/usr/share/glvnd/egl_vendor.d"
cp /usr/share/glvnd/egl_vendor.d/50_mesa.json "$root/usr/share/glvnd/egl_vendor.d/"
comm -13 <(echo "$before") <(cd "$root" && find . -type f | sort) | sed 's|^\./||' \
  >"$out/driver-stack.txt"
echo "   driver stack: $(wc -l <"$out/driver-stack.txt") files ($out/driver-stack.txt)"
in_root "$root" LD_DEBUG=libs LD_DEBUG_OUTPUT=/tmp/ld MESA_SHADER_CACHE_DISABLE=true \
  /opt/vtkao-gpu/bin/vtkao-gpu-check /out $quick 2>&1 | tee "$out/check.log"
cp -r "$root/out/." "$out/"
end=$(date +%s)

# Every object any process initialised: the tarball's, glibc's or the driver stack's.
cat "$root"/tmp/ld.* | sed -n 's/^[[:space:]]*[0-9]*:[[:space:]]*calling init: //p' | sort -u >"$out/loaded.txt"
bundled="$(cd "$root/opt/vtkao-gpu/lib" && ls)"
failures=0
from_tarball=0
from_host=()
while read -r path; do
  case "$path" in
    /opt/vtkao-gpu/*) from_tarball=$((from_tarball + 1)); continue ;;
  esac
  name="$(basename "$path")"
  from_host+=("$name")
  if grep -qxF "$name" <<<"$bundled"; then
    echo "FAILED: $path is bundled in the tarball but was loaded from the host" >&2
    failures=$((failures + 1))
  elif [[ "$name" =~ ^lib(vtk|embree|tbb) ]]; then
    echo "FAILED: $path: not a driver library" >&2
    failures=$((failures + 1))
  fi
done <"$out/loaded.txt"
echo "== loaded: $from_tarball libraries from the tarball, ${#from_host[@]} from the host" \
  "(glibc and the driver stack): ${from_host[*]}"
grep -q '^window: vtkEGLRenderWindow$' "$out/gl-info.txt" ||
  { echo "FAILED: not rendered through EGL" >&2; failures=$((failures + 1)); }
python3 - "$out" <<'EOF' || failures=$((failures + 1))
import json, sys
out = sys.argv[1]
bench = json.load(open(f"{out}/bench-main.json"))
quality = json.load(open(f"{out}/quality/quality.json"))
print(f"== bench-main.json: {len(bench['cases'])} cases on {bench['gl_vendor']} / "
      f"{bench['gl_renderer']}; quality.json: {len(json.dumps(quality))} bytes")
assert bench["cases"], "no bench cases"
EOF
echo "== ${failures} failure(s); the chroots took $((end - start)) s; results in $out"
[ "$failures" -eq 0 ]
