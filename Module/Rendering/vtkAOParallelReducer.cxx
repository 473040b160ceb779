#include "vtkAOParallelReducer.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkAOParallelReducer);

//------------------------------------------------------------------------------
void vtkAOParallelReducer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
void vtkAOParallelReducer::ReduceBounds(double*) {}

//------------------------------------------------------------------------------
bool vtkAOParallelReducer::ReduceAny(bool local)
{
  return local;
}

//------------------------------------------------------------------------------
bool vtkAOParallelReducer::ReduceGrid(vtkAOBitmaskVoxelizer*)
{
  return true;
}
