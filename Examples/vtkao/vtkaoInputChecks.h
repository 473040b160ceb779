// Checks of the vtkao program's input files against what VTK 9.1's readers and importers crash
// on (found by fuzzing: Testing/Fuzz, Documentation/reliability.md). vtkao::AddFile runs them
// before (and DataSetProblem after) a reader sees a file. Each returns the problem as a phrase
// for the one-line error message, empty if there is none. None rejects a file the reader reads
// correctly: each check is the reader's own parse rule, applied without the reader's bug.
#ifndef vtkaoInputChecks_h
#define vtkaoInputChecks_h

#include <functional>
#include <string>

class vtkDataSet;

namespace vtkao
{
/// A binary STL header declaring far more triangles than the file holds (VTK allocates them).
std::string BinarySTLProblem(const std::string& path);

/// OBJ face, line and point indices naming no vertex, texture coordinate or normal; NUL bytes.
std::string OBJProblem(const std::string& path);

/// MTL statements before any `newmtl`, colours of more than 3 numbers; NUL bytes.
std::string MTLProblem(const std::string& path);

/// PLY headers and bodies that do not match (ASCII or binary), face indices naming no vertex.
std::string PLYProblem(const std::string& path);

/// glTF/GLB (@p binary) documents whose indices, accessors, views or buffers do not fit.
std::string GLTFProblem(const std::string& path, bool binary);

/// What a reader or importer produced that VTK's filters would index out of bounds with:
/// inconsistent cells, point ids out of range, short attribute arrays.
std::string DataSetProblem(vtkDataSet* data);

/// Run @p read (a reader's Update on the file) in a child process first, where a crash of the
/// reader cannot take the program down: VTK 9.1's legacy and XML readers crash inside
/// themselves on some malformed files, where a check in front would re-implement the format.
/// Returns a problem if the child died (by a signal or a sanitizer's exit), empty if it
/// finished, or if there is no fork() (not POSIX), it failed, the child ran for over a minute,
/// or (under AddressSanitizer, whose allocator is not fork-safe) the process has more than one
/// thread: then only the caller's read runs, as before.
std::string ReaderCrashProblem(const std::function<void()>& read);
}

#endif
