#!/usr/bin/env python3
"""Make a Linux VTK SDK (headers + CMake package) for PyPI's `vtk` wheel.

PyPI's `vtk-sdk` (the C++ headers and CMake package of the `vtk` wheels) is published there
for macOS only (9.5.0: cp310 macosx wheels); the Linux SDK wheels live on Kitware's own index,
which this project's machines cannot reach. The headers are the same source on every platform
except a few configured ones, and the wheels of one release are built from one configuration,
so this script takes the macOS SDK wheel's headers and CMake package and points them at the
Linux `vtk` wheel's shared libraries:

- every imported library `.../vtkmodules/.dylibs/libvtkX.dylib` becomes the installed wheel's
  `vtkmodules/libvtkX.so` (same names; the Linux libraries' SONAME is the file name);
- the file-existence checks of the imported targets are dropped (a handful of macOS-only
  modules have no Linux library; nothing here links them);
- `-framework Cocoa` leaves the link interfaces;
- the wheel's old libstdc++ string ABI (manylinux2014) becomes a compile definition of
  VTK::CommonCore, so every target that links VTK is compiled for it;
- the libraries named for a Python version (vtkWrappingPythonCore3.10) take this interpreter's;
- vtkRenderingOpenGLConfigure.h says what the Linux wheel was built with: X (GLX) and EGL, no
  Cocoa (OSMesa is loaded at run time and needs no define).

Checked for 9.5.0: the type sizes come from KWIML at compile time (not configured), and the SMP
backends (Sequential, STDThread) of vtkSMP.h match the Linux libraries' symbols.
Usage: vtk95-sdk.py SDK_WHEEL SITE_PACKAGES OUTPUT_DIR ; prints the VTK_DIR to use.
"""
import pathlib
import re
import sys
import zipfile


ABI_NOTE = """
# Added by vtkao's scripts/vtk95-sdk.py: the Linux vtk wheel's libraries use libstdc++'s old
# std::string ABI (manylinux2014), so code that calls them must be compiled with it.
set_property(TARGET VTK::CommonCore APPEND PROPERTY
  INTERFACE_COMPILE_DEFINITIONS "_GLIBCXX_USE_CXX11_ABI=0")
"""


def main():
    wheel, site, out = (pathlib.Path(a).resolve() for a in sys.argv[1:4])
    py = f"{sys.version_info.major}.{sys.version_info.minor}"
    libs = site / "vtkmodules"
    if not (libs / "libvtkCommonCore.so").exists():
        sys.exit(f"vtk95-sdk: {libs}/libvtkCommonCore.so not found: pip install the vtk wheel first")
    # Every file is made in memory first and written only where it differs from what is there,
    # so making the SDK again leaves a build against it up to date.
    prefix = "vtk_sdk/content/"
    with zipfile.ZipFile(wheel) as z:
        files = {n[len(prefix):]: z.read(n) for n in z.namelist()
                 if n.startswith(prefix) and "/headers/" in n and not n.endswith("/")}
    if not files:
        sys.exit(f"vtk95-sdk: {wheel} holds no headers")
    data = next(n.split("/")[0] for n in files if n.split("/")[0].endswith(".data"))
    cmake_dir = f"{data}/headers/cmake"
    conf = next(n for n in files if n.endswith("/vtkRenderingOpenGLConfigure.h"))

    dylib = re.compile(r'"\$\{_IMPORT_PREFIX\}/build/[^"]*/\.dylibs/(lib[^"/]+)\.dylib"')
    for name in files:
        if not (name.startswith(cmake_dir) and name.endswith(".cmake")):
            continue
        text = files[name].decode()
        if re.search(r"[Tt]argets-[a-z]+\.cmake$", name):
            text = dylib.sub(lambda m: f'"{libs}/{m.group(1)}.so"', text)
            text = re.sub(r'"@rpath/(lib[^"]+)\.dylib"', r'"\1.so"', text)
            # The macOS SDK is cp310's; the Linux wheel's Python-version-named libraries follow
            # this interpreter (vtkWrappingPythonCore3.11 for cp311).
            text = re.sub(r"(libvtk[A-Za-z]+)3\.[0-9]+\.so", rf"\g<1>{py}.so", text)
            text = "\n".join(l for l in text.splitlines()
                             if "_cmake_import_check_files_for_" not in l) + "\n"
        text = text.replace(";-framework Cocoa", "").replace("-framework Cocoa;", "")
        # manylinux2014 wheels use libstdc++'s old std::string ABI; whatever compiles against
        # this VTK must too (VTK::CommonCore carries the define to every target that links VTK).
        if name == f"{cmake_dir}/VTK-targets.cmake" and \
                b"St7__cxx11" not in (libs / "libvtkCommonCore.so").read_bytes():
            text += ABI_NOTE
        files[name] = text.encode()

    text = files[conf].decode()
    for old, new in (("#define VTK_USE_COCOA", "/* #undef VTK_USE_COCOA */"),
                     ("/* #undef VTK_USE_X */", "#define VTK_USE_X"),
                     ("/* #undef VTK_OPENGL_HAS_EGL */", "#define VTK_OPENGL_HAS_EGL")):
        if old not in text:
            sys.exit(f"vtk95-sdk: {conf} has no '{old}': not the 9.5 SDK this script knows")
        text = text.replace(old, new)
    files[conf] = text.encode()

    for name, content in files.items():
        target = out / name
        if target.exists() and target.read_bytes() == content:
            continue
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(content)
    print(out / cmake_dir)


if __name__ == "__main__":
    main()
