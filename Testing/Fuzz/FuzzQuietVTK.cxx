#include "FuzzInput.h"

#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"

#include <cstdlib>

namespace
{
class SilentOutputWindow : public vtkOutputWindow
{
public:
  static SilentOutputWindow* New();
  vtkTypeMacro(SilentOutputWindow, vtkOutputWindow);
  void DisplayText(const char*) override {}
};
vtkStandardNewMacro(SilentOutputWindow);
} // namespace

void FuzzQuietVTK()
{
  static bool done = false;
  if (done || std::getenv("AVS_FUZZ_VERBOSE"))
  {
    return;
  }
  done = true;
  vtkOutputWindow::SetInstance(SilentOutputWindow::New());
}
