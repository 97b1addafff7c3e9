// Records vtkErrorMacro / vtkWarningMacro output of an object so tests can assert on it.
#ifndef TestErrorObserver_h
#define TestErrorObserver_h

#include "vtkCommand.h"

#include <string>
#include <vector>

class TestErrorObserver : public vtkCommand
{
public:
  static TestErrorObserver* New() { return new TestErrorObserver; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    for (const std::string& known : this->Known)
    {
      if (event == vtkCommand::ErrorEvent && text.find(known) != std::string::npos)
      {
        ++this->KnownErrors; // an error of VTK's that the test names and says why it is there
        return;
      }
    }
    if (event == vtkCommand::ErrorEvent)
    {
      ++this->Errors;
      this->LastError = text;
    }
    else if (event == vtkCommand::WarningEvent)
    {
      ++this->Warnings;
      this->LastWarning = text;
    }
  }
  void Clear()
  {
    this->Errors = this->Warnings = 0;
    this->LastError.clear();
    this->LastWarning.clear();
  }
  int Errors = 0;
  int Warnings = 0;
  /// Errors of VTK's own that a test expects (each with its reason there): counted apart.
  std::vector<std::string> Known;
  int KnownErrors = 0;
  std::string LastError;
  std::string LastWarning;
};

#define AVS_CHECK(condition)                                                                       \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #condition << std::endl;      \
      ++failures;                                                                                  \
    }                                                                                              \
  } while (0)

#endif
