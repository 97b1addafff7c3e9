#include "vtkAVSDiffuseVolume.h"

#include "vtkAVSRenderPasses.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

vtkAVSDiffuseVolume::vtkAVSDiffuseVolume() = default;

vtkAVSDiffuseVolume::~vtkAVSDiffuseVolume() = default;

bool vtkAVSDiffuseVolume::Upload(vtkOpenGLRenderWindow* window,
  const std::vector<avs::Grid>& phi,
  std::string& error)
{
  if (phi.size() != 3 || phi[0].Values.size() != phi[0].Geometry.NumberOfPoints() ||
    phi[1].Values.size() != phi[0].Values.size() || phi[2].Values.size() != phi[0].Values.size())
  {
    error = "the diffuse fluence is not three grids of one size";
    return false;
  }
  const std::array<int, 3> d = phi[0].Geometry.Dimensions;
  const std::size_t n = phi[0].Values.size();
  std::vector<float> packed(4 * n, 0.0f);
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      packed[4 * i + c] = phi[c].Values[i];
    }
  }
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  this->Texture = vtkSmartPointer<vtkTextureObject>::New();
  this->Texture->SetContext(window);
  this->Texture->SetWrapS(vtkTextureObject::ClampToEdge);
  this->Texture->SetWrapT(vtkTextureObject::ClampToEdge);
  this->Texture->SetWrapR(vtkTextureObject::ClampToEdge);
  this->Texture->SetMinificationFilter(vtkTextureObject::Linear);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Linear);
  this->Texture->SetInternalFormat(GL_RGBA32F);
  vtkAVSRenderPasses::DiscardErrors();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (!this->Texture->Create3DFromRaw(static_cast<unsigned int>(d[0]),
        static_cast<unsigned int>(d[1]),
        static_cast<unsigned int>(d[2]),
        4,
        VTK_FLOAT,
        packed.data()) ||
    glGetError() != GL_NO_ERROR)
  {
    error = "the GPU could not allocate the diffuse-fluence texture (" + std::to_string(d[0]) +
      " x " + std::to_string(d[1]) + " x " + std::to_string(d[2]) + ")";
    this->Texture->ReleaseGraphicsResources(window);
    this->Texture = nullptr;
    return false;
  }
  this->Dimensions = d;
  return true;
}

void vtkAVSDiffuseVolume::Bind(vtkShaderProgram* program)
{
  if (!this->Texture)
  {
    return;
  }
  this->Texture->Activate();
  program->SetUniformi("u_diffuse", this->Texture->GetTextureUnit());
  const float d[3] = { static_cast<float>(this->Dimensions[0]),
    static_cast<float>(this->Dimensions[1]),
    static_cast<float>(this->Dimensions[2]) };
  program->SetUniform3f("u_diffuseDimensions", d);
}

void vtkAVSDiffuseVolume::Unbind()
{
  if (this->Texture && this->Texture->GetTextureUnit() >= 0)
  {
    this->Texture->Deactivate();
  }
}

void vtkAVSDiffuseVolume::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  this->Texture = nullptr;
  this->Dimensions = { 0, 0, 0 };
}
