// Helpers shared by the libFuzzer targets of the vtkao program (Testing/Fuzz/CMakeLists.txt).
#ifndef vtkaoFuzzCommon_h
#define vtkaoFuzzCommon_h

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <string>
#include <unistd.h>
#include <vector>

namespace vtkaoFuzz
{
/// Report a finding that is not a crash by itself (a wrong exception type, a message that
/// breaks the one-line contract, an inconsistency) as a crash, so libFuzzer saves the input.
[[noreturn]] inline void Fail(const std::string& what)
{
  std::fprintf(stderr, "vtkao fuzz finding: %s\n", what.c_str());
  std::abort();
}

/// A fresh private directory under $TMPDIR (or /tmp), created once per process.
inline const std::string& ScratchDirectory()
{
  static const std::string dir = []
  {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/vtkao-fuzz-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (!mkdtemp(buffer.data()))
    {
      std::perror("vtkao fuzz: mkdtemp");
      std::abort();
    }
    return std::string(buffer.data());
  }();
  return dir;
}

/// Remove every file in @p dir (not recursive: the targets only create plain files).
inline void EmptyDirectory(const std::string& dir)
{
  if (DIR* d = opendir(dir.c_str()))
  {
    std::vector<std::string> names;
    while (dirent* e = readdir(d))
    {
      if (std::strcmp(e->d_name, ".") != 0 && std::strcmp(e->d_name, "..") != 0)
      {
        names.push_back(dir + "/" + e->d_name);
      }
    }
    closedir(d);
    for (const auto& n : names)
    {
      unlink(n.c_str());
    }
  }
}

/// The input as a command line: arguments separated by NUL bytes.
inline std::vector<std::string> Arguments(const uint8_t* data, size_t size)
{
  std::vector<std::string> args(1);
  for (size_t i = 0; i < size; ++i)
  {
    if (data[i] == 0)
    {
      args.emplace_back();
    }
    else
    {
      args.back().push_back(static_cast<char>(data[i]));
    }
  }
  if (size == 0)
  {
    args.clear();
  }
  return args;
}

/// argv-style pointers into @p args (which must outlive them), NULL-terminated.
inline std::vector<char*> Argv(std::vector<std::string>& args)
{
  std::vector<char*> argv;
  for (auto& a : args)
  {
    argv.push_back(&a[0]);
  }
  argv.push_back(nullptr);
  return argv;
}

/// Whether any argument contains @p c.
inline bool AnyContains(const std::vector<std::string>& args, char c)
{
  for (const auto& a : args)
  {
    if (a.find(c) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

/// The program's error contract: a non-empty message on one line (unless an argument that the
/// message quotes has a line break itself).
inline void CheckMessage(const char* what, const std::string& message, bool argumentsHaveNewline)
{
  if (message.empty())
  {
    Fail(std::string(what) + ": empty error message");
  }
  if (!argumentsHaveNewline && message.find('\n') != std::string::npos)
  {
    Fail(std::string(what) + ": error message on more than one line: " + message);
  }
}
}

#endif
