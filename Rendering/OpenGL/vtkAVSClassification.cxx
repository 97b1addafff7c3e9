#include "vtkAVSClassification.h"

#include "vtkAVSRenderPasses.h"
#include "vtkAVSTextureUpload.h"

#include "vtkAVSOpenGL.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

#include <algorithm>

namespace
{
// A one-channel float 3D texture of `grid` (vtkAVSTextureUpload), filtered linearly or by the
// nearest texel.
bool UploadGrid(vtkOpenGLRenderWindow* window,
  vtkSmartPointer<vtkTextureObject>& texture,
  const avs::Grid& grid,
  bool nearest,
  const std::vector<vtkTextureObject*>& held,
  std::string& error)
{
  if (!vtkAVSTextureUpload::UploadFloats(
        window, texture, grid.Geometry.Dimensions, 1, grid.Values.data(), 0, held, error))
  {
    return false;
  }
  const int filter = nearest ? vtkTextureObject::Nearest : vtkTextureObject::Linear;
  texture->SetMinificationFilter(filter);
  texture->SetMagnificationFilter(filter);
  return true;
}

// A table over [lo, hi]: value -> (value - lo) / (hi - lo) * a + b, as map[0] value + map[1].
void MapOf(const avs::TransferFunction& t, double a, double b, float* map)
{
  const double lo = t.Minimum, hi = t.Maximum > t.Minimum ? t.Maximum : t.Minimum + 1.0;
  map[0] = static_cast<float>(a / (hi - lo));
  map[1] = static_cast<float>(b - a * lo / (hi - lo));
}
} // namespace

std::string vtkAVSClassification::Layout::Defines() const
{
  return "#define AVS_COMPONENTS " + std::to_string(this->Components) + "\n#define AVS_MODE " +
    std::to_string(this->Mode) + "\n#define AVS_VALIDITY " + std::to_string(this->Validity) +
    "\n#define AVS_GRADIENT " + std::to_string(this->Gradient) + "\n#define AVS_MASK " +
    std::to_string(this->Mask) + "\n";
}

vtkAVSClassification::Layout vtkAVSClassification::LayoutOf(const avs::VolumeScene& scene)
{
  const avs::MediumOptions& m = scene.Medium;
  Layout l;
  l.Components = std::min(4, m.NumberOfComponents());
  l.Mode = static_cast<int>(m.Mode);
  l.Validity = m.Validity.Values.empty() ? 0 : (l.Components < 4 ? 1 : 2);
  if (!m.GradientOpacity.Opacity.empty())
  {
    l.Gradient |= 1;
  }
  for (int c = 1; c < l.Components; ++c)
  {
    if (!m.Components[c - 1].GradientOpacity.Opacity.empty())
    {
      l.Gradient |= 1 << c;
    }
  }
  l.Mask = m.MaskValues.Values.empty() ? 0 : static_cast<int>(m.Mask);
  l.Nearest = m.Sampling == avs::Interpolation::Nearest;
  return l;
}

void vtkAVSClassification::ReleaseTransfer()
{
  if (this->Transfer && this->Window)
  {
    this->Transfer->ReleaseGraphicsResources(this->Window);
  }
  this->Transfer = nullptr;
  if (this->TransferHandle && this->Window)
  {
    // AssignToExistingTexture leaves the texture to its creator.
    GLuint handle = this->TransferHandle;
    glDeleteTextures(1, &handle);
  }
  this->TransferHandle = 0;
}

std::vector<vtkTextureObject*> vtkAVSClassification::VolumeTextures() const
{
  std::vector<vtkTextureObject*> held = { this->Mask.Get(), this->Validity.Get() };
  for (const auto* textures : { &this->MaskBricks, &this->ValidityBricks })
  {
    for (vtkTextureObject* t : *textures)
    {
      held.push_back(t);
    }
  }
  return held;
}

void vtkAVSClassification::ReleaseBricks()
{
  for (auto* textures : { &this->MaskBricks, &this->ValidityBricks })
  {
    for (auto& t : *textures)
    {
      if (t && this->Window)
      {
        t->ReleaseGraphicsResources(this->Window);
      }
    }
    textures->clear();
  }
}

void vtkAVSClassification::BindBrick(unsigned int program, int brick)
{
  const std::size_t b = static_cast<std::size_t>(brick);
  const char* names[2] = { "u_mask", "u_validity" };
  int which = 0;
  for (const auto* textures : { &this->MaskBricks, &this->ValidityBricks })
  {
    const char* name = names[which++];
    if (b >= textures->size())
    {
      continue;
    }
    for (vtkTextureObject* t : *textures)
    {
      if (t->GetTextureUnit() >= 0)
      {
        t->Deactivate();
      }
    }
    vtkTextureObject* t = (*textures)[b];
    t->Activate();
    glUniform1i(glGetUniformLocation(static_cast<GLuint>(program), name), t->GetTextureUnit());
  }
  if (b < this->MaskBricks.size())
  {
    glUniform1f(glGetUniformLocation(static_cast<GLuint>(program), "u_maskBlend"), this->MaskBlend);
    glUniform1f(glGetUniformLocation(static_cast<GLuint>(program), "u_labels"), this->Labels);
  }
}

void vtkAVSClassification::ReleaseGraphicsResources(vtkWindow* window)
{
  if (window)
  {
    this->ReleaseBricks();
  }
  this->MaskBricks.clear();
  this->ValidityBricks.clear();
  if (window)
  {
    this->ReleaseTransfer();
  }
  this->Transfer = nullptr;
  this->TransferHandle = 0;
  for (auto* t : { &this->Transfer, &this->Mask, &this->Validity })
  {
    if (*t && window)
    {
      (*t)->ReleaseGraphicsResources(window);
    }
    *t = nullptr;
  }
}

bool vtkAVSClassification::Upload(const avs::VolumeScene& scene,
  const std::vector<vtkTextureObject*>& callerHeld,
  const vtkAVSBricks& bricks,
  std::string& error)
{
  const Layout layout = LayoutOf(scene);
  const avs::MediumOptions& m = scene.Medium;
  const int c = layout.Components;
  // Rows: the components' functions, their gradient opacities, the labels'.
  std::vector<const avs::TransferFunction*> rows;
  for (int k = 0; k < c; ++k)
  {
    rows.push_back(k == 0 ? &scene.Transfer : &m.Components[k - 1].Transfer);
  }
  for (int k = 0; k < c; ++k)
  {
    rows.push_back(k == 0 ? &m.GradientOpacity : &m.Components[k - 1].GradientOpacity);
  }
  for (const avs::TransferFunction& t : m.Labels)
  {
    rows.push_back(&t);
  }
  std::size_t width = 2;
  for (const auto* t : rows)
  {
    width = std::max({ width, t->Color.size(), t->Opacity.size() });
  }
  std::vector<float> rgba(4 * width * rows.size(), 1.0f);
  for (std::size_t r = 0; r < rows.size(); ++r)
  {
    const avs::TransferFunction& t = *rows[r];
    for (std::size_t i = 0; i < width; ++i)
    {
      // At the table's nodes (tables of another size are resampled).
      const double value = t.Minimum + (t.Maximum - t.Minimum) * i / (width - 1.0);
      float* texel = &rgba[4 * (r * width + i)];
      if (!t.Color.empty())
      {
        const avs::Vec3 color = t.Color.size() == width
          ? avs::Vec3{ t.Color[i][0], t.Color[i][1], t.Color[i][2] }
          : t.ColorAt(value);
        texel[0] = static_cast<float>(color.x);
        texel[1] = static_cast<float>(color.y);
        texel[2] = static_cast<float>(color.z);
      }
      if (!t.Opacity.empty())
      {
        texel[3] =
          t.Opacity.size() == width ? t.Opacity[i] : static_cast<float>(t.OpacityAt(value));
      }
    }
  }
  // A 1D array texture: linear along the table, one layer per row (a 2D texture would filter
  // across rows too, four taps instead of two on a software rasterizer). Half floats: a 128-bit
  // texel filters at a quarter of the rate of a 64-bit one on NVIDIA GPUs, and this texture is
  // read at every sample (measured on an H100: EA 1.35x VTK's frame time with RGBA32F, 0.72x
  // with RGBA16F).
  this->ReleaseTransfer();
  vtkAVSRenderPasses::DiscardErrors();
  GLuint handle = 0;
  glGenTextures(1, &handle);
  glBindTexture(GL_TEXTURE_1D_ARRAY, handle);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_1D_ARRAY,
    0,
    GL_RGBA16F,
    static_cast<GLsizei>(width),
    static_cast<GLsizei>(rows.size()),
    0,
    GL_RGBA,
    GL_FLOAT,
    rgba.data());
  // Sampling parameters set here, once: vtkTextureObject does not know 1D array textures (its
  // IsBound, which its automatic parameter upload asserts, has no case for them; ParaView's VTK
  // is built with assertions on), so its automatic parameters stay off for this texture.
  glTexParameteri(GL_TEXTURE_1D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_1D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D_ARRAY, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_1D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
  glBindTexture(GL_TEXTURE_1D_ARRAY, 0);
  if (glGetError() != GL_NO_ERROR)
  {
    glDeleteTextures(1, &handle);
    error = "the GPU could not allocate the transfer-function texture";
    return false;
  }
  this->TransferHandle = handle;
  this->Transfer = vtkSmartPointer<vtkTextureObject>::New();
  this->Transfer->SetContext(this->Window);
  this->Transfer->AssignToExistingTexture(handle, GL_TEXTURE_1D_ARRAY);
  this->Transfer->SetAutoParameters(0);
  this->TransferSize[0] = static_cast<float>(width);
  this->TransferSize[1] = static_cast<float>(rows.size());
  // Texel centres on the nodes: [0, 1] -> [0.5 / N, 1 - 0.5 / N]; beyond, the texture clamps.
  std::fill(this->RowMap, this->RowMap + 16, 0.0f);
  std::fill(this->ColorMap, this->ColorMap + 6, 0.0f);
  const double n = static_cast<double>(width);
  for (std::size_t r = 0; r < rows.size() && r < 8; ++r)
  {
    MapOf(*rows[r], (n - 1.0) / n, 0.5 / n, this->RowMap + 2 * r);
    this->RowY[r] = static_cast<float>(r); // the layer
    if (r < 3)
    {
      MapOf(*rows[r], 1.0, 0.0, this->ColorMap + 2 * r);
    }
  }
  for (int k = 0; k < 4; ++k)
  {
    const avs::MediumComponent* mc = k > 0 && k < c ? &m.Components[k - 1] : nullptr;
    this->UnitDistance[k] =
      static_cast<float>(k == 0 ? scene.UnitDistance : (mc ? mc->UnitDistance : 1.0));
    this->Weight[k] =
      static_cast<float>(std::clamp(k == 0 ? m.Weight : (mc ? mc->Weight : 0.0), 0.0, 1.0));
  }
  const avs::GridGeometry& g = scene.Scalars.Geometry;
  const double mean = (g.Spacing.x + g.Spacing.y + g.Spacing.z) / 3.0;
  for (int a = 0; a < 3; ++a)
  {
    this->GradientScale[a] = static_cast<float>(0.5 * mean / g.Spacing[a]);
    this->VoxelStep[a] = static_cast<float>(1.0 / g.Dimensions[a]);
  }
  this->MaskBlend = static_cast<float>(std::clamp(m.MaskBlendFactor, 0.0, 1.0));
  this->Labels = static_cast<float>(m.Labels.size());
  this->ReleaseBricks();
  if (bricks.IsSplit())
  {
    // One mask (and validity) texture per brick, on the scalars' bricks.
    for (auto* t : { &this->Mask, &this->Validity })
    {
      if (*t)
      {
        (*t)->ReleaseGraphicsResources(this->Window);
      }
      *t = nullptr;
    }
    for (const vtkAVSBricks::Brick& brick : bricks.GetBricks())
    {
      for (int which = 0; which < 2; ++which)
      {
        if (which == 0 ? layout.Mask == 0 : layout.Validity != 2)
        {
          continue;
        }
        auto& textures = which == 0 ? this->MaskBricks : this->ValidityBricks;
        std::vector<vtkTextureObject*> held = callerHeld;
        for (vtkTextureObject* t : this->VolumeTextures())
        {
          held.push_back(t);
        }
        textures.emplace_back();
        const avs::Grid part = vtkAVSBricks::Crop(
          which == 0 ? m.MaskValues : m.Validity, brick.Origin, brick.Dimensions);
        if (!UploadGrid(
              this->Window, textures.back(), part, which == 0 || layout.Nearest, held, error))
        {
          this->ReleaseBricks();
          return false;
        }
      }
    }
    this->Current = layout;
    return true;
  }
  std::vector<vtkTextureObject*> held = callerHeld;
  held.push_back(this->Mask);
  held.push_back(this->Validity);
  if (layout.Mask > 0)
  {
    if (!UploadGrid(this->Window, this->Mask, m.MaskValues, true, held, error))
    {
      return false;
    }
  }
  else if (this->Mask)
  {
    this->Mask->ReleaseGraphicsResources(this->Window);
    this->Mask = nullptr;
  }
  if (layout.Validity == 2)
  {
    held.back() = this->Validity; // the mask may have been replaced
    held[held.size() - 2] = this->Mask;
    if (!UploadGrid(this->Window, this->Validity, m.Validity, layout.Nearest, held, error))
    {
      return false;
    }
  }
  else if (this->Validity)
  {
    this->Validity->ReleaseGraphicsResources(this->Window);
    this->Validity = nullptr;
  }
  this->Current = layout;
  return true;
}

void vtkAVSClassification::Bind(unsigned int program)
{
  auto location = [program](const char* name)
  { return glGetUniformLocation(static_cast<GLuint>(program), name); };
  this->Transfer->Activate();
  glUniform1i(location("u_transfer"), this->Transfer->GetTextureUnit());
  glUniform2fv(location("u_transferSize"), 1, this->TransferSize);
  glUniform2fv(location("u_rowMap"), 8, this->RowMap);
  glUniform1fv(location("u_rowY"), 8, this->RowY);
  glUniform2fv(location("u_colorMap"), 3, this->ColorMap);
  glUniform1fv(location("u_unitDistance"), 4, this->UnitDistance);
  glUniform1fv(location("u_weight"), 4, this->Weight);
  glUniform3fv(location("u_gradientScale"), 1, this->GradientScale);
  glUniform3fv(location("u_voxelStep"), 1, this->VoxelStep);
  glUniform4fv(location("u_valueScale"), 1, this->ValueScale);
  glUniform4fv(location("u_valueShift"), 1, this->ValueShift);
  if (this->Mask)
  {
    this->Mask->Activate();
    glUniform1i(location("u_mask"), this->Mask->GetTextureUnit());
    glUniform1f(location("u_maskBlend"), this->MaskBlend);
    glUniform1f(location("u_labels"), this->Labels);
  }
  if (this->Validity)
  {
    const int filter = this->Current.Nearest ? vtkTextureObject::Nearest : vtkTextureObject::Linear;
    this->Validity->SetMinificationFilter(filter);
    this->Validity->SetMagnificationFilter(filter);
    this->Validity->Activate();
    glUniform1i(location("u_validity"), this->Validity->GetTextureUnit());
  }
}

void vtkAVSClassification::SetValueMap(float scale, float shift)
{
  // Every channel: a validity channel comes only with float texels (scale 1, shift 0).
  std::fill(this->ValueScale, this->ValueScale + 4, scale);
  std::fill(this->ValueShift, this->ValueShift + 4, shift);
}

void vtkAVSClassification::Unbind()
{
  for (const auto* textures : { &this->MaskBricks, &this->ValidityBricks })
  {
    for (vtkTextureObject* t : *textures)
    {
      if (t && t->GetTextureUnit() >= 0)
      {
        t->Deactivate();
      }
    }
  }
  for (vtkTextureObject* t : { this->Transfer.Get(), this->Mask.Get(), this->Validity.Get() })
  {
    if (t && t->GetTextureUnit() >= 0)
    {
      t->Deactivate();
    }
  }
}
