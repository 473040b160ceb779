// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkAOCompat.h
 * @brief  The VTK API differences between the versions this tree builds against, in one place.
 *
 * VTK 9.1 (Debian 12), 9.2 (ParaView 5.11) and 9.5 (PyPI). The OpenGL loader (glew before 9.4,
 * glad since) is the other half, in vtkAOGL.h.
 */
#ifndef vtkAOCompat_h
#define vtkAOCompat_h

#include "vtkPolygon.h"
#include "vtkVersionMacros.h"

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
#include "vtkCompositePolyDataMapper.h" // IWYU pragma: export
/// The OpenGL composite-dataset mapper: vtkCompositePolyDataMapper2 was folded into
/// vtkCompositePolyDataMapper in VTK 9.3 and removed in 9.4.
using vtkAOCompositePolyDataMapper = vtkCompositePolyDataMapper;
#else
#include "vtkCompositePolyDataMapper2.h" // IWYU pragma: export
using vtkAOCompositePolyDataMapper = vtkCompositePolyDataMapper2;
#endif

/// Ear-cut triangulation of an initialized vtkPolygon as indices into its own points, three per
/// triangle (VTK 9.4 replaced Triangulate(vtkIdList*) by TriangulateLocalIds(int, vtkIdList*)).
inline int vtkAOTriangulatePolygon(vtkPolygon* polygon, vtkIdList* localIds)
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
  return polygon->TriangulateLocalIds(0, localIds);
#else
  return polygon->Triangulate(localIds);
#endif
}

#endif
// VTK-HeaderTest-Exclude: vtkAOCompat.h
