// vtkao._vtkao: the Hybrid Ambient Occlusion pass for PyPI's `vtk` (and PyVista) in one process.
//
// VTK's Python wrapping tools ship only in Kitware's SDK wheels (on PyPI for macOS only), so
// this small extension is written by hand against the wheel's own vtkWrappingPythonCore: it
// takes and returns the very Python objects of `vtkmodules` (vtkPythonUtil), so a pass made
// here goes on a renderer made by vtkmodules or PyVista, and they share one VTK in memory.
// The pass comes back as a vtkmodules object of its nearest wrapped base class
// (vtkImageProcessingPass); its parameters are read and set through this module.
#include "vtkPython.h" // first: Python.h

#include "vtkHybridAmbientOcclusionPass.h"
#include "vtkPythonUtil.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkVersion.h"

#include <cstring>
#include <string>

namespace
{
struct Parameter
{
  const char* Name;
  char Kind; // 'd' double, 'i' int, 'b' bool
};

// The user parameters of vtkHybridAmbientOcclusionPass (the header gives ranges and defaults).
const Parameter Parameters[] = {
  { "radius", 'd' },
  { "bias", 'd' },
  { "spread", 'd' },
  { "intensity", 'd' },
  { "cell_erosion", 'd' },
  { "refinement_contrast", 'd' },
  { "cells_per_radius", 'd' },
  { "number_of_rays", 'i' },
  { "number_of_steps", 'i' },
  { "voxel_resolution", 'i' },
  { "ao_scale", 'i' },
  { "filter_size", 'i' },
  { "falloff", 'i' },
  { "region_mode", 'i' },
  { "voxelization_axes", 'i' },
  { "maximum_accumulated_frames", 'i' },
  { "refinement_rays", 'i' },
  { "refinement_filter_radius", 'i' },
  { "filter", 'b' },
  { "refinement", 'b' },
  { "refinement_list", 'b' },
  { "accumulation", 'b' },
  { "ao_only", 'b' },
};

// The presets of ApplyPreset, by name (the `preset` keyword, applied before the others).
const char* const Presets[] = { "interactive", "balanced", "quality" };

PyObject* Get(vtkHybridAmbientOcclusionPass* p, const std::string& n)
{
  if (n == "radius")
    return PyFloat_FromDouble(p->GetRadius());
  if (n == "bias")
    return PyFloat_FromDouble(p->GetBias());
  if (n == "spread")
    return PyFloat_FromDouble(p->GetSpread());
  if (n == "intensity")
    return PyFloat_FromDouble(p->GetIntensity());
  if (n == "cell_erosion")
    return PyFloat_FromDouble(p->GetCellErosion());
  if (n == "refinement_contrast")
    return PyFloat_FromDouble(p->GetRefinementContrast());
  if (n == "cells_per_radius")
    return PyFloat_FromDouble(p->GetCellsPerRadius());
  if (n == "number_of_rays")
    return PyLong_FromLong(p->GetNumberOfRays());
  if (n == "number_of_steps")
    return PyLong_FromLong(p->GetNumberOfSteps());
  if (n == "voxel_resolution")
    return PyLong_FromLong(p->GetVoxelResolution());
  if (n == "ao_scale")
    return PyLong_FromLong(p->GetAOScale());
  if (n == "filter_size")
    return PyLong_FromLong(p->GetFilterSize());
  if (n == "falloff")
    return PyLong_FromLong(p->GetFalloff());
  if (n == "region_mode")
    return PyLong_FromLong(p->GetRegionMode());
  if (n == "voxelization_axes")
    return PyLong_FromLong(p->GetVoxelizationAxes());
  if (n == "maximum_accumulated_frames")
    return PyLong_FromLong(p->GetMaximumAccumulatedFrames());
  if (n == "refinement_rays")
    return PyLong_FromLong(p->GetRefinementRays());
  if (n == "refinement_filter_radius")
    return PyLong_FromLong(p->GetRefinementFilterRadius());
  if (n == "filter")
    return PyBool_FromLong(p->GetFilter());
  if (n == "refinement")
    return PyBool_FromLong(p->GetRefinement());
  if (n == "refinement_list")
    return PyBool_FromLong(p->GetRefinementList());
  if (n == "accumulation")
    return PyBool_FromLong(p->GetAccumulation());
  return PyBool_FromLong(p->GetAOOnly()); // "ao_only"
}

bool Set(vtkHybridAmbientOcclusionPass* p, const Parameter& parameter, PyObject* value)
{
  const std::string n = parameter.Name;
  if (parameter.Kind == 'd')
  {
    const double v = PyFloat_AsDouble(value);
    if (v == -1.0 && PyErr_Occurred())
      return false;
    if (n == "radius")
      p->SetRadius(v);
    else if (n == "bias")
      p->SetBias(v);
    else if (n == "spread")
      p->SetSpread(v);
    else if (n == "cell_erosion")
      p->SetCellErosion(v);
    else if (n == "refinement_contrast")
      p->SetRefinementContrast(v);
    else if (n == "cells_per_radius")
      p->SetCellsPerRadius(v);
    else
      p->SetIntensity(v);
    return true;
  }
  if (parameter.Kind == 'i')
  {
    const long v = PyLong_AsLong(value);
    if (v == -1 && PyErr_Occurred())
      return false;
    const int i = static_cast<int>(v);
    if (n == "number_of_rays")
      p->SetNumberOfRays(i);
    else if (n == "number_of_steps")
      p->SetNumberOfSteps(i);
    else if (n == "voxel_resolution")
      p->SetVoxelResolution(i);
    else if (n == "ao_scale")
      p->SetAOScale(i);
    else if (n == "filter_size")
      p->SetFilterSize(i);
    else if (n == "falloff")
      p->SetFalloff(i);
    else if (n == "voxelization_axes")
      p->SetVoxelizationAxes(i);
    else if (n == "maximum_accumulated_frames")
      p->SetMaximumAccumulatedFrames(i);
    else if (n == "refinement_rays")
      p->SetRefinementRays(i);
    else if (n == "refinement_filter_radius")
      p->SetRefinementFilterRadius(i);
    else
      p->SetRegionMode(i);
    return true;
  }
  const int truth = PyObject_IsTrue(value);
  if (truth < 0)
    return false;
  if (n == "filter")
    p->SetFilter(truth != 0);
  else if (n == "refinement")
    p->SetRefinement(truth != 0);
  else if (n == "refinement_list")
    p->SetRefinementList(truth != 0);
  else if (n == "accumulation")
    p->SetAccumulation(truth != 0);
  else
    p->SetAOOnly(truth != 0);
  return true;
}

// The `preset` keyword of @p kwargs, if any, on @p pass; false (with a Python error) for an
// unknown one.
bool ApplyPresetKeyword(vtkHybridAmbientOcclusionPass* pass, PyObject* kwargs)
{
  PyObject* value = PyDict_GetItemString(kwargs, "preset"); // borrowed
  if (!value)
    return true;
  const char* name = PyUnicode_Check(value) ? PyUnicode_AsUTF8(value) : nullptr;
  for (int i = 0; name && i < 3; ++i)
  {
    if (std::strcmp(name, Presets[i]) == 0)
    {
      pass->ApplyPreset(vtkHybridAmbientOcclusionPass::INTERACTIVE + i);
      return true;
    }
  }
  PyErr_SetString(PyExc_ValueError, "preset: expected 'interactive', 'balanced' or 'quality'");
  return false;
}

vtkHybridAmbientOcclusionPass* PassFrom(PyObject* object)
{
  vtkObjectBase* base = vtkPythonUtil::GetPointerFromObject(object, "vtkRenderPass");
  auto* pass = vtkHybridAmbientOcclusionPass::SafeDownCast(base);
  if (!pass && !PyErr_Occurred())
  {
    PyErr_SetString(PyExc_TypeError, "expected a pass made by vtkao.hybrid_ambient_occlusion_pass");
  }
  return pass;
}

bool ApplyKeywords(vtkHybridAmbientOcclusionPass* pass, PyObject* kwargs)
{
  if (!kwargs)
    return true;
  if (!ApplyPresetKeyword(pass, kwargs)) // first: the other keywords override it
    return false;
  PyObject *key, *value;
  Py_ssize_t position = 0;
  while (PyDict_Next(kwargs, &position, &key, &value))
  {
    const char* name = PyUnicode_AsUTF8(key);
    if (!name)
      return false;
    if (std::strcmp(name, "preset") == 0)
      continue;
    const Parameter* found = nullptr;
    for (const Parameter& parameter : Parameters)
    {
      if (std::strcmp(parameter.Name, name) == 0)
        found = &parameter;
    }
    if (!found)
    {
      PyErr_Format(PyExc_TypeError, "unknown HAO parameter '%s'", name);
      return false;
    }
    if (!Set(pass, *found, value))
      return false;
  }
  return true;
}

PyObject* NewPass(PyObject*, PyObject* args, PyObject* kwargs)
{
  if (!PyArg_ParseTuple(args, ":hybrid_ambient_occlusion_pass"))
    return nullptr;
  vtkHybridAmbientOcclusionPass* pass = vtkHybridAmbientOcclusionPass::New();
  vtkRenderStepsPass* steps = vtkRenderStepsPass::New();
  pass->SetDelegatePass(steps);
  steps->Delete();
  if (!ApplyKeywords(pass, kwargs))
  {
    pass->Delete();
    return nullptr;
  }
  PyObject* object = vtkPythonUtil::GetObjectFromPointer(pass);
  pass->Delete(); // the Python object holds the reference now
  return object;
}

PyObject* SetParameters(PyObject*, PyObject* args, PyObject* kwargs)
{
  PyObject* object = nullptr;
  if (!PyArg_ParseTuple(args, "O:set_parameters", &object))
    return nullptr;
  vtkHybridAmbientOcclusionPass* pass = PassFrom(object);
  if (!pass || !ApplyKeywords(pass, kwargs))
    return nullptr;
  Py_RETURN_NONE;
}

PyObject* GetParameters(PyObject*, PyObject* args)
{
  PyObject* object = nullptr;
  if (!PyArg_ParseTuple(args, "O:get_parameters", &object))
    return nullptr;
  vtkHybridAmbientOcclusionPass* pass = PassFrom(object);
  if (!pass)
    return nullptr;
  PyObject* dict = PyDict_New();
  for (const Parameter& parameter : Parameters)
  {
    PyObject* value = Get(pass, parameter.Name);
    PyDict_SetItemString(dict, parameter.Name, value);
    Py_DECREF(value);
  }
  return dict;
}

PyObject* IsHAOPass(PyObject*, PyObject* args)
{
  PyObject* object = nullptr;
  if (!PyArg_ParseTuple(args, "O:is_hao_pass", &object))
    return nullptr;
  vtkObjectBase* base = vtkPythonUtil::GetPointerFromObject(object, "vtkObjectBase");
  if (!base)
  {
    PyErr_Clear();
    Py_RETURN_FALSE;
  }
  return PyBool_FromLong(vtkHybridAmbientOcclusionPass::SafeDownCast(base) != nullptr);
}

PyObject* BuiltWithVTK(PyObject*, PyObject*)
{
  return PyUnicode_FromString(VTK_VERSION);
}

PyMethodDef Methods[] = {
  { "hybrid_ambient_occlusion_pass",
    reinterpret_cast<PyCFunction>(NewPass),
    METH_VARARGS | METH_KEYWORDS,
    "hybrid_ambient_occlusion_pass(**parameters) -> a vtkHybridAmbientOcclusionPass (seen from "
    "Python as its base vtkImageProcessingPass) delegating to a vtkRenderStepsPass" },
  { "set_parameters",
    reinterpret_cast<PyCFunction>(SetParameters),
    METH_VARARGS | METH_KEYWORDS,
    "set_parameters(pass, **parameters): preset ('interactive', 'balanced', 'quality'; applied "
    "first), radius, bias, spread, intensity, cell_erosion, number_of_rays, number_of_steps, "
    "voxel_resolution, ao_scale, filter_size, falloff, region_mode, voxelization_axes, "
    "maximum_accumulated_frames, refinement_rays, refinement_filter_radius, refinement_contrast, "
    "cells_per_radius, filter, refinement, refinement_list, "
    "accumulation, ao_only" },
  { "get_parameters", GetParameters, METH_VARARGS, "get_parameters(pass) -> dict" },
  { "is_hao_pass", IsHAOPass, METH_VARARGS, "is_hao_pass(object) -> bool" },
  { "built_with_vtk", BuiltWithVTK, METH_NOARGS, "the VTK version this module was built against" },
  { nullptr, nullptr, 0, nullptr },
};

PyModuleDef Module = { PyModuleDef_HEAD_INIT,
  "_vtkao",
  "Hybrid Ambient Occlusion for PyPI's vtk (see the package vtkao)",
  -1,
  Methods,
  nullptr,
  nullptr,
  nullptr,
  nullptr };
}

PyMODINIT_FUNC PyInit__vtkao()
{
  return PyModule_Create(&Module);
}
