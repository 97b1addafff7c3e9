#include "vtkAmbientScatteringTable.h"

#include "ScatteringTable.h"

#include "vtkObjectFactory.h"

#include <dlfcn.h>

#include <cstdlib>
#include <fstream>

vtkStandardNewMacro(vtkAmbientScatteringTable);

vtkAmbientScatteringTable::vtkAmbientScatteringTable() = default;

vtkAmbientScatteringTable::~vtkAmbientScatteringTable()
{
  this->SetFileName(nullptr);
}

namespace
{
// The folder of the library this code is in (build tree or install tree alike).
std::string LibraryFolder()
{
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&LibraryFolder), &info) == 0 || !info.dli_fname)
  {
    return std::string();
  }
  const std::string path = info.dli_fname;
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}
} // namespace

std::string vtkAmbientScatteringTable::GetDefaultFileName()
{
  auto exists = [](const std::string& path)
  {
    std::ifstream f(path, std::ios::binary);
    return static_cast<bool>(f);
  };
  if (const char* env = std::getenv("AVS_SCATTERING_TABLE"))
  {
    if (*env)
    {
      return env;
    }
  }
  // Beside the library: share/ambientscattering, as the build tree and an installed tree (moved
  // anywhere) lay it out.
  const std::string folder = LibraryFolder();
  if (!folder.empty())
  {
    const std::string beside = folder + "/" + AVS_TABLE_FROM_LIBRARY;
    if (exists(beside))
    {
      return beside;
    }
  }
  // Where the install prefix put it.
#ifdef AVS_INSTALL_TABLE_PATH
  if (exists(AVS_INSTALL_TABLE_PATH))
  {
    return AVS_INSTALL_TABLE_PATH;
  }
#endif
  return std::string();
}

bool vtkAmbientScatteringTable::Load()
{
  const std::string fileName =
    (this->FileName && *this->FileName) ? std::string(this->FileName) : GetDefaultFileName();
  if (fileName.empty())
  {
    vtkErrorMacro("No scattering table file: set FileName or AVS_SCATTERING_TABLE (the shipped "
                  "table was not found).");
    return false;
  }
  auto table = std::make_unique<avs::ScatteringTable>();
  std::string error;
  if (!table->Read(fileName, &error))
  {
    vtkErrorMacro("Cannot load the scattering table: " << error);
    return false;
  }
  this->Table = std::move(table);
  this->LoadedFileName = fileName;
  this->Modified();
  return true;
}

bool vtkAmbientScatteringTable::Update()
{
  const std::string wanted =
    (this->FileName && *this->FileName) ? std::string(this->FileName) : GetDefaultFileName();
  if (this->Table && wanted == this->LoadedFileName)
  {
    return true;
  }
  return this->Load();
}

bool vtkAmbientScatteringTable::IsLoaded() const
{
  return this->Table != nullptr;
}

const avs::ScatteringTable* vtkAmbientScatteringTable::GetTable() const
{
  return this->Table.get();
}

double vtkAmbientScatteringTable::GetInScattering(double theta,
  double tau,
  double g,
  double albedo) const
{
  return this->Table ? this->Table->InScattering(theta, tau, g, albedo) : 0.0;
}

double vtkAmbientScatteringTable::GetForwardTransport(double tau, double g, double albedo) const
{
  return this->Table ? this->Table->ForwardTransport(tau, g, albedo) : 1.0;
}

int vtkAmbientScatteringTable::GetNumberOfTheta() const
{
  return this->Table ? this->Table->Axes.NumberOfTheta : 0;
}

int vtkAmbientScatteringTable::GetNumberOfOpticalRadii() const
{
  return this->Table ? this->Table->Axes.NumberOfTau : 0;
}

int vtkAmbientScatteringTable::GetNumberOfAnisotropies() const
{
  return this->Table ? this->Table->Axes.NumberOfAnisotropy : 0;
}

int vtkAmbientScatteringTable::GetNumberOfAlbedos() const
{
  return this->Table ? this->Table->Axes.NumberOfAlbedo : 0;
}

double vtkAmbientScatteringTable::GetMaximumOpticalRadius() const
{
  return this->Table ? this->Table->Axes.TauMaximum : 0.0;
}

const char* vtkAmbientScatteringTable::GetGenerator() const
{
  return this->Table ? this->Table->Generator.c_str() : "";
}

double vtkAmbientScatteringTable::GetMaximumRelativeErrorA() const
{
  return this->Table ? this->Table->MaximumRelativeErrorA() : 0.0;
}

double vtkAmbientScatteringTable::GetMaximumRelativeErrorF() const
{
  return this->Table ? this->Table->MaximumRelativeErrorF() : 0.0;
}

void vtkAmbientScatteringTable::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(default)") << "\n";
  os << indent << "DefaultFileName: " << GetDefaultFileName() << "\n";
  os << indent << "Loaded: " << (this->Table ? "yes" : "no") << "\n";
  if (this->Table)
  {
    const auto& ax = this->Table->Axes;
    os << indent << "LoadedFileName: " << this->LoadedFileName << "\n";
    os << indent << "Axes: theta " << ax.NumberOfTheta << ", tau " << ax.NumberOfTau << " (max "
       << ax.TauMaximum << "), g " << ax.NumberOfAnisotropy << " [" << ax.AnisotropyMinimum << ", "
       << ax.AnisotropyMaximum << "], albedo " << ax.NumberOfAlbedo << "\n";
    os << indent << "Generator: " << this->Table->Generator << ", seed " << this->Table->Seed
       << ", " << this->Table->GenerationSeconds << " s\n";
    os << indent << "MaximumRelativeErrorA: " << this->Table->MaximumRelativeErrorA() << "\n";
    os << indent << "MaximumRelativeErrorF: " << this->Table->MaximumRelativeErrorF() << "\n";
  }
}
