// vtkAmbientScatteringTable: loads the shipped table, answers lookups, rejects missing and
// corrupt files with an error while keeping the loaded table, prints itself.
#include "TestErrorObserver.h"
#include "vtkAmbientScatteringTable.h"

#include "vtkNew.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

int main(int argc, char* argv[])
{
  int failures = 0;
  const std::string dir = argc > 1 ? argv[1] : ".";
  vtkNew<vtkAmbientScatteringTable> table;
  vtkNew<TestErrorObserver> errors;
  table->AddObserver(vtkCommand::ErrorEvent, errors);

  AVS_CHECK(!table->IsLoaded());
  AVS_CHECK(table->GetForwardTransport(1.0, 0.0, 0.5) == 1.0);
  AVS_CHECK(!vtkAmbientScatteringTable::GetDefaultFileName().empty());
  AVS_CHECK(table->Load());
  AVS_CHECK(errors->Errors == 0);
  AVS_CHECK(table->IsLoaded());
  AVS_CHECK(table->GetNumberOfTheta() >= 2);
  AVS_CHECK(std::abs(table->GetForwardTransport(2.0, 0.3, 0.0) - std::exp(-4.0)) < 1e-6);
  AVS_CHECK(table->GetInScattering(0.5, 1.0, 0.3, 0.9) > 0.0);
  const int thetas = table->GetNumberOfTheta();

  // Missing file.
  table->SetFileName((dir + "/no-such-table.avst").c_str());
  AVS_CHECK(!table->Load());
  AVS_CHECK(errors->Errors == 1);
  AVS_CHECK(errors->LastError.find("cannot open") != std::string::npos);
  AVS_CHECK(table->IsLoaded() && table->GetNumberOfTheta() == thetas);

  // Random bytes, and a truncated copy of the real table.
  {
    std::ofstream junk(dir + "/junk.avst", std::ios::binary);
    for (int i = 0; i < 4096; ++i)
    {
      junk.put(static_cast<char>((i * 7919) & 0xff));
    }
  }
  errors->Clear();
  table->SetFileName((dir + "/junk.avst").c_str());
  AVS_CHECK(!table->Load());
  AVS_CHECK(errors->LastError.find("magic") != std::string::npos);
  {
    std::ifstream in(vtkAmbientScatteringTable::GetDefaultFileName(), std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream out(dir + "/truncated.avst", std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 3));
  }
  errors->Clear();
  table->SetFileName((dir + "/truncated.avst").c_str());
  AVS_CHECK(!table->Load());
  AVS_CHECK(errors->LastError.find("truncated") != std::string::npos);
  AVS_CHECK(table->IsLoaded());

  std::ostringstream os;
  table->Print(os);
  for (const char* key : { "FileName", "Loaded", "Axes", "Generator", "MaximumRelativeErrorF" })
  {
    AVS_CHECK(os.str().find(key) != std::string::npos);
  }
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
