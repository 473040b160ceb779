# The CMake half of the OpenGL-loader choice (the C++ half is Module/Rendering/vtkAOGL.h):
# VTK <= 9.3 ships VTK::glew, VTK >= 9.4 VTK::glad. A vtk.module file cannot say "one or the
# other", so the modules name neither there and link the one this VTK has here.
# vtkao_gl_loader_component: the find_package(VTK) component name (glew or glad).
# vtkao_link_gl_loader(<module>): links the module privately to the loader.
if (DEFINED VTK_VERSION AND VTK_VERSION VERSION_GREATER_EQUAL "9.4")
  set(vtkao_gl_loader_component glad)
elseif (TARGET VTK::glad)
  set(vtkao_gl_loader_component glad)
else ()
  set(vtkao_gl_loader_component glew)
endif ()

function (vtkao_link_gl_loader module)
  vtk_module_link("${module}" PRIVATE "VTK::${vtkao_gl_loader_component}")
endfunction ()
