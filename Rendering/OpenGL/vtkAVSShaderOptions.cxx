#include "vtkAVSShaderOptions.h"

#include "vtkAVSOpenGL.h"
#include "vtkShaderProgram.h"
#include "vtkVolumeMapper.h"

#include <algorithm>

struct vtkAVSShaderOptions::ClipUniforms
{
  int Count = 0;
  float Planes[avs::ClipRegion::MaximumNumberOfPlanes][4] = {};
  int Cropping = 0;
  float CropLow[3] = {}, CropHigh[3] = {};
  int CropFlags = 0;
  float KeptLow[3] = {}, KeptHigh[3] = {};
};

bool vtkAVSShaderOptions::IsSupportedBlend(int mode)
{
  return mode == vtkVolumeMapper::COMPOSITE_BLEND ||
    mode == vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND ||
    mode == vtkVolumeMapper::MINIMUM_INTENSITY_BLEND ||
    mode == vtkVolumeMapper::AVERAGE_INTENSITY_BLEND || mode == vtkVolumeMapper::ADDITIVE_BLEND ||
    mode == vtkVolumeMapper::ISOSURFACE_BLEND;
}

const char* vtkAVSShaderOptions::BlendModeName(int mode)
{
  switch (mode)
  {
    case vtkVolumeMapper::COMPOSITE_BLEND:
      return "composite";
    case vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND:
      return "maximum intensity";
    case vtkVolumeMapper::MINIMUM_INTENSITY_BLEND:
      return "minimum intensity";
    case vtkVolumeMapper::AVERAGE_INTENSITY_BLEND:
      return "average intensity";
    case vtkVolumeMapper::ADDITIVE_BLEND:
      return "additive";
    case vtkVolumeMapper::ISOSURFACE_BLEND:
      return "isosurface";
    case vtkVolumeMapper::SLICE_BLEND:
      return "slice";
    default:
      return "unknown";
  }
}

vtkAVSShaderOptions::ClipUniforms vtkAVSShaderOptions::Pack(const avs::ClipRegion& region)
{
  ClipUniforms u;
  // The mappers refuse more planes than the shader holds.
  u.Count =
    std::min<int>(static_cast<int>(region.Planes.size()), avs::ClipRegion::MaximumNumberOfPlanes);
  for (int p = 0; p < u.Count; ++p)
  {
    const avs::IndexPlane& plane = region.Planes[p];
    u.Planes[p][0] = static_cast<float>(plane.Normal.x);
    u.Planes[p][1] = static_cast<float>(plane.Normal.y);
    u.Planes[p][2] = static_cast<float>(plane.Normal.z);
    u.Planes[p][3] = static_cast<float>(plane.Offset);
  }
  if (region.Cropping)
  {
    avs::Vec3 low, high;
    if (!region.KeptBox(low, high))
    {
      // No region kept: one plane that keeps nothing (and cropping off, which adds nothing).
      u.Count = 1;
      u.Planes[0][0] = u.Planes[0][1] = u.Planes[0][2] = 0.0f;
      u.Planes[0][3] = -1.0f;
      return u;
    }
    u.Cropping = 1;
    u.CropFlags = region.CroppingRegionFlags;
    for (int a = 0; a < 3; ++a)
    {
      const double lo = region.CroppingPlanes[2 * a], hi = region.CroppingPlanes[2 * a + 1];
      // The shader counts the planes a point is at or above: with hi < lo that would give the
      // middle interval, which the core's (and VTK's) comparisons never give.
      u.CropLow[a] = static_cast<float>(lo);
      u.CropHigh[a] = static_cast<float>(std::max(lo, hi));
      u.KeptLow[a] = static_cast<float>(low[a]);
      u.KeptHigh[a] = static_cast<float>(high[a]);
    }
  }
  return u;
}

std::string vtkAVSShaderOptions::ClipDefines(const avs::ClipRegion& region)
{
  std::string defines;
  if (region.Clips())
  {
    defines += "#define AVS_CLIPPING\n";
  }
  if (region.Cropping)
  {
    defines += "#define AVS_CROPPING\n";
  }
  return defines;
}

void vtkAVSShaderOptions::SetClipUniforms(vtkShaderProgram* program, const avs::ClipRegion& region)
{
  const ClipUniforms u = Pack(region);
  program->SetUniformi("u_clipPlaneCount", u.Count);
  program->SetUniform4fv("u_clipPlanes", avs::ClipRegion::MaximumNumberOfPlanes, u.Planes);
  program->SetUniformi("u_cropping", u.Cropping);
  program->SetUniform3f("u_cropLow", u.CropLow);
  program->SetUniform3f("u_cropHigh", u.CropHigh);
  program->SetUniformi("u_cropFlags", u.CropFlags);
  program->SetUniform3f("u_keptLow", u.KeptLow);
  program->SetUniform3f("u_keptHigh", u.KeptHigh);
}

void vtkAVSShaderOptions::SetClipUniforms(unsigned int glProgram, const avs::ClipRegion& region)
{
  const ClipUniforms u = Pack(region);
  auto location = [glProgram](const char* name) { return glGetUniformLocation(glProgram, name); };
  glUniform1i(location("u_clipPlaneCount"), u.Count);
  glUniform4fv(location("u_clipPlanes"), avs::ClipRegion::MaximumNumberOfPlanes, &u.Planes[0][0]);
  glUniform1i(location("u_cropping"), u.Cropping);
  glUniform3fv(location("u_cropLow"), 1, u.CropLow);
  glUniform3fv(location("u_cropHigh"), 1, u.CropHigh);
  glUniform1i(location("u_cropFlags"), u.CropFlags);
  glUniform3fv(location("u_keptLow"), 1, u.KeptLow);
  glUniform3fv(location("u_keptHigh"), 1, u.KeptHigh);
}

std::string vtkAVSShaderOptions::BlendDefines(const Blend& blend)
{
  if (blend.Mode == vtkVolumeMapper::COMPOSITE_BLEND)
  {
    return std::string();
  }
  std::string defines = "#define AVS_BLEND " + std::to_string(blend.Mode) + "\n";
  if (blend.Mode == vtkVolumeMapper::ISOSURFACE_BLEND)
  {
    defines += "#define AVS_ISO_COUNT " + std::to_string(blend.IsoValues.size()) + "\n";
  }
  return defines;
}

void vtkAVSShaderOptions::SetBlendUniforms(vtkShaderProgram* program, const Blend& blend)
{
  const float range[2] = { static_cast<float>(blend.ScalarRange[0]),
    static_cast<float>(blend.ScalarRange[1]) };
  program->SetUniform2f("u_blendRange", range);
  const float average[2] = { static_cast<float>(blend.AverageRange[0]),
    static_cast<float>(blend.AverageRange[1]) };
  program->SetUniform2f("u_averageRange", average);
  if (!blend.IsoValues.empty())
  {
    std::vector<float> values(blend.IsoValues.begin(), blend.IsoValues.end());
    program->SetUniform1fv("u_isoValues", static_cast<int>(values.size()), values.data());
  }
}
