#!/usr/bin/env bash
# A relocatable vtkao for GPU servers: one .tar.xz that runs on a bare x86-64 Linux machine
# with only the vendor's GL/EGL driver (no X, no Debian packages, no network).
#   scripts/make-tarball.sh [OUTPUT.tar.xz]   (default: build-95/vtkao-gpu-linux-x86_64.tar.xz)
# It builds vtkao against VTK 9.5 (PyPI's wheel, scripts/setup-vtk95.sh) with
# VTKAO_IMAGE_IO=builtin (no OpenImageIO) in build-95/tarball-build (VTKAO_TARBALL_BUILD), then
# bundles vtkao and its shared-library closure except glibc and the GL, EGL and GLX driver
# libraries, which are the host's (VTK loads those with dlopen). Layout:
#   vtkao-gpu/bin/vtkao            wrapper: the host's libstdc++ when it is new enough, else
#                                  lib/compat's (see below), then libexec/vtkao
#   vtkao-gpu/bin/vtkao-gpu-check  GL vendor and renderer, bench's main series, quality --quick
#   vtkao-gpu/libexec/vtkao        the program (DT_RPATH $ORIGIN/../lib)
#   vtkao-gpu/lib/                 VTK 9.5, Embree, TBB, X11 client libraries, zlib ...
#   vtkao-gpu/lib/compat/          libstdc++ and libgcc_s (used only when the host's are older
#                                  or missing: a driver such as Mesa links libstdc++ itself and
#                                  must get one at least as new as its own)
# Documentation/gpu-tarball.md; scripts/test-tarball.sh runs it in a chroot.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
output="$(realpath -m "${1:-$here/build-95/vtkao-gpu-linux-x86_64.tar.xz}")"
build="${VTKAO_TARBALL_BUILD:-$here/build-95/tarball-build}"

# shellcheck source=apt-install-missing.sh
. "$here/scripts/apt-install-missing.sh"
apt_install_missing patchelf xz-utils binutils
# The VTK 9.5 venv and SDK (installs nothing when they are there).
VTKAO_SETUP_ONLY=1 "$here/scripts/setup-vtk95.sh" "$here/build-95" >/dev/null
vtk_dir="$(cat "$here/build-95/vtk-dir.txt")"
vtklibs="$("$here/build-95/venv/bin/python" -c \
  'import os, vtkmodules; print(os.path.dirname(vtkmodules.__file__))')"

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DVTK_DIR="$vtk_dir" \
  -DVTKAO_WRAP_PYTHON=OFF -DVTKAO_PYTHON_WHEEL=OFF -DBUILD_TESTING=OFF \
  -DVTKAO_IMAGE_IO=builtin >/dev/null
cmake --build "$build" -j"${VTKAO_JOBS:-$(nproc)}" --target vtkao
program="$build/Examples/vtkao"

stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
root="$stage/vtkao-gpu"
mkdir -p "$root/bin" "$root/libexec" "$root/lib/compat"

# The host's: glibc (and the loader) and the GL/EGL/GLX driver stack (libglvnd and the vendor's).
host_lib='^(linux-vdso|ld-linux|libc|libm|libdl|libpthread|librt|libresolv|libutil'
host_lib+='|libGL|libEGL|libGLX|libGLdispatch|libOpenGL|libGLES|libOSMesa|libgbm|libdrm'
host_lib+='|libnvidia-[a-z0-9_-]*)[.-]'
closure="$(LD_LIBRARY_PATH="$vtklibs" ldd "$program")"
if grep -q "not found" <<<"$closure"; then
  echo "make-tarball: unresolved libraries:" >&2
  grep "not found" <<<"$closure" >&2
  exit 1
fi
while read -r name _ path _; do
  [ -n "${path:-}" ] && [ -f "$path" ] || continue
  if [[ "$name" =~ $host_lib ]]; then
    continue
  fi
  case "$name" in
    libstdc++.so.*|libgcc_s.so.*) cp -L "$path" "$root/lib/compat/$name" ;;
    *) cp -L "$path" "$root/lib/$name" ;;
  esac
done <<<"$closure"
# TBB loads its scalable allocator with dlopen when it is there.
for extra in /usr/lib/x86_64-linux-gnu/libtbbmalloc.so.2; do
  [ ! -f "$extra" ] || cp -L "$extra" "$root/lib/"
done
cp "$program" "$root/libexec/vtkao"
chmod u+w "$root"/lib/*.so* "$root"/lib/compat/*
strip --strip-unneeded "$root/libexec/vtkao" "$root"/lib/*.so* "$root"/lib/compat/*
# DT_RPATH, not RUNPATH: searched before LD_LIBRARY_PATH, so a host's LD_LIBRARY_PATH (where
# container runtimes put the driver) cannot swap VTK or Embree for other builds, and it is also
# searched for the libraries' own dependencies.
patchelf --force-rpath --set-rpath '$ORIGIN/../lib' "$root/libexec/vtkao"
for lib in "$root"/lib/*.so*; do
  patchelf --force-rpath --set-rpath '$ORIGIN' "$lib"
done

cat >"$root/bin/vtkao" <<'EOF'
#!/bin/sh
# vtkao from the relocatable tarball (Documentation/gpu-tarball.md). The bundled libstdc++ and
# libgcc_s (lib/compat) are used only when the host's cannot run vtkao (missing or too old);
# otherwise the host's, which the GL driver may need at its own version.
here="$(cd "$(dirname "$0")/.." && pwd)"
if ! "$here/libexec/vtkao" --help >/dev/null 2>&1; then
  LD_LIBRARY_PATH="$here/lib/compat${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  export LD_LIBRARY_PATH
fi
exec "$here/libexec/vtkao" "$@"
EOF
cat >"$root/bin/vtkao-gpu-check" <<'EOF'
#!/bin/sh
# The GPU check of the vtkao tarball: prints the OpenGL window, vendor and renderer, then runs
# `vtkao bench --series main` and `vtkao quality --quick`, their JSON (and Markdown) in OUT_DIR.
#   vtkao-gpu-check OUT_DIR [--quick]     (--quick: the bench's quick main series, 2 frames)
# EGL unless VTK_DEFAULT_OPENGL_WINDOW says otherwise (vtkXOpenGLRenderWindow needs an X
# server; vtkOSOpenGLRenderWindow needs libOSMesa). Exit status: the first failing step's.
set -e
[ $# -ge 1 ] && [ "$1" != "-h" ] && [ "$1" != "--help" ] || {
  echo "usage: $0 OUT_DIR [--quick]" >&2
  exit 2
}
out="$1"
bench_quick=
[ "${2:-}" != "--quick" ] || bench_quick=--quick
vtkao="$(cd "$(dirname "$0")" && pwd)/vtkao"
VTK_DEFAULT_OPENGL_WINDOW="${VTK_DEFAULT_OPENGL_WINDOW:-vtkEGLRenderWindow}"
export VTK_DEFAULT_OPENGL_WINDOW
mkdir -p "$out/quality"
echo "== vtkao gl-info"
"$vtkao" gl-info | tee "$out/gl-info.txt"
echo "== vtkao bench --series main $bench_quick"
"$vtkao" bench $bench_quick --series main --output-json "$out/bench-main.json" \
  --output-md "$out/bench-main.md"
echo "== vtkao quality --quick"
"$vtkao" quality --quick --output-dir "$out/quality"
echo "== wrote $out/gl-info.txt, $out/bench-main.json, $out/quality/quality.json"
EOF
chmod 755 "$root/bin/vtkao" "$root/bin/vtkao-gpu-check"

# The newest symbol version (GLIBC_ or GLIBCXX_) the files ask for: the host's must have it.
newest() {
  local prefix="$1" f
  shift
  for f in "$@"; do objdump -T "$f" | grep -o "${prefix}_[0-9.]*" || true; done | sort -u -V |
    tail -1 | sed "s/${prefix}_//"
}
glibc="$(newest GLIBC "$root/libexec/vtkao" "$root"/lib/*.so*)"
glibc_compat="$(newest GLIBC "$root"/lib/compat/*)"
glibcxx="$(newest GLIBCXX "$root/libexec/vtkao" "$root"/lib/*.so*)"
cat >"$root/README.txt" <<EOF
vtkao (object-space ambient occlusion for VTK), built against VTK 9.5 for x86-64 Linux.
Needs from the host: glibc >= $glibc; libstdc++ with GLIBCXX_$glibcxx, or else glibc >= $glibc_compat
(then the bundled libstdc++ of lib/compat is used); a POSIX shell with dirname, mkdir and tee; and
an OpenGL driver reached through EGL (libEGL.so.1: libglvnd with the vendor's EGL, e.g.
NVIDIA's), or GLX with an X server. Nothing else: VTK 9.5, Embree, TBB, the X11 client
libraries VTK links and zlib are in lib/.

  bin/vtkao-gpu-check OUT_DIR    GL vendor/renderer, vtkao bench --series main and
                                 vtkao quality --quick, JSON in OUT_DIR
  bin/vtkao render --help        the program (render, bench, quality, bake, gl-info)

VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow forces EGL (vtkao-gpu-check sets it); with
several GPUs, VTK_DEFAULT_EGL_DEVICE_INDEX=N picks one.
EOF

mkdir -p "$(dirname "$output")"
tar -C "$stage" --owner=0 --group=0 --numeric-owner -cf - vtkao-gpu |
  xz -T"${VTKAO_JOBS:-$(nproc)}" -9 >"$output.partial"
mv "$output.partial" "$output"
echo "unpacked: $(du -sm "$root" | cut -f1) MiB in $(find "$root" -type f | wc -l) files;" \
  "needs glibc >= $glibc and GLIBCXX_$glibcxx (else glibc >= $glibc_compat: lib/compat)"
echo "wrote $output: $(du -m "$output" | cut -f1) MiB ($(stat -c %s "$output") bytes)"
