#!/usr/bin/env bash
# A relocatable vtkao for GPU servers: a tarball (at most 60 MiB) holding the program built against
# PyPI's VTK 9.5 and every shared library it needs except the OpenGL/EGL/GLX driver libraries
# (and the C library, which any Linux has), plus gpu-check.sh: it prints the GL vendor and
# renderer and runs `vtkao bench`'s main series and `vtkao quality --quick` to JSON, through EGL.
#   scripts/make-relocatable.sh [BUILD_DIR] [OUTPUT.tar.gz]   (defaults: build-95, out/vtkao-linux-x86_64.tar.gz)
# Needs glibc >= the build machine's (Debian 12: 2.36) on the target.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build-95}"
tarball="${2:-$here/out/vtkao-linux-x86_64.tar.gz}"
command -v patchelf >/dev/null || { apt-get update -qq && apt-get install -y -qq patchelf; }
[ -x "$build/build/Examples/vtkao" ] || VTKAO_BUILD_TARGET=vtkao "$here/scripts/setup-vtk95.sh" "$build"
stage="$(mktemp -d)/vtkao"
mkdir -p "$stage/bin" "$stage/lib"
cp "$build/build/Examples/vtkao" "$stage/bin/vtkao"
# Left to the target machine: its GL/EGL/GLX driver (libglvnd and the vendor's libraries), the
# C library and the dynamic loader.
skip='^(linux-vdso|ld-linux|libc\.so|libm\.so|libdl\.so|libpthread\.so|librt\.so|libresolv\.so|libGL\.so|libGLX|libGLdispatch|libEGL|libOpenGL|libgbm|libdrm|libglapi|libnvidia|libcuda)'
ldd "$stage/bin/vtkao" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}' | while read -r name path; do
  if ! [[ "$name" =~ $skip ]]; then
    cp -L "$path" "$stage/lib/$name"
  fi
done
patchelf --set-rpath '$ORIGIN/../lib' "$stage/bin/vtkao"
for lib in "$stage"/lib/*; do
  patchelf --set-rpath '$ORIGIN' "$lib"
done
strip --strip-unneeded "$stage/bin/vtkao" "$stage"/lib/* 2>/dev/null || true
cat > "$stage/gpu-check.sh" <<'CHECK'
#!/usr/bin/env bash
# GL vendor and renderer, then vtkao bench (main series) and vtkao quality --quick, as JSON in
# OUT_DIR (default ./vtkao-gpu-check). Renders through EGL (no X server needed);
# VTK_DEFAULT_OPENGL_WINDOW=vtkOSOpenGLRenderWindow or vtkXOpenGLRenderWindow chooses otherwise.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
out="${1:-$PWD/vtkao-gpu-check}"
mkdir -p "$out"
export VTK_DEFAULT_OPENGL_WINDOW="${VTK_DEFAULT_OPENGL_WINDOW:-vtkEGLRenderWindow}"
"$here/bin/vtkao" bench --series main --output-json "$out/bench.json" --output-md "$out/bench.md"
grep -o '"gl_[a-z]*": *"[^"]*"' "$out/bench.json" || true
"$here/bin/vtkao" quality --quick --no-images --output-dir "$out/quality"
echo "wrote $out/bench.json, $out/bench.md and $out/quality"
CHECK
chmod +x "$stage/gpu-check.sh"
mkdir -p "$(dirname "$tarball")"
tar -C "$(dirname "$stage")" -czf "$tarball" vtkao
size=$(stat -c %s "$tarball")
echo "$tarball: $((size / 1048576)) MiB ($(ls "$stage/lib" | wc -l) libraries)"
rm -rf "$(dirname "$stage")"
[ "$size" -le $((60 * 1048576)) ] || { echo "larger than 60 MiB" >&2; exit 1; }
