// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkAOGL.h
 * @brief  The one place that hides which OpenGL loader VTK ships.
 *
 * VTK <= 9.3 loads OpenGL through glew (module VTK::glew, header vtk_glew.h); VTK >= 9.4
 * through glad (VTK::glad, vtk_glad.h). Sources and tests that call OpenGL directly include
 * this header instead of either; the CMake side of the same choice is
 * CMake/vtkaoGLLoader.cmake. Other API differences between the VTK versions this tree builds
 * against (9.1 Debian, 9.2 ParaView 5.11, 9.5 PyPI) go here too.
 */
#ifndef vtkAOGL_h
#define vtkAOGL_h

#include "vtkVersionMacros.h"

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
#include "vtk_glad.h" // IWYU pragma: export
#define VTKAO_GL_LOADER_GLAD 1
#else
#include "vtk_glew.h" // IWYU pragma: export
#define VTKAO_GL_LOADER_GLAD 0
#endif

#endif
// VTK-HeaderTest-Exclude: vtkAOGL.h
