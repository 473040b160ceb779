#!/usr/bin/env bash
# Runs a command on the VTK 9.5 build with no X server: VTK 9.5 makes its OpenGL context through
# EGL (Mesa's software device on a machine without a GPU, the vendor's EGL on a GPU server) or
# OSMesa (Debian's libosmesa6), chosen here, not by whatever DISPLAY happens to be set.
#   scripts/run-headless.sh egl|osmesa COMMAND [ARG ...]
set -euo pipefail
case "${1:-}" in
  egl) window=vtkEGLRenderWindow ;;
  osmesa) window=vtkOSOpenGLRenderWindow ;;
  *) echo "usage: $0 egl|osmesa COMMAND [ARG ...]" >&2; exit 2 ;;
esac
shift
exec env -u DISPLAY -u WAYLAND_DISPLAY VTK_DEFAULT_OPENGL_WINDOW="$window" "$@"
