#include "vtkAVSFrameUniforms.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include <algorithm>
#include <cmath>

void vtkAVSFrameUniforms::SetGeometry(vtkShaderProgram* program,
  vtkRenderer* renderer,
  int width,
  int height,
  const vtkAVSRayCaster::Frame& frame)
{
  // Matrices: NDC -> world from the camera, world -> index from the mapper.
  vtkCamera* camera = renderer->GetActiveCamera();
  const double aspect = static_cast<double>(width) / std::max(1, height);
  vtkNew<vtkMatrix4x4> ndcToWorld;
  ndcToWorld->DeepCopy(camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1));
  ndcToWorld->Invert();
  auto upload = [program](const char* name, vtkMatrix4x4* m)
  {
    float data[16];
    for (int r = 0; r < 4; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        data[c * 4 + r] = static_cast<float>(m->GetElement(r, c)); // column-major for GLSL
      }
    }
    program->SetUniformMatrix4x4(name, data);
  };
  // SetUniformMatrix4x4 sends the array as is (column-major), so GLSL sees M and M * v works.
  upload("u_ndcToWorld", ndcToWorld);
  upload("u_worldToIndex", frame.WorldToIndex);
  const float dims[3] = { static_cast<float>(frame.Dimensions[0]),
    static_cast<float>(frame.Dimensions[1]),
    static_cast<float>(frame.Dimensions[2]) };
  program->SetUniform3f("u_dimensions", dims);
  const float spacing[3] = { static_cast<float>(frame.Spacing.x),
    static_cast<float>(frame.Spacing.y),
    static_cast<float>(frame.Spacing.z) };
  program->SetUniform3f("u_spacing", spacing);
  program->SetUniformf("u_border", static_cast<float>(frame.Border));
}

void vtkAVSFrameUniforms::SetLights(vtkShaderProgram* program,
  const std::vector<avs::Light>& lights)
{
  constexpr int MaximumNumberOfLights = vtkAVSRayCaster::MaximumNumberOfLights;
  const int n = static_cast<int>(std::min<std::size_t>(lights.size(), MaximumNumberOfLights));
  float position[MaximumNumberOfLights][3] = {}, axis[MaximumNumberOfLights][3] = {},
        irradiance[MaximumNumberOfLights][3] = {}, attenuation[MaximumNumberOfLights][3] = {};
  float coneCos[MaximumNumberOfLights] = {}, exponent[MaximumNumberOfLights] = {};
  for (int j = 0; j < n; ++j)
  {
    const avs::Light& l = lights[j];
    const avs::Vec3 a = avs::Normalize(l.FocalPoint - l.Position);
    for (int k = 0; k < 3; ++k)
    {
      position[j][k] = static_cast<float>(l.Position[k]);
      axis[j][k] = static_cast<float>(a[k]);
      irradiance[j][k] = static_cast<float>(l.Irradiance[k]);
      attenuation[j][k] = static_cast<float>(l.Attenuation[k]);
    }
    coneCos[j] = l.IsSpot() ? static_cast<float>(std::cos(l.ConeAngle * avs::Pi / 180.0)) : -2.0f;
    // Not a spot: no cone and exponent 0, so the shader's spot code leaves the light unchanged.
    exponent[j] = l.IsSpot() ? static_cast<float>(l.Exponent) : 0.0f;
  }
  program->SetUniform3fv("u_lightPosition", MaximumNumberOfLights, position);
  program->SetUniform3fv("u_lightAxis", MaximumNumberOfLights, axis);
  program->SetUniform3fv("u_lightIrradiance", MaximumNumberOfLights, irradiance);
  program->SetUniform3fv("u_lightAttenuation", MaximumNumberOfLights, attenuation);
  program->SetUniform1fv("u_lightConeCos", MaximumNumberOfLights, coneCos);
  program->SetUniform1fv("u_lightExponent", MaximumNumberOfLights, exponent);
}

void vtkAVSFrameUniforms::SetParameters(vtkShaderProgram* program,
  const vtkAVSRayCaster::Frame& frame)
{
  const avs::ScatteringParameters& p = frame.Parameters;
  program->SetUniformf("u_sampleDistance", static_cast<float>(p.SampleDistance));
  program->SetUniformf("u_termination", static_cast<float>(p.TerminationTransmittance));
  program->SetUniformi("u_jitter", frame.Jitter ? 1 : 0);
  program->SetUniformf("u_albedo", static_cast<float>(p.Albedo));
  program->SetUniformf("u_anisotropy", static_cast<float>(p.Anisotropy));
  program->SetUniformf("u_emissionWeight", static_cast<float>(p.EmissionWeight));
  if (frame.Mode == avs::RenderMode::AmbientOcclusion)
  {
    program->SetUniformf("u_ambientWeight", static_cast<float>(p.AmbientWeight));
    program->SetUniformf("u_directLightWeight", static_cast<float>(p.DirectLightWeight));
  }
  else if (frame.Mode == avs::RenderMode::AmbientScattering)
  {
    program->SetUniformf("u_ambientRadius", static_cast<float>(p.AmbientRadius));
    if (p.Surface.Active())
    {
      // Surfaces inside the medium (avs_surface.glsl).
      const avs::SurfaceShading& s = p.Surface;
      program->SetUniformf("u_surfaceBlending", static_cast<float>(s.Blending));
      const float coefficients[4] = { static_cast<float>(s.Ambient),
        static_cast<float>(s.Diffuse),
        static_cast<float>(s.Specular),
        static_cast<float>(s.SpecularPower) };
      program->SetUniform4f("u_surfaceCoefficients", coefficients);
      program->SetUniformi("u_surfaceTwoSided", s.TwoSided ? 1 : 0);
      // The precomputed gradient's local direction n in world space: the transpose of
      // d index / d world times the spacing (n is per world unit of the local frame),
      // column-major: row r of the world -> index matrix's upper 3 x 3 times h_r.
      float toWorld[9];
      for (int r = 0; r < 3; ++r)
      {
        for (int c = 0; c < 3; ++c)
        {
          toWorld[3 * r + c] =
            static_cast<float>(frame.WorldToIndex->GetElement(r, c) * frame.Spacing[r]);
        }
      }
      program->SetUniformMatrix3x3("u_surfaceToWorld", toWorld);
    }
  }
}

void vtkAVSFrameUniforms::SetBrick(vtkShaderProgram* program, const vtkAVSBricks::Brick& brick)
{
  float low[3], high[3], origin[3], dims[3], step[3];
  for (int a = 0; a < 3; ++a)
  {
    low[a] = static_cast<float>(brick.Low[a]);
    high[a] = static_cast<float>(brick.High[a]);
    origin[a] = static_cast<float>(brick.Origin[a]);
    dims[a] = static_cast<float>(brick.Dimensions[a]);
    step[a] = 1.0f / dims[a];
  }
  program->SetUniform3f("u_brickLow", low);
  program->SetUniform3f("u_brickHigh", high);
  program->SetUniform3f("u_brickOrigin", origin);
  program->SetUniform3f("u_brickDimensions", dims);
  program->SetUniform3f("u_voxelStep", step); // the classification's, for the whole volume
}

std::array<double, 3> vtkAVSFrameUniforms::EyeInIndexFrame(vtkRenderer* renderer,
  const vtkAVSRayCaster::Frame& frame)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  double world[4] = { 0, 0, 0, 1 };
  camera->GetPosition(world);
  if (camera->GetParallelProjection())
  {
    // The eye at infinity behind the volume: the bricks' order only needs the side of each cut
    // plane it lies on, which is the side the rays come from along each axis (below the grid
    // where they run towards +a, above it where they run towards -a; an axis they run across
    // has no face a ray crosses, and any side will do).
    double direction[4] = { 0, 0, 0, 0 };
    camera->GetDirectionOfProjection(direction);
    double index[4];
    frame.WorldToIndex->MultiplyPoint(direction, index);
    std::array<double, 3> eye;
    for (int a = 0; a < 3; ++a)
    {
      eye[a] = index[a] > 0.0 ? -1.0
        : index[a] < 0.0      ? static_cast<double>(frame.Dimensions[a])
                              : 0.5 * (frame.Dimensions[a] - 1);
    }
    return eye;
  }
  double index[4];
  frame.WorldToIndex->MultiplyPoint(world, index);
  return { index[0] / index[3], index[1] / index[3], index[2] / index[3] };
}

void vtkAVSFrameUniforms::SetDisplay(vtkShaderProgram* program,
  const avs::DisplayTransform& display)
{
  program->SetUniformf("u_exposure", static_cast<float>(display.Exposure));
  program->SetUniformi("u_toneMapping", display.Curve == avs::ToneMapping::Shoulder ? 1 : 0);
  program->SetUniformf("u_shoulderStart", static_cast<float>(avs::DisplayTransform::ShoulderStart));
}
