// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialScene without anything to draw, and with an unwritable PNG path: an error
// reported by the scene itself and a failed result; no crash.
#include "MedialTestSupport.h"

#include "vtkMedialScene.h"
#include "vtkMedialShapeSource.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"

#include <string>

int TestMedialSceneBadInput(int, char*[])
{
  vtkNew<vtkMedialScene> scene;
  std::string errors;
  vtkNew<vtkCallbackCommand> collect;
  collect->SetClientData(&errors);
  collect->SetCallback([](vtkObject*, unsigned long, void* client, void* text) {
    *static_cast<std::string*>(client) += std::string(static_cast<const char*>(text)) + "\n";
  });
  scene->AddObserver(vtkCommand::ErrorEvent, collect);
  MEDIAL_CHECK(scene->Render() == nullptr && !scene->GetRenderWindow(), "an empty scene was rendered");
  MEDIAL_CHECK(errors.find("Nothing to draw") != std::string::npos, "no error: '%s'", errors.c_str());
  errors.clear();

  vtkNew<vtkMedialShapeSource> jack;
  jack->Update();
  scene->SetSurface(jack->GetOutput());
  scene->SetWindowSize(64, 48);
  const int written = scene->WritePNG("/nonexistent-folder/x.png");
  const size_t reason = errors.find("vtkMedialScene (");
  const std::string first = reason == std::string::npos ? "" : errors.substr(reason, errors.find('\n', reason) - reason);
  std::printf("unwritable: WritePNG gives %d, first error: %s\n", written, first.c_str());
  MEDIAL_CHECK(written == 0, "a PNG was written into a missing folder");
  MEDIAL_CHECK(first.find("Unable to open file /nonexistent-folder/x.png") != std::string::npos,
    "the writer's error is not the scene's");
  MEDIAL_CHECK(scene->GetRenderWindow() && scene->GetRenderWindow()->GetSize()[0] == 64, "no window after Render");
  return EXIT_SUCCESS;
}
