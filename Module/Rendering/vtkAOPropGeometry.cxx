#include "vtkAOPropGeometry.h"

#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkAssembly.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkBillboardTextActor3D.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkGeometryFilter.h"
#include "vtkGlyph3DMapper.h"
#include "vtkInformation.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProp3D.h"
#include "vtkPropAssembly.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor3D.h"
#include "vtkTransform.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace
{
bool ValidBounds(const double b[6])
{
  for (int i = 0; i < 6; ++i)
  {
    if (!std::isfinite(b[i]))
    {
      return false;
    }
  }
  return b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5];
}

// The array the glyph mapper uses for @p which (SCALE, ORIENTATION, ...), or null.
vtkDataArray* GlyphArray(vtkGlyph3DMapper* mapper, int which, vtkDataSet* points)
{
  vtkInformation* info = mapper->GetInputArrayInformation(which);
  if (!info)
  {
    return nullptr;
  }
  if (info->Has(vtkDataObject::FIELD_NAME()))
  {
    return points->GetPointData()->GetArray(info->Get(vtkDataObject::FIELD_NAME()));
  }
  if (info->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
  {
    return points->GetPointData()->GetAttribute(info->Get(vtkDataObject::FIELD_ATTRIBUTE_TYPE()));
  }
  return nullptr;
}

// Rotation of glyph @p i's orientation tuple @p o into @p glyph (post-multiplied).
void Orient(vtkGlyph3DMapper* mapper, const double o[4], vtkTransform* glyph)
{
  switch (mapper->GetOrientationMode())
  {
    case vtkGlyph3DMapper::ROTATION:
      glyph->RotateZ(o[2]);
      glyph->RotateX(o[0]);
      glyph->RotateY(o[1]);
      break;
    case vtkGlyph3DMapper::QUATERNION:
    {
      double rotation[3][3];
      vtkMath::QuaternionToMatrix3x3(o, rotation);
      vtkNew<vtkMatrix4x4> m;
      for (int r = 0; r < 3; ++r)
      {
        for (int c = 0; c < 3; ++c)
        {
          m->SetElement(r, c, rotation[r][c]);
        }
      }
      glyph->Concatenate(m);
      break;
    }
    default: // DIRECTION: the source's x axis turned onto the vector (half-way axis, 180 deg)
    {
      const double length = vtkMath::Norm(o);
      if (length <= 0.0)
      {
        break;
      }
      if (o[1] == 0.0 && o[2] == 0.0)
      {
        if (o[0] < 0.0)
        {
          glyph->RotateWXYZ(180.0, 0, 1, 0);
        }
      }
      else
      {
        glyph->RotateWXYZ(180.0, 0.5 * (o[0] + length), 0.5 * o[1], 0.5 * o[2]);
      }
    }
  }
}

// Scale of glyph @p i; false for a zero-size glyph (the mapper draws nothing).
bool GlyphScale(vtkGlyph3DMapper* mapper, vtkDataArray* scaleArray, vtkIdType i, double s[3])
{
  s[0] = s[1] = s[2] = 1.0;
  if (scaleArray && mapper->GetScaleMode() != vtkGlyph3DMapper::NO_DATA_SCALING)
  {
    double tuple[9] = { 0 };
    const int components = std::min(9, scaleArray->GetNumberOfComponents());
    scaleArray->GetTuple(i, tuple);
    if (mapper->GetScaleMode() == vtkGlyph3DMapper::SCALE_BY_COMPONENTS && components == 3)
    {
      std::copy(tuple, tuple + 3, s);
    }
    else
    {
      double norm = 0.0;
      for (int c = 0; c < components; ++c)
      {
        norm += tuple[c] * tuple[c];
      }
      s[0] = s[1] = s[2] = std::sqrt(norm);
    }
    if (mapper->GetClamping())
    {
      const double* range = mapper->GetRange();
      const double span = range[1] != range[0] ? range[1] - range[0] : 1.0;
      for (int c = 0; c < 3; ++c)
      {
        s[c] = (std::min(std::max(s[c], range[0]), range[1]) - range[0]) / span;
      }
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    s[c] *= mapper->GetScaleFactor();
  }
  return s[0] != 0.0 || s[1] != 0.0 || s[2] != 0.0;
}

void VisitGlyphs(vtkGlyph3DMapper* mapper,
  vtkActor* actor,
  vtkMatrix4x4* matrix,
  int group,
  const vtkAOPropGeometry::Visitor& visit)
{
  vtkDataSet* input = vtkDataSet::SafeDownCast(mapper->GetInputDataObject(0, 0));
  if (!input || input->GetNumberOfPoints() == 0)
  {
    return;
  }
  vtkDataArray* scaleArray = GlyphArray(mapper, vtkGlyph3DMapper::SCALE, input);
  vtkDataArray* orientArray = GlyphArray(mapper, vtkGlyph3DMapper::ORIENTATION, input);
  vtkDataArray* indexArray = GlyphArray(mapper, vtkGlyph3DMapper::SOURCE_INDEX, input);
  vtkDataArray* maskArray = GlyphArray(mapper, vtkGlyph3DMapper::MASK, input);
  const int sources = std::max(1, mapper->GetNumberOfInputConnections(1));
  vtkNew<vtkTransform> glyph;
  vtkNew<vtkMatrix4x4> combined;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    if (mapper->GetMasking() && maskArray && maskArray->GetComponent(i, 0) == 0.0)
    {
      continue;
    }
    int index = 0;
    if (mapper->GetSourceIndexing() && indexArray)
    {
      index = static_cast<int>(indexArray->GetComponent(i, 0)) % sources;
      index = index < 0 ? index + sources : index;
    }
    vtkPolyData* source = mapper->GetSource(index);
    if (!source)
    {
      continue;
    }
    // M = T R S: scale, then orient, then move to the point (as the mapper draws them).
    double x[3];
    input->GetPoint(i, x);
    glyph->Identity();
    glyph->PreMultiply();
    glyph->Translate(x);
    if (mapper->GetOrient() && orientArray)
    {
      double o[4] = { 0, 0, 0, 0 };
      orientArray->GetTuple(i, o);
      Orient(mapper, o, glyph);
    }
    if (mapper->GetScaling())
    {
      double s[3];
      if (!GlyphScale(mapper, scaleArray, i, s))
      {
        continue;
      }
      glyph->Scale(s);
    }
    vtkMatrix4x4::Multiply4x4(matrix, glyph->GetMatrix(), combined);
    visit({ source, combined, actor, group });
  }
}

void VisitDataObject(vtkDataObject* data,
  vtkActor* actor,
  vtkMatrix4x4* matrix,
  int group,
  const vtkAOPropGeometry::Visitor& visit)
{
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    auto it = vtk::TakeSmartPointer(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      VisitDataObject(it->GetCurrentDataObject(), actor, matrix, group, visit);
    }
    return;
  }
  vtkSmartPointer<vtkPolyData> surface = vtkPolyData::SafeDownCast(data);
  if (!surface && vtkDataSet::SafeDownCast(data))
  {
    vtkNew<vtkGeometryFilter> geometry;
    geometry->SetInputData(data);
    geometry->Update();
    surface = geometry->GetOutput();
  }
  if (surface && surface->GetNumberOfPoints() > 0)
  {
    visit({ surface, matrix, actor, group });
  }
}

// Calls @p f(actor, matrix) for the actor or each visible part of the assembly @p prop.
template<typename F>
void ForEachPart(vtkProp* prop, bool translucent, F&& f)
{
  if (auto* assembly = vtkAssembly::SafeDownCast(prop))
  {
    assembly->InitPathTraversal();
    while (vtkAssemblyPath* path = assembly->GetNextPath())
    {
      vtkAssemblyNode* node = path->GetLastNode();
      auto* part = vtkActor::SafeDownCast(node->GetViewProp());
      if (part && part->GetVisibility() && (translucent || part->HasOpaqueGeometry()))
      {
        f(part, node->GetMatrix() ? node->GetMatrix() : part->GetMatrix());
      }
    }
  }
  else if (auto* actor = vtkActor::SafeDownCast(prop))
  {
    f(actor, actor->GetMatrix());
  }
}

void VisitActor(vtkActor* actor,
  vtkMatrix4x4* matrix,
  int& group,
  const vtkAOPropGeometry::Visitor& visit)
{
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  if (!mapper)
  {
    return;
  }
  actor->GetBounds(); // brings the mapper's input up to date
  const int id = group++;
  if (auto* glyphs = vtkGlyph3DMapper::SafeDownCast(mapper))
  {
    VisitGlyphs(glyphs, actor, matrix, id, visit);
  }
  else if (mapper->GetNumberOfInputPorts() > 0 && mapper->GetNumberOfInputConnections(0) > 0)
  {
    VisitDataObject(mapper->GetInputDataObject(0, 0), actor, matrix, id, visit);
  }
}
}

//------------------------------------------------------------------------------
bool vtkAOPropGeometry::Occludes(vtkProp* prop, bool translucent, double bounds[6])
{
  // An actor without a mapper (vtkFlagpoleLabel, vtkCubeAxesActor) draws annotation through
  // internal actors: no surface of it occludes (IsOverlay).
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (!prop || !prop->GetVisibility() ||
    (actor ? !actor->GetMapper() : !vtkAssembly::SafeDownCast(prop)))
  {
    return false;
  }
  const double* b = prop->GetBounds();
  if (!b || !ValidBounds(b) || (!translucent && !prop->HasOpaqueGeometry()))
  {
    return false;
  }
  if (bounds)
  {
    std::copy(b, b + 6, bounds);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOPropGeometry::CollectOccluders(vtkRenderer* renderer,
  bool translucent,
  std::vector<vtkProp*>& props,
  double bounds[6])
{
  bounds[0] = bounds[2] = bounds[4] = VTK_DOUBLE_MAX;
  bounds[1] = bounds[3] = bounds[5] = VTK_DOUBLE_MIN;
  vtkPropCollection* viewProps = renderer ? renderer->GetViewProps() : nullptr;
  if (!viewProps)
  {
    return false;
  }
  bool nonFinite = false;
  vtkCollectionSimpleIterator it;
  viewProps->InitTraversal(it);
  while (vtkProp* prop = viewProps->GetNextProp(it))
  {
    double b[6];
    if (Occludes(prop, translucent, b))
    {
      props.push_back(prop);
      for (int i = 0; i < 3; ++i)
      {
        bounds[2 * i] = std::min(bounds[2 * i], b[2 * i]);
        bounds[2 * i + 1] = std::max(bounds[2 * i + 1], b[2 * i + 1]);
      }
    }
    else if (prop->GetVisibility() &&
      (vtkActor::SafeDownCast(prop) || vtkAssembly::SafeDownCast(prop)))
    {
      // Empty data has uninitialized (inverted, finite) bounds; NaN or infinite ones are a defect.
      const double* pb = prop->GetBounds();
      nonFinite = nonFinite || (pb && !(std::isfinite(pb[0]) && std::isfinite(pb[1])));
    }
  }
  return nonFinite;
}

//------------------------------------------------------------------------------
bool vtkAOPropGeometry::VisitProp(vtkProp* prop, bool translucent, int& group, const Visitor& visit)
{
  if (!Occludes(prop, translucent))
  {
    return false;
  }
  ForEachPart(prop,
    translucent,
    [&](vtkActor* actor, vtkMatrix4x4* matrix) { VisitActor(actor, matrix, group, visit); });
  return true;
}

//------------------------------------------------------------------------------
void vtkAOPropGeometry::AppendSignature(vtkProp* prop, std::vector<double>& signature)
{
  ForEachPart(prop,
    false,
    [&signature](vtkActor* actor, vtkMatrix4x4* matrix)
    {
      signature.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(actor)));
      const double* m = &matrix->Element[0][0];
      signature.insert(signature.end(), m, m + 16);
      vtkMapper* mapper = actor->GetMapper();
      signature.push_back(mapper ? static_cast<double>(mapper->GetMTime()) : 0.0);
      for (int port = 0; mapper && port < mapper->GetNumberOfInputPorts(); ++port)
      {
        for (int c = 0; c < mapper->GetNumberOfInputConnections(port); ++c)
        {
          vtkDataObject* input = mapper->GetInputDataObject(port, c);
          signature.push_back(input ? static_cast<double>(input->GetMTime()) : 0.0);
        }
      }
    });
}

//------------------------------------------------------------------------------
int vtkAOPropGeometry::VisitRenderer(vtkRenderer* renderer, bool translucent, const Visitor& visit)
{
  vtkPropCollection* props = renderer ? renderer->GetViewProps() : nullptr;
  if (!props)
  {
    return 0;
  }
  int used = 0;
  int group = 0;
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    used += VisitProp(prop, translucent, group, visit) ? 1 : 0;
  }
  return used;
}

//------------------------------------------------------------------------------
bool vtkAOPropGeometry::IsOverlay(vtkProp* prop)
{
  if (!prop)
  {
    return false;
  }
  if (vtkActor2D::SafeDownCast(prop))
  {
    return true;
  }
  if (!vtkProp3D::SafeDownCast(prop))
  {
    return !vtkPropAssembly::SafeDownCast(prop); // widget representations
  }
  // Annotation placed in 3-D: text on a textured quad, and actors without a mapper, which draw
  // through internal actors of their own (flagpole labels, cube and polar axes).
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  return vtkBillboardTextActor3D::SafeDownCast(prop) || vtkTextActor3D::SafeDownCast(prop) ||
    (actor && !actor->GetMapper());
}
