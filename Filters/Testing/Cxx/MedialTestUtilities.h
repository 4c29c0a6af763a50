// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the filter tests: error capture, array access, shared-mesh lookup.
#ifndef MedialTestUtilities_h
#define MedialTestUtilities_h

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace medialtest
{
/// Counts error and warning events of the objects it watches, keeping the texts.
struct EventLog
{
  int Errors = 0;
  int Warnings = 0;
  std::string Text;
  vtkNew<vtkCallbackCommand> Command;
  EventLog()
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject*, unsigned long event, void* client, void* data) {
      auto* self = static_cast<EventLog*>(client);
      (event == vtkCommand::ErrorEvent ? self->Errors : self->Warnings)++;
      self->Text += data ? static_cast<const char*>(data) : "";
    });
  }
  void Watch(vtkObject* o)
  {
    o->AddObserver(vtkCommand::ErrorEvent, this->Command);
    o->AddObserver(vtkCommand::WarningEvent, this->Command);
  }
};

inline double Value(vtkPolyData* pd, const char* name, vtkIdType i, int c = 0)
{
  return pd->GetPointData()->GetArray(name)->GetComponent(i, c);
}

inline double FieldValue(vtkPolyData* pd, const char* name)
{
  vtkDataArray* a = pd->GetFieldData()->GetArray(name);
  return a ? a->GetComponent(0, 0) : std::nan("");
}

inline double Diagonal(vtkPolyData* pd)
{
  return pd->GetLength();
}

/// Full path of a shared mesh, or empty when ../shared is absent.
inline std::string SharedMesh(const char* name)
{
  const std::string path = std::string(MEDIALAXIS_SHARED_MESH_DIR) + "/" + name;
  struct stat st;
  return stat(path.c_str(), &st) == 0 ? path : std::string();
}

inline double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return std::nan("");
  }
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

#define MEDIAL_CHECK(cond, ...)                                                                    \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::printf("FAILED %s:%d: %s: ", __FILE__, __LINE__, #cond);                                 \
      std::printf(__VA_ARGS__);                                                                    \
      std::printf("\n");                                                                           \
      return EXIT_FAILURE;                                                                         \
    }                                                                                              \
  } while (0)
}

#endif
